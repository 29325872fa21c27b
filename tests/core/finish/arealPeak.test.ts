/**
 * The highest point of the surface the teeth leave over one cell (src/core/finish/areal.ts, Sp and Sz):
 * the line maxima over y have narrow ridges that the shared maximiser's 24-line scan can step over, so
 * it is searched again about the highest sample of the integral's lines. Checked against heights that
 * do not share that search: the sampled map's (arealMap, a midpoint grid of the surface's heights),
 * and with runout the plain maximiser's where it stepped over a ridge.
 */
import { describe, expect, it } from 'vitest';
import { arealMap, arealParameters, arealPeak, toothModel } from '../../../src/core/finish/index';
import { forwardInput } from '../../../src/core/input/validate';
import { seededRandom } from '../../../src/core/math/seededRandom';
import { planeIntervalMm } from '../../../src/core/surfaces/exact';
import { teethFinish as finish } from '../../support/teethFinish';

describe('the highest point of the cell', () => {
  it('without runout is at least the highest of the 256 x 256 map, which the plain scan missed by 4.4e-5 mm (seed 2934, case 7)', () => {
    // The seventh case of a seeded sweep (seed 2934: the paper's tools, lead 2-15, tilt 0 or +-5, h
    // 0.002-0.008, z 2-4, fz 0.05-0.2): the plain maximiser answered 0.0036220 mm, the map 0.0036665.
    const r = seededRandom(2934);
    const draw = () => {
      const big = r() < 0.5;
      const tool = {
        toolRadiusMm: big ? 6 : 3,
        cornerRadiusMm: big ? 2 : 1,
        leadAngleDeg: 2 + 13 * r(),
        tiltAngleDeg: r() < 0.5 ? 0 : 10 * (r() - 0.5),
      };
      const pattern = r() < 0.4 ? 'zigzag' : 'one-way';
      const L = planeIntervalMm(forwardInput(tool, pattern, 0.002 + 0.006 * r()));
      return toothModel({ tool, pattern, intervalMm: L, finish: finish(2 + Math.floor(3 * r()), 0.05 + 0.15 * r()) });
    };
    for (let i = 0; i < 6; i++) draw();
    const m = draw();
    const a = arealParameters(m);
    let mapMax = Number.NEGATIVE_INFINITY;
    for (const h of arealMap(m, 256, 256).heightsMm) mapMax = Math.max(mapMax, h);
    expect(a.spMm + a.meanMm).toBeGreaterThanOrEqual(mapMax - 1e-12);
  });

  it("with runout is searched again from the integral's lines: above the shared maximiser's 24-line scan, which missed a narrow ridge of the line maxima by 3.3e-8 mm (seed 2933)", () => {
    // The second case of a seeded search (seed 2933: lead 2-15, h 0.003-0.009, z 1-2, fz 0.08-0.2,
    // e 0.003-0.01) for a highest point above the plain maximiser's (5 of its 12 cases, by 1e-10 to
    // 1.4e-7 mm): here 3.3e-8 mm above it, a height the surface reaches (a line's maximum).
    const r = seededRandom(2933);
    const draw = () => {
      const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 2 + 13 * r(), tiltAngleDeg: 0 };
      const h = 0.003 + 0.006 * r();
      const L = planeIntervalMm(forwardInput(tool, 'one-way', h));
      const fin = finish(1 + Math.floor(2 * r()), 0.08 + 0.12 * r(), 0.003 + 0.007 * r(), 360 * r());
      return toothModel({ tool, pattern: 'one-way', intervalMm: L, finish: fin });
    };
    draw();
    const m = draw();
    const a = arealParameters(m);
    const plain = arealPeak(m).highMm;
    expect(a.spMm + a.meanMm).toBeGreaterThan(plain + 1e-8);
    expect(a.spMm + a.meanMm).toBeLessThan(plain + 1e-7);
  });
});
