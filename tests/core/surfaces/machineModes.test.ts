/**
 * Machine modes as posture suppliers (issue 27 point 3): five-axis gives the surface model its own
 * lead and tilt, to the last digit of the solvers' entry; three-axis gives the plane the upright
 * tool's posture over the slope, to 1e-9 mm of the sloped plane's own solver; a mode on a surface it
 * has no posture for is refused in one line naming the constraint.
 */
import { describe, expect, it } from 'vitest';
import { answerQuestion, type Question, validateQuestion } from '../../../src/core/surfaces/question';
import { exactForward, exactInverse } from '../../../src/core/surfaces/solve';
import { scallopHeightLimits } from '../../../src/core/surfaces/validate';
import { slopedPlaneForward, slopedPlaneInverse } from '../../../src/core/threeAxis/slopedPlane';
import { waterlineForward, waterlineInverse } from '../../../src/core/threeAxis/waterlineRevolution';
import { seededRandom } from '../../support/bruteForce';

function answered(q: Question) {
  const v = validateQuestion(q);
  if (!v.ok) throw new Error(JSON.stringify(v.errors));
  return answerQuestion(v.value);
}

describe('five-axis: the given posture over every product surface', () => {
  it('equals exactForward and exactInverse on the plane, cylinders and doubly curved points (seed 31)', () => {
    const rand = seededRandom(31);
    let compared = 0;
    for (let i = 0; i < 300; i++) {
      const R = 0.5 + 10 * rand();
      const tool = {
        toolRadiusMm: R,
        cornerRadiusMm: R * rand(),
        leadAngleDeg: 60 * rand(),
        tiltAngleDeg: 40 * rand() - 20,
      };
      const pick = Math.floor(3 * rand());
      const radius = (rand() < 0.5 ? 1 : -1) * (20 + 500 * rand());
      const surface =
        pick === 0
          ? ({ kind: 'plane' } as const)
          : pick === 1
            ? ({ kind: 'cylinder', radiusMm: Math.abs(radius), axis: rand() < 0.5 ? 'feed' : 'cross' } as const)
            : ({ kind: 'doublyCurved', feedRadiusMm: Math.abs(radius), crossRadiusMm: 30 + 300 * rand() } as const);
      const pattern = rand() < 0.5 ? 'one-way' : 'zigzag';
      const h = scallopHeightLimits(tool, surface).limitMm * (0.01 + 0.5 * rand());
      const q = {
        tool: { toolRadiusMm: tool.toolRadiusMm, cornerRadiusMm: tool.cornerRadiusMm },
        mode: { kind: 'fiveAxis', leadAngleDeg: tool.leadAngleDeg, tiltAngleDeg: tool.tiltAngleDeg },
        surface,
        pattern,
      } as const;
      const v = validateQuestion({ ...q, target: { quantity: 'h', mm: h } });
      if (!v.ok) continue;
      const f = answerQuestion(v.value);
      const e = exactForward({ ...tool, pattern, surface, scallopHeightMm: h });
      expect(f.intervalMm).toBe(e.intervalMm);
      expect(f.cuspHeightMm).toBe(e.cuspHeightMm);
      const L = e.intervalMm * 0.9;
      const inv = answered({ ...q, target: { quantity: 'interval', mm: L } });
      expect(inv.cuspHeightMm).toBe(exactInverse({ ...tool, pattern, surface, intervalMm: L }).cuspHeightMm);
      compared++;
    }
    expect(compared).toBeGreaterThan(200);
  });
});

describe('three-axis: the upright posture over the plane', () => {
  it('equals the sloped plane solver within 1e-9 mm, forward and inverse, raster and waterline (seed 32)', () => {
    const rand = seededRandom(32);
    let compared = 0;
    for (let i = 0; i < 300; i++) {
      const R = 0.5 + 10 * rand();
      const Rcr = R * (0.05 + 0.95 * rand());
      const waterline = rand() < 0.4;
      const slopeDeg = waterline ? 0.5 + 85 * rand() : 85 * rand();
      const c = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        slopeDeg,
        passes: waterline ? 'waterline' : 'raster',
        rasterAngleDeg: 90 * rand(),
      } as const;
      const probe = slopedPlaneForward(c, 1e-7);
      if (!probe.ok || probe.value.noScallop) continue;
      const h = Math.min(probe.value.heightLimitMm, Rcr) * (0.01 + 0.9 * rand());
      const own = slopedPlaneForward(c, h);
      if (!own.ok) continue;
      const q = {
        tool: { toolRadiusMm: R, cornerRadiusMm: Rcr },
        mode: { kind: 'threeAxis', slopeDeg, passes: c.passes, rasterAngleDeg: c.rasterAngleDeg },
        surface: { kind: 'plane' },
        pattern: 'zigzag', // three-axis passes are one-way whichever way they feed
      } as const;
      const f = answered({ ...q, target: { quantity: 'h', mm: h } });
      expect(f.posture.pattern).toBe('one-way');
      expect(Math.abs(f.intervalMm - own.value.intervalMm)).toBeLessThan(1e-9 * Math.max(1, R));
      const L = own.value.intervalMm * 0.8;
      const back = slopedPlaneInverse(c, { field: 'interval', mm: L });
      const inv = answered({ ...q, target: { quantity: 'interval', mm: L } });
      expect(back.ok && Math.abs(inv.cuspHeightMm - back.value.cuspHeightMm)).toBeLessThan(1e-9 * Math.max(1, R));
      compared++;
    }
    expect(compared).toBeGreaterThan(150);
  });

  it('answers waterline passes on a surface of revolution itself, as waterlineRevolution.ts does, without per-flank parts (seed 33)', () => {
    const rand = seededRandom(33);
    let compared = 0;
    for (let i = 0; i < 200; i++) {
      const R = 1 + 8 * rand();
      const Rcr = R * (0.1 + 0.9 * rand());
      const side = () => (rand() < 0.5 ? 1 : -1) * (R * 4 + 300 * rand());
      const straight = rand() < 0.2;
      const feed = side();
      const cross = straight ? Number.POSITIVE_INFINITY : side();
      const slopeDeg = 5 + 80 * rand();
      const c = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        slopeDeg,
        feedRadiusMm: feed,
        crossRadiusMm: straight ? null : cross,
      };
      const h = Rcr * 10 ** (-4 + 2.5 * rand());
      const own = waterlineForward(c, h);
      const q = {
        tool: { toolRadiusMm: R, cornerRadiusMm: Rcr },
        mode: { kind: 'threeAxis', slopeDeg, passes: 'waterline', rasterAngleDeg: 0 },
        surface: { kind: 'doublyCurved', feedRadiusMm: feed, crossRadiusMm: cross },
        pattern: 'one-way',
      } as const;
      const v = validateQuestion({ ...q, target: { quantity: 'h', mm: h } });
      expect(v.ok, JSON.stringify(c)).toBe(own.ok);
      if (!own.ok || !v.ok) {
        expect(!v.ok && v.errors.map((e) => e.message)).toEqual(!own.ok && own.errors.map((e) => e.message));
        continue;
      }
      const f = answerQuestion(v.value);
      expect(f.intervalMm).toBe(own.value.intervalMm);
      expect(f.cuspHeightMm).toBe(own.value.cuspHeightMm);
      expect([f.halfWidthRightMm, f.halfWidthLeftMm, f.contactOffsetMm, f.maxIntervalMm]).toEqual([
        null,
        null,
        null,
        null,
      ]);
      expect(f.posture).toEqual({
        leadAngleDeg: own.value.leadDeg,
        tiltAngleDeg: own.value.tiltDeg,
        pattern: 'one-way',
      });
      const L = 0.7 * own.value.intervalMm;
      const back = waterlineInverse(c, { field: 'interval', mm: L });
      const inv = validateQuestion({ ...q, target: { quantity: 'interval', mm: L } });
      expect(inv.ok && answerQuestion(inv.value).cuspHeightMm).toBe(back.ok && back.value.cuspHeightMm);
      compared++;
    }
    expect(compared).toBeGreaterThan(80);
  });

  it('is refused where it has neither a posture nor its own answer, in one line naming the constraint', () => {
    for (const [surface, passes] of [
      [{ kind: 'cylinder', radiusMm: 50, axis: 'feed' }, 'raster'],
      [{ kind: 'cylinder', radiusMm: 50, axis: 'feed' }, 'waterline'],
      [{ kind: 'doublyCurved', feedRadiusMm: 50, crossRadiusMm: 80 }, 'raster'],
    ] as const) {
      const v = validateQuestion({
        tool: { toolRadiusMm: 5, cornerRadiusMm: 1 },
        mode: { kind: 'threeAxis', slopeDeg: 30, passes, rasterAngleDeg: 0 },
        surface,
        pattern: 'one-way',
        target: { quantity: 'h', mm: 0.01 },
      });
      expect(v.ok).toBe(false);
      const e = !v.ok ? v.errors : [];
      expect(e).toHaveLength(1);
      expect(e[0]?.field).toBe('surface');
      expect(e[0]?.message).toBe(
        `Three-axis machining is answered on a sloped plane, or with waterline passes on a surface of revolution, not here (a surface of kind "${surface.kind}"): the upright tool's posture is known there only.`,
      );
    }
  });

  it('refuses its own parameters and the target beyond the limits, each in one line', () => {
    const base = {
      tool: { toolRadiusMm: 5, cornerRadiusMm: 1 },
      surface: { kind: 'plane' },
      pattern: 'one-way',
    } as const;
    const wall = validateQuestion({
      ...base,
      mode: { kind: 'threeAxis', slopeDeg: 90, passes: 'raster', rasterAngleDeg: 0 },
      target: { quantity: 'h', mm: 0.01 },
    });
    expect(!wall.ok && wall.errors.map((e) => e.field)).toEqual(['slope']);
    const flat = validateQuestion({
      ...base,
      mode: { kind: 'threeAxis', slopeDeg: 0, passes: 'waterline', rasterAngleDeg: 0 },
      target: { quantity: 'h', mm: 0.01 },
    });
    // The sloped plane solver's own words (threeAxis/slopedPlane.ts slopeErrors: one place for the rule).
    expect(!flat.ok && flat.errors[0]?.message).toBe(
      'Slope alpha must be above 0 degrees for waterline passes: on a flat floor every level is the same, so there is no step-down.',
    );
    const nanSlope = validateQuestion({
      ...base,
      mode: { kind: 'threeAxis', slopeDeg: Number.NaN, passes: 'raster', rasterAngleDeg: 0 },
      target: { quantity: 'h', mm: 0.01 },
    });
    expect(!nanSlope.ok && nanSlope.errors[0]?.message).toBe(
      'Slope must be a number of degrees (got no finite number).',
    );
    const high = validateQuestion({
      ...base,
      mode: { kind: 'threeAxis', slopeDeg: 30, passes: 'raster', rasterAngleDeg: 0 },
      target: { quantity: 'h', mm: 4 },
    });
    expect(!high.ok && high.errors[0]?.message).toMatch(
      /^Scallop height h must be below \d+(\.\d+)? mm here \(got 4\)/,
    );
    const nonFinite = validateQuestion({
      ...base,
      tool: { toolRadiusMm: Number.NaN, cornerRadiusMm: 1 },
      mode: { kind: 'fiveAxis', leadAngleDeg: Number.POSITIVE_INFINITY, tiltAngleDeg: 0 },
      target: { quantity: 'h', mm: 0.01 },
    });
    const words = !nonFinite.ok ? nonFinite.errors.map((e) => e.message) : [];
    expect(words).toEqual([
      'Tool radius R must be from 0.001 mm to 1000 mm (got no finite number).',
      'Lead angle must be from 0 to below 90 degrees (got no finite number).',
    ]);
    const unknown = validateQuestion({ ...base, mode: { kind: 'fourAxis' }, target: { quantity: 'h', mm: 0.01 } });
    expect(!unknown.ok && unknown.errors[0]?.message).toBe('No machine mode of kind "fourAxis" is registered.');
  });
});
