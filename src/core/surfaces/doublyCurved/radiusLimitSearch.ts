/**
 * The search of a principal radius's limit at a doubly curved point (gouging.ts), the other held: from
 * the given curvature along a grid of radii doubling, then bisection in the radius. Curvatures 1/mm.
 */
import { MAX_PRINCIPAL_RADIUS_MM, MIN_PRINCIPAL_RADIUS_MM } from './types';

/** Largest |curvature| a principal radius can have: 1 / 0.001 mm. */
const MAX_CURVATURE_PER_MM = 1 / MIN_PRINCIPAL_RADIUS_MM;

/** What one principal radius must be, the other held, for the tool not to gouge. */
export interface RadiusLimit {
  /**
   * The smallest admissible signed curvature `1/R` (1/mm): admissible radii are those with
   * `1/R >= minCurvaturePerMm` (straight is 0). Below -1000 every radius passes; above 1000 none.
   */
  readonly minCurvaturePerMm: number;
  /**
   * `any`: every radius passes; `concave-at-least`: a concave radius needs |R| >= radiusMm (convex and
   * straight pass); `not-concave`: straight and every convex radius pass, no concave one;
   * `convex-at-most`: the radius must be convex with R <= radiusMm; `none`: no radius passes ("at any
   * radius").
   */
  readonly kind: 'any' | 'concave-at-least' | 'not-concave' | 'convex-at-most' | 'none';
  /** The limiting magnitude (mm) for the two bounded kinds, else null. */
  readonly radiusMm: number | null;
}

/** The limit of a radius from the smallest admissible curvature (1/mm) the search found. */
export function limitOf(kMin: number): RadiusLimit {
  if (kMin < -MAX_CURVATURE_PER_MM) return { minCurvaturePerMm: kMin, kind: 'any', radiusMm: null };
  if (kMin > MAX_CURVATURE_PER_MM) return { minCurvaturePerMm: kMin, kind: 'none', radiusMm: null };
  // Limits beyond the largest radius accepted (1e6 mm) are no radius of that side at all.
  if (kMin < -1 / MAX_PRINCIPAL_RADIUS_MM)
    return { minCurvaturePerMm: kMin, kind: 'concave-at-least', radiusMm: -1 / kMin };
  if (kMin > 1 / MAX_PRINCIPAL_RADIUS_MM)
    return { minCurvaturePerMm: kMin, kind: 'convex-at-most', radiusMm: 1 / kMin };
  // kMin = 0: straight passes, every convex radius too; no concave one.
  return { minCurvaturePerMm: 0, kind: 'not-concave', radiusMm: null };
}

/** Curvatures from -1000 to 1000 per mm: radii 0.001 mm to 1e6 mm doubling, both signs, and 0. */
const GRID: readonly number[] = (() => {
  const radii: number[] = [];
  for (let r = MIN_PRINCIPAL_RADIUS_MM; r <= MAX_PRINCIPAL_RADIUS_MM; r *= 2) radii.push(r);
  radii.push(MAX_PRINCIPAL_RADIUS_MM);
  const k = [...radii.map((r) => -1 / r), 0, ...radii.map((r) => 1 / r)];
  return k.sort((a, b) => a - b);
})();

/**
 * The smallest passing curvature of the run of passing curvatures next to k0 (when k0 passes: going
 * down to the first failure; else going up to the first pass). -Infinity when nothing fails below,
 * +Infinity when nothing passes above.
 */
export function boundary(ok: (k: number) => boolean, k0: number, passesHere: boolean): number {
  if (passesHere) {
    let pass = k0;
    for (let i = GRID.length - 1; i >= 0; i--) {
      const k = GRID[i] as number;
      if (k >= pass) continue;
      if (!ok(k)) return bisectCurvature(ok, k, pass);
      pass = k;
    }
    return Number.NEGATIVE_INFINITY;
  }
  let fail = k0;
  for (const k of GRID) {
    if (k <= fail) continue;
    if (ok(k)) return bisectCurvature(ok, fail, k);
    fail = k;
  }
  return Number.POSITIVE_INFINITY;
}

/**
 * The boundary between a failing curvature `a` and a passing one `b > a`, bisected in the radius on
 * its side of straight (so the limit radius keeps its digits), to 1e-13 of the radius.
 */
function bisectCurvature(ok: (k: number) => boolean, a: number, b: number): number {
  if (a < 0 && b > 0) {
    if (ok(0)) b = 0;
    else a = 0;
  }
  if (b <= 0) {
    // Concave: radii from -1/a (fails) to -1/b (passes; infinite at b = 0, capped at 1e12 mm).
    let lo = -1 / a;
    let hi = b < 0 ? -1 / b : 1e12;
    for (let i = 0; i < 200 && hi - lo > 1e-13 * hi; i++) {
      const m = hi / lo > 4 ? Math.sqrt(lo * hi) : 0.5 * (lo + hi);
      if (ok(-1 / m)) hi = m;
      else lo = m;
    }
    return -1 / hi;
  }
  // Convex: radii from 1/b (passes) to 1/a (fails; infinite at a = 0).
  let lo = 1 / b;
  let hi = a > 0 ? 1 / a : 1e12;
  for (let i = 0; i < 200 && hi - lo > 1e-13 * hi; i++) {
    const m = hi / lo > 4 ? Math.sqrt(lo * hi) : 0.5 * (lo + hi);
    if (ok(1 / m)) lo = m;
    else hi = m;
  }
  return 1 / lo;
}
