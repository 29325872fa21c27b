/**
 * The doubly curved point (issue 19; shared/notes/doubly-curved-and-3-axis.md, section 1): exact
 * step-over and cusp heights, flank and shank limits and gouging with each radius's limit. Pure: no
 * DOM, no three.js. What sits above the surfaces is elsewhere: the comparison rows in
 * procedures/compareDoublyCurved.ts, the roughness in roughness/doublyCurved.ts, and the validation
 * of its three questions (h, L or Ra: the Ra bound is roughness's) in roughness/doublyCurvedValidate.ts.
 */
export * from './equatorFlank';
export * from './gouging';
export * from './passSection';
export * from './shankLimit';
export * from './solve';
export * from './types';
