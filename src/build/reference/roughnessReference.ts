/**
 * Reference roughness (Ra, Rq) across the feed on a plane, from the brute-force profile of the real
 * tool (oracles/bruteForce3d.ts: sampled and polished 3D tool surface, sharing nothing with the
 * solver) by the layer-cake formulas, integrated in height by Gauss-Legendre quadrature.
 *
 * One period of the profile is a list of flank segments, each a flank from its contact out to a
 * width `W` (one-way: the right flank to wR(h) and the left to wL(h); zigzag: both to L/2). With
 * `mu(s) = sum over segments of min(w(s), W)` the length of the period lying below the level s and
 * `P = sum W` the period, the mean line, Ra and Rq are
 *
 *   m = (1/P) int_0^H (P - mu) ds,   Ra = (2/P) int_m^H (P - mu) ds,
 *   Rq^2 = (1/P) [ int_0^m 2 (m - s) mu ds + int_m^H 2 (s - m) (P - mu) ds ],
 *
 * H the highest cusp. Each integral is split at 0, m, the segments' tops and H, and integrated in
 * u = sqrt(s) (a flank's width grows as sqrt(s) from its contact) with 16-point Gauss-Legendre on
 * one and on two panels per piece; the two-panel value is taken and their difference is its stated
 * quadrature uncertainty (an a-posteriori estimate, exact for polynomials of degree 31 in u), plus the
 * widths' (1e-9 R each, the brute force's asserted accuracy) carried through the formulas.
 */
import { type BruteForceProfile, bruteForceProfile } from './oracles/bruteForce3d.ts';

/** n-point Gauss-Legendre nodes and weights on [-1, 1], by Newton on the Legendre polynomial P_n. */
export function gaussLegendre(n: number): [number[], number[]] {
  const xs: number[] = [];
  const ws: number[] = [];
  for (let i = 1; i <= n; i++) {
    let x = Math.cos((Math.PI * (i - 0.25)) / (n + 0.5));
    for (let k = 0; k < 100; k++) {
      let p0 = 1;
      let p1 = x;
      for (let j = 2; j <= n; j++) [p0, p1] = [p1, ((2 * j - 1) * x * p1 - (j - 1) * p0) / j];
      const dp = (n * (x * p1 - p0)) / (x * x - 1);
      const dx = p1 / dp;
      x -= dx;
      if (Math.abs(dx) < 1e-16) {
        xs.push(x);
        ws.push(2 / ((1 - x * x) * dp * dp));
        break;
      }
    }
  }
  return [xs, ws];
}

const [GL_X, GL_W] = gaussLegendre(16);

/** int_a^b f(s) ds in u = sqrt(s) on `panels` panels: the value. */
function integrate(f: (s: number) => number, a: number, b: number, panels: number): number {
  const ua = Math.sqrt(a);
  const ub = Math.sqrt(b);
  let sum = 0;
  for (let p = 0; p < panels; p++) {
    const lo = ua + ((ub - ua) * p) / panels;
    const hi = ua + ((ub - ua) * (p + 1)) / panels;
    for (let i = 0; i < GL_X.length; i++) {
      const u = 0.5 * (lo + hi) + 0.5 * (hi - lo) * (GL_X[i] as number);
      sum += (GL_W[i] as number) * f(u * u) * 2 * u * 0.5 * (hi - lo);
    }
  }
  return sum;
}

/** int over [a, b] split at `breaks`: the two-panel value and |one-panel - two-panel|. */
function piecewise(f: (s: number) => number, a: number, b: number, breaks: readonly number[]): [number, number] {
  const cuts = [a, ...breaks.filter((x) => x > a && x < b).sort((x, y) => x - y), b];
  let value = 0;
  let error = 0;
  for (let k = 1; k < cuts.length; k++) {
    const lo = cuts[k - 1] as number;
    const hi = cuts[k] as number;
    const one = integrate(f, lo, hi, 1);
    const two = integrate(f, lo, hi, 2);
    value += two;
    error += Math.abs(two - one);
  }
  return [value, error];
}

/** The reference Ra and Rq (mm) with their uncertainties, and the reference period's highest cusp. */
export interface RoughnessReference {
  readonly raMm: number;
  readonly raUncertaintyMm: number;
  readonly rqMm: number;
  readonly rqUncertaintyMm: number;
  /** Highest cusp of the period (Rz, the contacts being its lowest points), mm. */
  readonly rzMm: number;
}

/**
 * Reference roughness of passes on a plane leaving the scallop height `h` (mm): tool radius `R`,
 * corner radius `Rcr` (mm), lead and tilt (degrees), one-way or zigzag. The step-over is the
 * reference's own (from its flank widths at h), not the solver's.
 */
export function referenceRoughness(
  R: number,
  Rcr: number,
  rhoDeg: number,
  tiltDeg: number,
  pattern: 'one-way' | 'zigzag',
  h: number,
): RoughnessReference {
  return roughnessOfProfile(bruteForceProfile(R, Rcr, rhoDeg, tiltDeg), R, pattern, h);
}

/** {@link referenceRoughness} of a brute-force profile already sampled (tool radius R, mm). */
export function roughnessOfProfile(
  p: BruteForceProfile,
  R: number,
  pattern: 'one-way' | 'zigzag',
  h: number,
): RoughnessReference {
  const wR = (s: number) => p.widthRightWithShankMm(s);
  const wL = (s: number) => p.widthLeftWithShankMm(s);
  const rightAtH = wR(h);
  const leftAtH = wL(h);
  const half = Math.min(rightAtH, leftAtH);
  const segments =
    pattern === 'one-way'
      ? [
          { w: wR, W: rightAtH, top: h },
          { w: wL, W: leftAtH, top: h },
        ]
      : [
          { w: wR, W: half, top: rightAtH > leftAtH ? lowerTop(wR, half, h) : h },
          { w: wL, W: half, top: leftAtH > rightAtH ? lowerTop(wL, half, h) : h },
        ];
  const P = segments.reduce((sum, g) => sum + g.W, 0);
  const mu = (s: number) => segments.reduce((sum, g) => sum + (s >= g.top ? g.W : Math.min(g.w(s), g.W)), 0);
  const tops = segments.map((g) => g.top);
  const H = Math.max(...tops);
  const [meanArea, meanErr] = piecewise((s) => P - mu(s), 0, H, tops);
  const m = meanArea / P;
  const [upper, upperErr] = piecewise((s) => P - mu(s), m, H, tops);
  const [lowSq, lowSqErr] = piecewise((s) => 2 * (m - s) * mu(s), 0, m, tops);
  const [upSq, upSqErr] = piecewise((s) => 2 * (s - m) * (P - mu(s)), m, H, tops);
  const ra = (2 * upper) / P;
  const rq = Math.sqrt((lowSq + upSq) / P);
  // The widths' error (1e-9 R each, two segments) moves each integral by at most that times its length.
  const widthErr = (2 * 1e-9 * R * H) / P;
  const meanUnc = meanErr / P + widthErr;
  const raUnc = (2 * upperErr) / P + 2 * widthErr + 2 * meanUnc;
  const rqUnc = (lowSqErr + upSqErr) / (2 * P * Math.max(rq, 1e-300)) + 2 * widthErr + 2 * meanUnc;
  return {
    raMm: ra,
    raUncertaintyMm: raUnc + 4 * Number.EPSILON * ra,
    rqMm: rq,
    rqUncertaintyMm: rqUnc + 4 * Number.EPSILON * rq,
    rzMm: H,
  };
}

/** The height (mm) at which a flank reaches width `W` (below h, where it reaches farther): bisection. */
function lowerTop(w: (s: number) => number, W: number, h: number): number {
  let lo = 0;
  let hi = h;
  for (let k = 0; k < 200 && hi - lo > 1e-16 * h; k++) {
    const mid = 0.5 * (lo + hi);
    if (w(mid) < W) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

/** The reference scallop height for a target Ra, with its uncertainty (mm). */
export interface HeightForRaReference {
  readonly heightMm: number;
  readonly uncertaintyMm: number;
}

/**
 * The scallop height (mm) whose passes leave the reference Ra `targetRaMm`: Illinois regula falsi
 * on Ra(h) - target over [2 Ra, the lower flank top] (Ra(2 Ra) <= Ra: the profile lies between 0
 * and h, so its mean deviation is at most h / 2), to a bracket of 1e-13 h. Its uncertainty: the
 * reference Ra's at the root divided by dRa/dh there, plus the bracket.
 */
export function referenceHeightForRa(
  R: number,
  Rcr: number,
  rhoDeg: number,
  tiltDeg: number,
  pattern: 'one-way' | 'zigzag',
  targetRaMm: number,
): HeightForRaReference {
  const p = bruteForceProfile(R, Rcr, rhoDeg, tiltDeg);
  const f = (h: number) => roughnessOfProfile(p, R, pattern, h).raMm - targetRaMm;
  let lo = 2 * targetRaMm;
  let hi = Math.min(p.hmaxRightMm, p.hmaxLeftMm) * (1 - 1e-9);
  let flo = f(lo);
  let fhi = f(hi);
  if (!(flo <= 0 && fhi > 0)) throw new Error(`target Ra ${targetRaMm} not bracketed in [${lo}, ${hi}]`);
  let side = 0;
  for (let k = 0; k < 200 && hi - lo > 1e-13 * hi; k++) {
    const x = hi - (fhi * (hi - lo)) / (fhi - flo);
    const m = x > lo && x < hi ? x : 0.5 * (lo + hi);
    const fm = f(m);
    if (fm > 0) {
      hi = m;
      fhi = fm;
      if (side === 1) flo /= 2;
      side = 1;
    } else {
      lo = m;
      flo = fm;
      if (side === -1) fhi /= 2;
      side = -1;
    }
  }
  const h = 0.5 * (lo + hi);
  const dh = 1e-6 * h;
  const slope = (f(h + dh) - f(h - dh)) / (2 * dh);
  const raUnc = roughnessOfProfile(p, R, pattern, h).raUncertaintyMm;
  return { heightMm: h, uncertaintyMm: raUnc / slope + (hi - lo) };
}
