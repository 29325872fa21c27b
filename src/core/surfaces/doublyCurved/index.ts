/**
 * The doubly curved point (issue 19; shared/notes/doubly-curved-and-3-axis.md, section 1): exact
 * step-over and cusp heights, flank and shank limits, gouging with each radius's limit, and the
 * comparison rows. Pure: no DOM, no three.js.
 */
export * from './compare';
export * from './equatorFlank';
export * from './gouging';
export * from './passSection';
export * from './roughness';
export * from './shankLimit';
export * from './solve';
export * from './types';
export * from './validate';
