/**
 * The profiles along and across the feed (src/core/finish/profiles.ts), against values that do not
 * share their derivation:
 *
 * - Along the CC path: the sampled heights' max - min is the feed-mark height hf that feedMarks finds
 *   by its own search (the row envelope's valley and Brent's maximiser, or runoutLine's breaks),
 *   never above it (1e-9 mm), and below it by at most the sampling's bound: the steepest sampled
 *   slope times the spacing, at the crest and at the valley (a kink can hide between two samples),
 *   a bound that shrinks as the samples are refined.
 * - Across, a ball end: at any lead and tilt the continuous surface is the envelope of spheres,
 *   R - sqrt(R^2 - (y - j L)^2) over the passes j (closed form), and at a tiny fz the teeth leave it
 *   within fz^2 / (8 R) (below 1e-9 mm here).
 * - Across, a bull-nose at a tiny fz: max - min over one period is the continuous scallop h of the
 *   exact solver (planeInverse), within the sampling's bound.
 */
import { describe, expect, it } from 'vitest';
import { feedMarks, toothModel } from '../../../src/core/finish/index';
import { finishProfiles } from '../../../src/core/finish/profiles';
import type { PassPattern } from '../../../src/core/input/validate';
import { inverseInput } from '../../../src/core/input/validate';
import { seededRandom } from '../../../src/core/math/seededRandom';
import { planeInverse } from '../../../src/core/surfaces/exact';
import { randomBullNose } from '../../support/randomBullNose';
import { teethFinish as finish } from '../../support/teethFinish';

/** max - min of the heights, and the sampling's bound: steepest sampled slope x spacing, at both ends (x 1.5). */
function spread(p: { atMm: Float64Array; heightsMm: Float64Array }): { range: number; bound: number } {
  let lo = Number.POSITIVE_INFINITY;
  let hi = Number.NEGATIVE_INFINITY;
  let slope = 0;
  const h = p.heightsMm;
  for (let i = 0; i < h.length; i++) {
    lo = Math.min(lo, h[i] as number);
    hi = Math.max(hi, h[i] as number);
    if (i > 0)
      slope = Math.max(
        slope,
        Math.abs(((h[i] as number) - (h[i - 1] as number)) / ((p.atMm[i] as number) - (p.atMm[i - 1] as number))),
      );
  }
  const dx = ((p.atMm.at(-1) as number) - (p.atMm[0] as number)) / (h.length - 1);
  return { range: hi - lo, bound: 2 * 1.5 * slope * dx };
}

describe('the profile along the CC path', () => {
  it('seed 2933: max - min is hf (feedMarks) from below, within the sampling bound, which shrinks (bull-nose, one-way and zigzag, 1-6 teeth)', () => {
    const r = seededRandom(2933);
    for (let k = 0; k < 12; k++) {
      const tool = randomBullNose(r);
      const pattern: PassPattern = k % 2 === 0 ? 'one-way' : 'zigzag';
      const L = tool.toolRadiusMm * (0.2 + 0.6 * r());
      const fz = tool.toolRadiusMm * (0.01 + 0.2 * r());
      const m = toothModel({ tool, pattern, intervalMm: L, finish: finish(1 + Math.floor(6 * r()), fz) });
      const hf = feedMarks(m).heightMm;
      const label = `${JSON.stringify(tool)} ${pattern} L ${L} fz ${fz}`;
      let last = Number.POSITIVE_INFINITY;
      for (const points of [65, 513]) {
        const { range, bound } = spread(finishProfiles(m, points, 0).along);
        expect(range, label).toBeLessThanOrEqual(hf + 1e-9);
        expect(hf - range, label).toBeLessThanOrEqual(bound + 1e-9);
        expect(bound, label).toBeLessThan(last);
        last = bound;
      }
    }
  });

  it('seed 2935: with runout too (the period a turn, z fz; the runout search)', () => {
    const r = seededRandom(2935);
    for (let k = 0; k < 3; k++) {
      const tool = randomBullNose(r);
      const fz = tool.toolRadiusMm * (0.01 + 0.05 * r());
      const e = fz * (0.1 + r());
      const m = toothModel({
        tool,
        pattern: 'one-way',
        intervalMm: tool.toolRadiusMm / 2,
        finish: finish(3, fz, e, 360 * r()),
      });
      const hf = feedMarks(m).heightMm;
      const p = finishProfiles(m, 129, 0).along;
      expect((p.atMm.at(-1) as number) - (p.atMm[0] as number)).toBeCloseTo(2 * 3 * fz, 12);
      const { range, bound } = spread(p);
      expect(range).toBeLessThanOrEqual(hf + 1e-9);
      expect(hf - range).toBeLessThanOrEqual(bound + 1e-9);
    }
  });
});

describe('the profile across the feed', () => {
  it('seed 2934: a ball end at a tiny fz is the envelope of spheres (closed form) within 2e-9 mm, at any lead, tilt, pattern', () => {
    const r = seededRandom(2934);
    for (let k = 0; k < 12; k++) {
      const R = 1 + 5 * r();
      const tool = { toolRadiusMm: R, cornerRadiusMm: R, leadAngleDeg: 20 * r(), tiltAngleDeg: -10 + 20 * r() };
      const pattern: PassPattern = k % 2 === 0 ? 'one-way' : 'zigzag';
      const L = R * (0.1 + 0.8 * r());
      const fz = 1e-4;
      const m = toothModel({ tool, pattern, intervalMm: L, finish: finish(2, fz) });
      const p = finishProfiles(m, 65, fz * r()).across;
      const label = `${JSON.stringify(tool)} ${pattern} L ${L}`;
      expect(p.atMm[0]).toBe(-L / 2);
      expect(p.atMm.at(-1)).toBe(-L / 2 + (pattern === 'zigzag' ? 2 * L : L));
      p.atMm.forEach((y, i) => {
        let sphere = Number.POSITIVE_INFINITY;
        for (let j = -2; j <= 3; j++) {
          const d = y - j * L;
          if (Math.abs(d) < R) sphere = Math.min(sphere, R - Math.sqrt(R * R - d * d));
        }
        expect(Math.abs((p.heightsMm[i] as number) - sphere), `${label} y ${y}`).toBeLessThanOrEqual(2e-9);
      });
    }
  });

  it('seed 2936: a bull-nose at a tiny fz spans the continuous scallop h (exact solver) over one period, within the sampling bound', () => {
    const r = seededRandom(2936);
    for (let k = 0; k < 8; k++) {
      const tool = randomBullNose(r);
      const L = tool.toolRadiusMm * (0.2 + 0.6 * r());
      const h = planeInverse(inverseInput(tool, 'one-way', L)).cuspHeightMm;
      const m = toothModel({ tool, pattern: 'one-way', intervalMm: L, finish: finish(2, 1e-4) });
      const { range, bound } = spread(finishProfiles(m, 1025, 0).across);
      const label = `${JSON.stringify(tool)} L ${L}`;
      expect(range, label).toBeLessThanOrEqual(h + 2e-9);
      expect(h - range, label).toBeLessThanOrEqual(bound + 2e-9);
      expect(bound, label).toBeLessThan(0.02 * h);
    }
  });
});
