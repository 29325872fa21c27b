import { describe, expect, it } from 'vitest';
import { slopedPlaneForward, slopedPlaneInverse } from '../../../src/core/threeAxis/slopedPlane';
import {
  flatFloorStepMm,
  largestValidSlopeDeg,
  rasterWaterlineCrossingDeg,
  slopeSweep,
} from '../../../src/core/threeAxis/slopeSweep';
import { waterlineForward } from '../../../src/core/threeAxis/waterlineRevolution';
import { bruteRasterCusp } from '../../support/reference/threeAxisBruteForce';

/** The slope sweep: its range, its points against the solvers, a few against the brute force. */
describe('slope sweep', () => {
  const bull = { toolRadiusMm: 3, cornerRadiusMm: 1, hMm: 0.05 } as const;

  it('raster, psi 0: 200 slopes from 0 to just below 90; each point is the solvers answer', () => {
    const s = slopeSweep({ ...bull, passes: 'raster', rasterAngleDeg: 0 });
    expect(s.points).toHaveLength(200);
    expect(s.largestSlopeDeg).toBeGreaterThan(90 - 1e-9);
    expect(s.largestSlopeDeg).toBeLessThan(90);
    expect(s.points[0]?.slopeDeg).toBe(0);
    expect(s.flatFloorStepMm).toBeCloseTo(2 * (2 + Math.sqrt(0.1 - 0.0025)), 14);
    // The flat floor's step leaves h on the floor, more on every slope (the lead narrows the profile).
    expect(s.points[0]?.cuspAtProgrammedStepMm).toBeCloseTo(0.05, 12);
    for (const p of s.points) {
      const c = {
        toolRadiusMm: 3,
        cornerRadiusMm: 1,
        slopeDeg: p.slopeDeg,
        passes: 'raster',
        rasterAngleDeg: 0,
      } as const;
      const f = slopedPlaneForward(c, 0.05);
      expect(f.ok && f.value.horizontalStepMm).toBe(p.stepMm);
      const inv = slopedPlaneInverse(c, { field: 'horizontalStep', mm: s.programmedStepMm });
      expect(inv.ok ? inv.value.cuspHeightMm : null).toBe(p.cuspAtProgrammedStepMm);
    }
    const cusps = s.points.map((p) => p.cuspAtProgrammedStepMm as number);
    for (let i = 1; i < cusps.length; i++) expect(cusps[i]).toBeGreaterThanOrEqual((cusps[i - 1] as number) - 1e-12);
  });

  it('the constant step leaves what the brute force finds (raster psi 30, three slopes)', () => {
    const s = slopeSweep({ ...bull, passes: 'raster', rasterAngleDeg: 30, programmedStepMm: 1.2 });
    for (const i of [40, 120, 199]) {
      const p = s.points[i];
      if (!p || p.cuspAtProgrammedStepMm === null) throw new Error(`point ${i} refused`);
      const L = 1.2 / slopeFactor(p.slopeDeg, 30);
      const b = bruteRasterCusp({ R: 3, Rcr: 1 }, p.slopeDeg, 30, L, 4);
      expect(Math.abs(b.polishedMm - p.cuspAtProgrammedStepMm)).toBeLessThan(1e-9);
    }
  });

  it('waterline on the plane: the largest slope is asin(1 - h/Rcr) (the shank), dz grows from 0', () => {
    const s = slopeSweep({ ...bull, passes: 'waterline', rasterAngleDeg: 0 });
    expect(Math.abs(s.largestSlopeDeg - (Math.asin(1 - 0.05) * 180) / Math.PI)).toBeLessThan(1e-9);
    expect(s.points[0]).toMatchObject({ slopeDeg: 0, stepMm: 0, cuspAtProgrammedStepMm: null });
    const steps = s.points.map((p) => p.stepMm as number);
    for (let i = 1; i < steps.length; i++) expect(steps[i]).toBeGreaterThan(steps[i - 1] as number);
    // Every point below the largest slope is answered.
    expect(s.points.every((p) => p.stepMm !== null)).toBe(true);
    // The flat floor's step typed as dz is beyond the widest step at every slope for this bull-nose.
    expect(s.points.slice(1).every((p) => p.cuspAtProgrammedStepMm === null)).toBe(true);
  });

  it('waterline on a sphere: points are the revolution solver; a bowl starts above 0 degrees', () => {
    const dome = slopeSweep({
      ...bull,
      passes: 'waterline',
      rasterAngleDeg: 0,
      feedRadiusMm: 30,
      crossRadiusMm: 30,
      count: 40,
    });
    for (const p of dome.points.slice(1)) {
      const f = waterlineForward(
        { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: p.slopeDeg, feedRadiusMm: 30, crossRadiusMm: 30 },
        0.05,
      );
      expect(f.ok ? f.value.stepDownMm : null).toBe(p.stepMm);
    }
    const bowl = slopeSweep({
      ...bull,
      passes: 'waterline',
      rasterAngleDeg: 0,
      feedRadiusMm: -30,
      crossRadiusMm: -30,
      count: 40,
    });
    expect(bowl.largestSlopeDeg).toBeGreaterThan(60);
    expect(bowl.points[1]?.stepMm).toBeNull();
    expect(bowl.points[39]?.stepMm).not.toBeNull();
  });

  it('largest slope, flat floor step and the raster/waterline crossing', () => {
    expect(flatFloorStepMm(3, 0, 0.1)).toBe(6);
    expect(flatFloorStepMm(3, 3, 0.05)).toBeCloseTo(2 * Math.sqrt(0.3 - 0.0025), 14);
    // A flat end in waterline: no valid slope.
    expect(
      largestValidSlopeDeg({ toolRadiusMm: 3, cornerRadiusMm: 0, hMm: 0.01, passes: 'waterline', rasterAngleDeg: 0 }),
    ).toBe(0);
    // Raster across the slope (psi 90) and waterline are the same passes: Lxy = L cos a, dz = L sin a.
    expect(rasterWaterlineCrossingDeg(3, 1, 0.05, 90)).toBeCloseTo(45, 9);
    // Along the fall line a bull-nose's Lxy stays above the waterline dz on the plane: no crossing.
    expect(rasterWaterlineCrossingDeg(3, 1, 0.05, 0)).toBeNull();
  });
});

function slopeFactor(slopeDeg: number, psiDeg: number): number {
  const a = (slopeDeg * Math.PI) / 180;
  const p = (psiDeg * Math.PI) / 180;
  return Math.sqrt(Math.cos(p) ** 2 + Math.cos(a) ** 2 * Math.sin(p) ** 2);
}
