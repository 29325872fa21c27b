/**
 * Pure solver core: no DOM, no three.js. Runs unchanged in Node, a Web Worker and tests.
 */
export * from './approximations';
export * from './compare';
export * from './cylinder';
export * from './exact';
export * from './geometry';
export * from './placement';
export * from './posture';
export * from './procedures';
export * from './roughness';
export * from './simulation';
export * from './stepOverRule';
export * from './surfaceGeometry';
export * from './trace';
export * from './units';
export * from './validate';
