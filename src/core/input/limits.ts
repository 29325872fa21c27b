/** The physical limits of the inputs, mm: the bounds validation checks and error messages name. */

/** Smallest and largest |Rs| of a cylinder, mm; beyond the largest a plane answers to 1e-9 mm (and the arithmetic keeps its digits). */
export const MIN_SURFACE_RADIUS_MM = 0.001;
export const MAX_SURFACE_RADIUS_MM = 1e6;

/** Largest tool radius accepted, in mm: keeps every intermediate product far from overflow. */
export const MAX_TOOL_RADIUS_MM = 1000;

/** Smallest tool radius accepted, in mm (the smallest micro end mills are 0.005 mm across). */
export const MIN_TOOL_RADIUS_MM = 0.001;

/**
 * Smallest scallop height accepted, in mm: one nanometre, far below any measurable scallop,
 * so every result stays a normal floating-point number. The step-over's smallest is twice it.
 */
export const MIN_LENGTH_MM = 1e-9;
