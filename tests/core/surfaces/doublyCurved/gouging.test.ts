/**
 * Gouging at a doubly curved point: the existing cylinder rule where the shank cannot bind, the
 * kinds of limit ("at any radius" included), and the predicate alone against the full check.
 */
import { describe, expect, it } from 'vitest';
import type { ToolInput } from '../../../../src/core/input/validate';
import { minConcaveRadiusMm } from '../../../../src/core/surfaces/cylinder';
import {
  doublyCurvedGouges,
  doublyCurvedGouging,
  doublyCurvedRadiusLimit,
} from '../../../../src/core/surfaces/doublyCurved/gouging';
import { seededRandom } from '../../../support/bruteForce';

const I = Number.POSITIVE_INFINITY;

describe('doubly curved gouging', () => {
  for (const seed of [1931, 1932]) {
    it(`troughs without tilt (the shank cannot bind) give the existing cylinder rule to 1e-9 relative (seed ${seed})`, () => {
      const rand = seededRandom(seed);
      for (let n = 0; n < 6; n++) {
        const R = 0.5 + 6 * rand();
        const tool: ToolInput = {
          toolRadiusMm: R,
          cornerRadiusMm: rand() < 0.2 ? 0 : R * rand(),
          leadAngleDeg: 2 + 28 * rand(),
          tiltAngleDeg: 0,
        };
        const label = `R ${R} Rcr ${tool.cornerRadiusMm} rho ${tool.leadAngleDeg}`;
        // A trough along the feed (Rf straight, Rc concave) is the existing axis = feed rule; across, axis = cross.
        const along = doublyCurvedRadiusLimit(tool, { feedRadiusMm: I, crossRadiusMm: -1e5 }, 'cross');
        const across = doublyCurvedRadiusLimit(tool, { feedRadiusMm: -1e5, crossRadiusMm: I }, 'feed');
        for (const [got, axis] of [
          [along, 'feed'],
          [across, 'cross'],
        ] as const) {
          const expected = minConcaveRadiusMm(tool, axis);
          expect(got.kind, `${label} ${axis}`).toBe('concave-at-least');
          expect(Math.abs((got.radiusMm as number) / expected - 1), `${label} ${axis}`).toBeLessThan(1e-9);
        }
      }
    });
  }

  it('names what no value of a radius can help ("at any radius") and what every value passes', () => {
    const tool: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
    // Rf = -20 is tighter than the tool along the feed (it needs |Rf| >= 23.95): no Rc clears it.
    const tight = doublyCurvedGouging(tool, { feedRadiusMm: -20, crossRadiusMm: 30 });
    expect(tight.gouges).toBe(true);
    expect(tight.cross.kind).toBe('none');
    expect(tight.feed.kind).toBe('concave-at-least');
    // A ball end on a dome: across, a concave Rc of at least the ball's radius; along the feed too (a
    // concave feed circle tighter than the ball, |Rf| < 3, holds the CC point inside the ball's swept
    // image: issue 26 point 1), a little more for the shank. A flat bottom lying flat gouges every bowl.
    const ball = doublyCurvedGouging({ ...tool, cornerRadiusMm: 3 }, { feedRadiusMm: 40, crossRadiusMm: 40 });
    expect([ball.gouges, ball.feed.kind, ball.cross.kind]).toEqual([false, 'concave-at-least', 'concave-at-least']);
    expect(ball.cross.radiusMm).toBeCloseTo(3, 9);
    expect(ball.feed.radiusMm).toBeGreaterThanOrEqual(3);
    expect(ball.feed.radiusMm).toBeLessThan(3.05);
    const flat = doublyCurvedGouging(
      { toolRadiusMm: 5, cornerRadiusMm: 0.5, leadAngleDeg: 0, tiltAngleDeg: 0 },
      { feedRadiusMm: 40, crossRadiusMm: 40 },
    );
    expect([flat.gouges, flat.feed.kind, flat.cross.kind]).toEqual([false, 'not-concave', 'not-concave']);
  });

  it('the predicate alone agrees with the full check (seed 1933)', () => {
    const rand = seededRandom(1933);
    for (let n = 0; n < 6; n++) {
      const R = 1 + 4 * rand();
      const tool: ToolInput = {
        toolRadiusMm: R,
        cornerRadiusMm: R * rand(),
        leadAngleDeg: 40 * rand(),
        tiltAngleDeg: 60 * rand() - 30,
      };
      const radii = {
        feedRadiusMm: (rand() < 0.5 ? 1 : -1) * R * (2 + 20 * rand()),
        crossRadiusMm: (rand() < 0.5 ? 1 : -1) * R * (2 + 20 * rand()),
      };
      expect(doublyCurvedGouges(tool, radii)).toBe(doublyCurvedGouging(tool, radii).gouges);
    }
  });
});
