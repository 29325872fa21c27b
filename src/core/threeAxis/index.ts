/**
 * Three-axis machining (issue 20): the tool upright, the surface sloped. Sloped planes with raster
 * or waterline passes (the posture in closed form, then the posture solver), waterline passes on
 * surfaces of revolution (the exact meridian-plane construction), and the slope sweep.
 */
export * from './errors';
export * from './meridianCusp';
export * from './meridianPasses';
export * from './meridianTool';
export * from './revolutionGouging';
export * from './slopedPlane';
export * from './slopePosture';
export * from './slopeSweep';
export * from './solve';
export * from './validate';
export * from './waterlineRevolution';
