/**
 * Height exaggeration of the 3D scene (pure). At a realistic scallop height (50 um under a 6 mm
 * tool) the h pseudo plane lies on the design plane and the scallop cannot be seen; the scene then
 * draws heights from the plane up to a band just above the scallop N times taller, and the rest
 * of the tool above that band at true scale (so the tool keeps its shape). Only the drawing
 * changes: every number shown stays the solver's.
 */
import { autoExaggeration } from '../core/output/drawingScale';

/**
 * The largest 1-2-5 factor (up to x1000, as the profile view offers) at which the scallop height
 * `scallopHeightMm` is drawn at most `fraction` of the tool radius `toolRadiusMm` (1, true
 * scale, when the scallop is already that tall or a size is not a positive finite number).
 */
export function sceneHeightExaggeration(toolRadiusMm: number, scallopHeightMm: number, fraction = 0.12): number {
  return autoExaggeration(toolRadiusMm, scallopHeightMm, fraction);
}

/** Heights drawn: `factor` times taller from the plane up to `bandMm`, true scale below and above. */
export interface HeightMap {
  readonly factor: number;
  /** The top of the exaggerated band (mm above the plane, true value). */
  readonly bandMm: number;
}

/** The band exaggerated for a scallop `scallopHeightMm` high: twice its height. */
export function heightMapFor(factor: number, scallopHeightMm: number): HeightMap {
  return { factor, bandMm: factor === 1 ? 0 : 2 * scallopHeightMm };
}

/**
 * The drawn height of a point `zMm` above the plane: `factor * z` in the band, continued at true
 * scale above it (continuous and increasing, so nothing folds over); below the plane unchanged.
 */
export function drawnHeightMm(map: HeightMap, zMm: number): number {
  if (map.factor === 1 || zMm <= 0) return zMm;
  if (zMm <= map.bandMm) return map.factor * zMm;
  return map.factor * map.bandMm + (zMm - map.bandMm);
}

/** A copy of flat xyz points with each z drawn through `map`. */
export function drawnPoints(map: HeightMap, xyz: ArrayLike<number>): Float32Array {
  const out = Float32Array.from(xyz as ArrayLike<number>);
  drawHeightsInPlace(map, out, out.length / 3);
  return out;
}

/**
 * Draws the heights of the first `count` points of flat xyz `xyz` through `map`, in place (a
 * view's vertex buffer, just written with true heights: nothing is allocated).
 */
export function drawHeightsInPlace(map: HeightMap, xyz: { [index: number]: number }, count: number): void {
  if (map.factor === 1) return;
  for (let i = 2; i < 3 * count; i += 3) xyz[i] = drawnHeightMm(map, xyz[i] as number);
}
