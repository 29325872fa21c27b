import { describe, expect, it } from 'vitest';
import { forwardInput, type PassPattern, type ToolInput } from '../../../src/core/input/validate';
import { exactRoughness } from '../../../src/core/roughness/roughness';
import { simulatePasses, startSimulation } from '../../../src/core/simulation/simulation';
import { exactForward } from '../../../src/core/surfaces/solve';
import { scallopHeightLimits } from '../../../src/core/surfaces/validate';
import { seededRandom } from '../../support/bruteForce';

/**
 * The simulation samples the real tool surface and sweeps it (no projection, no exact solver): it
 * must agree with the exact cusp heights and roughness within the bound it states.
 */
function compare(tool: ToolInput, pattern: PassPattern, h: number, cells = 512) {
  const input = forwardInput(tool, pattern, h);
  const e = exactForward(input);
  const r = exactRoughness(input, e);
  const sim = simulatePasses({ tool, pattern, intervalMm: e.intervalMm }, { cellsAcross: cells, cellsAlong: 8 });
  // Exact cusps in the order the passes meet: one-way all h; zigzag alternating (right-right first).
  const hR = e.halfWidthRightMm <= e.halfWidthLeftMm ? h : (e.otherCuspHeightMm ?? h);
  const hL = e.halfWidthRightMm <= e.halfWidthLeftMm ? (e.otherCuspHeightMm ?? h) : h;
  const exactCusps = sim.cuspHeightsMm.map((_, k) => (pattern === 'one-way' ? h : k % 2 === 0 ? hR : hL));
  return { e, r, sim, exactCusps };
}

describe('simulation of the passes against the exact solution', () => {
  for (const seed of [51, 52, 53]) {
    it(`seed ${seed}: 6 random tools, postures and patterns agree within the stated resolution bound`, () => {
      const rand = seededRandom(seed);
      let checked = 0;
      for (let k = 0; k < 6; k++) {
        const R = 0.3 + 8 * rand();
        const tool = {
          toolRadiusMm: R,
          cornerRadiusMm: R * (0.1 + 0.9 * rand()),
          leadAngleDeg: 45 * rand(),
          tiltAngleDeg: 40 * rand() - 20,
        };
        const limit = scallopHeightLimits(tool).limitMm;
        const pattern: PassPattern = rand() < 0.5 ? 'one-way' : 'zigzag';
        const h = limit * (0.005 + 0.3 * rand());
        const { r, sim, exactCusps } = compare(tool, pattern, h);
        const label = JSON.stringify({ tool, pattern, h });
        sim.cuspHeightsMm.forEach((c, i) => {
          expect(Math.abs(c - (exactCusps[i] as number)), `cusp ${i} ${label}`).toBeLessThanOrEqual(
            sim.resolutionBoundMm,
          );
        });
        expect(Math.abs(sim.roughness.raMm - r.raMm), `Ra ${label}`).toBeLessThanOrEqual(sim.roughnessBoundMm);
        expect(Math.abs(sim.roughness.rqMm - r.rqMm), `Rq ${label}`).toBeLessThanOrEqual(sim.roughnessBoundMm);
        expect(Math.abs(sim.roughness.rzMm - r.rzMm), `Rz ${label}`).toBeLessThanOrEqual(sim.roughnessBoundMm);
        // The bound is a useful one: well below the scallop itself.
        expect(sim.resolutionBoundMm).toBeLessThan(0.1 * h);
        checked++;
      }
      expect(checked).toBe(6);
    });
  }

  it('the error and the bound shrink when the field is refined (256, 512, 1024 cells)', () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 8 };
    const errors = [256, 512, 1024].map((cells) => {
      const { sim } = compare(tool, 'one-way', 0.05, cells);
      return { err: Math.abs(sim.cuspHeightMm - 0.05), bound: sim.resolutionBoundMm };
    });
    expect(errors[2]?.bound).toBeLessThan((errors[0]?.bound ?? 0) / 3);
    expect(errors[2]?.err).toBeLessThan(errors[0]?.err ?? 0);
    for (const e of errors) expect(e.err).toBeLessThanOrEqual(e.bound);
  });

  it('a flat bottom lying on the plane (rho = 0) and a ball end: cusps and Ra within the bound', () => {
    for (const [tool, h] of [
      [{ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 0, tiltAngleDeg: 0 }, 0.05],
      [{ toolRadiusMm: 2, cornerRadiusMm: 2, leadAngleDeg: 30, tiltAngleDeg: 20 }, 0.02],
    ] as const) {
      const { r, sim } = compare(tool, 'one-way', h);
      for (const c of sim.cuspHeightsMm) expect(Math.abs(c - h)).toBeLessThanOrEqual(sim.resolutionBoundMm);
      expect(Math.abs(sim.roughness.raMm - r.raMm)).toBeLessThanOrEqual(sim.roughnessBoundMm);
    }
  });

  it('flat and nearly flat ends with lead and tilt (a tiny scallop under a large flat bottom): both patterns within the bound', () => {
    // Cases that once meshed the whole bottom disk (an infinite margin for Rcr = 0) and ran out of memory.
    for (const [tool, h] of [
      [{ toolRadiusMm: 5.7, cornerRadiusMm: 0, leadAngleDeg: 51, tiltAngleDeg: -19 }, 0.0033],
      [{ toolRadiusMm: 1.14, cornerRadiusMm: 0, leadAngleDeg: 7.5, tiltAngleDeg: -12 }, 0.00045],
      [{ toolRadiusMm: 3, cornerRadiusMm: 1e-6, leadAngleDeg: 20, tiltAngleDeg: 5 }, 0.001],
    ] as const) {
      for (const pattern of ['one-way', 'zigzag'] as const) {
        const { sim, exactCusps } = compare(tool, pattern, h);
        const label = JSON.stringify({ tool, pattern, h });
        expect(sim.cuspHeightsMm.length, label).toBeGreaterThanOrEqual(3);
        // The bound is meaningful: well below the scallop itself.
        expect(sim.resolutionBoundMm, label).toBeLessThan(h / 100);
        sim.cuspHeightsMm.forEach((c, i) => {
          expect(Math.abs(c - (exactCusps[i] as number)), `cusp ${i} ${label}`).toBeLessThanOrEqual(
            sim.resolutionBoundMm,
          );
        });
      }
    }
  });

  it('runs in steps with a growing progress, and reports its size', () => {
    const run = startSimulation({
      tool: { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 },
      pattern: 'one-way',
      intervalMm: 2.887,
    });
    const progress: number[] = [run.progress];
    while (!run.step()) progress.push(run.progress);
    progress.push(run.progress);
    for (let i = 1; i < progress.length; i++) expect(progress[i]).toBeGreaterThanOrEqual(progress[i - 1] as number);
    expect(progress[progress.length - 1]).toBe(1);
    const res = run.result();
    expect(res.cells).toBe(512 * 512);
    expect(res.placements).toBe(5 * 512);
    expect(res.heightsMm).toHaveLength(512 * 512);
    expect(res.cuspHeightsMm).toHaveLength(4);
  });
});
