/**
 * Gauss-Legendre rules on [-1, 1], computed once: the n roots of the Legendre polynomial P_n by
 * Newton's method from Tricomi's approximation `cos(pi (i - 1/4) / (n + 1/2))`, with the weights
 * `2 / ((1 - x^2) P_n'(x)^2)` (Abramowitz and Stegun 25.4.29). A rule of n points integrates
 * polynomials up to degree 2n - 1 exactly.
 */

/** Nodes and weights of an n-point rule. */
export interface GaussRule {
  readonly nodes: Float64Array;
  readonly weights: Float64Array;
}

/** The n-point Gauss-Legendre rule on [-1, 1] (n >= 1). */
export function gaussLegendre(n: number): GaussRule {
  const nodes = new Float64Array(n);
  const weights = new Float64Array(n);
  for (let i = 1; i <= n; i++) {
    let x = Math.cos((Math.PI * (i - 0.25)) / (n + 0.5));
    let dp = 0;
    for (let iter = 0; iter < 100; iter++) {
      // P_n(x) and P_n'(x) by the three-term recurrence.
      let p0 = 1;
      let p1 = x;
      for (let k = 2; k <= n; k++) {
        const p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const pn = n === 1 ? x : p1;
      const pPrev = n === 1 ? 1 : p0;
      dp = (n * (x * pn - pPrev)) / (x * x - 1);
      const step = pn / dp;
      x -= step;
      if (Math.abs(step) <= 1e-16) break;
    }
    nodes[i - 1] = x;
    weights[i - 1] = 2 / ((1 - x * x) * dp * dp);
  }
  return { nodes, weights };
}
