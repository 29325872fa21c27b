/**
 * The exact cross-feed profile of a filleted end mill inclined by `rho` along the feed.
 *
 * Derivation (geometry notes, "The exact answer"): the tool translates along X, so the
 * surface it leaves is its projection along X onto the YZ plane. The ring of corner
 * centres (radius `Rb = R - Rcr`) projects to an ellipse with semi-axes `a = Rb` (Y) and
 * `b = Rb sin(rho)` (Z); the profile is that ellipse offset outward by `Rcr`.
 *
 * Here the profile is parametrised by `theta`, the angle of its outward normal
 * `(sin theta, -cos theta)` from straight down; `theta` runs over [0, pi/2] from the
 * lowest point to the widest point. For the ellipse point with that normal,
 * `D = sqrt(a^2 sin^2 + b^2 cos^2)`, `y_E = a^2 sin/D`, `z_E = -b^2 cos/D`. Then
 *
 *   height  H(theta) = 2 Rcr sin^2(theta/2) + b a^2 sin^2 / (D (D + b cos))
 *   width   Y(theta) = (a^2/D + Rcr) sin
 *   H' = sin * K,  Y' = cos * K,  K(theta) = Rcr + a^2 b^2 / D^3   (so dH/dY = tan theta)
 *
 * The height form is free of cancellation, so tiny scallops keep full precision, and it
 * stays valid for `rho = 0` (flat bottom plus corner), `Rcr = R` (ball) and `Rcr = 0`.
 * All lengths in mm, angles in radians.
 */

/** Semi-axes of the projected ring ellipse and the corner radius, all in mm. */
export interface ProfileShape {
  /** Semi-axis along Y: `Rb = R - Rcr`, mm. */
  readonly a: number;
  /** Semi-axis along Z: `Rb sin(rho)`, mm. */
  readonly b: number;
  /** Corner radius `Rcr`, mm. */
  readonly rcr: number;
}

const HALF_PI = Math.PI / 2;

/**
 * Builds the profile shape of a tool.
 * @param toolRadiusMm R > 0, mm. @param cornerRadiusMm 0 <= Rcr <= R, mm.
 * @param leadAngleRad 0 <= rho < pi/2, radians.
 */
export function profileShape(toolRadiusMm: number, cornerRadiusMm: number, leadAngleRad: number): ProfileShape {
  const a = toolRadiusMm - cornerRadiusMm;
  return { a, b: a * Math.sin(leadAngleRad), rcr: cornerRadiusMm };
}

/**
 * Height (mm) of the profile point with normal angle `theta` above the lowest profile point.
 * Valid for theta in [0, pi/2]; increasing; `H(pi/2) = b + Rcr`.
 */
export function profileHeightMm(s: ProfileShape, theta: number): number {
  const sin = Math.sin(theta);
  const cos = Math.cos(theta);
  const half = Math.sin(theta / 2);
  const d = Math.sqrt(s.a * s.a * sin * sin + s.b * s.b * cos * cos);
  const ellipse = d > 0 ? (s.b * s.a * s.a * sin * sin) / (d * (d + s.b * cos)) : 0;
  return 2 * s.rcr * half * half + ellipse;
}

/**
 * Half width Y (mm) of the profile point with normal angle `theta` (distance from the tool
 * centre line). Valid for theta in (0, pi/2]; increasing; `Y(pi/2) = a + Rcr = R`.
 * At theta = 0 it returns the right end of the flat bottom: `a` when `b = 0`, else 0.
 */
export function profileHalfWidthMm(s: ProfileShape, theta: number): number {
  const sin = Math.sin(theta);
  const cos = Math.cos(theta);
  const d = Math.sqrt(s.a * s.a * sin * sin + s.b * s.b * cos * cos);
  const ellipse = d > 0 ? (s.a * s.a * sin) / d : s.b === 0 ? s.a : 0;
  // Y <= a + Rcr = R holds exactly; clamp the last-bit round-off at theta = pi/2.
  return Math.min(ellipse + s.rcr * sin, s.a + s.rcr);
}

/** `K(theta) = Rcr + a^2 b^2 / D^3` in mm: the common factor of H' and Y'. */
function slopeFactorMm(s: ProfileShape, sin: number, cos: number): number {
  const d2 = s.a * s.a * sin * sin + s.b * s.b * cos * cos;
  const ab = s.a * s.b;
  if (ab === 0) return s.rcr;
  return s.rcr + (ab * ab) / (d2 * Math.sqrt(d2));
}

/**
 * Ring angle `gamma` (radians, from the lowest ring point) of the torus section whose
 * silhouette point has normal angle `theta`: `tan(theta) = (b/a) tan(gamma)`.
 * For `b = 0` and theta > 0 the silhouette lies on the side section, gamma = pi/2.
 */
export function ringAngleRad(s: ProfileShape, theta: number): number {
  if (s.a === 0) return theta;
  return Math.atan2(s.a * Math.sin(theta), s.b * Math.cos(theta));
}

const MAX_ITERATIONS = 200;

/**
 * Safeguarded Newton on an increasing function `f - target` inside a bracket [lo, hi]: a
 * Newton step that leaves the bracket is replaced by a secant step between the bracket ends
 * (once both are known), else by bisection; the bracket always shrinks.
 */
function solveIncreasing(
  value: (theta: number) => number,
  slope: (theta: number) => number,
  target: number,
  loStart: number,
  hiStart: number,
  start: number,
): number {
  let lo = loStart;
  let hi = hiStart;
  let fLo = Number.NaN;
  let fHi = Number.NaN;
  let theta = Math.min(Math.max(start, lo), hi);
  for (let i = 0; i < MAX_ITERATIONS; i++) {
    const f = value(theta) - target;
    if (f === 0) return theta;
    if (f > 0) {
      hi = theta;
      fHi = f;
    } else {
      lo = theta;
      fLo = f;
    }
    const df = slope(theta);
    let next = df > 0 ? theta - f / df : Number.NaN;
    // A Newton step below 1e-14 (relative) means the next one would be near 1e-28: done. This
    // comes before the bracket test, which a converged step can fail by rounding alone.
    if (Math.abs(next - theta) <= 1e-14 * theta) return Math.min(Math.max(next, lo), hi);
    if (!(next > lo && next < hi)) {
      next = fLo < 0 && fHi > 0 ? lo - (fLo * (hi - lo)) / (fHi - fLo) : 0.5 * (lo + hi);
      // A secant step that hugs one end makes little progress: bisect instead.
      const width = hi - lo;
      if (!(next > lo + 0.05 * width && next < hi - 0.05 * width)) next = 0.5 * (lo + hi);
    }
    if (hi - lo <= 2e-16 * hi) return next;
    theta = next;
  }
  return theta;
}

/**
 * Normal angle theta in [0, pi/2] (radians) at which the profile height equals `heightMm`.
 *
 * Bracket from three one-sided models (all proved in the derivation comments below):
 * the osculating circle `Reff = a^2/b + Rcr` and the corner circle alone both give
 * angles at or below the root; the bare ellipse gives one at or above it.
 *
 * @param heightMm 0 < h < b + Rcr, mm.
 */
export function normalAngleAtHeight(s: ProfileShape, heightMm: number): number {
  const { a, b, rcr } = s;
  if (a === 0) return 2 * Math.asin(Math.min(1, Math.sqrt(heightMm / (2 * rcr))));
  // H' = sin K <= theta K(0), so H <= Reff theta^2 / 2: theta1 = sqrt(2h/Reff) is low.
  const reff = b > 0 ? (a * a) / b + rcr : Number.POSITIVE_INFINITY;
  let lo = Math.sqrt((2 * heightMm) / reff);
  // H >= corner term + b (1 - ...) <= corner term + b: the corner alone at h - b is low.
  if (heightMm > b && rcr > 0) lo = Math.max(lo, 2 * Math.asin(Math.min(1, Math.sqrt((heightMm - b) / (2 * rcr)))));
  // H >= ellipse term: the bare ellipse at height h is high.
  let hi = HALF_PI;
  if (heightMm < b) {
    const cosG = 1 - heightMm / b;
    const sinG = Math.sqrt(Math.max(0, 1 - cosG * cosG));
    hi = Math.min(hi, Math.atan2(b * sinG, a * cosG));
  }
  lo = Math.min(lo, hi);
  return solveIncreasing(
    (t) => profileHeightMm(s, t),
    (t) => {
      const sin = Math.sin(t);
      return sin * slopeFactorMm(s, sin, Math.cos(t));
    },
    heightMm,
    lo,
    hi,
    lo,
  );
}

/**
 * Normal angle theta in [0, pi/2] (radians) at which the profile's half width equals
 * `halfWidthMm`. Returns 0 when the point lies on the flat bottom (`b = 0`, Y <= a).
 *
 * Bracket: `Y <= Reff theta` (Y' <= K(0)) and `Y <= a + Rcr sin` give angles at or below
 * the root; `Y >= Rcr sin` and `Y >= a sin(gamma)` give angles at or above it.
 *
 * @param halfWidthMm 0 < Y < R, mm.
 */
export function normalAngleAtHalfWidth(s: ProfileShape, halfWidthMm: number): number {
  const { a, b, rcr } = s;
  if (b === 0) {
    if (halfWidthMm <= a) return 0;
    return Math.asin(Math.min(1, (halfWidthMm - a) / rcr));
  }
  const reff = (a * a) / b + rcr;
  let lo = Math.min(HALF_PI, halfWidthMm / reff);
  if (halfWidthMm > a) lo = Math.max(lo, Math.asin(Math.min(1, (halfWidthMm - a) / rcr)));
  let hi = HALF_PI;
  if (rcr > 0 && halfWidthMm < rcr) hi = Math.min(hi, Math.asin(halfWidthMm / rcr));
  if (halfWidthMm < a) {
    const sinG = halfWidthMm / a;
    const cosG = Math.sqrt(Math.max(0, 1 - sinG * sinG));
    hi = Math.min(hi, Math.atan2(b * sinG, a * cosG));
  }
  lo = Math.min(lo, hi);
  return solveIncreasing(
    (t) => profileHalfWidthMm(s, t),
    (t) => {
      const sin = Math.sin(t);
      const cos = Math.cos(t);
      return cos * slopeFactorMm(s, sin, cos);
    },
    halfWidthMm,
    lo,
    hi,
    lo,
  );
}
