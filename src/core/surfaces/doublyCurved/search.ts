/**
 * One-dimensional searches for the doubly curved solver: Brent's maximisation (parabolic steps,
 * golden-section steps where they do not help, so kinks are safe; R. P. Brent, "Algorithms for
 * Minimization without Derivatives", 1973, ch. 5) and a bracketed Illinois root. Allocation-free:
 * the objective is an object with a method, and the argument of the last maximum is kept in
 * {@link searchState}.
 */

/** A function of one variable, as an object (no closure built per call). */
export interface Objective {
  value(x: number): number;
}

/** Where the last {@link maximise} found its maximum (read it right after the call). */
export const searchState = { argMax: 0 };

const GOLDEN = 0.381966011250105;

/**
 * The maximum of `f` on [lo, hi]: `samples + 1` equally spaced values pick the best point, then
 * Brent's method between its neighbours to `tol` in the argument. Returns the largest value seen
 * and leaves its argument in `searchState.argMax`.
 * @param samples at least 1. @param tol absolute tolerance in x, > 0.
 */
export function maximise(f: Objective, lo: number, hi: number, samples: number, tol: number): number {
  let best = lo;
  let fBest = Number.NEGATIVE_INFINITY;
  let k = 0;
  for (let i = 0; i <= samples; i++) {
    const x = lo + ((hi - lo) * i) / samples;
    const v = f.value(x);
    if (v > fBest) {
      fBest = v;
      best = x;
      k = i;
    }
  }
  if (!(hi > lo)) {
    searchState.argMax = best;
    return fBest;
  }
  let a = lo + ((hi - lo) * Math.max(0, k - 1)) / samples;
  let b = lo + ((hi - lo) * Math.min(samples, k + 1)) / samples;
  let x = best;
  let w = x;
  let v = x;
  let fx = fBest;
  let fw = fx;
  let fv = fx;
  let d = 0;
  let e = 0;
  for (let i = 0; i < 200; i++) {
    const m = 0.5 * (a + b);
    if (Math.abs(x - m) <= 2 * tol - 0.5 * (b - a)) break;
    let parabolic = false;
    if (Math.abs(e) > tol) {
      const r = (x - w) * (fv - fx);
      let q = (x - v) * (fw - fx);
      let p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = Math.abs(q);
      if (Math.abs(p) < Math.abs(0.5 * q * e) && p > q * (a - x) && p < q * (b - x)) {
        e = d;
        d = p / q;
        parabolic = true;
      }
    }
    if (!parabolic) {
      e = x < m ? b - x : a - x;
      d = GOLDEN * e;
    }
    const u = Math.abs(d) >= tol ? x + d : x + (d > 0 ? tol : -tol);
    const fu = f.value(u);
    if (fu >= fx) {
      if (u < x) b = x;
      else a = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      if (u < x) a = u;
      else b = u;
      if (fu >= fw || w === x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu >= fv || v === x || v === w) {
        v = u;
        fv = fu;
      }
    }
  }
  if (fx >= fBest) {
    searchState.argMax = x;
    return fx;
  }
  searchState.argMax = best;
  return fBest;
}

/**
 * A root of `f` in [lo, hi] where `f(lo) <= 0 <= f(hi)` (or the reverse), by the Illinois variant
 * of regula falsi with a bisection every fourth step; to the last bits of x.
 * @param fLo f(lo), @param fHi f(hi), already evaluated.
 */
export function bracketedRoot(f: Objective, lo: number, hi: number, fLo: number, fHi: number): number {
  if (fLo === 0) return lo;
  if (fHi === 0) return hi;
  const rising = fHi > fLo;
  let side = 0;
  for (let i = 0; i < 200; i++) {
    if (!(Math.abs(hi - lo) > 2e-16 * Math.max(Math.abs(lo), Math.abs(hi)))) break;
    let x = lo - (fLo * (hi - lo)) / (fHi - fLo);
    if (!(x > Math.min(lo, hi) && x < Math.max(lo, hi)) || i % 4 === 3) x = 0.5 * (lo + hi);
    if (x === lo || x === hi) break;
    const fx = f.value(x);
    if (fx === 0) return x;
    if (fx < 0 === rising) {
      lo = x;
      fLo = fx;
      if (side === -1) fHi /= 2;
      side = -1;
    } else {
      hi = x;
      fHi = fx;
      if (side === 1) fLo /= 2;
      side = 1;
    }
  }
  return Math.abs(fLo) < Math.abs(fHi) ? lo : hi;
}
