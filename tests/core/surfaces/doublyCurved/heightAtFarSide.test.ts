/**
 * A flank's height at a reach (equatorFlank.ts heightAtMm, the zigzag and untilted inverse and the
 * zigzag's other cusp) is the inverse of its reach below the top. Where the pass section's disk
 * centres rise steeply (a high lead over a convex Rc below the tool radius) the ray from C crosses
 * the disks in more than one run of u, and the ray's first entry was read on the flank's far side,
 * above the top: one case gave an inverse cusp of 2.56 mm above its 1.46 mm flank limit, with both
 * radii curved (Rf = 1000 mm), where the cylinder's answer (Rf straight) and a brute force give 0.835 mm.
 */
import { describe, expect, it } from 'vitest';
import type { DoublyCurvedSurface } from '../../../../src/core/domain/surface';
import { seededRandom } from '../../../../src/core/math/seededRandom';
import { doublyCurvedGouges } from '../../../../src/core/surfaces/doublyCurved/gouging';
import { doublyCurvedSolver } from '../../../../src/core/surfaces/doublyCurved/solve';
import { doublyCurvedModel } from '../../../../src/core/surfaces/models/doublyCurved';
import { bruteForceDoublyCurved } from '../../../support/reference/doublyCurvedBruteForce';

describe("a flank's height at a reach at a doubly curved point", () => {
  it('seed 2732: below the top it is the height whose reach that is (small convex Rc, high lead, both radii curved)', () => {
    const rand = seededRandom(2732);
    let checked = 0;
    while (checked < 200) {
      const R = 0.5 + 10 * rand();
      const tool = {
        toolRadiusMm: R,
        cornerRadiusMm: R * (0.1 + 0.8 * rand()),
        leadAngleDeg: 30 + 55 * rand(),
        tiltAngleDeg: rand() < 0.5 ? 0 : 60 * rand() - 30,
      };
      const radii = {
        feedRadiusMm: (rand() < 0.5 ? 1 : -1) * R * 10 ** (1 + 3 * rand()),
        crossRadiusMm: R * (0.1 + 1.9 * rand()),
      };
      if (doublyCurvedGouges(tool, radii)) continue;
      const s = doublyCurvedSolver(tool, radii);
      for (const [flank, top] of [
        [s.right, s.limits().topRightMm],
        [s.left, s.limits().topLeftMm],
      ] as const) {
        const h = top * (0.05 + 0.9 * rand());
        const w = flank.reachMm(h);
        const back = flank.heightAtMm(w);
        const label = JSON.stringify({ tool, radii, h, w, back, top });
        expect(back, label).toBeLessThanOrEqual(top);
        expect(Math.abs(flank.reachMm(back) - w), label).toBeLessThanOrEqual(1e-9 * Math.max(1, w));
        checked++;
      }
    }
  });

  it('the case found: Rf 1000 mm, Rc 1.217 mm, lead 74.35 degrees: the inverse cusp is the brute force, below the flank limit', () => {
    const tool = { toolRadiusMm: 2.33, cornerRadiusMm: 0.63, leadAngleDeg: 74.35, tiltAngleDeg: 0 };
    const surface: DoublyCurvedSurface = { kind: 'doublyCurved', feedRadiusMm: 1000, crossRadiusMm: 1.217 };
    const L = 1.6545;
    const e = doublyCurvedModel.inverse({ ...tool, pattern: 'one-way', surface, intervalMm: L });
    expect(e.cuspHeightMm).toBeLessThan(doublyCurvedModel.limits(tool, surface).limitMm);
    const b = bruteForceDoublyCurved({ R: 2.33, Rcr: 0.63, leadDeg: 74.35, tiltDeg: 0 }, 'one-way', 1000, 1.217, L, {
      spacingMm: 2.33 / 60,
      levels: 3,
    });
    expect(Math.abs(e.cuspHeightMm - b.cuspHeightMm), JSON.stringify(b)).toBeLessThanOrEqual(b.boundMm);
  });
});
