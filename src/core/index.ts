/**
 * Pure solver core: no DOM, no three.js. Runs unchanged in Node, a Web Worker and tests.
 */

export * from './finish/index';
export * from './input/units';
export * from './input/validate';
export * from './output/geometry';
export * from './output/surfaceGeometry';
export * from './procedures/approximations';
export * from './procedures/compare';
export * from './procedures/procedures';
export * from './procedures/trace';
export * from './roughness/roughness';
export * from './simulation/simulation';
export * from './surfaces/cylinder';
export * from './surfaces/exact';
export * from './surfaces/registry';
export * from './surfaces/solve';
export * from './surfaces/surface';
export * from './surfaces/validate';
export * from './tool/placement';
export * from './tool/posture';
export * from './tool/profile';
export * from './tool/stepOverRule';
