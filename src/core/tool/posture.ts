/**
 * The exact cross-feed profile of a filleted end mill in any posture (lead `rho`, tilt `beta`),
 * on a plane, and its two flanks. Derivation (conventions of shared/notes/posture-and-surfaces.md):
 *
 * The tool end is the disk of radius `Rb` (centre O, normal the axis `a`) grown by a ball of
 * radius `Rcr`. Moving along X it leaves the lower boundary of its projection along X onto YZ:
 * the projected disk grown by a disk of radius `Rcr`. The projected disk is an ellipse whose
 * shape matrix is `Rb^2 (I - a_yz a_yz^T)`: semi-axis `a = Rb` across `a_yz` and
 * `b = Rb |a_x| = Rb cos(beta) sin(rho)` along it, rotated from the paper's frame by
 * `phi = atan2(sin beta, cos beta cos rho)`. So the profile is the paper's offset ellipse
 * (semi-axes `Rb`, `Rb cos(beta) sin(rho)`) turned by `phi`; `beta = 0` gives `phi = 0`.
 *
 * In the ellipse's own frame a ring point is `e(t) = (a sin t, -b cos t)` (t is the ring angle:
 * the 3D ring point `O + Rb (sin t v1 + cos t v2)` projects onto it). The contact (lowest point)
 * is the support point in the global down direction, at `t0` with
 * `(sin t0, cos t0) = (a sin phi, b cos phi) / D0`, `D0 = sqrt(a^2 sin^2 phi + b^2 cos^2 phi)`.
 * With `delta = t - t0`, relative to the contact's ring point:
 *
 *   height  dz(delta) = 2 D0 sin^2(delta/2)
 *   width   dy(delta) = 2 sin(delta/2) (a cos phi cos(t0 + delta/2) + b sin phi sin(t0 + delta/2))
 *
 * both free of cancellation. The section (ball) around the ring point meets the plane `h` above
 * the contact at vertical offset `q = h - dz` above its lowest point; its farthest crossing lies
 * `r = sqrt(q (2 Rcr - q))` beyond `dy` (the paper's farthest `P_hp` of a section). The flank's
 * width at height h is the maximum over sections of `W(delta) = dy + r`, attained where the
 * profile's normal angle `theta(delta) = atan2(D0 sin delta, a cos phi cos t + b sin phi sin t)`
 * equals the angle of the crossing on its ball, `atan2(r, Rcr - q)`. That condition is
 * monotone in delta, so a bracketed Newton solves it; the width is then `W(delta*)`, whose
 * error is second order in the error of delta* (it is a maximum). The left flank is the right
 * flank of the mirrored posture (`phi -> -phi`). Lengths mm, angles radians.
 *
 * The shape and its sections are in postureShape.ts (re-exported here); this module solves the
 * flanks: their limits, the width at a height and the inverse.
 */
import { NewtonState, newtonStart, newtonStep } from '../math/rootFinder';
import {
  evalSection,
  type Flank,
  flankSign,
  newSection,
  type PostureShape,
  type Section,
  widestOffsetRad,
} from './postureShape';

export {
  centreHeightMm,
  contactOffsetMm,
  evalSection,
  type Flank,
  flankSign,
  mirrorShape,
  newSection,
  type PostureShape,
  postureShape,
  type Section,
  shapeOfTool,
} from './postureShape';

/**
 * Height (mm) above the contact of the right flank's widest point (`hmax`): above it the flank
 * is a wall. `2 D0 sin^2(delta_w / 2) + Rcr`; `b + Rcr` without tilt.
 */
function flankTopMm(s: PostureShape, sign: number): number {
  const half = Math.sin(widestOffsetRad(s, sign) / 2);
  return 2 * s.d0 * half * half + s.rcr;
}

/**
 * Height (mm) above the contact at which the shank (the cylinder of radius R above the corner)
 * starts to cut on the right flank, or null when it never reaches below that flank's top (the
 * tool does not lean to +Y). The shank's silhouette is the line tangent to the profile where its
 * normal is `(cos phi, -sin phi)`, the end of the ellipse's long axis (t = pi/2):
 * `D0 - a sin phi + Rcr (1 - sin phi) = b^2 cos^2 phi / (D0 + a sin phi) + Rcr cos^2 phi / (1 + sin phi)`.
 * For a ball end leaning by beta' it is `R (1 - sin beta')`.
 */
function shankTopMm(s: PostureShape, sign: number): number | null {
  const sinPhi = sign * s.sinPhi;
  if (!(sinPhi > 0)) return null;
  const c2 = s.cosPhi * s.cosPhi;
  const ellipse = s.b === 0 ? 0 : (s.b * s.b * c2) / (s.d0 + s.a * sinPhi);
  return ellipse + (s.rcr * c2) / (1 + sinPhi);
}

/** Where each flank stops being a scallop flank (mm above the contact). */
export interface FlankLimits {
  /** Height of the right / left flank's widest point: above it the flank is a wall. */
  readonly topRightMm: number;
  readonly topLeftMm: number;
  /** Height at which the shank starts to cut on that side, or null where it never does. */
  readonly shankRightMm: number | null;
  readonly shankLeftMm: number | null;
  /** The binding limit: scallop heights must stay below it. */
  readonly limitMm: number;
  /** What sets `limitMm`. */
  readonly limitBy: 'right-flank' | 'left-flank' | 'shank-right' | 'shank-left';
}

/** The flank and shank limits of a posture (see flankTopMm, shankTopMm). */
export function flankLimits(s: PostureShape): FlankLimits {
  const topRightMm = flankTopMm(s, 1);
  const topLeftMm = flankTopMm(s, -1);
  const shankRightMm = shankTopMm(s, 1);
  const shankLeftMm = shankTopMm(s, -1);
  return flankLimitsOf(topRightMm, topLeftMm, shankRightMm, shankLeftMm);
}

/**
 * The flank and shank limits from the heights of the flanks' tops and of the shank's start (null
 * where it never cuts): the least binds. The shank first: on the side the tool leans to it binds
 * before (or with) that flank's top, and a tie is better explained by the shank. The one rule of
 * the plane's, the cylinder's and the doubly curved point's limits.
 */
export function flankLimitsOf(
  topRightMm: number,
  topLeftMm: number,
  shankRightMm: number | null,
  shankLeftMm: number | null,
): FlankLimits {
  const candidates: Array<[number, FlankLimits['limitBy']]> = [];
  if (shankRightMm !== null) candidates.push([shankRightMm, 'shank-right']);
  if (shankLeftMm !== null) candidates.push([shankLeftMm, 'shank-left']);
  candidates.push([topRightMm, 'right-flank'], [topLeftMm, 'left-flank']);
  let best = candidates[0] as [number, FlankLimits['limitBy']];
  for (const c of candidates) if (c[0] < best[0]) best = c;
  return { topRightMm, topLeftMm, shankRightMm, shankLeftMm, limitMm: best[0], limitBy: best[1] };
}

/** Radius of curvature (mm) of the profile at the contact: `Rcr + a^2 b^2 / D0^3`; null if infinite. */
export function contactCurvatureRadiusMm(s: PostureShape): number | null {
  if (s.flatOnPlane) return null;
  if (s.a === 0 || s.b === 0) return s.rcr;
  const ab = s.a * s.b;
  return s.rcr + (ab * ab) / (s.d0 * s.d0 * s.d0);
}

/** Where a flank reaches a given height: its width and the section that carries it. */
export interface FlankPoint {
  /** Horizontal distance from the contact (from O when flat on the plane), mm. */
  readonly widthMm: number;
  /** Height above the contact, mm. */
  readonly heightMm: number;
  /** Ring-angle offset `delta = |t - t0|` of the section through the point (radians, >= 0). */
  readonly ringOffsetRad: number;
  /** Normal angle of the profile there, from straight down towards the flank (radians). */
  readonly normalAngleRad: number;
}

/** `sqrt(q (2 Rcr - q))`, 0 outside [0, 2 Rcr]: the ball's horizontal reach at offset q. */
function reachMm(rcr: number, q: number): number {
  if (!(q > 0) || !(q < 2 * rcr)) return 0;
  return Math.sqrt(q * (2 * rcr - q));
}

/** Half-angle form of the corner's normal angle at vertical offset q: `acos(1 - q/Rcr)`. */
function cornerAngleRad(rcr: number, q: number): number {
  return 2 * Math.asin(Math.min(1, Math.sqrt(Math.max(0, q) / (2 * rcr))));
}

/**
 * Ring-angle offset of the section carrying the flank `sign` at height h (0 < h below the
 * flank's top). The shared safeguarded Newton step (rootFinder.ts) on the sign-monotone
 * `G(delta) = D0 sin(delta) (Rcr - q) - (a cos phi cos t + b sin phi sin t) r`, zero where the
 * profile normal meets the section's crossing with the plane.
 * Fills `sec` with that section (allocation-free).
 */
function sectionAtHeight(s: PostureShape, sign: number, h: number, sec: Section): number {
  const rcr = s.rcr;
  if (s.flatOnPlane) {
    evalSection(s, sign, Math.PI / 2, sec);
    return Math.PI / 2;
  }
  let delta = 0;
  if (s.a > 0) {
    const deltaTop = widestOffsetRad(s, sign);
    if (rcr === 0) {
      // Flat end: the flank is the ring ellipse itself, dz(delta) = h in closed form.
      delta = Math.min(deltaTop, 2 * Math.asin(Math.min(1, Math.sqrt(h / (2 * s.d0)))));
    } else {
      // The section's ring point cannot rise above h: dz(delta) <= h bounds delta from above.
      const hi = h < 2 * s.d0 ? Math.min(deltaTop, 2 * Math.asin(Math.sqrt(h / (2 * s.d0)))) : deltaTop;
      if (hi > 0) {
        // Start from the osculating circle: theta ~ sqrt(2h/Reff), delta ~ theta ab / D0^2.
        const ab = s.a * s.b;
        const reff = rcr + (ab * ab) / (s.d0 * s.d0 * s.d0);
        const start = (Math.sqrt((2 * h) / reff) * ab) / (s.d0 * s.d0);
        // A Newton step below 1e-12 (relative) ends it (1e-8 was measured to cost up to 7e-9 mm
        // with a corner of 1e-9 R, where the root sits next to the ball's vertical tangent).
        const st = new NewtonState();
        newtonStart(st, 0, hi, start);
        for (let i = 0; i < 100 && !st.done; i++) {
          evalSection(s, sign, st.x, sec);
          const q = h - sec.dz;
          const c = rcr - q;
          const r = reachMm(rcr, q);
          let slope = s.d0 * sec.cosD * c + sec.nSin * sec.nSin - sec.dNCos * r;
          if (r > 0) slope += (sec.nCos * sec.nSin * c) / r;
          newtonStep(st, sec.nSin * c - sec.nCos * r, slope, true, 1e-12);
        }
        delta = st.x;
      }
    }
  }
  evalSection(s, sign, delta, sec);
  return delta;
}

/** flankWidthMm's workspace (filled and read within one call). */
const widthSection: Section = newSection();

/**
 * Width (mm) of a flank at `heightMm` above the contact: the farthest crossing of any torus
 * section with the plane h above the contact (measured from the contact; from O when the tool
 * is flat on the plane). Valid for 0 < h below that flank's top (flankLimits); error below
 * 1e-9 mm over the valid domain. Allocation-free.
 */
export function flankWidthMm(s: PostureShape, flank: Flank, heightMm: number): number {
  const rcr = s.rcr;
  if (s.a === 0) return reachMm(rcr, heightMm);
  const sec = widthSection;
  sectionAtHeight(s, flankSign(flank), heightMm, sec);
  return sec.dy + reachMm(rcr, heightMm - sec.dz);
}

/** The point of a flank at `heightMm` above the contact (see flankWidthMm), with its section. */
export function flankAtHeight(s: PostureShape, flank: Flank, heightMm: number): FlankPoint {
  const rcr = s.rcr;
  if (s.a === 0) {
    return {
      widthMm: reachMm(rcr, heightMm),
      heightMm,
      ringOffsetRad: 0,
      normalAngleRad: cornerAngleRad(rcr, heightMm),
    };
  }
  const sec = atHeightSection;
  const delta = sectionAtHeight(s, flankSign(flank), heightMm, sec);
  const q = heightMm - sec.dz;
  // At the root the profile normal is the angle of the crossing on its ball, acos(1 - q/Rcr),
  // which stays defined where a corner collapses onto one ring angle (b = 0).
  const normal = rcr > 0 ? cornerAngleRad(rcr, q) : Math.atan2(sec.nSin, sec.nCos);
  return { widthMm: sec.dy + reachMm(rcr, q), heightMm, ringOffsetRad: delta, normalAngleRad: normal };
}

/** flankAtWidth's workspace (filled and read within one call). */
const atWidthSection: Section = newSection();
/** flankAtHeight's workspace (filled and read within one call). */
const atHeightSection: Section = newSection();

/**
 * The point of a flank at horizontal distance `widthMm` from the contact: the inverse of
 * flankAtHeight. The height is the minimum over sections of `dz + Rcr - sqrt(Rcr^2 - (w - dy)^2)`,
 * found at the section where the profile normal meets the ball's lowest point at that width.
 * Valid for 0 <= w up to the flank's widest point; 0 on a flat bottom lying on the plane.
 */
export function flankAtWidth(s: PostureShape, flank: Flank, widthMm: number): FlankPoint {
  const rcr = s.rcr;
  const w = widthMm;
  const lowest = (u: number) => (u * u) / (rcr + Math.sqrt(Math.max(0, (rcr - u) * (rcr + u))));
  if (s.a === 0 || s.flatOnPlane) {
    const edge = s.a === 0 ? 0 : s.a;
    if (w <= edge) return { widthMm: w, heightMm: 0, ringOffsetRad: 0, normalAngleRad: 0 };
    const u = Math.min(w - edge, rcr);
    return {
      widthMm: w,
      heightMm: lowest(u),
      ringOffsetRad: s.a === 0 ? 0 : Math.PI / 2,
      normalAngleRad: Math.asin(Math.min(1, u / rcr)),
    };
  }
  const sign = flankSign(flank);
  const sec = atWidthSection;
  const hi = widestOffsetRad(s, sign);
  let delta = 0;
  if (hi > 0) {
    // The mismatch between the profile normal and the ball's normal at offset u = w - dy:
    // D0 sin(delta) sqrt(Rcr^2 - u^2) - nCos u; past the ball's reach (+-1), move on.
    const st = new NewtonState();
    newtonStart(st, 0, hi, 0.5 * hi);
    for (let i = 0; i < 200 && !st.done; i++) {
      evalSection(s, sign, st.x, sec);
      const u = w - sec.dy;
      let g: number;
      let slope = 0;
      if (rcr === 0) {
        g = -u; // flat end: solve dy(delta) = w
        slope = sec.nCos;
      } else if (u >= rcr) g = -1;
      else if (u <= -rcr) g = 1;
      else {
        const v = Math.sqrt((rcr - u) * (rcr + u));
        g = sec.nSin * v - sec.nCos * u;
        // u' = -nCos, v' = u nCos / v
        slope = s.d0 * sec.cosD * v + (sec.nSin * u * sec.nCos) / v - sec.dNCos * u + sec.nCos * sec.nCos;
      }
      newtonStep(st, g, slope, true, 1e-15);
    }
    delta = st.x;
  }
  evalSection(s, sign, delta, sec);
  const u = Math.min(rcr, Math.max(-rcr, w - sec.dy));
  const height = rcr === 0 ? sec.dz : sec.dz + lowest(u);
  const normal = rcr > 0 ? Math.asin(Math.max(0, u) / rcr) : Math.atan2(sec.nSin, sec.nCos);
  return { widthMm: w, heightMm: height, ringOffsetRad: delta, normalAngleRad: normal };
}
