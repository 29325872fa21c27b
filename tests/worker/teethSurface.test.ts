/**
 * The surface the Machined surface view draws for the teeth (src/worker/teethSurface.ts, sent with
 * the finish job's areal answer): a whole number of period cells, at most 240 points a side, each
 * sample the core's envelope height envelopeHeightMm at its grid point (x = (i + 1/2) dx along the
 * feed, y = (j + 1/2) dy across), and its colour range the finish's exact lowest point and Sz.
 */
import { describe, expect, it } from 'vitest';
import { arealParameters, envelopeHeightMm, toothModel } from '../../src/core/finish/index';
import { seededRandom } from '../../src/core/math/seededRandom';
import { TEETH_SURFACE_MAX_POINTS, teethSurface, teethSurfaceGrid } from '../../src/worker/teethSurface';

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };

const CASES = [
  { name: 'one-way, 4 teeth, fz 0.1', pattern: 'one-way', L: 0.9, flutes: 4, fz: 0.1, runout: 0 },
  { name: 'zigzag, 2 teeth, fz 0.05, tilt 3', pattern: 'zigzag', L: 0.6, flutes: 2, fz: 0.05, runout: 0, tilt: 3 },
  { name: 'one-way, 3 teeth, fz 0.3, lead 15', pattern: 'one-way', L: 1.2, flutes: 3, fz: 0.3, runout: 0, lead: 15 },
] as const;

describe('the teeth surface drawn in 3D', () => {
  for (const c of CASES)
    it(`${c.name}: whole cells, <= 240 points a side, envelopeHeightMm at 300 random grid points (seed 29)`, () => {
      const m = toothModel({
        tool: { ...TOOL, tiltAngleDeg: 'tilt' in c ? c.tilt : 0, leadAngleDeg: 'lead' in c ? c.lead : 5 },
        pattern: c.pattern,
        intervalMm: c.L,
        finish: { flutes: c.flutes, feedPerToothMm: c.fz, runoutMm: c.runout, runoutPhaseDeg: 0, passPhase: 0 },
      });
      const a = arealParameters(m);
      const s = teethSurface(m, a);
      // A whole number of cells, a whole number of points in each.
      expect(Number.isInteger(s.feedPeriods) && s.feedPeriods >= 3).toBe(true);
      expect(s.crossPeriods).toBe(c.pattern === 'zigzag' ? 2 : 3);
      expect(s.cellsAlong % s.feedPeriods).toBe(0);
      expect(s.cellsAcross % s.crossPeriods).toBe(0);
      expect(Math.max(s.cellsAlong, s.cellsAcross)).toBeLessThanOrEqual(TEETH_SURFACE_MAX_POINTS);
      expect(s.heightsMm.length).toBe(s.cellsAlong * s.cellsAcross);
      const dx = s.alongLengthMm / (s.cellsAlong - 1);
      const dy = (s.acrossToMm - s.acrossFromMm) / (s.cellsAcross - 1);
      expect(s.cellsAlong * dx).toBeCloseTo(s.feedPeriods * m.feedPeriodMm, 12);
      expect(s.cellsAcross * dy).toBeCloseTo(s.crossPeriods * m.crossPeriodMm, 12);
      expect(s.acrossFromMm).toBeCloseTo(dy / 2, 14);
      // Each sample is the envelope's height at its grid point (float32: within 1e-9 mm).
      const r = seededRandom(29);
      for (let k = 0; k < 300; k++) {
        const i = Math.floor(r() * s.cellsAlong);
        const j = Math.floor(r() * s.cellsAcross);
        const exact = envelopeHeightMm(m, (i + 0.5) * dx, (j + 0.5) * dy);
        expect(Math.abs((s.heightsMm[i * s.cellsAcross + j] as number) - exact), `${i},${j}`).toBeLessThan(1e-9);
      }
      // The colour range: the exact lowest point and Sz, which the samples stay within.
      expect([s.lowestMm, s.szMm]).toEqual([a.meanMm - a.svMm, a.szMm]);
      const lo = Math.min(...s.heightsMm);
      const hi = Math.max(...s.heightsMm);
      expect(lo).toBeGreaterThanOrEqual(s.lowestMm - 1e-9);
      expect(hi).toBeLessThanOrEqual(s.lowestMm + s.szMm + 1e-9);
      expect(hi - lo).toBeGreaterThan(0.9 * s.szMm);
    });

  it('as long as wide within 3 to 12 feed periods; a tiny feed keeps 12, a huge one 3', () => {
    expect(teethSurfaceGrid(0.1, 0.9, false)).toEqual({
      feedPeriods: 12,
      crossPeriods: 3,
      pointsAlong: 240,
      pointsAcross: 240,
    });
    expect(teethSurfaceGrid(0.5, 1, false).feedPeriods).toBe(6);
    expect(teethSurfaceGrid(0.25, 0.5, true).feedPeriods).toBe(4);
    expect(teethSurfaceGrid(2, 0.1, false).feedPeriods).toBe(3);
    expect(teethSurfaceGrid(0.5, 1, false, 100)).toMatchObject({ pointsAlong: 96, pointsAcross: 99 });
  });
});
