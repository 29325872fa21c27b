/**
 * The target-Sa and target-Rz inverses (issue 29; src/core/roughness/targetSa.ts), checked against
 * what does not share their search: the full areal parameters at the best pair (Sa the target within
 * 1e-6 relative), the sampled areal map's Sa (a midpoint grid of the envelope's heights, within its
 * sampling bound), the continuous Ra at L0 (roughness.ts), the products of the curve (none beats the
 * best), and for Rz the forward solver's cusp height and the feed-mark search at the pair, with pairs
 * at smaller step-overs found by an independent bisection on hf.
 */
import { describe, expect, it } from 'vitest';
import { PLANE } from '../../../src/core/domain/surface';
import type { PassPattern } from '../../../src/core/domain/tool';
import { arealParameters } from '../../../src/core/finish/areal';
import { arealMap } from '../../../src/core/finish/arealMap';
import { feedMarks } from '../../../src/core/finish/feedMarks';
import { toothModel } from '../../../src/core/finish/toothModel';
import { inverseInput } from '../../../src/core/input/validate';
import { arealSampled } from '../../../src/core/output/arealSampled';
import { exactRoughnessAtInterval } from '../../../src/core/roughness/roughness';
import { targetRzPair, targetSaPairs, validateTargetSa } from '../../../src/core/roughness/targetSa';
import { planeInverse } from '../../../src/core/surfaces/exact';

const TEETH = { flutes: 2, runoutMm: 0, runoutPhaseDeg: 0, passPhase: 0 };

function pass(R: number, Rcr: number, lead: number, tilt: number, pattern: PassPattern) {
  return { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: lead, tiltAngleDeg: tilt, pattern, surface: PLANE };
}

function modelAt(p: ReturnType<typeof pass>, L: number, fz: number) {
  return toothModel({ tool: p, pattern: p.pattern, intervalMm: L, finish: { ...TEETH, feedPerToothMm: fz } });
}

describe('target Sa: the best (L, fz) pair', () => {
  it.each([['paper tool R 3 Rcr 1, lead 5, one-way, Sa 0.8 um', pass(3, 1, 5, 0, 'one-way'), 0.0008]])(
    '%s: Sa at the pair is the target, L0 leaves Ra = target, no pair of the curve machines more',
    (_name, p, target) => {
      const a = targetSaPairs(p, TEETH, target);
      const b = a.best;
      expect(b.feedLimited).toBe(false);
      expect(b.intervalMm).toBeGreaterThan(0);
      expect(b.intervalMm).toBeLessThan(a.zeroFeedIntervalMm);
      // The full areal parameters of a fresh model at the pair.
      const full = arealParameters(modelAt(p, b.intervalMm, b.feedPerToothMm));
      expect(Math.abs(full.saMm / target - 1)).toBeLessThan(1e-6);
      // The sampled map (midpoints of a 128 x 128 grid of envelope heights): within its sampling error.
      const map = arealMap(modelAt(p, b.intervalMm, b.feedPerToothMm), 128, 128);
      expect(Math.abs(arealSampled(map.heightsMm).saMm / target - 1)).toBeLessThan(2e-3);
      // L0: the continuous profile's Ra there is the target.
      const e = planeInverse(inverseInput(p, p.pattern, a.zeroFeedIntervalMm));
      expect(Math.abs(exactRoughnessAtInterval(p, p.pattern, e).raMm / target - 1)).toBeLessThan(1e-9);
      // The curve: L ascending inside (0, L0), and none of its pairs machines more per tooth.
      const best = b.intervalMm * b.feedPerToothMm;
      let last = 0;
      for (const c of a.curve) {
        expect(c.intervalMm).toBeGreaterThan(last);
        last = c.intervalMm;
        expect(c.intervalMm * c.feedPerToothMm).toBeLessThan(best * (1 + 5e-3));
      }
      expect(last).toBeLessThan(a.zeroFeedIntervalMm);
      expect(a.curve.length).toBeGreaterThanOrEqual(10);
      // A pair of the curve far from the best, on the full Sa: the quick integral's 1e-3.
      const mid = a.curve[Math.floor(a.curve.length / 3)];
      if (mid === undefined) throw new Error('no curve');
      const midSa = arealParameters(modelAt(p, mid.intervalMm, mid.feedPerToothMm)).saMm;
      expect(Math.abs(midSa / target - 1)).toBeLessThan(1e-2);
    },
    300_000,
  );

  it('validates once: the target-Ra bound, named as the target Sa', () => {
    const raw = { R: 3, Rcr: 1, rho: 5, tilt: 0, pattern: 'one-way' };
    const bad = validateTargetSa({ ...raw, sa: 1 });
    expect(bad.ok).toBe(false);
    if (!bad.ok) expect(bad.errors.map((e) => [e.field, e.code])).toEqual([['targetSa', 'beyond-max-ra']]);
    const none = validateTargetSa({ ...raw, sa: '' });
    expect(none.ok).toBe(false);
    if (!none.ok) expect(none.errors[0]?.field).toBe('targetSa');
    const ok = validateTargetSa({ ...raw, sa: 0.0008 });
    expect(ok.ok && ok.value.targetSaMm).toBe(0.0008);
  });
});

describe('target Rz: scallop and feed marks both at most Rz', () => {
  /** The largest fz with hf <= rz at L, by bisection on feedMarks (independent of balancedFeed's search). */
  function bisectFz(p: ReturnType<typeof pass>, L: number, rz: number): number {
    let lo = 1e-6;
    let hi = p.toolRadiusMm;
    if (feedMarks(modelAt(p, L, hi)).heightMm <= rz) return hi;
    for (let i = 0; i < 60; i++) {
      const mid = 0.5 * (lo + hi);
      if (feedMarks(modelAt(p, L, mid)).heightMm <= rz) lo = mid;
      else hi = mid;
    }
    return lo;
  }

  it.each([
    ['R 3 Rcr 1, lead 5, one-way', pass(3, 1, 5, 0, 'one-way'), 0.003],
    ['R 6 Rcr 2, lead 15, tilt 10, zigzag', pass(6, 2, 15, 10, 'zigzag'), 0.002],
    ['R 3 Rcr 0.2, lead 2, one-way', pass(3, 0.2, 2, 0, 'one-way'), 0.001],
  ])('%s: h and hf are the target at the pair, and smaller step-overs machine less', (_name, p, rz) => {
    const r = targetRzPair(p, TEETH, rz);
    expect(r.feedLimited).toBe(false);
    expect(Math.abs(planeInverse(inverseInput(p, p.pattern, r.intervalMm)).cuspHeightMm - rz)).toBeLessThan(1e-12);
    expect(Math.abs(feedMarks(modelAt(p, r.intervalMm, r.feedPerToothMm)).heightMm - rz)).toBeLessThan(1e-9);
    const best = r.intervalMm * r.feedPerToothMm;
    for (const k of [0.5, 0.8, 0.95]) {
      const L = k * r.intervalMm;
      expect(L * bisectFz(p, L, rz)).toBeLessThan(best);
    }
  });

  it('a ball end at lead 0 drags its tip along the CC path: fz is the largest accepted, R', () => {
    const r = targetRzPair(pass(3, 3, 0, 0, 'one-way'), TEETH, 0.002);
    expect(r.feedLimited).toBe(true);
    expect(r.feedPerToothMm).toBe(3);
  });
});
