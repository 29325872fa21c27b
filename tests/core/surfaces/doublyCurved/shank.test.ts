/**
 * The shank's limit at a doubly curved point (shankLimit.ts): the existing plane and cylinder-along
 * heights where they are exact, and the brute force elsewhere (below the limit the shank leaves the
 * cusp alone; above it, it cuts the cusp down).
 */
import { describe, expect, it } from 'vitest';
import type { ToolInput } from '../../../../src/core/input/validate';
import type { Surface } from '../../../../src/core/surfaces/cylinder';
import { shankCutHeights } from '../../../../src/core/surfaces/doublyCurved/shankLimit';
import { doublyCurvedForward, doublyCurvedLimits } from '../../../../src/core/surfaces/doublyCurved/solve';
import { scallopHeightLimits } from '../../../../src/core/surfaces/validate';
import { seededRandom } from '../../../support/bruteForce';
import { bruteForceDoublyCurved } from '../../../support/reference/doublyCurvedBruteForce';

const I = Number.POSITIVE_INFINITY;

describe('doubly curved point: where the shank starts to cut', () => {
  for (const seed of [1941, 1942]) {
    it(`the plane's and the cylinder-along's shank heights to 1e-12 mm (seed ${seed})`, () => {
      const rand = seededRandom(seed);
      for (let n = 0; n < 40; n++) {
        const R = 0.5 + 5 * rand();
        const tool: ToolInput = {
          toolRadiusMm: R,
          cornerRadiusMm: R * rand(),
          leadAngleDeg: 60 * rand(),
          tiltAngleDeg: 120 * rand() - 60,
        };
        const rs = (rand() < 0.5 ? 1 : -1) * R * (3 + 30 * rand());
        const pairs: Array<[Surface, number, number]> = [
          [{ kind: 'plane' }, I, I],
          [{ kind: 'cylinder', radiusMm: rs, axis: 'feed' }, I, rs],
        ];
        for (const [surface, rf, rc] of pairs) {
          const expected = scallopHeightLimits(tool, surface);
          const got = shankCutHeights(tool, { feedRadiusMm: rf, crossRadiusMm: rc });
          const label = `R ${R} Rcr ${tool.cornerRadiusMm} rho ${tool.leadAngleDeg} tilt ${tool.tiltAngleDeg} Rc ${rc}`;
          // A shank height above its side's wall never binds, and the cylinder solver leaves it out
          // (null): compare the heights where the shank cuts before the flank turns into a wall.
          const binding = (shank: number | null, top: number) => (shank !== null && shank < top ? shank : null);
          const pairsOfSides: Array<[number | null, number | null]> = [
            [binding(got.rightMm, expected.topRightMm), binding(expected.shankRightMm, expected.topRightMm)],
            [binding(got.leftMm, expected.topLeftMm), binding(expected.shankLeftMm, expected.topLeftMm)],
          ];
          for (const [mine, theirs] of pairsOfSides) {
            expect(mine === null, label).toBe(theirs === null);
            expect(Math.abs((mine ?? 0) - (theirs ?? 0)), label).toBeLessThan(1e-12);
          }
        }
      }
    });
  }

  for (const [R, Rcr, rho, tilt, rf, rc] of [
    [3, 1, 5, 30, 20, I],
    [3, 1, 5, 30, -40, 25],
    [3, 3, 0, -35, -50, -40],
  ] as const) {
    it(`brute force: the shank leaves the cusp alone below its limit and cuts it above (R ${R} Rcr ${Rcr} rho ${rho} tilt ${tilt} Rf ${rf} Rc ${rc})`, () => {
      const tool: ToolInput = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt };
      const limits = doublyCurvedLimits({ ...tool, feedRadiusMm: rf, crossRadiusMm: rc });
      expect(limits.limitBy).toBe(tilt > 0 ? 'shank-right' : 'shank-left');
      for (const factor of [0.9, 1.1]) {
        const h = factor * limits.limitMm;
        const L = doublyCurvedForward({
          ...tool,
          pattern: 'one-way',
          feedRadiusMm: rf,
          crossRadiusMm: rc,
          scallopHeightMm: h,
        }).intervalMm;
        const b = bruteForceDoublyCurved({ R, Rcr, leadDeg: rho, tiltDeg: tilt }, 'one-way', rf, rc, L, {
          spacingMm: R / 60,
          levels: 3,
          shankLengthMm: 3 * R,
        });
        if (factor < 1) expect(Math.abs(b.cuspHeightMm - h)).toBeLessThanOrEqual(b.boundMm);
        else expect(b.cuspHeightMm).toBeLessThan(h - b.boundMm);
      }
    });
  }
});
