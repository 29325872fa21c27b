import { describe, expect, it } from 'vitest';
import { fillPassPair, meridian, newPassPair } from '../../../src/core/threeAxis/meridianPasses';
import { meridianTool } from '../../../src/core/threeAxis/meridianTool';
import { gougeDepthMm, revolutionSurface } from '../../../src/core/threeAxis/revolutionGouging';
import { type RevolutionCase, waterlineForward } from '../../../src/core/threeAxis/waterlineRevolution';
import { seededRandom } from '../../support/bruteForce';
import { bruteGougeDepthMm, brutePair } from '../../support/reference/threeAxisBruteForce';

/**
 * The exact gouging test against sampled points of the 3D tool tested against the torus patch
 * (tool placed by the reference, material by distance from the axis): a sampled point inside the
 * material proves a gouge, so "no gouge" must come with no such point; where the test finds one,
 * the sampled depth approaches its depth. And the named limit: just above it the case is answered,
 * just below it refused.
 */
describe('gouging of a surface of revolution', () => {
  it('agrees with sampled tool points (seed 21)', () => {
    const rand = seededRandom(21);
    let gouged = 0;
    let clear = 0;
    for (let i = 0; i < 60; i++) {
      const R = 1 + 5 * rand();
      const Rcr = R * (0.05 + 0.95 * rand());
      const alpha = 1 + 85 * rand();
      const pick = () => (rand() < 0.15 ? null : (rand() < 0.5 ? 1 : -1) * R * (0.3 + 6 * rand() ** 2));
      const rf = pick();
      const rc = pick();
      const t = meridianTool(R, Rcr);
      const m = meridian((alpha * Math.PI) / 180, rc);
      const pair = newPassPair();
      // Every other case tests the lower pass of a pair (its own slope, the same surface).
      const lower = i % 2 === 1;
      // (within the usable meridian: the lower pass's slope between 0 and 90 degrees)
      const a0 = (alpha * Math.PI) / 180;
      const maxL = rc === null ? Number.POSITIVE_INFINITY : rc > 0 ? (Math.PI / 2 - a0) * rc : -a0 * rc;
      const L = lower ? Math.min(R * rand(), 0.9 * maxL) : 0.1;
      fillPassPair(t, m, L, pair);
      const surf = revolutionSurface(m.sin0, m.cos0, rc, rf);
      const depth = lower
        ? gougeDepthMm(t, surf, pair.tipS1, pair.tipZ1)
        : gougeDepthMm(t, surf, pair.tipS0, pair.tipZ0);
      const s = { slopeDeg: alpha, feedRadiusMm: rf, crossRadiusMm: rc };
      const placed = brutePair({ R, Rcr }, s, L);
      const tip = lower ? placed.tip1 : placed.tip0;
      const sampled = bruteGougeDepthMm({ R, Rcr }, s, tip, 120, 240);
      const label = JSON.stringify({ i, R, Rcr, alpha, rf, rc, L, lower, depth, sampled });
      if (depth === 0) {
        clear += 1;
        expect(sampled, label).toBeLessThan(1e-9 * (1 + Math.abs(rc ?? 0)));
      } else {
        gouged += 1;
        expect(sampled, label).toBeLessThanOrEqual(depth + 1e-9);
        expect(sampled, label).toBeGreaterThan(depth - 0.02 * R);
      }
    }
    expect(
      [gouged, clear].every((k) => k >= 8),
      `${gouged} gouged, ${clear} clear`,
    ).toBe(true);
  });

  it('names the radius to change and its smallest magnitude (a tight meridian, a tight bowl)', () => {
    const base: RevolutionCase = {
      toolRadiusMm: 3,
      cornerRadiusMm: 1,
      slopeDeg: 30,
      feedRadiusMm: -40,
      crossRadiusMm: -2,
    };
    const f = waterlineForward(base, 0.02);
    expect(f.ok).toBe(false);
    if (!f.ok) {
      expect(f.errors[0]).toMatchObject({ field: 'crossRadius', code: 'gouging' });
      const limit = f.errors[0]?.limit as number;
      expect(limit).toBeLessThan(-2);
      expect(waterlineForward({ ...base, crossRadiusMm: limit * (1 + 1e-6) }, 0.02).ok).toBe(true);
      const tighter = waterlineForward({ ...base, crossRadiusMm: limit * (1 - 1e-6) }, 0.02);
      expect(!tighter.ok && tighter.errors[0]?.code).toBe('gouging');
    }
    // A cone-shaped bowl too narrow: the tool would reach across the axis; Rf is the one to change.
    const cone: RevolutionCase = {
      toolRadiusMm: 3,
      cornerRadiusMm: 1,
      slopeDeg: 20,
      feedRadiusMm: -4,
      crossRadiusMm: null,
    };
    const g = waterlineForward(cone, 0.02);
    expect(g.ok).toBe(false);
    if (!g.ok) {
      expect(g.errors[0]).toMatchObject({ field: 'feedRadius', code: 'gouging' });
      const limit = g.errors[0]?.limit as number;
      expect(waterlineForward({ ...cone, feedRadiusMm: limit * (1 + 1e-6) }, 0.02).ok).toBe(true);
    }
  });
});
