/**
 * The tool in its posture in 3D: frame, ring and torus sections. Pure (plain tuples and numbers).
 *
 * Frame (shared/notes/posture-and-surfaces.md): X = feed, Z = surface normal, Y = Z x X; the
 * cutter-contact point of the pass is the origin and the design plane is z = 0. The tool axis is
 * `a = (cos beta sin rho, sin beta, cos beta cos rho)`. The ring of corner centres (radius Rb,
 * centre O) is spanned by `v1 = (0, cos phi, -sin phi)` and `v2 = v1 x a =
 * (k, -a_x sin phi, -a_x cos phi)` with `k = sqrt(1 - a_x^2)`: its point at ring angle t is
 * `O + Rb (sin t v1 + cos t v2)`, which projects along X onto the ellipse point
 * `e(t) = (a sin t, -b cos t)` of posture.ts. Without tilt v2 is the paper's XT and t is its gamma.
 * A torus section is the circle of radius Rcr around a ring point, in the plane spanned by the
 * radial direction `r(t) = sin t v1 + cos t v2` and `a`; its normal is the ring tangent
 * `T(t) = cos t v1 - sin t v2`. Lengths mm, angles radians.
 */

import type { ToolInput } from '../domain/tool';
import { degToRad } from '../input/units';
import { addScaled, type Vec3 } from '../math/vec';
import { type PostureShape, shapeOfTool } from './posture';

export interface Placement {
  readonly shape: PostureShape;
  readonly ringRadiusMm: number;
  readonly cornerRadiusMm: number;
  /** Tool centre point O (centre of the ring of corner centres), mm. */
  readonly centre: Vec3;
  /** Unit tool axis a (tip to shank). */
  readonly axis: Vec3;
  /** Orthonormal ring basis (see the module comment). */
  readonly v1: Vec3;
  readonly v2: Vec3;
  /** Ring angle of the contact. */
  readonly contactRingAngleRad: number;
}

/** The tool placed with its contact at the origin. @param tool validated tool and posture. */
export function placeTool(tool: ToolInput): Placement {
  const shape = shapeOfTool(tool);
  const rho = degToRad(tool.leadAngleDeg);
  const beta = degToRad(tool.tiltAngleDeg);
  const ax = Math.cos(beta) * Math.sin(rho);
  const axis: Vec3 = [ax, Math.sin(beta), Math.cos(beta) * Math.cos(rho)];
  const k = Math.sqrt(Math.max(0, 1 - ax * ax));
  const { sinPhi, cosPhi } = shape;
  const v1: Vec3 = [0, cosPhi, -sinPhi];
  const v2: Vec3 = [k, -ax * sinPhi, -ax * cosPhi];
  const rb = shape.a;
  const rcr = shape.rcr;
  // O = contact + Rcr Z - Rb (sin t0 v1 + cos t0 v2); `0 -` keeps a zero offset +0, never -0. A
  // flat bottom lying flat touches with its whole face: the contact is the face's centre, under O.
  const centre: Vec3 = shape.flatOnPlane
    ? [0, 0, rcr]
    : [
        0 - rb * (shape.sinT0 * v1[0] + shape.cosT0 * v2[0]),
        0 - rb * (shape.sinT0 * v1[1] + shape.cosT0 * v2[1]),
        rcr - rb * (shape.sinT0 * v1[2] + shape.cosT0 * v2[2]),
      ];
  return {
    shape,
    ringRadiusMm: rb,
    cornerRadiusMm: rcr,
    centre,
    axis,
    v1,
    v2,
    contactRingAngleRad: Math.atan2(shape.sinT0, shape.cosT0),
  };
}

/** Unit radial direction r(t) of the ring. */
export function ringRadial(p: Placement, t: number): Vec3 {
  const s = Math.sin(t);
  const c = Math.cos(t);
  return [s * p.v1[0] + c * p.v2[0], s * p.v1[1] + c * p.v2[1], s * p.v1[2] + c * p.v2[2]];
}

/** Unit ring tangent T(t): the normal of the section plane at ring angle t. */
export function ringTangent(p: Placement, t: number): Vec3 {
  const s = Math.sin(t);
  const c = Math.cos(t);
  return [c * p.v1[0] - s * p.v2[0], c * p.v1[1] - s * p.v2[1], c * p.v1[2] - s * p.v2[2]];
}

/** Centre of the torus section at ring angle t (a ring point), mm. */
export function sectionCentre(p: Placement, t: number): Vec3 {
  return addScaled(p.centre, ringRadial(p, t), p.ringRadiusMm);
}

/** Point of the section at ring angle t with in-section angle psi (from r(t) towards a), mm. */
export function sectionPoint(p: Placement, t: number, psi: number): Vec3 {
  const r = ringRadial(p, t);
  const c = Math.cos(psi) * p.cornerRadiusMm;
  const s = Math.sin(psi) * p.cornerRadiusMm;
  const o = sectionCentre(p, t);
  return [o[0] + c * r[0] + s * p.axis[0], o[1] + c * r[1] + s * p.axis[1], o[2] + c * r[2] + s * p.axis[2]];
}

/** How the section at one ring angle meets the plane z = heightMm. */
export interface SectionCut {
  /** Distance (mm) from the section centre down to the plane, measured inside the section plane (Eqs. 2-3). */
  readonly inPlaneDistanceMm: number;
  /** In-section angles of the two crossings, or null when the section misses the plane. */
  readonly psi: readonly [number, number] | null;
}

/**
 * Cuts the section at ring angle t with the plane z = h. Inside the section plane a circle point's
 * height is `C_z + Rcr (r_z cos psi + a_z sin psi)`; the in-plane distance from the centre to
 * the plane is `(C_z - h) / sqrt(r_z^2 + a_z^2)`, and `sqrt(r_z^2 + a_z^2) = sqrt(1 - T_z^2)`.
 */
export function cutSection(p: Placement, t: number, heightMm: number): SectionCut {
  const r = ringRadial(p, t);
  const A = r[2];
  const B = p.axis[2];
  const m = Math.hypot(A, B);
  const cz = p.centre[2] + p.ringRadiusMm * r[2];
  const inPlaneDistanceMm = (cz - heightMm) / m;
  const k = p.cornerRadiusMm;
  if (k === 0 || Math.abs(inPlaneDistanceMm) > k) return { inPlaneDistanceMm, psi: null };
  const phase = Math.atan2(B, A);
  const spread = Math.acos(Math.max(-1, Math.min(1, -inPlaneDistanceMm / k)));
  return { inPlaneDistanceMm, psi: [phase - spread, phase + spread] };
}

/**
 * The crossing of the section at t with the plane z = h that lies farthest towards `side`
 * (+1: +Y, -1: -Y), or null when the section misses the plane (the paper's P_hp[i]).
 */
export function farthestCrossing(p: Placement, t: number, heightMm: number, side: 1 | -1 = 1): Vec3 | null {
  const cut = cutSection(p, t, heightMm);
  if (cut.psi === null) {
    if (p.cornerRadiusMm === 0 && Math.abs(cut.inPlaneDistanceMm) === 0) return sectionCentre(p, t);
    return null;
  }
  const a = sectionPoint(p, t, cut.psi[0]);
  const b = sectionPoint(p, t, cut.psi[1]);
  return side * a[1] >= side * b[1] ? a : b;
}
