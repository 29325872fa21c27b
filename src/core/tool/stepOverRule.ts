/**
 * The step-over rule: how two flanks of a pass combine into the distance between adjacent passes
 * (shared/notes/posture-and-surfaces.md, "Pass patterns"). The one place it is written: the plane's
 * and the cylinders' solvers, their fast paths and the validators' widest step-over all call it.
 */
import type { PassPattern } from '../domain/tool';

/**
 * Step-over from the reaches of the two flanks at the scallop height.
 *
 * One-way (every pass the same profile): the cusp joins the right flank of one pass and the left
 * flank of the next, so the step-over is `right + left`. Zigzag (every other pass mirrored): cusps
 * alternate between two right flanks and two left flanks, and no cusp may rise above the height, so
 * the step-over is `2 min(right, left)`. Without tilt both give the paper's `2 (L/2)`.
 *
 * @param pattern the pass pattern.
 * @param rightReach reach of the right (+Y) flank from the contact, >= 0: a width in mm on a plane
 *   or across a cylinder's axis, a polar angle in radians along it (the caller converts).
 * @param leftReach the left flank's, in the same unit.
 * @returns the step-over in the reaches' unit.
 */
export function stepOverFromReaches(pattern: PassPattern, rightReach: number, leftReach: number): number {
  return pattern === 'one-way' ? rightReach + leftReach : 2 * Math.min(rightReach, leftReach);
}

/**
 * The cusps and flank widths of an inverse answer (mm, every surface's, before its own extras) for
 * passes `L` apart whose cusps stand where each flank reaches L/2 (zigzag, or one-way without
 * tilt): the scallop height is the higher cusp, zigzag's other cusp the lower one.
 *
 * @param hR height of the right flank's cusp, mm; `hL` the left's.
 * @param zigzag whether the passes alternate (then both cusps stand).
 * @param contactOffsetMm the contact offset y0.
 */
export function cuspsAtHalfInterval(L: number, hR: number, hL: number, zigzag: boolean, contactOffsetMm: number) {
  return {
    intervalMm: L,
    cuspHeightMm: Math.max(hR, hL),
    otherCuspHeightMm: zigzag ? Math.min(hR, hL) : null,
    rightCuspHeightMm: hR,
    leftCuspHeightMm: hL,
    halfWidthRightMm: L / 2,
    halfWidthLeftMm: L / 2,
    contactOffsetMm,
  };
}

/** One-way passes `L` apart whose one cusp stands at height `z` (mm), the flanks `wR` and `wL` wide there. */
export function oneWayCusps(L: number, z: number, wR: number, wL: number, contactOffsetMm: number) {
  return {
    intervalMm: L,
    cuspHeightMm: z,
    otherCuspHeightMm: null,
    rightCuspHeightMm: z,
    leftCuspHeightMm: z,
    halfWidthRightMm: wR,
    halfWidthLeftMm: wL,
    contactOffsetMm,
  };
}
