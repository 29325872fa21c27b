/**
 * Golden-section search, the one loop the brute-force references narrow a bracket with (each
 * reference keeps its own tolerances, and what it makes of the last bracket).
 */

/** The golden ratio's conjugate, (sqrt(5) - 1) / 2. */
const GOLDEN = (Math.sqrt(5) - 1) / 2;

/** A bracket narrowed by golden section: its ends `a`, `b` and its inner points `c < d` with f there. */
export interface GoldenBracket {
  readonly a: number;
  readonly b: number;
  readonly c: number;
  readonly d: number;
  readonly fc: number;
  readonly fd: number;
}

/**
 * Narrows [a0, b0] around a minimum of f (f unimodal there): at most `iterations` steps, while
 * `b - a > relTol (|a| + |b|) + absTol`. f is asked at c, then d, then once a step, at the new point.
 * For a maximum, pass -f (the comparisons and the values are exactly those of f, negated).
 *
 * @returns the last bracket.
 */
export function goldenSection(
  f: (x: number) => number,
  a0: number,
  b0: number,
  iterations: number,
  relTol: number,
  absTol: number,
): GoldenBracket {
  let a = a0;
  let b = b0;
  let c = b - GOLDEN * (b - a);
  let d = a + GOLDEN * (b - a);
  let fc = f(c);
  let fd = f(d);
  for (let i = 0; i < iterations && b - a > relTol * (Math.abs(a) + Math.abs(b)) + absTol; i++) {
    if (fc <= fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - GOLDEN * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + GOLDEN * (b - a);
      fd = f(d);
    }
  }
  return { a, b, c, d, fc, fd };
}
