/**
 * The posture's profile as posture.ts derives it (see its module comment): the rotated offset
 * ellipse with its contact, and the sections (ring point and profile normal) along a flank.
 * Lengths mm, angles radians.
 */
import { degToRad } from '../input/units';

/** The profile of one posture: the rotated offset ellipse, with its contact precomputed. */
export interface PostureShape {
  /** Long semi-axis of the projected ring, `Rb = R - Rcr`, mm. */
  readonly a: number;
  /** Short semi-axis, `Rb cos(beta) sin(rho)`, mm (>= 0). */
  readonly b: number;
  /** Corner radius `Rcr`, mm. */
  readonly rcr: number;
  /** Rotation `phi` of the ellipse (radians, in (-pi/2, pi/2)), its sine and cosine. */
  readonly phi: number;
  readonly sinPhi: number;
  readonly cosPhi: number;
  /** Support of the ring ellipse in the down direction: `sqrt(a^2 sin^2 phi + b^2 cos^2 phi)`, mm. */
  readonly d0: number;
  /** Ring angle `t0` of the contact: its sine and cosine. */
  readonly sinT0: number;
  readonly cosT0: number;
  /**
   * True for a flat bottom lying flat on the plane (b = 0 and phi = 0: no lead, no tilt): the
   * contact is the whole bottom face; widths are then measured from the tool centre point.
   */
  readonly flatOnPlane: boolean;
}

/** Which flank: right (+Y, towards the tilt) or left (-Y). */
export type Flank = 'right' | 'left';

/**
 * The profile shape of a tool in a posture.
 * @param toolRadiusMm R > 0, mm. @param cornerRadiusMm 0 <= Rcr <= R, mm.
 * @param leadAngleRad rho in [0, pi/2). @param tiltAngleRad beta in (-pi/2, pi/2).
 */
export function postureShape(
  toolRadiusMm: number,
  cornerRadiusMm: number,
  leadAngleRad: number,
  tiltAngleRad: number,
): PostureShape {
  const a = toolRadiusMm - cornerRadiusMm;
  const cosBeta = Math.cos(tiltAngleRad);
  const sinBeta = Math.sin(tiltAngleRad);
  const b = a * cosBeta * Math.sin(leadAngleRad);
  const phi = Math.atan2(sinBeta, cosBeta * Math.cos(leadAngleRad));
  return shapeWithPhi(a, b, cornerRadiusMm, phi, Math.sin(phi), Math.cos(phi));
}

function shapeWithPhi(a: number, b: number, rcr: number, phi: number, sinPhi: number, cosPhi: number): PostureShape {
  const as = a * sinPhi;
  const bc = b * cosPhi;
  // sqrt rather than Math.hypot (slow in V8): |R| <= 1000 mm keeps the squares far from overflow.
  const d0 = Math.sqrt(as * as + bc * bc);
  const flatOnPlane = d0 === 0 && a > 0;
  // Ball end (a = 0): the ring is a point; t0 is immaterial. Flat on the plane: t0 = 0, the centre.
  const sinT0 = d0 > 0 ? as / d0 : 0;
  const cosT0 = d0 > 0 ? bc / d0 : 1;
  return { a, b, rcr, phi, sinPhi, cosPhi, d0, sinT0, cosT0, flatOnPlane };
}

/** The same tool seen in the mirror `y -> -y`: its right flank is the original's left flank. */
export function mirrorShape(s: PostureShape): PostureShape {
  return { ...s, phi: -s.phi, sinPhi: -s.sinPhi, sinT0: -s.sinT0 };
}

/** +1 for the right flank, -1 for the left (the right flank of the mirror image). */
export function flankSign(flank: Flank): 1 | -1 {
  return flank === 'right' ? 1 : -1;
}

/** The shape of a validated tool input (angles in degrees). */
export function shapeOfTool(tool: {
  readonly toolRadiusMm: number;
  readonly cornerRadiusMm: number;
  readonly leadAngleDeg: number;
  readonly tiltAngleDeg: number;
}): PostureShape {
  return postureShape(tool.toolRadiusMm, tool.cornerRadiusMm, degToRad(tool.leadAngleDeg), degToRad(tool.tiltAngleDeg));
}

/**
 * Contact offset `y0` (mm): Y of the contact point minus Y of the tool centre point O. Positive
 * when the tool leans to +Y (it touches down with its right side). `(a^2 - b^2) sin phi cos phi / D0`.
 */
export function contactOffsetMm(s: PostureShape): number {
  if (!(s.d0 > 0)) return 0;
  return ((s.a * s.a - s.b * s.b) * s.sinPhi * s.cosPhi) / s.d0;
}

/** Height (mm) of the tool centre point O above the contact: `D0 + Rcr` (Eq. 7 for beta = 0). */
export function centreHeightMm(s: PostureShape): number {
  return s.d0 + s.rcr;
}

/**
 * Ring-angle offset (radians, from the contact) of the right flank's widest point, where the
 * profile's normal is horizontal: `atan2(ab, (a^2 - b^2) sin phi cos phi)`; `pi/2` when flat on
 * the plane, 0 for a ball end (the ring is a point).
 */
export function widestOffsetRad(s: PostureShape, sign: number): number {
  if (s.flatOnPlane) return Math.PI / 2;
  if (s.a === 0) return 0;
  return Math.atan2(s.a * s.b, (s.a * s.a - s.b * s.b) * sign * s.sinPhi * s.cosPhi);
}

/**
 * Scratch state of one section, filled in place (no allocation in the solver loop). A class with
 * every field set at construction, so that evalSection sees one shape from every caller.
 */
export class Section {
  /** cos delta. */
  cosD = 1;
  /** dz, dy of the ring point relative to the contact's ring point. */
  dz = 0;
  dy = 0;
  /** `D0 sin delta` and `a cos phi cos t + b sin phi sin t`: the profile normal (unnormalised). */
  nSin = 0;
  nCos = 0;
  /** Derivative of nCos with respect to delta. */
  dNCos = 0;
}

/**
 * Fills `out` for the section `delta` past the contact on the flank `sign` (+1 right, -1 left:
 * the left flank is the right flank of the mirror image, phi -> -phi, t0 -> -t0).
 */
export function evalSection(s: PostureShape, sign: number, delta: number, out: Section): void {
  const sinT0 = sign * s.sinT0;
  const sinPhi = sign * s.sinPhi;
  const sinH = Math.sin(delta / 2);
  const cosH = Math.cos(delta / 2);
  // Double-angle forms: two trigonometric calls per section instead of four.
  const sinD = 2 * sinH * cosH;
  const cosD = (cosH - sinH) * (cosH + sinH);
  const sinT = sinT0 * cosD + s.cosT0 * sinD;
  const cosT = s.cosT0 * cosD - sinT0 * sinD;
  // t0 + delta/2: its sine and cosine by the half-angle rotation of t0.
  const sinM = sinT0 * cosH + s.cosT0 * sinH;
  const cosM = s.cosT0 * cosH - sinT0 * sinH;
  out.cosD = cosD;
  out.dz = 2 * s.d0 * sinH * sinH;
  out.dy = 2 * sinH * (s.a * s.cosPhi * cosM + s.b * sinPhi * sinM);
  out.nSin = s.d0 * sinD;
  out.nCos = s.a * s.cosPhi * cosT + s.b * sinPhi * sinT;
  out.dNCos = -s.a * s.cosPhi * sinT + s.b * sinPhi * cosT;
}

/** A section's scratch state, ready to be filled by {@link evalSection}. */
export function newSection(): Section {
  return new Section();
}
