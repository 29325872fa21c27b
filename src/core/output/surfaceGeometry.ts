/**
 * Geometry a viewer draws for the design surface, a plane or a cylinder (cylinder.ts's frame: the
 * contact of this pass at the origin, X the feed, Z the surface normal there; convex Rs > 0 with the
 * axis Rs below the contact, concave Rs < 0 with the axis |Rs| above, so the axis always passes
 * through z = -Rs). Pure functions returning plain numbers and typed arrays (mm, radians).
 *
 * Points on the surface are named by two lengths measured on it and a height above it:
 *  - `feed`: along the feed (X for a plane and for axis = feed; the arc length around the cylinder
 *    for axis = cross, where the passes go around it);
 *  - `cross`: across the feed (Y for a plane and for axis = cross, along the cylinder's axis; the
 *    arc length around the cylinder for axis = feed, where the step-over L is measured);
 *  - `height`: radially above the surface (away from the material), as the scallop height is
 *    measured (shared/notes/posture-and-surfaces.md): radius Rs + h convex, |Rs| - h concave.
 */

import type { Surface } from '../domain/surface';
import type { Vec3 } from '../math/vec';
import {
  aboveTangentMm,
  aroundMm,
  type CurvedPatch,
  curvedAxisFoot,
  curvedPatchExtent,
  curvedPointInto,
  type NumberSink,
} from './curvedSurfaceGeometry';

export type { NumberSink } from './curvedSurfaceGeometry';

/**
 * A surface the 3D scene draws: a plane, a cylinder, or a doubly curved patch (curvedSurfaceGeometry.ts:
 * the torus patch of a doubly curved point, a surface of revolution under three-axis waterline passes).
 */
export type DrawnSurface = Surface | CurvedPatch;

/** The point of the surface offset by `heightMm` at (feed, cross) (mm). */
export function surfacePoint(surface: DrawnSurface, feedMm: number, crossMm: number, heightMm: number): Vec3 {
  const p: Vec3 = [0, 0, 0];
  surfacePointInto(p, 0, surface, feedMm, crossMm, heightMm);
  return p;
}

/**
 * {@link surfacePoint} written into `out` at `offset`, `offset + 1`, `offset + 2` (x, y, z in mm),
 * so that a caller filling a buffer allocates nothing per point.
 */
export function surfacePointInto(
  out: NumberSink,
  offset: number,
  surface: DrawnSurface,
  feedMm: number,
  crossMm: number,
  heightMm: number,
): void {
  if (surface.kind === 'torus' || surface.kind === 'revolution') {
    curvedPointInto(out, offset, surface, feedMm, crossMm, heightMm);
    return;
  }
  if (surface.kind === 'plane') {
    out[offset] = feedMm;
    out[offset + 1] = crossMm;
    out[offset + 2] = heightMm;
    return;
  }
  // The arc length is the one coordinate measured around the cylinder.
  const feedAxis = surface.axis === 'feed';
  const arc = feedAxis ? crossMm : feedMm;
  const along = feedAxis ? feedMm : crossMm;
  const around = aroundMm(surface.radiusMm, arc, heightMm);
  out[offset] = feedAxis ? along : around;
  out[offset + 1] = feedAxis ? around : along;
  out[offset + 2] = aboveTangentMm(surface.radiusMm, arc, heightMm);
}

/**
 * A patch of the surface offset by `heightMm`: `feedHalfMm` and `crossHalfMm` either side of the
 * contact, measured on the surface (an arc around a cylinder is kept within half a turn either way),
 * as a grid of (segFeed + 1) x (segCross + 1) points, flat xyz, feed index outer. Triangles:
 * {@link patchIndices}. Written into `out` when given (at least that many numbers; a view's
 * vertex buffer, filled in place), else into a new array.
 */
export function surfacePatch<T extends NumberSink = Float64Array>(
  surface: DrawnSurface,
  heightMm: number,
  feedHalfMm: number,
  crossHalfMm: number,
  segFeed: number,
  segCross: number,
  out?: T,
): T {
  const [feedHalf, crossHalf] = patchExtent(surface, feedHalfMm, crossHalfMm);
  const to = out ?? (new Float64Array((segFeed + 1) * (segCross + 1) * 3) as NumberSink as T);
  let k = 0;
  for (let i = 0; i <= segFeed; i++) {
    const f = -feedHalf + (2 * feedHalf * i) / segFeed;
    for (let j = 0; j <= segCross; j++) {
      const c = -crossHalf + (2 * crossHalf * j) / segCross;
      surfacePointInto(to, k, surface, f, c, heightMm);
      k += 3;
    }
  }
  return to;
}

/** The patch's half extents (feed, cross) after keeping an arc within 0.98 of half a turn. */
export function patchExtent(surface: DrawnSurface, feedHalfMm: number, crossHalfMm: number): [number, number] {
  if (surface.kind === 'plane') return [feedHalfMm, crossHalfMm];
  if (surface.kind !== 'cylinder') return curvedPatchExtent(surface, feedHalfMm, crossHalfMm);
  const maxArc = 0.98 * Math.PI * Math.abs(surface.radiusMm);
  return surface.axis === 'feed'
    ? [feedHalfMm, Math.min(crossHalfMm, maxArc)]
    : [Math.min(feedHalfMm, maxArc), crossHalfMm];
}

/** Triangle indices of a {@link surfacePatch} grid. */
export function patchIndices(segFeed: number, segCross: number): Uint32Array {
  const out = new Uint32Array(segFeed * segCross * 6);
  const row = segCross + 1;
  let k = 0;
  for (let i = 0; i < segFeed; i++) {
    for (let j = 0; j < segCross; j++) {
      const a = i * row + j;
      const b = a + row;
      out[k++] = a;
      out[k++] = b;
      out[k++] = a + 1;
      out[k++] = a + 1;
      out[k++] = b;
      out[k++] = b + 1;
    }
  }
  return out;
}

/**
 * `n + 1` points of the surface offset by `heightMm` along the straight segment from
 * (feed, cross) `from` to `to` in surface coordinates (a circle's arc around a cylinder), flat xyz.
 */
export function surfacePolyline(
  surface: DrawnSurface,
  heightMm: number,
  from: readonly [number, number],
  to: readonly [number, number],
  n: number,
): Float64Array {
  const out = new Float64Array((n + 1) * 3);
  surfacePolylineInto(out, 0, surface, heightMm, from[0], from[1], to[0], to[1], n);
  return out;
}

/**
 * {@link surfacePolyline} from (fromFeedMm, fromCrossMm) to (toFeedMm, toCrossMm), written into
 * `out` from the point index `firstPoint` on (n + 1 points; nothing allocated).
 */
export function surfacePolylineInto(
  out: NumberSink,
  firstPoint: number,
  surface: DrawnSurface,
  heightMm: number,
  fromFeedMm: number,
  fromCrossMm: number,
  toFeedMm: number,
  toCrossMm: number,
  n: number,
): void {
  for (let i = 0; i <= n; i++) {
    const u = i / n;
    const feed = fromFeedMm + (toFeedMm - fromFeedMm) * u;
    const cross = fromCrossMm + (toCrossMm - fromCrossMm) * u;
    surfacePointInto(out, 3 * (firstPoint + i), surface, feed, cross, heightMm);
  }
}

/**
 * The rigid motion (a 4 x 4 matrix, column-major as three.js's Matrix4.fromArray reads it) that
 * carries the pass at the contact to the neighbouring pass whose contact lies `crossMm` across the
 * feed on the surface: a translation along Y on a plane and across a cylinder's axis (axis = cross,
 * passes stepped along the axis); a rotation about the cylinder's axis by -crossMm / Rs with the
 * axis along the feed. `mirror` first mirrors the pass across the feed (zigzag: the posture relative
 * to the feed). The surface's normal at the contact goes to the normal at the new contact. On the
 * torus patch of a doubly curved point, the rotation about m (Rs = Rc; a translation with Rc
 * infinite), as the notes define the next pass. (A surface of revolution's passes are not
 * congruent: its scene gives their motions itself; here a translation along Y.)
 */
export function passMatrix(surface: DrawnSurface, crossMm: number, mirror: boolean): number[] {
  const m = mirror ? -1 : 1;
  const rs =
    surface.kind === 'cylinder' && surface.axis === 'feed'
      ? surface.radiusMm
      : surface.kind === 'torus'
        ? surface.crossRadiusMm
        : Number.POSITIVE_INFINITY;
  if (!Number.isFinite(rs)) {
    return [1, 0, 0, 0, 0, m, 0, 0, 0, 0, 1, 0, 0, crossMm, 0, 1];
  }
  const alpha = -crossMm / rs;
  const c = Math.cos(alpha);
  const s = Math.sin(alpha);
  // p -> Rx(alpha) (S p - A) + A with A = (0, 0, -Rs) on the axis; Rx: y' = c y - s z, z' = s y + c z.
  // Translation A - Rx A = (0, -s Rs, -Rs + c Rs), the last written -2 Rs sin^2(alpha/2).
  const half = Math.sin(alpha / 2);
  const ty = -s * rs;
  const tz = -2 * rs * half * half;
  return [1, 0, 0, 0, 0, c * m, s * m, 0, 0, -s, c, 0, 0, ty, tz, 1];
}

/** A point transformed by a column-major 4 x 4 matrix (affine). */
export function applyMatrix(mat: readonly number[], p: Vec3): Vec3 {
  const e = (i: number) => mat[i] as number;
  return [
    e(0) * p[0] + e(4) * p[1] + e(8) * p[2] + e(12),
    e(1) * p[0] + e(5) * p[1] + e(9) * p[2] + e(13),
    e(2) * p[0] + e(6) * p[1] + e(10) * p[2] + e(14),
  ];
}

/**
 * Where the tool axis (through the tool centre `centre`, direction `axis` pointing up the shank)
 * meets the design surface below the centre: its foot. On a cylinder, the first crossing going
 * down (convex: the tool is outside; concave: inside the trough); the plane's foot if the line
 * misses a convex cylinder. On a doubly curved patch, curvedSurfaceGeometry.ts's foot.
 */
export function axisFoot(surface: DrawnSurface, centre: Vec3, axis: Vec3): Vec3 {
  if (surface.kind === 'torus' || surface.kind === 'revolution') return curvedAxisFoot(surface, centre, axis);
  const planeT = centre[2] / axis[2];
  const plane: Vec3 = [centre[0] - planeT * axis[0], centre[1] - planeT * axis[1], 0];
  if (surface.kind === 'plane') return plane;
  const rs = surface.radiusMm;
  // The components across the cylinder's axis (y, z for axis = feed; x, z for cross), from the axis.
  const i = surface.axis === 'feed' ? 1 : 0;
  const qy = centre[i];
  const qz = centre[2] + rs;
  const dy = -axis[i];
  const dz = -axis[2];
  // |q + t d|^2 = Rs^2, t >= 0 going down the axis.
  const a = dy * dy + dz * dz;
  const b = 2 * (qy * dy + qz * dz);
  const c = qy * qy + qz * qz - rs * rs;
  const disc = b * b - 4 * a * c;
  if (!(a > 0) || disc < 0) return plane;
  const root = Math.sqrt(disc);
  const t1 = (-b - root) / (2 * a);
  const t2 = (-b + root) / (2 * a);
  const t = rs > 0 ? (t1 >= 0 ? t1 : t2) : t2;
  if (!(t >= 0)) return plane;
  return [centre[0] - t * axis[0], centre[1] - t * axis[1], centre[2] - t * axis[2]];
}

/**
 * Points of a cross-feed section (flat y, z from the contact: a pass's plane profile, which with the
 * axis along the feed is also its profile on the cylinder) in surface coordinates: the arc length
 * across the feed from the contact, and the radial height (flat cross, height). A plane or a
 * cylinder with the axis across the feed (straight across the feed in this section) keeps them.
 */
export function toSurfaceSection(surface: Surface, points: ArrayLike<number>): Float64Array {
  const out = Float64Array.from(points as ArrayLike<number>);
  if (surface.kind === 'plane' || surface.axis === 'cross') return out;
  const rs = surface.radiusMm;
  const abs = Math.abs(rs);
  const side = rs > 0 ? 1 : -1;
  for (let i = 0; i + 1 < out.length; i += 2) {
    const y = out[i] as number;
    const z = out[i + 1] as number;
    const qz = z + rs;
    const rho = Math.sqrt(y * y + qz * qz);
    // (+ 0: no -0 at the contact.)
    out[i] = abs * Math.atan2(y, side * qz) + 0;
    // rho - Rs convex, |Rs| - rho concave, from rho^2 - Rs^2 = y^2 + z (z + 2 Rs).
    out[i + 1] = (side * (y * y + z * (z + 2 * rs))) / (rho + abs) + 0;
  }
  return out;
}

/**
 * The inverse of {@link toSurfaceSection} for one point: (y, z) of (cross, height), written into
 * `out` when given (a caller's two numbers, reused from point to point), else into a new pair.
 */
export function fromSurfaceSection(
  surface: Surface,
  crossMm: number,
  heightMm: number,
  out: [number, number] = [0, 0],
): [number, number] {
  if (surface.kind === 'plane' || surface.axis === 'cross') {
    out[0] = crossMm;
    out[1] = heightMm;
    return out;
  }
  // The point of the section through the contact (x = 0) around the cylinder, axis along the feed.
  out[0] = aroundMm(surface.radiusMm, crossMm, heightMm);
  out[1] = aboveTangentMm(surface.radiusMm, crossMm, heightMm);
  return out;
}
