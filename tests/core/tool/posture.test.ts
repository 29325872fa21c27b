import { afterAll, describe, expect, it } from 'vitest';
import {
  contactCurvatureRadiusMm,
  contactOffsetMm,
  flankAtWidth,
  flankLimits,
  flankWidthMm,
  shapeOfTool,
} from '../../../src/core/tool/posture';
import { seededRandom } from '../../support/bruteForce';
import { bruteForceProfile } from '../../support/reference/bruteForce3d';
import { referenceProfile } from '../../support/reference/highPrecision';

/**
 * The exact solver against the 40-digit reference of tests/support/reference (its own derivation:
 * the support function of the projected tool, solved in 64-digit arithmetic), stratified over the
 * whole valid domain. Every length is checked to 1e-9 mm (issue 7); the largest error per stratum
 * is printed at the end.
 */
const TOL_MM = 1e-9;
const worst = new Map<string, number>();
function record(stratum: string, errorMm: number): void {
  worst.set(stratum, Math.max(worst.get(stratum) ?? 0, errorMm));
}
afterAll(() => {
  const rows = [...worst].map(([k, v]) => `  ${k.padEnd(44)} ${v.toExponential(2)} mm`);
  console.info(`Largest |exact - 40-digit reference| per stratum:\n${rows.join('\n')}`);
});

interface Case {
  readonly R: number;
  readonly Rcr: number;
  readonly rho: number;
  readonly tilt: number;
  /** Fractions of the height limit at which to check the flanks. */
  readonly fractions: readonly number[];
}

/** Checks both flanks, the inverse, y0, the limits and the contact curvature against the reference. */
function checkCase(stratum: string, c: Case): void {
  const tool = { toolRadiusMm: c.R, cornerRadiusMm: c.Rcr, leadAngleDeg: c.rho, tiltAngleDeg: c.tilt };
  const s = shapeOfTool(tool);
  const ref = referenceProfile(c.R, c.Rcr, c.rho, c.tilt);
  const label = JSON.stringify(c);
  const err = (a: number, b: number) => Math.abs(a - b);
  const limits = flankLimits(s);
  // y0 and the widest points.
  const e0 = err(contactOffsetMm(s), ref.contactOffsetMm);
  record(`${stratum}: y0`, e0);
  expect(e0, `y0 ${label}`).toBeLessThan(TOL_MM);
  const eTop = Math.max(err(limits.topRightMm, ref.hmaxRightMm), err(limits.topLeftMm, ref.hmaxLeftMm));
  record(`${stratum}: flank tops`, eTop);
  expect(eTop, `hmax ${label}`).toBeLessThan(TOL_MM);
  // The shank: the reference gives the flank's top on the side it does not cut.
  const shankR = limits.shankRightMm ?? limits.topRightMm;
  const shankL = limits.shankLeftMm ?? limits.topLeftMm;
  const eShank = Math.max(
    err(Math.min(shankR, limits.topRightMm), ref.shankHeightRightMm),
    err(Math.min(shankL, limits.topLeftMm), ref.shankHeightLeftMm),
  );
  record(`${stratum}: shank`, eShank);
  expect(eShank, `shank ${label}`).toBeLessThan(TOL_MM);
  const limit = Math.min(ref.hmaxRightMm, ref.hmaxLeftMm, ref.shankHeightRightMm, ref.shankHeightLeftMm);
  for (const f of c.fractions) {
    const h = Math.max(1e-9, f * limit);
    if (!(h < limit)) continue;
    const wR = flankWidthMm(s, 'right', h);
    const wL = flankWidthMm(s, 'left', h);
    const e = Math.max(err(wR, ref.widthRightMm(h)), err(wL, ref.widthLeftMm(h)));
    record(`${stratum}: widths`, e);
    expect(e, `widths at h=${h} ${label}`).toBeLessThan(TOL_MM);
    // The inverse at the reference's own width returns h.
    const back = Math.max(
      err(flankAtWidth(s, 'right', ref.widthRightMm(h)).heightMm, h),
      err(flankAtWidth(s, 'left', ref.widthLeftMm(h)).heightMm, h),
    );
    record(`${stratum}: inverse`, back);
    expect(back, `inverse at h=${h} ${label}`).toBeLessThan(TOL_MM);
  }
  const r = contactCurvatureRadiusMm(s);
  if (r !== null && Number.isFinite(ref.radiusOfCurvatureAtContactMm)) {
    const rel = err(r, ref.radiusOfCurvatureAtContactMm) / Math.max(1, ref.radiusOfCurvatureAtContactMm);
    record(`${stratum}: contact radius (relative)`, rel);
    expect(rel, `contact radius ${label}`).toBeLessThan(1e-12);
  }
}

/** A stratum: n cases drawn by `draw` from a seeded generator. */
function stratum(name: string, seed: number, n: number, draw: (rand: () => number) => Case): void {
  it(`${name} (seed ${seed}, ${n} cases)`, () => {
    const rand = seededRandom(seed);
    for (let k = 0; k < n; k++) checkCase(name, draw(rand));
  });
}

const logUniform = (rand: () => number, lo: number, hi: number) => lo * (hi / lo) ** rand();
const pick = <T>(rand: () => number, xs: readonly T[]): T => xs[Math.floor(rand() * xs.length)] as T;
const TINY_FRACTIONS = [1e-12, 1e-9, 1e-6, 1e-3, 0.3, 0.999];

describe('exact flanks against the 40-digit reference, stratified over the valid domain', () => {
  it('issue 7, defect 1: tiny h against Rb sin(rho) (the two reported cases)', () => {
    const s = shapeOfTool({ toolRadiusMm: 1000, cornerRadiusMm: 0, leadAngleDeg: 80, tiltAngleDeg: 0 });
    // The true value (checked there with a 40-digit offset-ellipse profile).
    expect(Math.abs(flankWidthMm(s, 'right', 1e-9) - 0.0014250800762660529)).toBeLessThan(TOL_MM * 1e-3);
    checkCase('issue 7 defect 1', { R: 1000, Rcr: 0, rho: 80, tilt: 0, fractions: [] });
    const R = 504.5298455140055;
    const c = { R, Rcr: 0.0008072104456686401, rho: 42.66798693677832, tilt: 0, fractions: [] };
    checkCase('issue 7 defect 1', c);
    const s2 = shapeOfTool({ toolRadiusMm: c.R, cornerRadiusMm: c.Rcr, leadAngleDeg: c.rho, tiltAngleDeg: 0 });
    const ref = referenceProfile(c.R, c.Rcr, c.rho, 0);
    const h = 1.1757304282013866e-9;
    expect(Math.abs(flankWidthMm(s2, 'right', h) - ref.widthRightMm(h))).toBeLessThan(TOL_MM);
  });

  stratum('tiny h/b, flat end (Rcr = 0)', 701, 20, (rand) => ({
    R: logUniform(rand, 0.001, 1000),
    Rcr: 0,
    rho: 0.01 + 89 * rand(),
    tilt: pick(rand, [0, 0, 10 * rand() - 5]),
    fractions: TINY_FRACTIONS,
  }));
  stratum('tiny h/b, tiny corner (Rcr = 1e-9 R)', 702, 20, (rand) => {
    const R = logUniform(rand, 0.001, 1000);
    return {
      R,
      Rcr: 1e-9 * R,
      rho: 0.01 + 89 * rand(),
      tilt: pick(rand, [0, 20 * rand() - 10]),
      fractions: TINY_FRACTIONS,
    };
  });
  stratum('small corner (Rcr < 5% R)', 703, 20, (rand) => {
    const R = logUniform(rand, 0.001, 1000);
    return { R, Rcr: 0.05 * R * rand(), rho: 89 * rand(), tilt: 60 * rand() - 30, fractions: TINY_FRACTIONS };
  });
  stratum('ball end (Rcr = R), any posture', 704, 16, (rand) => {
    const R = logUniform(rand, 0.001, 1000);
    return { R, Rcr: R, rho: 89.9 * rand(), tilt: 170 * rand() - 85, fractions: [1e-12, 1e-3, 0.5, 0.999] };
  });
  stratum('rho 0 or near 0, with and without tilt', 705, 24, (rand) => {
    const R = logUniform(rand, 0.01, 100);
    return {
      R,
      Rcr: R * pick(rand, [0.1, 0.5, 1, rand()]),
      rho: pick(rand, [0, 1e-9, 1e-4, 0.01 * rand()]),
      tilt: pick(rand, [0, 1e-6, 5, -30 * rand()]),
      fractions: [1e-9, 1e-4, 0.1, 0.9],
    };
  });
  stratum('rho near 90', 706, 16, (rand) => {
    const R = logUniform(rand, 0.01, 100);
    return {
      R,
      Rcr: R * rand(),
      rho: 89.9 + 0.0999 * rand(),
      tilt: pick(rand, [0, 10 * rand()]),
      fractions: [1e-6, 0.2, 0.9],
    };
  });
  stratum('steep tilt (|beta| 60 to 89)', 707, 16, (rand) => {
    const R = logUniform(rand, 0.01, 100);
    return {
      R,
      Rcr: R * (0.2 + 0.8 * rand()),
      rho: 89 * rand(),
      tilt: (60 + 29 * rand()) * pick(rand, [1, -1]),
      fractions: [1e-6, 0.2, 0.9],
    };
  });
  stratum('anywhere (R 0.001 to 1000, any corner and posture)', 708, 40, (rand) => {
    const R = logUniform(rand, 0.001, 1000);
    return {
      R,
      Rcr: R * rand(),
      rho: 89.99 * rand(),
      tilt: 178 * rand() - 89,
      fractions: [1e-10, 1e-5, 0.01, 0.5, 0.99],
    };
  });
});

describe('exact flanks against brute-force sampling of the 3D tool surface (its own method)', () => {
  for (const seed of [11, 12]) {
    it(`seed ${seed}: 6 random tilted tools agree within the sampler's 1e-7 R`, () => {
      const rand = seededRandom(seed);
      for (let k = 0; k < 6; k++) {
        const R = 0.5 + 12 * rand();
        const Rcr = R * (0.05 + 0.95 * rand());
        const rho = 80 * rand();
        const tilt = 100 * rand() - 50;
        const s = shapeOfTool({ toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt });
        const b = bruteForceProfile(R, Rcr, rho, tilt);
        const h = flankLimits(s).limitMm * (0.01 + 0.9 * rand());
        expect(Math.abs(contactOffsetMm(s) - b.contactOffsetMm)).toBeLessThan(1e-7 * R);
        expect(Math.abs(flankWidthMm(s, 'right', h) - b.widthRightMm(h))).toBeLessThan(1e-7 * R);
        expect(Math.abs(flankWidthMm(s, 'left', h) - b.widthLeftMm(h))).toBeLessThan(1e-7 * R);
      }
    });
  }
});
