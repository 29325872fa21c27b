/**
 * Independent brute-force reference: the implicit torus equation sampled on the h pseudo
 * plane. No parametrisation by ring or normal angle is shared with the solvers.
 *
 * A point P is inside the torus solid when F(P) = (rho_r - Rb)^2 + w^2 - Rcr^2 <= 0, with
 * w = (P - O) . ZT and rho_r the distance of P from the tool axis. On the plane z = h,
 * L/2 is the largest Y at which some x has F(x, Y, h) <= 0: for each Y the minimum over x
 * is found by dense sampling plus golden-section polishing; Y is scanned, then bisected.
 */
export function bruteForceHalfIntervalMm(R: number, Rcr: number, rhoDeg: number, h: number): number {
  const rho = (rhoDeg * Math.PI) / 180;
  const rb = R - Rcr;
  const s = Math.sin(rho);
  const c = Math.cos(rho);
  const oz = rb * s + Rcr;
  const F = (x: number, y: number): number => {
    const pz = h - oz;
    const w = x * s + pz * c;
    const rx = x - w * s;
    const rz = pz - w * c;
    const radial = Math.sqrt(rx * rx + y * y + rz * rz);
    return (radial - rb) ** 2 + w * w - Rcr * Rcr;
  };
  const minOverX = (y: number): number => {
    const n = 4000;
    const x0 = -2 * R;
    const dx = (4 * R) / n;
    let bestI = 0;
    let best = Number.POSITIVE_INFINITY;
    for (let i = 0; i <= n; i++) {
      const v = F(x0 + i * dx, y);
      if (v < best) {
        best = v;
        bestI = i;
      }
    }
    let a = x0 + (bestI - 1) * dx;
    let b = x0 + (bestI + 1) * dx;
    const g = (Math.sqrt(5) - 1) / 2;
    for (let k = 0; k < 120; k++) {
      const m1 = b - g * (b - a);
      const m2 = a + g * (b - a);
      if (F(m1, y) < F(m2, y)) b = m2;
      else a = m1;
    }
    return Math.min(best, F(0.5 * (a + b), y));
  };
  // The set of such Y need not start at 0 (for h > 2 Rcr the plane misses the torus near
  // the contact), so scan down from R to the first Y inside, then bisect above it.
  const steps = 1000;
  let lo = Number.NaN;
  let hi = R;
  for (let i = steps - 1; i >= 0; i--) {
    const y = (R * i) / steps;
    if (minOverX(y) <= 0) {
      lo = y;
      hi = (R * (i + 1)) / steps;
      break;
    }
  }
  if (Number.isNaN(lo)) throw new Error(`brute force found no torus point on z = ${h}`);
  for (let k = 0; k < 60; k++) {
    const mid = 0.5 * (lo + hi);
    if (minOverX(mid) <= 0) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

/** Small seeded PRNG (mulberry32) so that a failing random case can be replayed from its seed. */
export { seededRandom } from '../../../core/math/seededRandom';
