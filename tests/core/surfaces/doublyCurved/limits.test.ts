/**
 * The doubly curved solver at infinite radii is the existing core: Rf infinite the cylinder with its
 * axis along the feed (Rs = Rc), Rc infinite the cylinder across (Rs = Rf), both the plane; and large
 * radii approach those answers.
 */
import { describe, expect, it } from 'vitest';
import { forwardInput, inverseInput, type PassPattern, type ToolInput } from '../../../../src/core/input/validate';
import { doublyCurvedRoughnessAtInterval } from '../../../../src/core/roughness/doublyCurved';
import type { Surface } from '../../../../src/core/surfaces/cylinder';
import {
  doublyCurvedForward,
  doublyCurvedInverse,
  doublyCurvedLimits,
  doublyCurvedSolver,
} from '../../../../src/core/surfaces/doublyCurved/solve';
import { curvedInverse, curvedPoint } from '../../../../src/core/surfaces/doublyCurvedPoint';
import { exactForward, exactInverse } from '../../../../src/core/surfaces/solve';
import { scallopHeightLimits } from '../../../../src/core/surfaces/validate';
import { seededRandom } from '../../../support/bruteForce';

const I = Number.POSITIVE_INFINITY;

function randomTool(rand: () => number): ToolInput {
  const R = 0.5 + 9.5 * rand();
  const kind = rand();
  // A quarter ball ends, a quarter flat ends, the rest bull-nose.
  const Rcr = kind < 0.25 ? R : kind < 0.5 ? 0 : R * (0.05 + 0.9 * rand());
  return {
    toolRadiusMm: R,
    cornerRadiusMm: Rcr,
    leadAngleDeg: rand() < 0.15 ? 0 : 40 * rand(),
    tiltAngleDeg: rand() < 0.3 ? 0 : 60 * (rand() - 0.5),
  };
}

/** The existing surface and the doubly curved radii that mean the same. */
function cases(rs: number): Array<{ name: string; surface: Surface; rf: number; rc: number }> {
  return [
    { name: 'plane', surface: { kind: 'plane' }, rf: I, rc: I },
    {
      name: `feed cylinder Rs=${rs}`,
      surface: { kind: 'cylinder', radiusMm: rs, axis: 'feed' },
      rf: I,
      rc: rs,
    },
    {
      name: `cross cylinder Rs=${rs}`,
      surface: { kind: 'cylinder', radiusMm: rs, axis: 'cross' },
      rf: rs,
      rc: I,
    },
  ];
}

describe('doubly curved point: infinite radii give the existing plane and cylinder answers', () => {
  for (const seed of [11, 12, 13, 14, 15, 16]) {
    it(`forward, inverse and the other cusp within 1e-9 mm (seed ${seed})`, () => {
      const rand = seededRandom(seed);
      let compared = 0;
      for (let n = 0; n < 12; n++) {
        const tool = randomTool(rand);
        const R = tool.toolRadiusMm;
        const rs = (rand() < 0.5 ? 1 : -1) * R * (2 + 40 * rand());
        const pattern: PassPattern = rand() < 0.5 ? 'one-way' : 'zigzag';
        for (const c of cases(rs)) {
          // The existing solvers do not model gouging themselves; a concave surface is compared only
          // where the doubly curved section stays out of it (its limits are finite and positive).
          const limit = Math.min(
            scallopHeightLimits(tool, c.surface).limitMm,
            doublyCurvedLimits({ ...tool, feedRadiusMm: c.rf, crossRadiusMm: c.rc }).limitMm,
          );
          if (!(limit > 1e-6)) continue;
          const h = limit * (0.01 + 0.8 * rand());
          const label = `${c.name} R=${R} Rcr=${tool.cornerRadiusMm} rho=${tool.leadAngleDeg} tilt=${tool.tiltAngleDeg} ${pattern} h=${h}`;
          let expected: ReturnType<typeof exactForward>;
          try {
            expected = exactForward(forwardInput(tool, pattern, h, c.surface));
          } catch {
            continue;
          }
          const got = doublyCurvedForward({
            ...tool,
            pattern,
            feedRadiusMm: c.rf,
            crossRadiusMm: c.rc,
            scallopHeightMm: h,
          });
          expect(Math.abs(got.intervalMm - expected.intervalMm), label).toBeLessThan(1e-9);
          expect(Math.abs(got.halfWidthRightMm - expected.halfWidthRightMm), label).toBeLessThan(1e-9);
          expect(Math.abs(got.halfWidthLeftMm - expected.halfWidthLeftMm), label).toBeLessThan(1e-9);
          expect(got.contactOffsetMm, label).toBe(expected.contactOffsetMm);
          if (pattern === 'zigzag')
            expect(
              Math.abs((got.otherCuspHeightMm as number) - (expected.otherCuspHeightMm as number)),
              label,
            ).toBeLessThan(1e-9);
          else expect(got.otherCuspHeightMm).toBeNull();
          const L = expected.intervalMm;
          const inv = doublyCurvedInverse({ ...tool, pattern, feedRadiusMm: c.rf, crossRadiusMm: c.rc, intervalMm: L });
          // The inverse must give back h (the forward answers agree); the existing cylinder inverse is
          // compared where it does so too (at this commit a concave cylinder along the feed can answer 0:
          // its reach at h = 0 is not 0, see the report of issue 19).
          expect(Math.abs(inv.cuspHeightMm - h), label).toBeLessThan(1e-9);
          const invExpected = exactInverse(inverseInput(tool, pattern, L, c.surface));
          if (Math.abs(invExpected.cuspHeightMm - h) < 1e-9)
            expect(Math.abs(inv.cuspHeightMm - invExpected.cuspHeightMm), label).toBeLessThan(1e-9);
          if (pattern === 'zigzag')
            expect(Math.abs((inv.otherCuspHeightMm as number) - (got.otherCuspHeightMm as number)), label).toBeLessThan(
              1e-9,
            );
          compared++;
        }
      }
      expect(compared).toBeGreaterThan(20);
    });
  }

  it('large radii approach the infinite answer like 1 / R (both radii, both signs, with tilt)', () => {
    const tool: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 8 };
    const h = 0.05;
    const at = (rf: number, rc: number) =>
      doublyCurvedForward({ ...tool, pattern: 'one-way', feedRadiusMm: rf, crossRadiusMm: rc, scallopHeightMm: h })
        .intervalMm;
    const plane = at(I, I);
    for (const [sf, sc] of [
      [1, 1],
      [-1, -1],
      [1, -1],
      [-1, 1],
    ] as const) {
      const errors = [1e2, 1e4, 1e6].map((r) => Math.abs(at(sf * r, sc * r) - plane));
      expect(errors[1]).toBeLessThan((errors[0] as number) / 50);
      expect(errors[2]).toBeLessThan((errors[1] as number) / 50 + 1e-12);
      // One radius large, the other held: the cylinder's answer.
      const cylinder = at(I, sc * 50);
      expect(Math.abs(at(sf * 1e6, sc * 50) - cylinder)).toBeLessThan(1e-5);
      const across = at(sf * 50, I);
      expect(Math.abs(at(sf * 50, sc * 1e6) - across)).toBeLessThan(1e-5);
    }
  });

  it('a flat bottom without lead on a dome: each flank reaches 0 at height 0, and a tiny cusp has a finite roughness (issue 26 fuzz, seed 2627)', () => {
    // The contact's own disk touches the radius |Rc + 0| and missed it by a rounding: the reach was
    // -Infinity at h = 0, and Ra, Rq of an --interval answer NaN (null in JSON).
    const tool: ToolInput = {
      toolRadiusMm: 1.0655663622423661,
      cornerRadiusMm: 0.5818938241443307,
      leadAngleDeg: 0,
      tiltAngleDeg: 0,
    };
    for (const crossRadiusMm of [1e6, 5000, I]) {
      const radii = { feedRadiusMm: 65.3173079543128, crossRadiusMm };
      const solver = doublyCurvedSolver(tool, radii);
      expect(Number.isFinite(solver.right.reachMm(0)), `Rc ${crossRadiusMm}`).toBe(true);
      const point = curvedPoint(tool, radii, 'one-way');
      const e = curvedInverse(point, 0.0046460868428474435);
      const r = doublyCurvedRoughnessAtInterval(point, e);
      expect([r.raMm, r.rqMm, r.rzMm].every(Number.isFinite), `Rc ${crossRadiusMm}`).toBe(true);
      // The flat bottom on a convex equator rises as y^2 / (2 Rc): the cusp at L/2 (parabola: Ra = 4 h / (9 sqrt 3)).
      if (Number.isFinite(crossRadiusMm)) {
        expect(e.cuspHeightMm / ((0.0046460868428474435 / 2) ** 2 / (2 * crossRadiusMm)) - 1).toBeLessThan(1e-3);
        expect(Math.abs(r.raMm / ((4 * e.cuspHeightMm) / (9 * Math.sqrt(3))) - 1)).toBeLessThan(1e-2);
      }
    }
  });
});
