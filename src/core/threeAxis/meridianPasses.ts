/**
 * Two adjacent waterline passes on a surface of revolution, in the meridian plane (frame of
 * meridianTool.ts: origin at the upper pass's CC point, `s` down-slope, `z` up).
 *
 * The meridian through the CC point is the circle of signed radius `Rc` tangent there (curvature
 * `k = 1/Rc`, 0 when straight), centre `M = -Rc n(alpha0)`. Its point at angle `theta` is
 * `M + Rc (sin theta, cos theta)`, with the normal `n(theta)` out of the material for either sign
 * of `Rc`; moving down the slope by the arc length `L` turns the normal by `phi = k L`:
 *
 *     alpha1 = alpha0 + k L                      (steeper on a convex meridian, flatter on a concave one)
 *     CC1 - CC0 = c t(abar),   c = 2 Rc sin(phi/2) = L sinc(kL/2),   abar = alpha0 + kL/2,
 *     t(a) = (cos a, -sin a)                     (the chord; c = L when straight)
 *
 * The tool tip is `CC + (Rcr sin a + Rb, -Rcr (1 - cos a))` (meridianTool.ts), and
 * `n(alpha1) - n(alpha0) = 2 sin(phi/2) t(abar)`, so the tips move along the same chord direction:
 *
 *     tip1 - tip0 = (1 + Rcr k) c t(abar),   dz = (1 + Rcr k) c sin(abar)
 *
 * (for `k != 0`, `dz = (Rc + Rcr)(cos alpha0 - cos alpha1)`: the corner centres ride the offset
 * circle of radius `Rc + Rcr`). `dz` grows with `L` at the rate `(1 + Rcr k) sin alpha1 > 0`,
 * so the step-down gives `L` by a safeguarded Newton iteration.
 */
import { newtonRoot } from '../math/rootFinder';
import type { MeridianTool } from './meridianTool';

/** sin(x)/x, 1 at 0 (series below 1e-4). */
export function sinc(x: number): number {
  const ax = Math.abs(x);
  if (ax < 1e-4) return 1 - (x * x) / 6;
  return Math.sin(x) / x;
}

/** Geometry of a pair of passes, filled in place (no allocation in the solvers' loops). */
export interface PassPair {
  /** Step along the meridian (arc length), mm. */
  L: number;
  /** Slope at the lower CC point, radians. */
  alpha1: number;
  /** Lower CC point, mm. */
  ccS1: number;
  ccZ1: number;
  /** Tool tips of the upper and lower pass, mm. */
  tipS0: number;
  tipZ0: number;
  tipS1: number;
  tipZ1: number;
  /** tip1 - tip0: horizontal (>= 0) and vertical drop dz (>= 0), mm. */
  dS: number;
  dz: number;
}

/** A pair's scratch state. */
export function newPassPair(): PassPair {
  return { L: 0, alpha1: 0, ccS1: 0, ccZ1: 0, tipS0: 0, tipZ0: 0, tipS1: 0, tipZ1: 0, dS: 0, dz: 0 };
}

/** The meridian at the upper CC point: its slope and curvature. */
export interface Meridian {
  /** Slope alpha0 at the upper CC point, radians, (0, pi/2). */
  readonly alpha0: number;
  readonly sin0: number;
  readonly cos0: number;
  /** Signed curvature 1/Rc (1/mm): > 0 convex, < 0 concave, 0 straight. */
  readonly k: number;
}

/** The meridian of slope `alphaRad` (radians) and signed radius `crossRadiusMm` (null: straight). */
export function meridian(alphaRad: number, crossRadiusMm: number | null): Meridian {
  return {
    alpha0: alphaRad,
    sin0: Math.sin(alphaRad),
    cos0: Math.cos(alphaRad),
    k: crossRadiusMm === null ? 0 : 1 / crossRadiusMm,
  };
}

/** Fills `out` with the pair of passes `L` (mm, >= 0) apart along the meridian. */
export function fillPassPair(t: MeridianTool, m: Meridian, L: number, out: PassPair): void {
  const half = (m.k * L) / 2;
  const abar = m.alpha0 + half;
  const sb = Math.sin(abar);
  const cb = Math.cos(abar);
  const c = L * sinc(half);
  out.L = L;
  out.alpha1 = m.alpha0 + 2 * half;
  out.ccS1 = c * cb;
  out.ccZ1 = -c * sb;
  const h0 = Math.sin(m.alpha0 / 2);
  out.tipS0 = t.rcr * m.sin0 + t.rb;
  out.tipZ0 = -2 * t.rcr * h0 * h0;
  const d = (1 + t.rcr * m.k) * c;
  out.dS = d * cb;
  out.dz = d * sb;
  out.tipS1 = out.tipS0 + out.dS;
  out.tipZ1 = out.tipZ0 - out.dz;
}

/** Step-down dz (mm) between the tool tips of passes `L` apart: `(1 + Rcr k) L sinc(kL/2) sin(abar)`. */
export function stepDownOfIntervalMm(t: MeridianTool, m: Meridian, L: number): number {
  const half = (m.k * L) / 2;
  return (1 + t.rcr * m.k) * L * sinc(half) * Math.sin(m.alpha0 + half);
}

/**
 * The arc length L (mm) whose step-down is `dzMm`, for `L` in [0, maxL] (dz increasing there):
 * the shared safeguarded Newton (rootFinder.ts) on `dz(L) - dzMm` with `dz'(L) = (1 + Rcr k)
 * sin(alpha0 + kL)`, kept in its bracket.
 * Returns null when even `maxL` steps down less than `dzMm`.
 */
export function intervalOfStepDownMm(t: MeridianTool, m: Meridian, dzMm: number, maxL: number): number | null {
  const scale = 1 + t.rcr * m.k;
  const f = {
    slope: 0,
    value(L: number): number {
      this.slope = scale * Math.sin(m.alpha0 + m.k * L);
      return stepDownOfIntervalMm(t, m, L) - dzMm;
    },
  };
  if (Number.isFinite(maxL) && !(f.value(maxL) >= 0)) return null;
  const start = dzMm / (scale * m.sin0);
  return newtonRoot(f, 0, maxL, start < maxL || !Number.isFinite(maxL) ? start : 0.5 * maxL, true, 1e-15, 100);
}
