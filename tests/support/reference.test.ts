/**
 * Self-tests of the independent references in tests/support/reference/: the high-precision
 * profile (support function of the projected tool, decimal.js) and the brute-force 3D one
 * (sampled tool surface, parallel circles cut by the level plane), against the exact column
 * and the closed-form limits of notes/geometry.md, closed forms derived here, each other,
 * and themselves (symmetry, inverses, working precision).
 */
import Decimal from 'decimal.js';
import { describe, expect, it } from 'vitest';
import { seededRandom } from '../../src/core/math/seededRandom';
import { bruteForceProfile } from './reference/bruteForce3d';
import { cylinderReach } from './reference/cylinderReach';
import { HighPrecisionProfile, referenceProfile } from './reference/highPrecision';

const DEG = Math.PI / 180;

/** Tool axis a = (cos(beta) sin(rho), sin(beta), cos(beta) cos(rho)) in doubles. */
function axis(rhoDeg: number, betaDeg: number): { ax: number; ay: number; az: number } {
  return {
    ax: Math.cos(betaDeg * DEG) * Math.sin(rhoDeg * DEG),
    ay: Math.sin(betaDeg * DEG),
    az: Math.cos(betaDeg * DEG) * Math.cos(rhoDeg * DEG),
  };
}

/** Mulberry32: a small seeded generator, so that every random case can be replayed. */
const seeded = seededRandom;

/** Closed forms are evaluated in 40 digits: in doubles, angles near 90 degrees cost up to 1e-11. */
const X = Decimal.clone({ precision: 40 });
const PI_X = X.acos(-1);
function axisX(rhoDeg: number, betaDeg: number): { ax: Decimal; ay: Decimal; az: Decimal } {
  const rho = new X(rhoDeg).mul(PI_X).div(180);
  const beta = new X(betaDeg).mul(PI_X).div(180);
  return { ax: X.cos(beta).mul(X.sin(rho)), ay: X.sin(beta), az: X.cos(beta).mul(X.cos(rho)) };
}
const x = (v: number): Decimal => new X(v);

const relErr = (got: number, want: number): number => Math.abs(got - want) / Math.max(Math.abs(want), 1e-300);

describe('beta = 0 against the exact column of notes/geometry.md', () => {
  const table: [number, number, number, number, number][] = [
    [3, 1, 5, 0.05, 1.443592412967],
    [3, 1, 5, 0.1, 1.892088335855],
    [3, 1, 10, 0.05, 1.08448834717],
    [3, 1, 10, 0.1, 1.484975306771],
    [6, 2, 5, 0.05, 2.115665155692],
    [6, 2, 5, 0.1, 2.887184825934],
    [6, 2, 10, 0.05, 1.558019138503],
    [6, 2, 10, 0.1, 2.16897669434],
  ];
  for (const [R, Rcr, rho, h, half] of table) {
    it(`R=${R} Rcr=${Rcr} rho=${rho} h=${h}: wR = wL = ${half} (12 decimals)`, () => {
      const p = referenceProfile(R, Rcr, rho, 0);
      expect(Math.abs(p.widthRightMm(h) - half)).toBeLessThan(6e-13);
      expect(Math.abs(p.widthLeftMm(h) - half)).toBeLessThan(6e-13);
      expect(p.contactOffsetMm).toBe(0);
      // The widest point: h = Rb sin(rho) + Rcr, at Y = R.
      expect(relErr(p.hmaxRightMm, (R - Rcr) * Math.sin(rho * DEG) + Rcr)).toBeLessThan(1e-15);
      expect(relErr(p.wmaxRightMm, R)).toBeLessThan(1e-15);
    });
  }
});

describe('closed-form limits of notes/geometry.md', () => {
  const radii = [0.001, 3, 1000];
  it('rho = 0, beta = 0: L/2 = Rb + sqrt(2 Rcr h - h^2), flat bottom (radius of curvature +Infinity)', () => {
    for (const R of radii) {
      for (const q of [1e-9, 0.3, 0.999]) {
        const Rcr = q * R;
        const p = referenceProfile(R, Rcr, 0, 0);
        expect(p.contactOffsetMm).toBe(0);
        expect(p.radiusOfCurvatureAtContactMm).toBe(Number.POSITIVE_INFINITY);
        expect(relErr(p.hmaxRightMm, Rcr)).toBeLessThan(1e-15);
        for (const f of [1e-12, 1e-6, 0.3, 0.999999, 1]) {
          const h = f * Rcr;
          const want = x(R)
            .sub(Rcr)
            .add(X.sqrt(x(h).mul(x(Rcr).mul(2).sub(h))))
            .toNumber();
          expect(relErr(p.widthRightMm(h), want)).toBeLessThan(2.3e-16);
          expect(relErr(p.widthLeftMm(h), want)).toBeLessThan(2.3e-16);
        }
        // The flat bottom: every width up to Rb is at height 0.
        expect(p.heightAtWidthRightMm(0.5 * (R - Rcr))).toBe(0);
      }
    }
  });

  it('flat end, no lead, no tilt: the profile is the flat bottom with vertical walls', () => {
    const p = referenceProfile(2, 0, 0, 0);
    expect(p.hmaxRightMm).toBe(0);
    expect(p.widthRightMm(0)).toBe(2);
    expect(p.heightAtWidthLeftMm(1.5)).toBe(0);
    expect(() => p.widthRightMm(1e-3)).toThrow(RangeError);
  });

  it('ball end (Rcr = R): wR = wL = sqrt(2 R h - h^2) in every posture, contact under O, radius R', () => {
    for (const R of radii) {
      for (const [rho, beta] of [
        [0, 0],
        [0, 60],
        [5, 0],
        [30, -45],
        [89.9999, 10],
        [45, 89.99],
        [0, -89.99],
        [89.9999, -89.99],
      ] as const) {
        const p = referenceProfile(R, R, rho, beta);
        expect(Math.abs(p.contactOffsetMm)).toBeLessThan(1e-15 * R);
        expect(relErr(p.hmaxRightMm, R)).toBeLessThan(1e-15);
        expect(relErr(p.hmaxLeftMm, R)).toBeLessThan(1e-15);
        expect(relErr(p.radiusOfCurvatureAtContactMm, R)).toBeLessThan(1e-15);
        for (const f of [1e-12, 1e-4, 0.37, 1]) {
          const h = f * R;
          const want = Math.sqrt(h * (2 * R - h));
          expect(relErr(p.widthRightMm(h), want)).toBeLessThan(1e-15);
          expect(relErr(p.widthLeftMm(h), want)).toBeLessThan(1e-15);
          const w = f * R;
          // Height of the circle at width w, without cancellation: w^2 / (R + sqrt(R^2 - w^2)).
          expect(relErr(p.heightAtWidthLeftMm(w), (w * w) / (R + Math.sqrt((R - w) * (R + w))))).toBeLessThan(1e-15);
        }
      }
    }
  });

  it('flat end (Rcr = 0), beta = 0: the ellipse L/2 = Rb sqrt(1 - (1 - h/(Rb sin rho))^2)', () => {
    for (const R of radii) {
      for (const rho of [1e-4, 5, 30, 89.9999]) {
        const p = referenceProfile(R, 0, rho, 0);
        const b = R * Math.sin(rho * DEG);
        expect(relErr(p.hmaxRightMm, b)).toBeLessThan(1e-15);
        expect(relErr(p.radiusOfCurvatureAtContactMm, R / Math.sin(rho * DEG))).toBeLessThan(1e-15);
        for (const f of [1e-6, 0.01, 0.5, 0.9, 1]) {
          const h = f * b;
          // The notes' form (its 1 - h/b cancels digits at small h: 1e-10 relative at h = 1e-6 b).
          expect(relErr(p.widthRightMm(h), R * Math.sqrt(1 - (1 - h / b) ** 2))).toBeLessThan(1e-9);
        }
        for (const f of [1e-12, 1e-9, 0.3, 1]) {
          const h = f * b;
          // The same without cancellation.
          expect(relErr(p.widthLeftMm(h), R * Math.sqrt(f * (2 - f)))).toBeLessThan(2e-15);
        }
      }
    }
  });
});

describe('closed forms derived for tilted tools', () => {
  // Flat end (Rcr = 0) in any posture with rho > 0: the projected rim is the ellipse
  // |p|^2 + (a'.p)^2 / a_x^2 = Rb^2 (p relative to O, a' = (a_y, a_z)); cut at z = z0 + h it gives
  //   w_R,L(h) = (a_x sqrt(h (2 Rb m - h)) -+ a_y a_z h) / m^2,   m^2 = a_x^2 + a_y^2,
  // with the contact at y0 = Rb a_y a_z / m, z0 = -Rb m.
  it('flat end, any posture: w = (a_x sqrt(h (2 Rb m - h)) -+ a_y a_z h) / m^2', () => {
    for (const R of [0.001, 1, 1000]) {
      for (const [rho, beta] of [
        [5, 20],
        [30, -45],
        [60, 80],
        [89.9999, 10],
        [0.5, -89.99],
        [89.9, 89.99],
        [1e-6, 30],
      ] as const) {
        const { ax, ay, az } = axisX(rho, beta);
        const m2 = ax.mul(ax).add(ay.mul(ay));
        const m = X.sqrt(m2);
        const p = referenceProfile(R, 0, rho, beta);
        expect(Math.abs(p.contactOffsetMm - x(R).mul(ay).mul(az).div(m).toNumber())).toBeLessThan(1.2e-16 * R);
        expect(relErr(p.radiusOfCurvatureAtContactMm, x(R).mul(ax).mul(ax).div(m2.mul(m)).toNumber())).toBeLessThan(
          1.2e-16,
        );
        for (const side of [1, -1]) {
          const hmax = side > 0 ? p.hmaxRightMm : p.hmaxLeftMm;
          for (const f of [1e-12, 1e-6, 0.2, 0.7, 1]) {
            const h = x(f * hmax);
            const root = X.sqrt(
              h.mul(
                x(2 * R)
                  .mul(m)
                  .sub(h),
              ),
            );
            const want = ax.mul(root).sub(ay.mul(az).mul(h).mul(side)).div(m2).toNumber();
            const got = side > 0 ? p.widthRightMm(h.toNumber()) : p.widthLeftMm(h.toNumber());
            expect(relErr(got, want)).toBeLessThan(2.3e-16);
          }
        }
      }
    }
  });

  // rho = 0, beta > 0: the disk projects to the segment from E1 = Rb (cos b, -sin b) (low end)
  // to -E1, grown by Rcr. Right flank: the arc around E1 (up to h = Rcr). Left flank: the arc
  // around E1 up to h1 = Rcr (1 - cos b), the straight segment (slope tan b) for 2 Rb sin b,
  // then the arc around -E1 up to hmaxL = 2 Rb sin b + Rcr. The shank starts cutting at
  // Rcr (1 - sin b).
  it('rho = 0 with tilt: arc, straight flat bottom seen edge-on, arc', () => {
    for (const [R, Rcr, beta] of [
      [3, 1, 20],
      [6, 2, -60],
      [1, 1e-9, 45],
      [1000, 400, 89.99],
      [0.001, 0.0007, -5],
    ] as const) {
      const { ay, az } = axisX(0, Math.abs(beta));
      const sinB = ay.toNumber();
      const cosB = az.toNumber();
      const Rb = x(R).sub(Rcr).toNumber();
      const p = referenceProfile(R, Rcr, 0, beta);
      const near = beta > 0 ? { w: p.widthRightMm, hmax: p.hmaxRightMm } : { w: p.widthLeftMm, hmax: p.hmaxLeftMm };
      const far = beta > 0 ? { w: p.widthLeftMm, hmax: p.hmaxLeftMm } : { w: p.widthRightMm, hmax: p.hmaxRightMm };
      expect(Math.abs(p.contactOffsetMm - Math.sign(beta) * Rb * cosB)).toBeLessThan(4e-16 * R);
      expect(relErr(p.radiusOfCurvatureAtContactMm, Rcr)).toBeLessThan(1e-15);
      expect(relErr(near.hmax, Rcr)).toBeLessThan(1e-15);
      expect(relErr(far.hmax, 2 * Rb * sinB + Rcr)).toBeLessThan(1e-15);
      const shank = beta > 0 ? p.shankHeightRightMm : p.shankHeightLeftMm;
      expect(Math.abs(shank - x(Rcr).mul(x(1).sub(ay)).toNumber())).toBeLessThan(2.3e-16 * R);
      for (const f of [1e-12, 0.3, 1]) {
        const h = f * Rcr;
        expect(relErr(near.w(h), Math.sqrt(h * (2 * Rcr - h)))).toBeLessThan(4e-16);
      }
      const h1 = Rcr * (1 - cosB);
      const h2 = h1 + 2 * Rb * sinB;
      const farWant = (h: number): number => {
        if (h <= h1) return Math.sqrt(h * (2 * Rcr - h));
        if (h <= h2) return Rcr * sinB + ((h - h1) * cosB) / sinB;
        const dz = h - 2 * Rb * sinB - Rcr;
        return 2 * Rb * cosB + Math.sqrt((Rcr - dz) * (Rcr + dz));
      };
      for (const h of [
        0.5 * h1,
        h1,
        h1 + 0.25 * (h2 - h1),
        0.5 * (h1 + h2),
        h2,
        h2 + 0.5 * (far.hmax - h2),
        far.hmax,
      ]) {
        expect(Math.abs(far.w(h) - farWant(h))).toBeLessThan(1e-12 * R);
      }
    }
  });
});

describe('symmetry: beta -> -beta mirrors the profile', () => {
  const rnd = seeded(20240601);
  for (let i = 0; i < 12; i++) {
    const R = 10 ** (-3 + 6 * rnd());
    const ratio = [0, 1, 1e-9, rnd()][i % 4] ?? 0;
    const rho = [0, 89.9999, 90 * rnd()][i % 3] ?? 0;
    const beta = [80, 89.99, 90 * rnd()][i % 3] ?? 0;
    it(`seed 20240601 #${i}: R=${R.toPrecision(4)} Rcr/R=${ratio.toPrecision(3)} rho=${rho.toPrecision(6)} beta=+-${beta.toPrecision(6)}`, () => {
      const p = referenceProfile(R, ratio * R, rho, beta);
      const q = referenceProfile(R, ratio * R, rho, -beta);
      expect(Math.abs(p.contactOffsetMm + q.contactOffsetMm)).toBeLessThan(1e-15 * R);
      expect(relErr(q.hmaxLeftMm, p.hmaxRightMm)).toBeLessThan(1e-15);
      expect(relErr(q.hmaxRightMm, p.hmaxLeftMm)).toBeLessThan(1e-15);
      expect(relErr(q.shankHeightLeftMm, p.shankHeightRightMm)).toBeLessThan(1e-15);
      expect(relErr(q.shankHeightRightMm, p.shankHeightLeftMm)).toBeLessThan(1e-15);
      for (const f of [1e-9, 0.4, 1]) {
        expect(relErr(q.widthLeftMm(f * p.hmaxRightMm), p.widthRightMm(f * p.hmaxRightMm))).toBeLessThan(1e-15);
        expect(relErr(q.widthRightMm(f * p.hmaxLeftMm), p.widthLeftMm(f * p.hmaxLeftMm))).toBeLessThan(1e-15);
      }
    });
  }
});

describe('high precision against the brute-force 3D sampling', () => {
  // Stratified: Rcr/R in {0, 1e-9, random, 1}, rho in {0, random, near 90}, beta in
  // {0, +-80, random}, R log-uniform in [0.001, 1000]; h from 1e-6 hmax to hmax on both flanks.
  const SEED = 7919;
  const rnd = seeded(SEED);
  const qs = [0, 1e-9, -1, 1];
  const rhos = [0, -1, 89.9];
  const betas = [0, 80, -80, -1];
  let n = 0;
  for (const q0 of qs) {
    for (const rho0 of rhos) {
      for (const beta0 of betas) {
        const R = 10 ** (-3 + 6 * rnd());
        const q = q0 < 0 ? rnd() : q0;
        const rho = rho0 < 0 ? 89.9 * rnd() : rho0;
        const beta = beta0 < 0 ? 178 * rnd() - 89 : beta0;
        const fractions = [1e-6, 10 ** (-5 * rnd()), rnd(), 1];
        const i = n++;
        it(`seed ${SEED} #${i}: R=${R.toPrecision(5)} Rcr/R=${q.toPrecision(4)} rho=${rho.toPrecision(6)} beta=${beta.toPrecision(6)}`, () => {
          const p = referenceProfile(R, q * R, rho, beta);
          const bf = bruteForceProfile(R, q * R, rho, beta);
          const tol = 1e-9 * R;
          expect(Math.abs(p.contactOffsetMm - bf.contactOffsetMm)).toBeLessThan(tol);
          expect(Math.abs(p.hmaxRightMm - bf.hmaxRightMm)).toBeLessThan(tol);
          expect(Math.abs(p.hmaxLeftMm - bf.hmaxLeftMm)).toBeLessThan(tol);
          expect(Math.abs(p.wmaxRightMm - bf.wmaxRightMm)).toBeLessThan(tol);
          expect(Math.abs(p.wmaxLeftMm - bf.wmaxLeftMm)).toBeLessThan(tol);
          for (const f of fractions) {
            expect(Math.abs(p.widthRightMm(f * p.hmaxRightMm) - bf.widthRightMm(f * p.hmaxRightMm))).toBeLessThan(tol);
            expect(Math.abs(p.widthLeftMm(f * p.hmaxLeftMm) - bf.widthLeftMm(f * p.hmaxLeftMm))).toBeLessThan(tol);
          }
          // The whole tool on the side the shank leans to, from the junction to the sampled shank's reach.
          const { az } = axis(rho, beta);
          const shankLength = 3 * R;
          for (const side of ['Right', 'Left'] as const) {
            const hs = side === 'Right' ? p.shankHeightRightMm : p.shankHeightLeftMm;
            const top = side === 'Right' ? p.hmaxRightMm : p.hmaxLeftMm;
            if (beta === 0 || hs >= top) continue;
            const reach = Math.min(1.5 * top, hs + 0.9 * shankLength * az);
            for (const f of [0.5, 1, 1 + 1e-3, 1.5]) {
              const h = f <= 1 ? f * hs : hs + (f - 1) * (reach - hs);
              const want = side === 'Right' ? p.widthRightWithShankMm(h) : p.widthLeftWithShankMm(h);
              const got = side === 'Right' ? bf.widthRightWithShankMm(h) : bf.widthLeftWithShankMm(h);
              expect(Math.abs(want - got)).toBeLessThan(tol);
            }
          }
        });
      }
    }
  }
});

describe('where the shank starts cutting', () => {
  it("ball end: R (1 - sin|beta'|), beta' the lean seen along the feed (tan beta' = tan beta / cos rho)", () => {
    for (const R of [0.001, 6, 1000]) {
      for (const rho of [0, 10, 60, 89.9999]) {
        for (const beta of [1e-3, 5, 30, 80, 89.99]) {
          // sin(beta') = |a_y| / sqrt(a_y^2 + a_z^2).
          const { ay, az } = axisX(rho, beta);
          const want = x(R)
            .mul(x(1).sub(ay.div(X.sqrt(ay.mul(ay).add(az.mul(az))))))
            .toNumber();
          const p = referenceProfile(R, R, rho, beta);
          const q = referenceProfile(R, R, rho, -beta);
          expect(relErr(p.shankHeightRightMm, want)).toBeLessThan(1.2e-16);
          expect(relErr(q.shankHeightLeftMm, want)).toBeLessThan(1.2e-16);
          // On the other side the junction lies on the wall, above the widest point.
          expect(p.shankHeightLeftMm).toBe(p.hmaxLeftMm);
          expect(p.shankJunctionLeftMm).toBeGreaterThan(p.hmaxLeftMm);
        }
      }
    }
  });

  it('no tilt: the shank joins at the widest point on both sides', () => {
    for (const [R, Rcr, rho] of [
      [3, 1, 5],
      [6, 0, 30],
      [1, 1, 0],
    ] as const) {
      const p = referenceProfile(R, Rcr, rho, 0);
      expect(relErr(p.shankHeightRightMm, p.hmaxRightMm)).toBeLessThan(1e-15);
      expect(relErr(p.shankJunctionLeftMm, p.hmaxLeftMm)).toBeLessThan(1e-15);
    }
  });

  // At the junction the end's flank, sampled by the brute force, has the slope of the shank's
  // straight edge, dw/dh = |a_y| / a_z; above it the sampled whole tool follows that edge.
  const SEED = 4242;
  const rnd = seeded(SEED);
  for (let i = 0; i < 10; i++) {
    const R = 10 ** (-3 + 6 * rnd());
    const q = [0, 1, rnd(), rnd(), 1e-9][i % 5] ?? 0;
    const rho = i % 2 === 1 && q > 0.01 ? 0 : 1 + 88 * rnd();
    const beta = (i % 2 === 0 ? 1 : -1) * (i < 8 ? ([10, 30, 60, 80][i % 4] ?? 10) : 1 + 88 * rnd());
    it(`seed ${SEED} #${i}: the brute force sees the shank edge tangent at the reference's height (R=${R.toPrecision(4)} Rcr/R=${q.toPrecision(3)} rho=${rho.toPrecision(5)} beta=${beta.toPrecision(5)})`, () => {
      const p = referenceProfile(R, q * R, rho, beta);
      const bf = bruteForceProfile(R, q * R, rho, beta);
      const { ay, az } = axis(rho, beta);
      const right = beta > 0;
      const hs = right ? p.shankHeightRightMm : p.shankHeightLeftMm;
      const top = right ? p.hmaxRightMm : p.hmaxLeftMm;
      const endW = right ? bf.widthRightMm : bf.widthLeftMm;
      const fullW = right ? bf.widthRightWithShankMm : bf.widthLeftWithShankMm;
      const step = 1e-4 * Math.min(hs, top - hs);
      const slope = (endW(hs + step) - endW(hs - step)) / (2 * step);
      expect(Math.abs(Math.atan(slope) - Math.atan(Math.abs(ay) / az))).toBeLessThan(1e-6);
      expect(Math.abs(fullW(hs - step) - endW(hs - step))).toBeLessThan(1e-9 * R);
      // Above the junction the whole tool is wider than its end by the edge's chord.
      const h2 = hs + 0.5 * (top - hs);
      expect(fullW(h2) - endW(h2)).toBeGreaterThan(1e-9 * R);
      expect(Math.abs(fullW(h2) - (fullW(hs) + ((h2 - hs) * Math.abs(ay)) / az))).toBeLessThan(1e-9 * R);
    });
  }
});

describe('radius of curvature at the contact, by finite differences of the high-precision profile', () => {
  // Z'' at the contact from the heights of both flanks at width w: r = w^2 / (hR(w) + hL(w)),
  // exact to O(w^2 / r^2); with w = 1e-15 min(r, R) and 64 working digits, 1e-20 relative.
  const SEED = 31337;
  const rnd = seeded(SEED);
  const cases: [number, number, number, number][] = [
    [3, 1, 5, 0],
    [3, 1, 5, 20],
    [6, 2, 0, 30],
    [1, 0, 10, 30],
    [1, 1, 45, 70],
    [2, 2e-9, 20, -10],
    [10, 3, 89.9999, 10],
    [1000, 200, 1e-4, -85],
    [0.001, 0.0003, 45, 89.99],
  ];
  for (let i = 0; i < 6; i++) {
    const R = 10 ** (-3 + 6 * rnd());
    cases.push([R, rnd() * R, 89 * rnd(), 178 * rnd() - 89]);
  }
  for (const [R, Rcr, rho, beta] of cases) {
    it(`seed ${SEED}: R=${R.toPrecision(4)} Rcr=${Rcr.toPrecision(4)} rho=${rho.toPrecision(5)} beta=${beta.toPrecision(5)}`, () => {
      const p = referenceProfile(R, Rcr, rho, beta);
      const r = p.radiusOfCurvatureAtContactMm;
      const hp = p.exact;
      const w = new hp.D(Math.min(r, R)).mul('1e-15');
      const hSum = hp.heightAtWidth('right', w).add(hp.heightAtWidth('left', w));
      const rFd = w.mul(w).div(hSum).toNumber();
      expect(relErr(rFd, r)).toBeLessThan(1e-12);
    });
  }
});

describe('working precision: 64 digits agree with 100 to 40 significant digits', () => {
  const extremes: [number, number, number, number][] = [
    [0.001, 0, 89.9999, 89.99],
    [1000, 1e-6, 0, -89.99],
    [1000, 1000, 89.9999, -89.99],
    [0.001, 0.0005, 1e-6, 45],
    [3, 1, 5, 0],
    [50, 49.9, 89.9999, 0.001],
  ];
  for (const [R, Rcr, rho, beta] of extremes) {
    it(`R=${R} Rcr=${Rcr} rho=${rho} beta=${beta}, h down to 1e-12 hmax`, () => {
      const lo = HighPrecisionProfile.create(R, Rcr, rho, beta);
      const hi = HighPrecisionProfile.create(R, Rcr, rho, beta, 100);
      const agree = (a: Decimal, b: Decimal, scale = Decimal.max(a.abs(), b.abs())): void => {
        if (scale.isZero()) return;
        expect(a.sub(b).abs().div(scale).lt('1e-40')).toBe(true);
      };
      agree(lo.contact.y, hi.contact.y, new Decimal(R));
      for (const side of ['right', 'left'] as const) {
        const top = hi.hmax(side);
        agree(lo.hmax(side), top);
        for (const f of ['1e-12', '1e-6', '0.5', '1']) {
          const h = top.mul(f);
          const wLo = lo.width(side, new lo.D(h.toString()));
          const wHi = hi.width(side, h);
          agree(wLo, wHi);
          agree(lo.heightAtWidth(side, new lo.D(wHi.toString())), hi.heightAtWidth(side, wHi));
        }
      }
    });
  }
});

describe('40 significant digits against closed forms evaluated in 60 digits', () => {
  // 64 against 100 working digits (above) checks the arithmetic; this checks the root finding
  // and the geometry to the claimed 40 digits, where a closed form exists.
  const Y = Decimal.clone({ precision: 60 });
  const axis60 = (rhoDeg: number, betaDeg: number): { ax: Decimal; ay: Decimal; az: Decimal } => {
    const pi = Y.acos(-1);
    const rho = new Y(rhoDeg).mul(pi).div(180);
    const beta = new Y(betaDeg).mul(pi).div(180);
    return { ax: Y.cos(beta).mul(Y.sin(rho)), ay: Y.sin(beta), az: Y.cos(beta).mul(Y.cos(rho)) };
  };
  const close40 = (got: Decimal, want: Decimal): void => {
    expect(new Y(got).sub(want).abs().lte(want.abs().mul('1e-40'))).toBe(true);
  };
  const cases: [number, number, number][] = [
    [0.001, 89.9999, 89.99],
    [1000, 0, -89.99],
    [3, 5, 20],
    [1, 1e-6, -30],
    [50, 60, 0.001],
  ];
  for (const [R, rho, beta] of cases) {
    it(`R=${R} rho=${rho} beta=${beta}: ball end, flat end (any posture) and rho = 0 corner, h from 1e-12 hmax`, () => {
      const ball = HighPrecisionProfile.create(R, R, rho, beta);
      const flat = rho > 0 ? HighPrecisionProfile.create(R, 0, rho, beta) : null;
      const { ax, ay, az } = axis60(rho, beta);
      const m2 = ax.mul(ax).add(ay.mul(ay));
      const m = Y.sqrt(m2);
      for (const f of ['1e-12', '1e-7', '0.3', '0.9999']) {
        for (const side of ['right', 'left'] as const) {
          const h = new Y(R).mul(f);
          close40(ball.width(side, new ball.D(h)), Y.sqrt(h.mul(new Y(2 * R).sub(h))));
          if (flat !== null) {
            const hf = flat.hmax(side).mul(f);
            const hY = new Y(hf);
            const root = Y.sqrt(hY.mul(new Y(2 * R).mul(m).sub(hY)));
            const sign = side === 'right' ? 1 : -1;
            close40(flat.width(side, hf), ax.mul(root).sub(ay.mul(az).mul(hY).mul(sign)).div(m2));
          }
        }
      }
      const corner = HighPrecisionProfile.create(R, 0.25 * R, 0, 0);
      const hc = new corner.D(R).mul('0.25e-12');
      const want = new Y(0.75 * R).add(Y.sqrt(new Y(hc).mul(new Y(0.5 * R).sub(hc))));
      close40(corner.width('left', hc), want);
    });
  }
});

describe('inverse and domain', () => {
  it('heightAtWidth(width(h)) = h on both flanks', () => {
    const rnd = seeded(99);
    for (let i = 0; i < 10; i++) {
      const R = 10 ** (-3 + 6 * rnd());
      const p = referenceProfile(R, rnd() * R, 89 * rnd(), 178 * rnd() - 89);
      for (const f of [1e-9, rnd(), 0.999]) {
        const h = f * p.hmaxRightMm;
        expect(relErr(p.heightAtWidthRightMm(p.widthRightMm(h)), h)).toBeLessThan(1e-12);
        const g = f * p.hmaxLeftMm;
        expect(relErr(p.heightAtWidthLeftMm(p.widthLeftMm(g)), g)).toBeLessThan(1e-12);
      }
    }
  });

  it('rejects postures and heights outside the domain', () => {
    expect(() => referenceProfile(1, 1.5, 5, 0)).toThrow(RangeError);
    expect(() => referenceProfile(1, 0.5, 90, 0)).toThrow(RangeError);
    expect(() => referenceProfile(1, 0.5, 5, -90)).toThrow(RangeError);
    expect(() => referenceProfile(0, 0, 5, 0)).toThrow(RangeError);
    const p = referenceProfile(3, 1, 5, 20);
    expect(() => p.widthRightMm(p.hmaxRightMm * 1.001)).toThrow(RangeError);
    expect(() => p.widthLeftMm(-1e-9)).toThrow(RangeError);
    expect(() => p.heightAtWidthRightMm(p.wmaxRightMm * 1.001)).toThrow(RangeError);
    // The rounded widest point itself is accepted.
    expect(p.widthRightMm(p.hmaxRightMm)).toBeCloseTo(p.wmaxRightMm, 14);
  });
});

describe('the polished cylinder brute force (reference/cylinderReach.ts) against closed forms and the plane', () => {
  const tool = (R: number, Rcr: number, rho: number, tilt: number) => ({
    toolRadiusMm: R,
    cornerRadiusMm: Rcr,
    leadAngleDeg: rho,
    tiltAngleDeg: tilt,
  });

  it('a ball end along the feed: the half-angle of two circles (law of cosines), convex and concave', () => {
    for (const [R, rs, h, rho, tilt] of [
      [3, 20, 0.05, 10, 20],
      [3, -20, 0.05, 0, 0],
      [1, 5, 0.2, 45, -30],
    ] as const) {
      const d = rs > 0 ? rs + R : -rs - R;
      const r = rs > 0 ? rs + h : -rs - h;
      const half = 2 * Math.asin(Math.sqrt((h * (2 * R - h)) / (4 * d * r)));
      const ref = cylinderReach(tool(R, R, rho, tilt), rs, 'feed', { ringSamples: 360 });
      for (const side of ['right', 'left'] as const)
        expect(Math.abs(ref.reach(side, h, false) - half) * Math.abs(rs)).toBeLessThan(1e-12);
    }
  });

  it('across the feed: a ball end leaves the plane circle, a flat bottom the plane profile Rb + sqrt(2 Rcr h - h^2)', () => {
    const ball = cylinderReach(tool(3, 3, 20, 10), 5, 'cross', { ringSamples: 360 });
    expect(Math.abs(ball.reach('right', 0.05, false) - Math.sqrt(0.05 * (6 - 0.05)))).toBeLessThan(1e-12);
    const flat = cylinderReach(tool(3, 1, 0, 0), 10, 'cross', { ringSamples: 360 });
    expect(Math.abs(flat.reach('left', 0.05, false) - (2 + Math.sqrt(2 * 0.05 - 0.0025)))).toBeLessThan(1e-12);
  });

  it('a nearly flat cylinder gives the plane flanks of the 3D brute force, with and without the shank', () => {
    for (const [R, Rcr, rho, tilt, h] of [
      [3, 1, 5, 20, 0.3],
      [2, 0.5, 30, -40, 0.2],
    ] as const) {
      const plane = bruteForceProfile(R, Rcr, rho, tilt);
      const ref = cylinderReach(tool(R, Rcr, rho, tilt), 1e7, 'cross', { ringSamples: 360 });
      // Across a cylinder of 1e7 mm the flanks differ from the plane's by about w^2 / Rs.
      expect(Math.abs(ref.reach('right', h, false) - plane.widthRightMm(h))).toBeLessThan(1e-6);
      expect(Math.abs(ref.reach('left', h, false) - plane.widthLeftMm(h))).toBeLessThan(1e-6);
      const hs = 1.5 * Math.min(plane.hmaxRightMm, plane.hmaxLeftMm);
      const above = Math.min(hs, 0.9 * Math.max(plane.hmaxRightMm, plane.hmaxLeftMm));
      const lean = tilt > 0 ? 'right' : 'left';
      const bf = lean === 'right' ? plane.widthRightWithShankMm(above) : plane.widthLeftWithShankMm(above);
      expect(Math.abs(ref.reach(lean, above, true) - bf)).toBeLessThan(1e-6);
    }
  });
});
