/**
 * Issue 17, items 9 and 10: the shank across the axis (turned about the cylinder's axis it starts to
 * cut lower than on the plane), and the shank in a trough (it must not cross the wall up to the
 * axis height). Limits against the polished brute force of tests/support/reference/cylinderReach.ts
 * (tests/support/cylinderChecks.ts) and troughs against the sampled tool
 * (tests/support/cylinderBruteForce.ts).
 */
import { describe, expect, it } from 'vitest';
import { concaveFit, cylinderSolver } from '../../../src/core/surfaces/cylinder';
import { validateForward, validateInverse } from '../../../src/core/surfaces/validate';
import { seededRandom } from '../../support/bruteForce';
import { concaveOverreach } from '../../support/cylinderBruteForce';
import { checkCase, cyl, referenceIntervalMm, tool } from '../../support/cylinderChecks';
import { cylinderReach } from '../../support/reference/cylinderReach';

describe('item 9: the shank across the axis (the shank turned about the cylinder axis)', () => {
  it('the issue cases: the shank shapes the flank from 0.11161 mm and 0.26627 mm, not the plane heights', () => {
    const cases = [
      {
        t: tool(1.871111796293297, 0.12571864957473206, 56.57251865974293, 41.97719031372606),
        rs: 17.33282843198444,
        h: 0.12107401350600806,
        pattern: 'zigzag' as const,
        limit: 0.11161,
        // The brute force of the real tool with its shank at h (issue 17): the old answer was 0.881141830901.
        withShank: 0.88196273553,
      },
      {
        t: tool(2.531141989038174, 0.9353402957968483, 24.689211810135557, 46.155666208552965),
        rs: 33.31116946595172,
        h: 0.26831402764152745,
        pattern: 'one-way' as const,
        limit: 0.26627,
        withShank: null,
      },
    ];
    for (const c of cases) {
      const s = cyl(c.rs, 'cross');
      const limits = cylinderSolver(c.t, s).limits();
      expect(limits.limitBy).toBe('shank-right');
      expect(Math.abs(limits.limitMm - c.limit)).toBeLessThan(5e-6);
      const ref = cylinderReach(c.t, c.rs, 'cross');
      if (c.withShank !== null)
        expect(Math.abs(referenceIntervalMm(ref, s, c.pattern, c.h) - c.withShank)).toBeLessThan(1e-11);
      // Beyond the limit: an input error naming it.
      const v = validateForward({
        R: c.t.toolRadiusMm,
        Rcr: c.t.cornerRadiusMm,
        rho: c.t.leadAngleDeg,
        tilt: c.t.tiltAngleDeg,
        pattern: c.pattern,
        h: c.h,
        surfaceRadius: c.rs,
        surfaceAxis: 'cross',
      });
      expect(!v.ok && v.errors[0]?.code).toBe('shank-cuts');
      expect(!v.ok && v.errors[0]?.limit).toBe(limits.limitMm);
      // Below it, L to 1e-9 mm; at it, the reference's shank starts to count.
      checkCase(c.t, s, JSON.stringify(c));
    }
  });

  for (const [seed, sign] of [
    [901, 1],
    [902, -1],
  ] as const) {
    it(`${sign > 0 ? 'convex' : 'concave'}: random tilted tools (seed ${seed}, 6 cases), the shank's height against the brute force`, () => {
      const rand = seededRandom(seed);
      let shank = 0;
      for (let k = 0; k < 6; k++) {
        const R = 0.5 * 20 ** rand();
        const t = tool(R, R * (0.05 + 0.95 * rand()), 60 * rand(), (rand() < 0.5 ? -1 : 1) * (5 + 45 * rand()));
        let rs = R * (3 + 30 * rand());
        if (sign < 0) {
          const min = concaveFit(t, 'cross').minRadiusMm;
          if (!Number.isFinite(min)) continue;
          rs = -Math.max(rs, 1.05 * min);
        }
        if (checkCase(t, cyl(rs, 'cross'), JSON.stringify({ t, rs })).limitBy.startsWith('shank')) shank++;
      }
      expect(shank).toBeGreaterThanOrEqual(3);
    });
  }
});

describe("item 10: a trough's wall and the shank", () => {
  it('the issue case: the shank leans 50 degrees along the feed and crosses the wall of any trough', () => {
    const v = validateForward({ R: 3, Rcr: 1, rho: 5, tilt: 50, h: 0.01, surfaceRadius: -3.7, surfaceAxis: 'feed' });
    expect(v.ok).toBe(false);
    if (v.ok) return;
    const e = v.errors[0];
    expect(e?.code).toBe('shank-gouging');
    expect(e?.limit).toBeUndefined();
    expect(e?.message).toMatch(/any radius/);
    expect(e?.message).toMatch(/50\.1\d* degrees/);
    expect(e?.message).toMatch(/Less tilt or lead would help/);
    // The sampled tool: the shank crosses the wall (by 1.09 mm) here and at a radius 100 times larger.
    const t = tool(3, 1, 5, 50);
    for (const rs of [-3.7, -370])
      expect(concaveOverreach(t, rs, 'feed', { spacingMm: 0.02 }).shankMm).toBeGreaterThan(0.5);
    // Across the axis the shank leans by the lead alone: the same tool fits there (head-limited).
    expect(concaveFit(t, 'cross').limitedBy).toBe('head');
    const cross = validateForward({
      R: 3,
      Rcr: 1,
      rho: 50,
      tilt: 5,
      h: 0.01,
      surfaceRadius: -100,
      surfaceAxis: 'cross',
    });
    expect(!cross.ok && cross.errors[0]?.message).toMatch(/any radius.*Less lead would help/);
  });

  it("where the shank sets the smallest radius (larger than the head's): named, and true by brute force", () => {
    for (const [t, axis] of [
      [tool(3, 1, 5, 44), 'feed'],
      [tool(3, 1, 44, 10), 'cross'],
      [tool(2, 0.5, 30, 38), 'feed'],
    ] as const) {
      const fit = concaveFit(t, axis);
      expect(fit.limitedBy).toBe('shank');
      expect(fit.shankMm).toBeGreaterThan(1.5 * fit.headMm);
      const min = fit.minRadiusMm;
      const raw = {
        R: t.toolRadiusMm,
        Rcr: t.cornerRadiusMm,
        rho: t.leadAngleDeg,
        tilt: t.tiltAngleDeg,
        surfaceAxis: axis,
      };
      const tight = validateForward({ ...raw, h: 0.01, surfaceRadius: -0.99 * min });
      expect(!tight.ok && tight.errors[0]?.code).toBe('shank-gouging');
      expect(!tight.ok && tight.errors[0]?.limit).toBe(-min);
      expect(!tight.ok && tight.errors[0]?.message).toMatch(/at least \d/);
      expect(validateInverse({ ...raw, interval: 0.1, surfaceRadius: -0.99 * min }).ok).toBe(false);
      expect(validateForward({ ...raw, h: 0.01, surfaceRadius: -1.01 * min }).ok).toBe(true);
      // The sampled tool: just below the limit the shank crosses the wall below the axis height,
      // just above it nothing does (the head fits with room to spare).
      const spacingMm = t.toolRadiusMm / 600;
      const below = concaveOverreach(t, -0.99 * min, axis, { spacingMm });
      const above = concaveOverreach(t, -1.01 * min, axis, { spacingMm });
      expect(below.shankMm, JSON.stringify(t)).toBeGreaterThan(0);
      expect(Math.max(above.headMm, above.shankMm), JSON.stringify(t)).toBeLessThanOrEqual(0);
    }
  });

  it('random postures (seed 1001, 16 cases): the smallest radius against the sampled tool', () => {
    const rand = seededRandom(1001);
    const by = { head: 0, shank: 0, any: 0 };
    for (let k = 0; k < 16; k++) {
      const R = 0.5 + 4 * rand();
      const t = tool(R, R * (0.05 + 0.95 * rand()), 70 * rand(), 120 * rand() - 60);
      const axis = rand() < 0.5 ? 'feed' : 'cross';
      const fit = concaveFit(t, axis);
      if (!Number.isFinite(fit.headMm)) continue;
      const spacingMm = R / 400;
      if (!Number.isFinite(fit.shankMm)) {
        // "Any radius": the shank crosses just above the head's limit and far beyond it.
        by.any++;
        for (const f of [1.001, 10])
          expect(concaveOverreach(t, -f * fit.headMm, axis, { spacingMm }).shankMm, JSON.stringify(t)).toBeGreaterThan(
            0,
          );
        continue;
      }
      by[fit.limitedBy]++;
      const below = concaveOverreach(t, -0.98 * fit.minRadiusMm, axis, { spacingMm });
      const above = concaveOverreach(t, -1.02 * fit.minRadiusMm, axis, { spacingMm });
      expect(Math.max(below.headMm, below.shankMm), JSON.stringify({ t, axis, fit })).toBeGreaterThan(0);
      expect(Math.max(above.headMm, above.shankMm), JSON.stringify({ t, axis, fit })).toBeLessThanOrEqual(0);
    }
    expect(by.head).toBeGreaterThan(0);
    expect(by.shank).toBeGreaterThan(0);
    expect(by.any).toBeGreaterThan(0);
  });
});
