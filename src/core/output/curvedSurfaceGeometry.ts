/**
 * Geometry a viewer draws for the doubly curved surfaces (shared/notes/doubly-curved-and-3-axis.md):
 * the torus patch of a doubly curved point (section 1) and the surface of revolution about a
 * vertical axis of three-axis waterline passes (section 2b), each in the local frame of its CC
 * point (the CC point at the origin, X the feed, Z the surface normal out of the material). Points
 * are named as in surfaceGeometry.ts: `feed` and `cross` lengths measured on the surface from the
 * CC point, `height` along the normal (the offset surface, as the scallop height is measured).
 * Pure functions returning plain numbers (mm, degrees at the interface).
 */

import type { Vec3 } from '../math/vec';

/** A writable list of numbers: a plain array or a typed one (a three.js buffer's Float32Array). */
export type NumberSink = { [index: number]: number };

/**
 * The torus patch of a doubly curved point (section 1): the feed circle (centre (0, 0, -Rf), in
 * the XZ plane) revolved about the main axis m (through (0, 0, -Rc), parallel to X). Signed radii
 * (mm): > 0 convex, < 0 concave, +-Infinity straight; |R| >= 0.001 mm.
 */
export interface TorusPatch {
  readonly kind: 'torus';
  readonly feedRadiusMm: number;
  readonly crossRadiusMm: number;
}

/**
 * A surface of revolution about a vertical axis at a CC point of slope `slopeDeg` (section 2b),
 * in a local frame whose X is the horizontal feed and whose Y runs DOWN the slope along the
 * meridian (so the next waterline pass lies at cross = +L): the meridian circle (radius |Rc|,
 * centre (0, 0, -Rc), in the YZ plane) revolved about the vertical line through the point
 * CC - Rf n. Machine frame of {@link revolutionFrame}: x uphill, z up. Radii signed as in
 * {@link TorusPatch} (`Rf` along the horizontal circle, `Rc` the meridian's); 0 < slope < 90 degrees.
 */
export interface RevolutionPatch {
  readonly kind: 'revolution';
  readonly slopeDeg: number;
  readonly feedRadiusMm: number;
  readonly crossRadiusMm: number;
}

/** A doubly curved surface the scene draws. */
export type CurvedPatch = TorusPatch | RevolutionPatch;

/**
 * On a circle of signed radius `rs` (+-Infinity: a straight line) tangent to the X axis at the
 * origin, the point `heightMm` above it (radially) at the arc length `arcMm`: its distance along
 * the tangent (mm). Convex rs > 0 has its centre at -rs below, concave above.
 */
export function aroundMm(rs: number, arcMm: number, heightMm: number): number {
  if (!Number.isFinite(rs)) return arcMm;
  const abs = Math.abs(rs);
  const side = rs > 0 ? 1 : -1;
  return (abs + side * heightMm) * Math.sin(arcMm / abs);
}

/** The same point's height above the tangent (mm), without cancellation for a large radius. */
export function aboveTangentMm(rs: number, arcMm: number, heightMm: number): number {
  if (!Number.isFinite(rs)) return heightMm;
  const abs = Math.abs(rs);
  const side = rs > 0 ? 1 : -1;
  const theta = arcMm / abs;
  const half = Math.sin(theta / 2);
  // Convex (Rs + h) cos(theta) - Rs = h cos(theta) - 2 Rs sin^2(theta/2); concave mirrored.
  return heightMm * Math.cos(theta) - side * 2 * abs * half * half;
}

/** A 3 x 3 rotation as its columns: the local frame's X, Y, Z in machine coordinates. */
export type Frame = readonly [Vec3, Vec3, Vec3];

/**
 * The local frame of a CC point of slope `slopeDeg` on a surface of revolution, in the machine frame
 * (x uphill in plan, z up, the meridian plane y = 0): X = (0, 1, 0) the horizontal feed, Y =
 * (-cos a, 0, -sin a) down the slope, Z = (-sin a, 0, cos a) the normal.
 */
export function revolutionFrame(slopeDeg: number): Frame {
  const a = (slopeDeg * Math.PI) / 180;
  const s = Math.sin(a);
  const c = Math.cos(a);
  return [
    [0, 1, 0],
    [-c, 0, -s],
    [-s, 0, c],
  ];
}

/** A local point in the machine frame (`frame` from {@link revolutionFrame} or machineGeometry.ts). */
export function toMachine(frame: Frame, p: Vec3): Vec3 {
  const [X, Y, Z] = frame;
  return [
    p[0] * X[0] + p[1] * Y[0] + p[2] * Z[0],
    p[0] * X[1] + p[1] * Y[1] + p[2] * Z[1],
    p[0] * X[2] + p[1] * Y[2] + p[2] * Z[2],
  ];
}

/** A machine point in the local frame (the transpose of {@link toMachine}). */
export function toLocal(frame: Frame, p: Vec3): Vec3 {
  const d = (v: Vec3) => p[0] * v[0] + p[1] * v[1] + p[2] * v[2];
  return [d(frame[0]), d(frame[1]), d(frame[2])];
}

/**
 * The point of the patch offset by `heightMm` at (feed, cross), local frame, written into `out` at
 * `offset`..`offset + 2` (mm; nothing allocated).
 * Torus: the feed circle's point at the arc `feed` (offset by h), turned about m by cross / |Rc|.
 * Revolution: the meridian circle's point at the arc `cross` (offset by h), turned about the
 * vertical axis by the angle that carries the CC point `feed` along its horizontal circle.
 */
export function curvedPointInto(
  out: NumberSink,
  offset: number,
  s: CurvedPatch,
  feedMm: number,
  crossMm: number,
  heightMm: number,
): void {
  if (s.kind === 'torus') {
    const z1 = aboveTangentMm(s.feedRadiusMm, feedMm, heightMm);
    out[offset] = aroundMm(s.feedRadiusMm, feedMm, heightMm);
    out[offset + 1] = aroundMm(s.crossRadiusMm, crossMm, z1);
    out[offset + 2] = aboveTangentMm(s.crossRadiusMm, crossMm, z1);
    return;
  }
  const frame = revolutionFrame(s.slopeDeg);
  // The meridian point, then in the machine frame (y = 0).
  const m = toMachine(frame, [
    0,
    aroundMm(s.crossRadiusMm, crossMm, heightMm),
    aboveTangentMm(s.crossRadiusMm, crossMm, heightMm),
  ]);
  let x = m[0];
  let y = feedMm;
  const rf = s.feedRadiusMm;
  if (Number.isFinite(rf)) {
    // About the vertical through x = Rf sin(a); the CC point moves +y (X) by `feed` along its circle.
    const xA = rf * Math.sin((s.slopeDeg * Math.PI) / 180);
    const gamma = -feedMm / xA;
    const half = Math.sin(gamma / 2);
    y = (m[0] - xA) * Math.sin(gamma);
    x = m[0] * Math.cos(gamma) + 2 * xA * half * half;
  }
  const local = toLocal(frame, [x, y, m[2]]);
  out[offset] = local[0];
  out[offset + 1] = local[1];
  out[offset + 2] = local[2];
}

/** Height of `r` above `q` (mm) with r^2 - q^2 = `diff` (no cancellation); r, q >= 0. */
function radialGap(diff: number, r: number, q: number): number {
  return diff / (r + q);
}

/**
 * The height of the local point `p` above the patch (mm): the offset `h` of the offset surface
 * through it (0 on the patch, > 0 on the tool's side), valid near the patch (within the radii).
 */
export function curvedHeightAboveMm(s: CurvedPatch, p: Vec3): number {
  if (s.kind === 'torus') {
    // Turned back about m into the plane Y = 0, then measured from the feed circle.
    const rc = s.crossRadiusMm;
    let z1 = p[2];
    if (Number.isFinite(rc)) {
      const rho = Math.hypot(p[1], p[2] + rc);
      z1 = (rc > 0 ? 1 : -1) * radialGap(p[1] * p[1] + p[2] * (p[2] + 2 * rc), rho, Math.abs(rc));
    }
    const rf = s.feedRadiusMm;
    if (!Number.isFinite(rf)) return z1;
    const d = Math.hypot(p[0], z1 + rf);
    return (rf > 0 ? 1 : -1) * radialGap(p[0] * p[0] + z1 * (z1 + 2 * rf), d, Math.abs(rf));
  }
  const frame = revolutionFrame(s.slopeDeg);
  const m = toMachine(frame, p);
  let x = m[0];
  const rf = s.feedRadiusMm;
  if (Number.isFinite(rf)) {
    // Turned back about the vertical axis into the meridian plane, on the CC point's side.
    const xA = rf * Math.sin((s.slopeDeg * Math.PI) / 180);
    x = xA - Math.sign(xA) * Math.hypot(m[0] - xA, m[1]);
  }
  const q = toLocal(frame, [x, 0, m[2]]);
  const rc = s.crossRadiusMm;
  if (!Number.isFinite(rc)) return q[2];
  const rho = Math.hypot(q[1], q[2] + rc);
  return (rc > 0 ? 1 : -1) * radialGap(q[1] * q[1] + q[2] * (q[2] + 2 * rc), rho, Math.abs(rc));
}

/**
 * Where the tool axis (through `centre`, direction `axis` up the shank, local frame) first meets
 * the patch going down from the centre: stepped down by a quarter of the height left, then bisected
 * (60 halvings). The tangent plane's foot when the axis does not reach the patch within 400 steps.
 */
export function curvedAxisFoot(s: CurvedPatch, centre: Vec3, axis: Vec3): Vec3 {
  const at = (t: number): Vec3 => [centre[0] - t * axis[0], centre[1] - t * axis[1], centre[2] - t * axis[2]];
  const planeT = centre[2] / axis[2];
  let lo = 0;
  let hLo = curvedHeightAboveMm(s, centre);
  if (!(hLo > 0)) return at(planeT);
  const scaleMm = Math.max(hLo, Math.abs(planeT));
  for (let i = 0; i < 400; i++) {
    const hi = lo + Math.max(0.25 * hLo, 1e-6 * scaleMm);
    const hHi = curvedHeightAboveMm(s, at(hi));
    if (hHi <= 0) {
      let a = lo;
      let b = hi;
      for (let j = 0; j < 60; j++) {
        const mid = 0.5 * (a + b);
        if (curvedHeightAboveMm(s, at(mid)) > 0) a = mid;
        else b = mid;
      }
      return at(0.5 * (a + b));
    }
    lo = hi;
    hLo = hHi;
  }
  return at(planeT);
}

/** Half extents (feed, cross) of a patch kept within 0.98 of half a turn of each circle. */
export function curvedPatchExtent(s: CurvedPatch, feedHalfMm: number, crossHalfMm: number): [number, number] {
  const turn = (r: number) => 0.98 * Math.PI * Math.abs(r);
  const feedCircle = s.kind === 'torus' ? s.feedRadiusMm : s.feedRadiusMm * Math.sin((s.slopeDeg * Math.PI) / 180);
  return [Math.min(feedHalfMm, turn(feedCircle)), Math.min(crossHalfMm, turn(s.crossRadiusMm))];
}
