/**
 * Pure geometry of the marks the 3D scene draws besides the surfaces and the tool: a circle in a
 * given plane (a cusp's section, the traced section) and a dimension along the design surface (the
 * step-over L and L/2, with extension lines and arrowheads). Each writes flat xyz points (mm) into
 * a caller's buffer from a given point index on, so a view fills its vertex buffers in place and
 * allocates nothing per point. The frame is surfaceGeometry.ts's: the contact at the origin, X the
 * feed, Z the surface normal there.
 */

import type { Vec3 } from '../math/vec';
import { type DrawnSurface, type NumberSink, surfacePointInto, surfacePolylineInto } from './surfaceGeometry';

/**
 * Writes `n` points of the circle of radius `radiusMm` about `centre` in the plane with the unit
 * normal `normal` into `out` from the point index `firstPoint` on: the point at angle 2 pi i / n
 * is centre + r (cos u + sin v), u and v unit vectors perpendicular to the normal and to each other
 * (u along Z x normal, or X when the normal is along Z).
 *
 * @param radiusMm the radius, mm (>= 0)
 * @param n points, >= 3 (a closed loop: the first point is not repeated)
 */
export function circleInto(
  out: NumberSink,
  firstPoint: number,
  centre: Vec3,
  normal: Vec3,
  radiusMm: number,
  n: number,
): void {
  const [nx, ny, nz] = normal;
  // u = Z x normal, normalised (X when the normal is along Z); v = normal x u, normalised.
  let ux = -ny;
  let uy = nx;
  let uz = 0;
  if (ux * ux + uy * uy < 1e-12) {
    ux = 1;
    uy = 0;
  }
  const uScale = 1 / (Math.sqrt(ux * ux + uy * uy + uz * uz) || 1);
  ux *= uScale;
  uy *= uScale;
  uz *= uScale;
  let vx = ny * uz - nz * uy;
  let vy = nz * ux - nx * uz;
  let vz = nx * uy - ny * ux;
  const vScale = 1 / (Math.sqrt(vx * vx + vy * vy + vz * vz) || 1);
  vx *= vScale;
  vy *= vScale;
  vz *= vScale;
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n;
    const c = Math.cos(a) * radiusMm;
    const s = Math.sin(a) * radiusMm;
    const k = 3 * (firstPoint + i);
    out[k] = centre[0] + c * ux + s * vx;
    out[k + 1] = centre[1] + c * uy + s * vy;
    out[k + 2] = centre[2] + c * uz + s * vz;
  }
}

/** Points of a {@link surfaceDimensionInto} drawn with `segments` segments along the surface. */
export function dimensionPointCount(segments: number): number {
  return segments + 12;
}

/**
 * Writes the dimension of a length measured across the feed along the design surface, at `xMm`
 * along the feed, from the contact's path (cross = 0) to `lengthMm` across: an extension line
 * `tickMm` high, an arrowhead, the arc along the surface in `segments` segments, the other arrowhead
 * and extension line, as one polyline of {@link dimensionPointCount} points from `firstPoint` on.
 * Each arrowhead is two strokes `arrowMm` long (back along the dimension, half as far aside).
 *
 * @returns the number of points written
 */
export function surfaceDimensionInto(
  out: NumberSink,
  firstPoint: number,
  surface: DrawnSurface,
  xMm: number,
  lengthMm: number,
  tickMm: number,
  arrowMm: number,
  segments: number,
): number {
  let i = firstPoint;
  const point = (feedMm: number, crossMm: number, heightMm: number) => {
    surfacePointInto(out, 3 * i, surface, feedMm, crossMm, heightMm);
    i++;
  };
  const head = (yMm: number, dir: 1 | -1) => {
    point(xMm - 0.5 * arrowMm, yMm + dir * arrowMm, 0);
    point(xMm, yMm, 0);
    point(xMm + 0.5 * arrowMm, yMm + dir * arrowMm, 0);
    point(xMm, yMm, 0);
  };
  point(xMm, 0, tickMm);
  point(xMm, 0, 0);
  head(0, 1);
  surfacePolylineInto(out, i, surface, 0, xMm, 0, xMm, lengthMm, segments);
  i += segments + 1;
  head(lengthMm, -1);
  point(xMm, lengthMm, tickMm);
  return i - firstPoint;
}
