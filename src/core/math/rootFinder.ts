/**
 * The one-dimensional searches every solver of the core shares (issue 18: one safeguarded root
 * finder):
 *
 * - {@link bracketedRoot}: a root of a continuous function whose values at the ends of a bracket
 *   differ in sign, by the Illinois variant of regula falsi (M. Dowell and P. Jarratt, BIT 11, 1971)
 *   with a bisection every fourth step and wherever the secant leaves the bracket.
 * - {@link newtonRoot}: the same bracket kept around Newton steps (a caller that has the slope
 *   cheaply converges in a few steps); bisection wherever a step leaves the bracket or the slope has
 *   the wrong sign. Its step, {@link newtonStep}, is exported for the hot loops (posture.ts, the
 *   feed cylinder), which evaluate f themselves: a callback shared by many solvers is polymorphic
 *   and was measured to cost about 10 % of the exact solve.
 * - {@link maximise}: the maximum on an interval, a scan then Brent's method (parabolic steps,
 *   golden-section steps where they do not help, so kinks are safe; R. P. Brent, "Algorithms for
 *   Minimization without Derivatives", 1973, ch. 5).
 * - {@link goldenMinimum}: golden-section search for the minimum of a unimodal function.
 *
 * Guarantees (any input, including NaN and infinite values of f): every search stops after at most
 * its iteration cap, returns a point of the closed interval it was given, and evaluates f only
 * inside it. Roots: the bracket only shrinks and always keeps the sign change, so the answer is
 * within the final bracket's width of a sign change of f (for a continuous f, a root). Allocation-
 * free: the function is an object with a method (no closure needed per call), and results beyond
 * the returned number go to an out-parameter the caller owns.
 */

/** A function of one variable, as an object (no closure built per call). */
export interface Objective {
  value(x: number): number;
}

/**
 * A function and its derivative: `value(x)` returns f(x) and leaves f'(x) in `slope` (read by
 * {@link newtonRoot} right after the call).
 */
export interface NewtonObjective {
  value(x: number): number;
  readonly slope: number;
}

/** Where a search ended: its last bracket (roots) or the argument of the maximum. */
export interface SearchEnd {
  lo: number;
  hi: number;
  /** The argument of the value returned ({@link maximise}). */
  x: number;
}

/** A fresh {@link SearchEnd} to pass to a search. */
export function newSearchEnd(): SearchEnd {
  return { lo: 0, hi: 0, x: 0 };
}

/** Default relative width of a root's bracket at which {@link bracketedRoot} stops: the last bits of x. */
export const ROOT_REL_TOL = 2e-16;
/** Default iteration cap of every search here (each iteration one evaluation of f). */
export const MAX_ITERATIONS = 200;

const GOLDEN = 0.381966011250105; // (3 - sqrt(5)) / 2

/**
 * A root of `f` in the bracket [lo, hi] (lo < hi or lo > hi) where f(lo) and f(hi) have opposite
 * signs (or one is 0), by the Illinois variant of regula falsi with a bisection every fourth step
 * (so at most 4 times the bisection's iteration count). f may be +-Infinity at an end (its secant
 * then bisects). Stops when the bracket is within `relTol` of its larger end, when no double lies
 * strictly inside it, at an exact zero, or after `maxIterations` evaluations.
 * @param fLo f(lo), @param fHi f(hi), already evaluated (the ends are not evaluated again).
 * @param relTol relative width of the final bracket, >= 0 (0: down to adjacent doubles).
 * @param end when given, receives the final bracket (`lo` keeps the side of the original lo).
 * @returns the bracket end with the smaller |f|, or the exact zero found; when the signs do not
 *   differ, the end with the smaller |f|.
 */
export function bracketedRoot(
  f: Objective,
  lo: number,
  hi: number,
  fLo: number,
  fHi: number,
  relTol = ROOT_REL_TOL,
  maxIterations = MAX_ITERATIONS,
  end?: SearchEnd,
): number {
  let root = Number.NaN;
  if (fLo === 0) root = lo;
  else if (fHi === 0) root = hi;
  else if (fLo < 0 === fHi < 0) root = Math.abs(fLo) <= Math.abs(fHi) ? lo : hi;
  else {
    const rising = fHi > fLo;
    let side = 0;
    for (let i = 0; i < maxIterations; i++) {
      if (!(Math.abs(hi - lo) > relTol * Math.max(Math.abs(lo), Math.abs(hi)))) break;
      let x = lo - (fLo * (hi - lo)) / (fHi - fLo);
      if (!(x > Math.min(lo, hi) && x < Math.max(lo, hi)) || i % 4 === 3) x = 0.5 * (lo + hi);
      if (x === lo || x === hi) break;
      const fx = f.value(x);
      if (fx === 0) {
        root = x;
        lo = x;
        hi = x;
        break;
      }
      if (Number.isNaN(fx)) {
        // No sign to keep: give up the hi side (the next step bisects what is left).
        hi = x;
        fHi = Number.POSITIVE_INFINITY * (rising ? 1 : -1);
        side = 0;
      } else if (fx < 0 === rising) {
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
    if (Number.isNaN(root)) root = Math.abs(fLo) < Math.abs(fHi) ? lo : hi;
  }
  if (end !== undefined) {
    end.lo = lo;
    end.hi = hi;
    end.x = root;
  }
  return root;
}

/**
 * Bisection on a predicate that holds at `lo` and not at `hi` (lo < hi or lo > hi): the bracket
 * halved, its `lo` end moved to the midpoint where `holds` is true and its `hi` end where false, at
 * most `maxSteps` times and while |hi - lo| exceeds `width` (none: all the steps). No evaluation at
 * the ends. Returns the final bracket.
 */
export function bisect(
  holds: (x: number) => boolean,
  lo: number,
  hi: number,
  maxSteps: number,
  width = Number.NEGATIVE_INFINITY,
): { lo: number; hi: number } {
  for (let i = 0; i < maxSteps && hi - lo > width; i++) {
    const mid = 0.5 * (lo + hi);
    if (holds(mid)) lo = mid;
    else hi = mid;
  }
  return { lo, hi };
}

/**
 * The state of a safeguarded Newton iteration driven by its caller ({@link newtonStep}): the
 * bracket [lo, hi] around the root, the next point x to evaluate, and whether it is done. A class
 * with its fields set in the constructor, so that every solver hands {@link newtonStep} objects of
 * one shape (its property accesses stay monomorphic and it inlines into the hot loops; objects of
 * several shapes were measured at +5 % of the exact solve along a cylinder's feed).
 */
export class NewtonState {
  lo = 0;
  hi = 0;
  x = 0;
  done = false;
}

/** A fresh {@link NewtonState}. */
export function newNewtonState(): NewtonState {
  return new NewtonState();
}

/**
 * Starts a safeguarded Newton iteration on [lo, hi] (lo < hi; hi may be +Infinity for a positive
 * root, then bracketing by doubling) from `x0` (the midpoint, or max(2 lo, 1) for an infinite hi,
 * when x0 is not inside).
 */
export function newtonStart(st: NewtonState, lo: number, hi: number, x0: number): void {
  st.lo = lo;
  st.hi = hi;
  st.x = x0 > lo && x0 < hi ? x0 : Number.isFinite(hi) ? 0.5 * (lo + hi) : Math.max(2 * lo, 1);
  st.done = false;
}

/**
 * One step of the safeguarded Newton iteration, given f and f' at `st.x` (the caller evaluates them,
 * so the hot loops of the solvers stay free of callbacks): the bracket shrinks to the side of the
 * root (`rising`: f < 0 below the root, > 0 above; else the reverse); the Newton step replaces x,
 * or a bisection (doubling while hi is infinite) where the step leaves the bracket or the slope
 * has the wrong sign or is not finite. Sets `done` at an exact zero, when the step is within
 * `stepRelTol` of x (x is then the step's end clamped to the bracket), or when the bracket is
 * within 4e-16 of hi. The caller caps the iterations.
 */
export function newtonStep(st: NewtonState, g: number, slope: number, rising: boolean, stepRelTol: number): void {
  const x = st.x;
  if (g === 0) {
    st.done = true;
    return;
  }
  if (g > 0 === rising) st.hi = x;
  else st.lo = x;
  const { lo, hi } = st;
  let next = (rising ? slope > 0 : slope < 0) && Number.isFinite(slope) ? x - g / slope : Number.NaN;
  if (Math.abs(next - x) <= stepRelTol * Math.abs(x)) {
    st.x = Math.min(Math.max(next, lo), hi);
    st.done = true;
    return;
  }
  if (!(next > lo && next < hi)) next = Number.isFinite(hi) ? 0.5 * (lo + hi) : 2 * x;
  st.x = next;
  if (hi - lo <= 4e-16 * Math.abs(hi) && Number.isFinite(hi)) st.done = true;
}

/**
 * A root of `f` in [lo, hi] by safeguarded Newton steps ({@link newtonStep}) from `x0`, for callers
 * outside the hot loops: f.value(x) returns f(x) and leaves f'(x) in f.slope.
 * @param stepRelTol relative Newton step at which to stop, >= 0.
 * @returns the last iterate (f was last evaluated there unless the step criterion stopped it).
 */
export function newtonRoot(
  f: NewtonObjective,
  lo: number,
  hi: number,
  x0: number,
  rising: boolean,
  stepRelTol: number,
  maxIterations = MAX_ITERATIONS,
): number {
  const st = newNewtonState();
  newtonStart(st, lo, hi, x0);
  for (let i = 0; i < maxIterations && !st.done; i++) {
    const g = f.value(st.x);
    newtonStep(st, g, f.slope, rising, stepRelTol);
  }
  return st.x;
}

/**
 * The maximum of `f` on [lo, hi]: `samples + 1` equally spaced values pick the best point, then
 * Brent's method between its neighbours to `tol` in the argument. A point `must` in [lo, hi] (a
 * point known to matter, e.g. where f has a kink the scan may step over) is evaluated too; when it
 * beats the scan the search runs between its neighbouring samples. At most `samples + 2 + 200`
 * evaluations.
 * @param samples >= 1. @param tol absolute tolerance in x, > 0.
 * @param end when given, `end.x` receives the argument of the value returned.
 * @returns the largest value seen (NaN values are never chosen; -Infinity if all are).
 */
export function maximise(
  f: Objective,
  lo: number,
  hi: number,
  samples: number,
  tol: number,
  end?: SearchEnd,
  must?: number,
): number {
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
    if (end !== undefined) end.x = best;
    return fBest;
  }
  let a = lo + ((hi - lo) * Math.max(0, k - 1)) / samples;
  let b = lo + ((hi - lo) * Math.min(samples, k + 1)) / samples;
  if (must !== undefined && must >= lo && must <= hi) {
    const fm = f.value(must);
    if (fm > fBest) {
      fBest = fm;
      best = must;
      const j = Math.floor(((must - lo) / (hi - lo)) * samples);
      a = lo + ((hi - lo) * Math.max(0, j)) / samples;
      b = lo + ((hi - lo) * Math.min(samples, j + 1)) / samples;
    }
  }
  let x = best;
  let w = x;
  let v = x;
  let fx = fBest;
  let fw = fx;
  let fv = fx;
  let d = 0;
  let e = 0;
  for (let i = 0; i < MAX_ITERATIONS; i++) {
    const m = 0.5 * (a + b);
    if (Math.abs(x - m) <= 2 * tol - 0.5 * (b - a)) break;
    let parabolic = false;
    if (Math.abs(e) > tol) {
      // Parabola through x, w, v (maximising: the same algebra on -f).
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
    if (end !== undefined) end.x = x;
    return fx;
  }
  if (end !== undefined) end.x = best;
  return fBest;
}

/**
 * Golden-section search for the minimum of `f` on [lo, hi] (f unimodal there): its argument,
 * the middle of the final bracket, which is within `relTol` of `scale` (default hi) wide or
 * reached the iteration cap.
 * @param relTol >= 0, relative to `scale`.
 */
export function goldenMinimum(
  f: Objective,
  lo: number,
  hi: number,
  relTol = 1e-15,
  scale = hi,
  maxIterations = MAX_ITERATIONS,
): number {
  const g = 1 - GOLDEN;
  let c = hi - g * (hi - lo);
  let e = lo + g * (hi - lo);
  let fc = f.value(c);
  let fe = f.value(e);
  const width = relTol * Math.max(Math.abs(scale), 1e-300);
  for (let i = 0; i < maxIterations && hi - lo > width; i++) {
    if (fc < fe) {
      hi = e;
      e = c;
      fe = fc;
      c = hi - g * (hi - lo);
      fc = f.value(c);
    } else {
      lo = c;
      c = e;
      fc = fe;
      e = lo + g * (hi - lo);
      fe = f.value(e);
    }
  }
  return 0.5 * (lo + hi);
}
