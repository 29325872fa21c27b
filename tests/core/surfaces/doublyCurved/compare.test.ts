/** The comparison rows at a doubly curved point (compare.ts). */
import { describe, expect, it } from 'vitest';
import { forwardInput, type ToolInput } from '../../../../src/core/input/validate';
import { compareForward } from '../../../../src/core/procedures/compare';
import { compareDoublyCurved } from '../../../../src/core/procedures/compareDoublyCurved';
import { doublyCurvedForward, doublyCurvedInverse } from '../../../../src/core/surfaces/doublyCurved/solve';

const I = Number.POSITIVE_INFINITY;
const tool: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 0 };

describe('doubly curved comparison rows', () => {
  it('on a cylinder along the feed: the existing rows (plane, corrected circles) to 1e-9 mm', () => {
    for (const rs of [20, -40]) {
      const mine = compareDoublyCurved({
        ...tool,
        pattern: 'one-way',
        feedRadiusMm: I,
        crossRadiusMm: rs,
        scallopHeightMm: 0.05,
      });
      const theirs = compareForward(
        forwardInput(tool, 'one-way', 0.05, { kind: 'cylinder', radiusMm: rs, axis: 'feed' }),
      );
      const c = theirs.curvature;
      if (c === null || !c.plane.ok || !mine.plane.ok) throw new Error('rows missing');
      expect(Math.abs(mine.exact.intervalMm - theirs.exact.intervalMm)).toBeLessThan(1e-9);
      expect(Math.abs(mine.plane.intervalMm - c.plane.intervalMm)).toBeLessThan(1e-9);
      expect(Math.abs((mine.plane.realScallopMm as number) - (c.plane.realScallopMm as number))).toBeLessThan(1e-9);
      for (const key of ['sekine', 'redonnet', 'osculating', 'cornerBall'] as const) {
        const a = mine.corrected[key];
        const b = c.corrected[key];
        expect(a.ok, key).toBe(b.ok);
        if (a.ok && b.ok) expect(Math.abs(a.intervalMm - b.intervalMm), key).toBeLessThan(1e-12);
      }
      // The cylinder along the feed is this surface itself: no deviation.
      expect(mine.cylinderAlong.ok && Math.abs(mine.cylinderAlong.deviationMm)).toBeLessThan(1e-12);
    }
  });

  it('each row leaves the scallop the exact inverse gives for its L, and the deviations are L minus the exact', () => {
    const input = {
      ...tool,
      tiltAngleDeg: 12,
      pattern: 'zigzag' as const,
      feedRadiusMm: 60,
      crossRadiusMm: -80,
      scallopHeightMm: 0.04,
    };
    const r = compareDoublyCurved(input);
    const exactL = doublyCurvedForward(input).intervalMm;
    for (const row of [r.plane, r.cylinderAlong, r.cylinderAcross, r.corrected.redonnet, r.corrected.osculating]) {
      if (!row.ok) throw new Error('row missing');
      expect(Math.abs(row.deviationMm - (row.intervalMm - exactL))).toBeLessThan(1e-12);
      const h = doublyCurvedInverse({ ...input, intervalMm: row.intervalMm }).cuspHeightMm;
      expect(row.realScallopMm).toBe(h);
    }
  });
});
