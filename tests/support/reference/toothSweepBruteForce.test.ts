/**
 * Self-tests of the tooth-sweep brute force (tests/support/reference/toothSweepBruteForce.ts):
 * convergence and bracket as the density grows, closed forms derived here (the ball end at
 * lead 0, the continuous cross-feed profile of a bull-nose tool at lead 0 as fz -> 0), the
 * exact identity "z teeth at fz = one tooth at z fz, shifted", and the symmetries of the model.
 */
import { describe, expect, it } from 'vitest';
import { seededRandom } from '../../../src/core/math/seededRandom';
import {
  bruteArealParameters,
  bruteArealQuadrature,
  bruteEnvelopeHeightMm,
  bruteFeedMarkHeightMm,
  certifiedEnvelopeHeightMm,
  type ToothSweepParams,
} from './toothSweepBruteForce';

const DEG = Math.PI / 180;

const rng = seededRandom;

const base: ToothSweepParams = {
  radiusMm: 3,
  cornerRadiusMm: 1,
  leadRad: 0,
  tiltRad: 0,
  pattern: 'one-way',
  stepOverMm: 2.5,
  flutes: 2,
  fzMm: 0.1,
  runoutMm: 0,
  runoutPhaseRad: 0,
  passPhase: 0,
};

const height = (p: ToothSweepParams, x: number, y: number, density = 50): number =>
  bruteEnvelopeHeightMm(p, x, y, density).heightMm;

describe('toothSweepBruteForce', () => {
  it('converges as the density grows: the refined height is stable and the bracket holds and halves (seed 29)', () => {
    const p: ToothSweepParams = {
      ...base,
      leadRad: 5 * DEG,
      tiltRad: 10 * DEG,
      pattern: 'zigzag',
      stepOverMm: 2,
      flutes: 3,
      fzMm: 0.08,
      runoutMm: 0.005,
      runoutPhaseRad: 0.7,
      passPhase: 0.3,
    };
    const r = rng(29);
    for (let n = 0; n < 5; n++) {
      const x = r() * 0.24;
      const y = -1 + r() * 4;
      const coarse = bruteEnvelopeHeightMm(p, x, y, 40);
      const mid = bruteEnvelopeHeightMm(p, x, y, 80);
      const fine = bruteEnvelopeHeightMm(p, x, y, 320);
      for (const c of [coarse, mid]) {
        expect(Math.abs(c.heightMm - fine.heightMm)).toBeLessThan(1e-11);
        expect(c.lowerBoundMm).toBeLessThanOrEqual(fine.heightMm);
      }
      expect(fine.newtonErrorMm).toBeLessThan(1e-12);
      expect(fine.boundMm).toBeGreaterThan(0);
      expect(fine.boundMm).toBeLessThan(coarse.boundMm / 4);
      expect(mid.boundMm).toBeLessThan(coarse.boundMm / 1.5);
    }
  });

  it('branch and bound certifies the refined height to 1e-9 mm over the strata: ball, flat, bull-nose, lead 0 and not, tilt, zigzag, runout (seed 41)', () => {
    const r = rng(41);
    const between = (lo: number, hi: number): number => lo + (hi - lo) * r();
    const strata: ((R: number) => Partial<ToothSweepParams>)[] = [
      (R) => ({ cornerRadiusMm: R, leadRad: 0 }),
      (R) => ({ cornerRadiusMm: R, leadRad: between(5, 20) * DEG, tiltRad: between(-15, 15) * DEG }),
      () => ({ cornerRadiusMm: 0, leadRad: between(2, 10) * DEG }),
      () => ({ cornerRadiusMm: 0, leadRad: between(2, 10) * DEG, tiltRad: between(-10, 10) * DEG, pattern: 'zigzag' }),
      (R) => ({ cornerRadiusMm: between(0.2, 0.5) * R, leadRad: 0, tiltRad: between(3, 12) * DEG }),
      (R) => ({
        cornerRadiusMm: between(0.2, 0.5) * R,
        leadRad: between(2, 15) * DEG,
        pattern: 'zigzag',
        runoutMm: between(0.002, 0.01),
        runoutPhaseRad: between(0, 2 * Math.PI),
        passPhase: r(),
      }),
    ];
    for (const stratum of strata) {
      const R = between(2, 5);
      const p: ToothSweepParams = {
        ...base,
        radiusMm: R,
        stepOverMm: between(0.2, 0.6) * R,
        flutes: 1 + Math.floor(r() * 4),
        fzMm: between(0.01, 0.15),
        ...stratum(R),
      };
      for (let n = 0; n < 2; n++) {
        const x = r() * p.flutes * p.fzMm;
        const y = between(-0.5, 1.5) * p.stepOverMm;
        const refined = height(p, x, y, 50);
        const c = certifiedEnvelopeHeightMm(p, x, y, 1e-9);
        expect(c.complete).toBe(true);
        expect(c.boundMm).toBeLessThanOrEqual(1e-9);
        expect(refined).toBeGreaterThanOrEqual(c.lowerBoundMm - 1e-12);
        expect(refined).toBeLessThanOrEqual(c.heightMm + 1e-9);
      }
    }
  });

  it('flat end near its rim at a small fz: cut by the side, then by no pass, then by the flat lower down; the walk bridges the gap', () => {
    // Found by a random sweep against the certificate (seed 2030): the cells hold only the rim's
    // samples, the chain of crossings through the point has 22 tooth passes that miss it.
    const p: ToothSweepParams = {
      ...base,
      radiusMm: 4.389472550712526,
      cornerRadiusMm: 0,
      leadRad: 0.3262924785878849,
      tiltRad: 0.2782325094551036,
      stepOverMm: 2.015322428892084,
      flutes: 1,
      fzMm: 0.004803778888657689,
      passPhase: 0.26882214541547,
    };
    const x = 0.002449308524197349;
    const y = 0.3901282521088128;
    const c = certifiedEnvelopeHeightMm(p, x, y, 1e-9, 40);
    expect(c.complete).toBe(true);
    const refined = height(p, x, y, 40);
    expect(refined).toBeGreaterThanOrEqual(c.lowerBoundMm - 1e-12);
    expect(refined).toBeLessThanOrEqual(c.heightMm + 1e-9);
  });

  it('lead 0: each tooth crossing gives the profile at rho = sqrt(y^2 + d^2), against a 1-D root per crossing; ball and bull-nose (seed 7)', () => {
    // Lead 0, tilt 0: O = (xc, 0, Rcr), tooth k at angle theta_k = -xc/F + 2 pi k/z
    // (F = z fz / 2 pi), its edge point at radius rho from the axis at the profile's height
    // p(rho) (0 on the flat, Rcr - sqrt(Rcr^2 - (rho - Rb)^2) on the corner; the ball's
    // R - sqrt(R^2 - rho^2) = rho^2/(2R) + ...). Over (x, y), y != 0: d = x - xc with
    // atan2(y, d) + (x - d)/F = 2 pi m / z for an integer m (monotone in d: one root per m),
    // height p(sqrt(y^2 + d^2)); the envelope is the lowest over m. With fz << |y| the roots
    // are about fz apart: the shop formula's fz^2/(8R) appears off the CC path. fz is smaller
    // than a cell here (1/60 mm): the crossing lowest at a point is often not among a cell's kept
    // ones, and only the walk along the chain of crossings finds it.
    const R = 3;
    const z = 2;
    const fz = 0.012;
    const F = (z * fz) / (2 * Math.PI);
    const r = rng(7);
    for (const Rcr of [R, 1]) {
      const Rb = R - Rcr;
      const prof = (rho: number): number => (rho <= Rb ? 0 : Rcr - Math.sqrt(Rcr * Rcr - (rho - Rb) ** 2));
      const p: ToothSweepParams = { ...base, radiusMm: R, cornerRadiusMm: Rcr, stepOverMm: 8, flutes: z, fzMm: fz };
      const closed = (x: number, y: number): number => {
        const dMax = Math.sqrt(R * R - y * y);
        const h = (d: number): number => Math.atan2(y, d) + (x - d) / F;
        const unitAngle = (2 * Math.PI) / z;
        let best = Number.POSITIVE_INFINITY;
        const lo0 = Math.min(h(dMax), h(-dMax));
        const hi0 = Math.max(h(dMax), h(-dMax));
        for (let m = Math.ceil(lo0 / unitAngle); m <= Math.floor(hi0 / unitAngle); m++) {
          let lo = -dMax;
          let hi = dMax;
          for (let i = 0; i < 200; i++) {
            const mid = (lo + hi) / 2;
            if (h(mid) > m * unitAngle) lo = mid;
            else hi = mid;
          }
          const d = (lo + hi) / 2;
          best = Math.min(best, prof(Math.sqrt(y * y + d * d)));
        }
        return best;
      };
      for (let n = 0; n < 8; n++) {
        const x = r() * 0.3;
        const y = (n % 2 === 0 ? 1 : -1) * (Rb + 0.05 + r() * (Rcr - 0.2));
        expect(Math.abs(height(p, x, y, 60) - closed(x, y))).toBeLessThan(1e-11);
      }
      // on the CC path the flat bottom, or the ball's tip, sweeps y = 0 at z = 0: no feed marks there
      expect(Math.abs(bruteFeedMarkHeightMm(p, 60).heightMm)).toBeLessThan(1e-12);
    }
  });

  it('lead > 0 without tilt: on the CC path each tooth leaves its corner arc, hf = Rcr - sqrt(Rcr^2 - fz^2/4); lead 0: hf = 0 (seed 13)', () => {
    // No tilt: the CC path y = 0 lies in the plane y = y_O of the axis. A half-plane through
    // the axis meets that plane only on the axis unless it lies in it (theta = 0 or pi); so the
    // line is cut by whole edges at those instants, the front ones (theta = 0, where the lowest
    // ring point is for a lead) lowest: circular arcs of radius Rcr through the contact
    // height, one per tooth, fz apart. Two equal arcs fz apart meet at the sag of their chord.
    const r = rng(13);
    for (const [R, Rcr] of [
      [3, 3],
      [3, 1],
      [6, 2],
    ] as const) {
      const fz = 0.03 + 0.1 * r();
      const p: ToothSweepParams = {
        ...base,
        radiusMm: R,
        cornerRadiusMm: Rcr,
        leadRad: (5 + 10 * r()) * DEG,
        flutes: 1 + Math.floor(4 * r()),
        fzMm: fz,
        stepOverMm: 1,
      };
      const hf = bruteFeedMarkHeightMm(p, 50);
      expect(Math.abs(hf.heightMm - (Rcr - Math.sqrt(Rcr * Rcr - (fz * fz) / 4)))).toBeLessThan(1e-12);
      expect(Math.abs(hf.minMm)).toBeLessThan(1e-12);
      // at lead 0 the flat bottom, or the ball's tip, sweeps the CC path at z = 0: hf = 0
      expect(Math.abs(bruteFeedMarkHeightMm({ ...p, leadRad: 0 }, 50).heightMm)).toBeLessThan(1e-12);
    }
  });

  it('fz -> 0 tends to the continuous cross-feed profile of a bull-nose at lead 0 (O(fz^2) from above; Sa -> Ra, Sz -> Rz) (seed 11)', () => {
    // Continuous profile of pass j (lead 0, tilt 0): 0 over |y - jL| <= Rb, the corner
    // Rcr - sqrt(Rcr^2 - (|y - jL| - Rb)^2) up to R; the surface left is the lowest pass.
    const R = 3;
    const Rcr = 1;
    const L = 4.6;
    const corner = (t: number): number => {
      const q = Math.abs(t) - (R - Rcr);
      if (q <= 0) return 0;
      return q <= Rcr ? Rcr - Math.sqrt(Rcr * Rcr - q * q) : Number.POSITIVE_INFINITY;
    };
    const profile = (y: number): number => Math.min(corner(y + L), corner(y), corner(y - L), corner(y - 2 * L));
    const r = rng(11);
    // the same phases of the feed period at every fz: the gap then scales as fz^2
    const pts = Array.from({ length: 6 }, () => [r(), 2.05 + r() * 0.5] as const);
    const gaps: number[] = [];
    for (const fz of [0.2, 0.1, 0.05]) {
      const p: ToothSweepParams = { ...base, stepOverMm: L, fzMm: fz };
      let gap = 0;
      for (const [t, y] of pts) {
        const d = height(p, t * fz, y) - profile(y);
        expect(d).toBeGreaterThan(-1e-12);
        gap = Math.max(gap, d);
      }
      gaps.push(gap);
    }
    expect(gaps[1] as number).toBeLessThan((gaps[0] as number) / 3);
    expect(gaps[2] as number).toBeLessThan((gaps[1] as number) / 3);
    // areal over a cell against the profile's Ra and Rz on the same y samples
    const ny = 128;
    const ys = Array.from({ length: ny }, (_, i) => -L / 2 + ((i + 0.5) * L) / ny);
    const zs = ys.map(profile);
    const mean = zs.reduce((s, v) => s + v, 0) / ny;
    const ra = zs.reduce((s, v) => s + Math.abs(v - mean), 0) / ny;
    const rz = Math.max(...zs) - Math.min(...zs);
    const errs: number[] = [];
    for (const fz of [0.1, 0.05]) {
      const a = bruteArealParameters({ ...base, stepOverMm: L, fzMm: fz }, 4, ny, 60);
      errs.push(Math.abs(a.Sa - ra) + Math.abs(a.Sz - rz));
      expect(a.Sa).toBeGreaterThan(0);
    }
    expect(errs[1] as number).toBeLessThan((errs[0] as number) / 2.5);
    expect(errs[1] as number).toBeLessThan(2e-4);
  });

  it('areal extremes: the refined highest and lowest points agree from two sampling grids, and no sample beats them (seed 17)', () => {
    // The peak where a cusp crest meets feed-mark crests is a kink; a coarse grid ranks crests
    // by how far off their top it samples them unless each crest is narrowed first.
    const r = rng(17);
    const p: ToothSweepParams = {
      ...base,
      leadRad: (4 + 4 * r()) * DEG,
      tiltRad: (2 + 4 * r()) * DEG,
      stepOverMm: 2.3 + 0.4 * r(),
      fzMm: 0.08 + 0.04 * r(),
    };
    const a = bruteArealParameters(p, 6, 20, 50, true);
    const b = bruteArealParameters(p, 8, 28, 50, true);
    expect(Math.abs(a.maxMm - b.maxMm)).toBeLessThan(1e-12);
    expect(Math.abs(a.minMm - b.minMm)).toBeLessThan(1e-12);
    const fine = bruteArealParameters(p, 16, 64, 50);
    expect(fine.maxMm).toBeLessThanOrEqual(a.maxMm + 1e-13);
    expect(fine.minMm).toBeGreaterThanOrEqual(a.minMm - 1e-13);
  });

  it('areal means by kink-following quadrature agree with the midpoint grid within its own error (seed 19)', () => {
    const r = rng(19);
    const p: ToothSweepParams = { ...base, leadRad: (4 + 4 * r()) * DEG, stepOverMm: 2.3 + 0.4 * r(), fzMm: 0.1 };
    const q = bruteArealQuadrature(p, 1e-5, 50);
    const coarse = bruteArealParameters(p, 8, 32, 50);
    const fine = bruteArealParameters(p, 16, 64, 50);
    for (const key of ['meanMm', 'Sa', 'Sq'] as const) {
      // the midpoint rule's error is O(h^2): about a third of its change when h halves
      const tol = Math.abs(fine[key] - coarse[key]) / 3 + 2e-6;
      expect(Math.abs(q[key] - fine[key])).toBeLessThan(tol);
    }
    expect(Math.abs(q.Ssk - fine.Ssk)).toBeLessThan(0.01);
    expect(Math.abs(q.Sku - fine.Sku)).toBeLessThan(0.02);
  });

  it('z teeth at fz equal one tooth at z fz shifted by k fz, with and without runout (seed 3)', () => {
    // Tooth k at rotation phi is at the angle of tooth 0 at phi - 2 pi k / z, where the tool
    // was k fz behind: its sweep is tooth 0's (runout phase phi_e - 2 pi k / z) moved by k fz.
    const r = rng(3);
    for (const e of [0, 0.006]) {
      const z = 3;
      const fz = 0.06;
      const p: ToothSweepParams = {
        ...base,
        cornerRadiusMm: 0.8,
        leadRad: 8 * DEG,
        tiltRad: 5 * DEG,
        stepOverMm: 2,
        flutes: z,
        fzMm: fz,
        runoutMm: e,
        runoutPhaseRad: 0.9,
        passPhase: e > 0 ? 0.25 : 0,
      };
      for (let n = 0; n < 4; n++) {
        const x = r() * z * fz;
        const y = -0.5 + r() * 2.5;
        let one = Number.POSITIVE_INFINITY;
        for (let k = 0; k < z; k++) {
          const single = { ...p, flutes: 1, fzMm: z * fz, runoutPhaseRad: p.runoutPhaseRad - (2 * Math.PI * k) / z };
          one = Math.min(one, height(single, x - k * fz, y));
        }
        expect(Math.abs(height(p, x, y) - one)).toBeLessThan(1e-11);
      }
    }
  });

  it('repeats every fz without runout, every z fz with it, and pass to pass by (q P, L); zigzag is symmetric about (0, L/2) (seed 5)', () => {
    const r = rng(5);
    const p: ToothSweepParams = {
      ...base,
      leadRad: 10 * DEG,
      tiltRad: -7 * DEG,
      stepOverMm: 1.8,
      flutes: 4,
      fzMm: 0.05,
    };
    const q = { ...p, passPhase: 0.37 };
    const ro = { ...p, runoutMm: 0.01, runoutPhaseRad: 2 };
    const zig = { ...p, pattern: 'zigzag' as const };
    for (let n = 0; n < 3; n++) {
      const x = r() * 0.2;
      const y = -0.9 + r() * 1.8;
      expect(Math.abs(height(p, x + p.fzMm, y) - height(p, x, y))).toBeLessThan(1e-11);
      expect(Math.abs(height(ro, x + 4 * p.fzMm, y) - height(ro, x, y))).toBeLessThan(1e-11);
      expect(Math.abs(height(q, x + 0.37 * p.fzMm, y + p.stepOverMm) - height(q, x, y))).toBeLessThan(1e-11);
      expect(Math.abs(height(zig, -x, p.stepOverMm - y) - height(zig, x, y))).toBeLessThan(1e-11);
    }
    // with runout the teeth cut unequally: not fz-periodic somewhere on the CC path
    const diffs = [0, 0.01, 0.02, 0.03, 0.04].map((x) => Math.abs(height(ro, x + p.fzMm, 0) - height(ro, x, 0)));
    expect(Math.max(...diffs)).toBeGreaterThan(1e-6);
  });
});
