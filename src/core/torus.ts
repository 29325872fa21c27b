/**
 * The inclined torus in the paper's frame (Figures 2-3): global X = feed, Y = cross-feed,
 * Z = designed-plane normal; tool axis `ZT = (sin rho, 0, cos rho)`, `YT = Y`,
 * `XT = YT x ZT = (cos rho, 0, -sin rho)`.
 *
 * Placement: the designed plane is z = 0 and the tool touches it at `P_base`; the tool
 * centre (centre of the ring of corner centres) lies on the Z axis at height
 * `Z_tc = Rb sin(rho) + Rcr` (Eq. 7). The ring point at angle `gamma` is
 * `O + Rb (cos gamma XT + sin gamma Y)`; gamma = 0 is the lowest ring point, above `P_base`.
 * A torus section is the circle of radius `Rcr` around a ring point, in the meridian plane
 * spanned by `r(gamma) = cos gamma XT + sin gamma Y` and `ZT`; its normal is the ring
 * tangent `t(gamma) = -sin gamma XT + cos gamma Y`. Lengths mm, angles radians.
 */
import { add, addScaled, type Vec3 } from './vec';

export interface TorusFrame {
  readonly ringRadiusMm: number;
  readonly cornerRadiusMm: number;
  readonly leadAngleRad: number;
  readonly sinRho: number;
  readonly cosRho: number;
  /** Tool centre O (centre of the ring), mm. */
  readonly centre: Vec3;
  readonly xt: Vec3;
  readonly zt: Vec3;
}

/**
 * @param toolRadiusMm R > 0. @param cornerRadiusMm 0 <= Rcr <= R. @param leadAngleRad 0 <= rho < pi/2.
 */
export function torusFrame(toolRadiusMm: number, cornerRadiusMm: number, leadAngleRad: number): TorusFrame {
  const ringRadiusMm = toolRadiusMm - cornerRadiusMm;
  const sinRho = Math.sin(leadAngleRad);
  const cosRho = Math.cos(leadAngleRad);
  return {
    ringRadiusMm,
    cornerRadiusMm,
    leadAngleRad,
    sinRho,
    cosRho,
    centre: [0, 0, ringRadiusMm * sinRho + cornerRadiusMm],
    xt: [cosRho, 0, -sinRho],
    zt: [sinRho, 0, cosRho],
  };
}

/** Unit radial direction `r(gamma)` of the ring. */
export function ringRadial(f: TorusFrame, gamma: number): Vec3 {
  const c = Math.cos(gamma);
  return [c * f.xt[0], Math.sin(gamma), c * f.xt[2]];
}

/** Unit ring tangent `t(gamma)`: the normal of the section plane at gamma. */
export function ringTangent(f: TorusFrame, gamma: number): Vec3 {
  const s = Math.sin(gamma);
  return [-s * f.xt[0], Math.cos(gamma), -s * f.xt[2]];
}

/** Centre of the torus section at ring angle gamma (a ring point), mm. */
export function sectionCentre(f: TorusFrame, gamma: number): Vec3 {
  return addScaled(f.centre, ringRadial(f, gamma), f.ringRadiusMm);
}

/** Point of the section circle at gamma with in-section angle psi (from r towards ZT). */
export function sectionPoint(f: TorusFrame, gamma: number, psi: number): Vec3 {
  const r = ringRadial(f, gamma);
  const k = f.cornerRadiusMm;
  return add(sectionCentre(f, gamma), [
    k * (Math.cos(psi) * r[0] + Math.sin(psi) * f.zt[0]),
    k * Math.cos(psi) * r[1],
    k * (Math.cos(psi) * r[2] + Math.sin(psi) * f.zt[2]),
  ]);
}

/** How the section at one ring angle meets the plane z = h. */
export interface SectionCut {
  /** Distance (mm) from the section centre to the plane, measured inside the section plane (Eqs. 2-3). */
  readonly inPlaneDistanceMm: number;
  /** In-section angles of the two crossings, or null when the section misses the plane. */
  readonly psi: readonly [number, number] | null;
}

/**
 * Cuts the section at ring angle gamma with the h pseudo plane z = h.
 *
 * In the section plane, the circle point's height is `C_z + Rcr (A cos psi + B sin psi)` with
 * `A = r_z = -sin rho cos gamma`, `B = ZT_z = cos rho`; the in-plane distance to the plane
 * is `(C_z - h) / sqrt(A^2 + B^2)` and `sqrt(A^2 + B^2) = sqrt(1 - (t . Z)^2)` (notes, Eqs. 2-3).
 */
export function cutSection(f: TorusFrame, gamma: number, heightMm: number): SectionCut {
  const A = -f.sinRho * Math.cos(gamma);
  const B = f.cosRho;
  const m = Math.sqrt(A * A + B * B);
  const cz = f.centre[2] - f.ringRadiusMm * f.sinRho * Math.cos(gamma);
  const inPlaneDistanceMm = (cz - heightMm) / m;
  const k = f.cornerRadiusMm;
  if (k === 0 || Math.abs(inPlaneDistanceMm) > k) return { inPlaneDistanceMm, psi: null };
  const phase = Math.atan2(B, A);
  const spread = Math.acos(Math.max(-1, Math.min(1, -inPlaneDistanceMm / k)));
  return { inPlaneDistanceMm, psi: [phase - spread, phase + spread] };
}
