/**
 * Geometry the 3D scene draws for three-axis machining (shared/notes/doubly-curved-and-3-axis.md,
 * section 2): where the local frame of the CC point (X the feed, Z the surface normal; the frame
 * every other drawing uses) sits in the machine frame (z up, the tool axis), and the steps as the
 * CAM system programs them as dimension lines: `Lxy`, the horizontal distance between the vertical
 * planes of two raster passes, and `dz`, the vertical distance between two waterline passes' tool
 * tips. Pure functions returning plain numbers (mm, degrees at the interface); points in the local
 * frame unless a name says machine.
 */

import { cross, dot, norm, type Vec3 } from '../math/vec';
import { type Frame, toLocal, toMachine } from './curvedSurfaceGeometry';

/**
 * The local frame of a CC point on a plane of slope `slopeDeg` (0 <= alpha < 90) under raster passes
 * at plan angle `rasterAngleDeg` to the fall line (90: waterline), in the machine frame whose x is
 * the uphill plan direction, as core/threeAxis/slopePosture.ts derives it: Z = (-sin a, 0, cos a),
 * X = (cos psi, -sin psi, tan a cos psi) / N climbing the slope, Y = Z x X (uphill on the left).
 * The machine's z in this frame is slopePosture's tool axis.
 */
export function slopeFrame(slopeDeg: number, rasterAngleDeg: number): Frame {
  const a = (slopeDeg * Math.PI) / 180;
  const p = (rasterAngleDeg * Math.PI) / 180;
  const sa = Math.sin(a);
  const ca = Math.cos(a);
  const Z: Vec3 = [-sa, 0, ca];
  // X along the CC path, perpendicular to Z: (cos psi, -sin psi, tan a cos psi) scaled by cos a.
  const xr: Vec3 = [ca * Math.cos(p), -ca * Math.sin(p), sa * Math.cos(p)];
  const n = norm(xr);
  const X: Vec3 = [xr[0] / n, xr[1] / n, xr[2] / n];
  return [X, cross(Z, X), Z];
}

/** The rotation local -> machine as a column-major 4 x 4 matrix (three.js's Matrix4.fromArray). */
export function frameMatrix(frame: Frame): number[] {
  const [X, Y, Z] = frame;
  return [X[0], X[1], X[2], 0, Y[0], Y[1], Y[2], 0, Z[0], Z[1], Z[2], 0, 0, 0, 0, 1];
}

/** A dimension line: its polyline (flat xyz, local frame), its two ends and where its label goes. */
export interface StepDimension {
  readonly points: Float64Array;
  readonly start: Vec3;
  readonly end: Vec3;
  readonly labelAt: Vec3;
}

/** Machine point p + k d. */
function along(p: Vec3, d: Vec3, k: number): Vec3 {
  return [p[0] + k * d[0], p[1] + k * d[1], p[2] + k * d[2]];
}

/**
 * Writes the dimension from `start` to `end` (machine frame) with extension lines from `fromA` and
 * `fromB` and two arrowheads `arrowMm` long whose strokes spread along `aside`, as one local polyline.
 */
function dimension(
  frame: Frame,
  fromA: Vec3,
  start: Vec3,
  end: Vec3,
  fromB: Vec3,
  aside: Vec3,
  arrowMm: number,
): StepDimension {
  const d: Vec3 = [end[0] - start[0], end[1] - start[1], end[2] - start[2]];
  const len = norm(d) || 1;
  const u: Vec3 = [d[0] / len, d[1] / len, d[2] / len];
  const head = (tip: Vec3, dir: 1 | -1): Vec3[] => {
    const back = along(tip, u, dir * arrowMm);
    return [along(back, aside, 0.5 * arrowMm), tip, along(back, aside, -0.5 * arrowMm), tip];
  };
  // Extension, line with its two arrowheads (each stroke out and back to the tip), extension.
  const machine = [fromA, start, ...head(start, 1), end, ...head(end, -1), fromB];
  const points = new Float64Array(machine.length * 3);
  machine.forEach((p, i) => {
    points.set(toLocal(frame, p), 3 * i);
  });
  const mid = along(start, d, 0.5);
  return { points, start: toLocal(frame, start), end: toLocal(frame, end), labelAt: toLocal(frame, mid) };
}

/**
 * `Lxy` of raster passes: from this pass's vertical plane (through the CC point, containing the
 * feed X and the machine's z) horizontally, along the planes' horizontal normal, to the next pass's
 * plane (through (0, L, 0)), `liftMm` above the higher CC point; extension lines drop vertically to
 * each pass's CC path. Its length is `L |Y . m|` (slopePosture.ts: `Lxy`).
 * @param intervalMm L along the surface (> 0); @param liftMm height of the line above the CC points.
 */
export function horizontalStepDimension(
  frame: Frame,
  intervalMm: number,
  liftMm: number,
  arrowMm: number,
): StepDimension {
  const X = frame[0];
  const up: Vec3 = [0, 0, 1];
  const c = cross(up, X);
  const cn = norm(c) || 1;
  const m: Vec3 = [c[0] / cn, c[1] / cn, 0];
  const p1 = toMachine(frame, [0, intervalMm, 0]);
  const span = dot(p1, m);
  const z = Math.max(0, p1[2]) + liftMm;
  const start: Vec3 = [0, 0, z];
  const end: Vec3 = along(start, m, span);
  // The point of the next CC path right below the line's end: p1 + t X with the same plan position.
  const xh = Math.hypot(X[0], X[1]) || 1;
  const t = ((end[0] - p1[0]) * X[0] + (end[1] - p1[1]) * X[1]) / (xh * xh);
  const foot1 = along(p1, X, t);
  return dimension(frame, [0, 0, 0], start, end, foot1, up, arrowMm);
}

/**
 * `dz` of waterline passes: a vertical line between the heights of the two tool tips `tip0` and
 * `tip1` (local frame), `outMm` beyond this pass's tip horizontally along the feed, with horizontal
 * extension lines from each tip. Its ends stand at the two tips' machine heights.
 */
export function stepDownDimension(frame: Frame, tip0: Vec3, tip1: Vec3, outMm: number, arrowMm: number): StepDimension {
  const a = toMachine(frame, tip0);
  const b = toMachine(frame, tip1);
  const X = frame[0];
  const xh = Math.hypot(X[0], X[1]) || 1;
  const out: Vec3 = [X[0] / xh, X[1] / xh, 0];
  const start = along(a, out, outMm);
  const end: Vec3 = [start[0], start[1], b[2]];
  return dimension(frame, a, start, end, b, out, arrowMm);
}
