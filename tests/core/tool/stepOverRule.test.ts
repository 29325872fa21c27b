/**
 * Issue 17, item 11: the step-over rule (one-way `wR + wL`, zigzag `2 min(wR, wL)`) is one function
 * that every solver calls, and tests that fail when a caller gets it wrong. Each case names the
 * mutant it kills; the expected values come from the references in tests/support (the 40-digit
 * profile, the brute-force 3D tool and the polished cylinder brute force), never from the solver.
 */
import { describe, expect, it } from 'vitest';
import { forwardInput } from '../../../src/core/input/validate';
import { stepOverSweep } from '../../../src/core/procedures/teaching';
import { cylinderSolver } from '../../../src/core/surfaces/cylinder';
import { exactForward, exactIntervalMm } from '../../../src/core/surfaces/solve';
import {
  maxIntervalMm,
  scallopHeightLimits,
  validateForward,
  validateInverse,
} from '../../../src/core/surfaces/validate';
import { flankLimits, shapeOfTool } from '../../../src/core/tool/posture';
import { stepOverFromReaches } from '../../../src/core/tool/stepOverRule';
import { cyl, referenceIntervalMm, TOL_MM, tool } from '../../support/cylinderChecks';
import { bruteForceProfile } from '../../support/reference/bruteForce3d';
import { cylinderReach } from '../../support/reference/cylinderReach';
import { referenceProfile } from '../../support/reference/highPrecision';

/** R 3, Rcr 1, rho 5, tilt 20: the shank cuts on the right from 0.674 mm (issue 17). */
const T20 = tool(3, 1, 5, 20);
const RAW20 = { R: 3, Rcr: 1, rho: 5, tilt: 20 };

describe('stepOverFromReaches', () => {
  it('one-way adds the two reaches; zigzag takes twice the smaller; without tilt both are 2 (L/2)', () => {
    expect(stepOverFromReaches('one-way', 0.3, 0.5)).toBe(0.8);
    expect(stepOverFromReaches('zigzag', 0.3, 0.5)).toBe(0.6);
    expect(stepOverFromReaches('zigzag', 0.5, 0.3)).toBe(0.6);
    expect(stepOverFromReaches('one-way', 0.4, 0.4)).toBe(stepOverFromReaches('zigzag', 0.4, 0.4));
  });
});

describe('the shank among the flank limits (mutant: flankLimits without its shank candidates)', () => {
  it('R 3, Rcr 1, rho 5, tilt 20: h = 0.848 is refused, the limit is where the brute-force shank starts to cut', () => {
    const ref = referenceProfile(3, 1, 5, 20);
    const limits = flankLimits(shapeOfTool(T20));
    const want = Math.min(ref.hmaxRightMm, ref.hmaxLeftMm, ref.shankHeightRightMm, ref.shankHeightLeftMm);
    expect(want).toBeCloseTo(0.674, 3);
    expect(Math.abs(limits.limitMm - want)).toBeLessThan(TOL_MM);
    expect(limits.limitBy).toBe('shank-right');
    // The sampled tool agrees: the shank shapes the right flank at 0.848 mm, not at 0.67 mm.
    const b = bruteForceProfile(3, 1, 5, 20);
    expect(b.widthRightWithShankMm(0.848) - b.widthRightMm(0.848)).toBeGreaterThan(1e-3);
    expect(Math.abs(b.widthRightWithShankMm(0.67) - b.widthRightMm(0.67))).toBeLessThan(1e-9);
    const v = validateForward({ ...RAW20, h: 0.848 });
    expect(!v.ok && v.errors[0]?.code).toBe('shank-cuts');
    expect(!v.ok && v.errors[0]?.limit).toBe(limits.limitMm);
    expect(validateForward({ ...RAW20, h: 0.9 * want }).ok).toBe(true);
  });
});

describe('zigzag is twice the smaller flank everywhere', () => {
  it('on the plane: exact L and the widest step-over (mutant: 2 max in validate.ts: L = 3 mm accepted where the maximum is 1.994)', () => {
    const ref = referenceProfile(3, 1, 5, 20);
    const h = 0.05;
    const zigzag = 2 * Math.min(ref.widthRightMm(h), ref.widthLeftMm(h));
    expect(Math.abs(exactIntervalMm(forwardInput(T20, 'zigzag', h)) - zigzag)).toBeLessThan(TOL_MM);
    const limit = scallopHeightLimits(T20).limitMm;
    const widest = 2 * Math.min(ref.widthRightMm(limit), ref.widthLeftMm(limit));
    expect(widest).toBeCloseTo(1.994, 3);
    expect(Math.abs(maxIntervalMm(T20, 'zigzag') - widest)).toBeLessThan(TOL_MM);
    const oneWay = ref.widthRightMm(limit) + ref.widthLeftMm(limit);
    expect(Math.abs(maxIntervalMm(T20, 'one-way') - oneWay)).toBeLessThan(TOL_MM);
    const beyond = validateInverse({ ...RAW20, pattern: 'zigzag', interval: 3 });
    expect(!beyond.ok && beyond.errors[0]?.code).toBe('beyond-interval');
    expect(!beyond.ok && beyond.errors[0]?.message).toMatch(/below 1\.99411/);
    expect(validateInverse({ ...RAW20, pattern: 'zigzag', interval: 1.99 }).ok).toBe(true);
  });

  it('on a cylinder: the fast path, the full answer and the widest step-over (mutant: 2 max in exact.ts, L 0.783 instead of 0.659 at Rs 20)', () => {
    for (const [rs, axis] of [
      [20, 'feed'],
      [-20, 'feed'],
      [20, 'cross'],
    ] as const) {
      const s = cyl(rs, axis);
      const ref = cylinderReach(T20, rs, axis, { ringSamples: 360 });
      const want = referenceIntervalMm(ref, s, 'zigzag', 0.05);
      if (rs === 20 && axis === 'feed') expect(want).toBeCloseTo(0.659, 3);
      const input = forwardInput(T20, 'zigzag', 0.05, s);
      expect(Math.abs(exactIntervalMm(input) - want), `${rs} ${axis}`).toBeLessThan(TOL_MM);
      expect(Math.abs(exactForward(input).intervalMm - want), `${rs} ${axis}`).toBeLessThan(TOL_MM);
      const limit = cylinderSolver(T20, s).limits().limitMm;
      for (const pattern of ['one-way', 'zigzag'] as const)
        expect(
          Math.abs(maxIntervalMm(T20, pattern, s) - referenceIntervalMm(ref, s, pattern, limit)),
          `${pattern} ${rs} ${axis}`,
        ).toBeLessThan(TOL_MM);
    }
  });

  it('the teaching sweep on a cylinder shows the zigzag step-over of the reference', () => {
    const s = cyl(20, 'feed');
    const sweep = stepOverSweep(T20, 'zigzag', 0.05, 'tilt', 0, 40, 8, null, s);
    const k = sweep.angleDeg.indexOf(20);
    const ref = cylinderReach(T20, 20, 'feed', { ringSamples: 360 });
    expect(Math.abs((sweep.values.exact[k] ?? 0) - referenceIntervalMm(ref, s, 'zigzag', 0.05))).toBeLessThan(TOL_MM);
  });
});
