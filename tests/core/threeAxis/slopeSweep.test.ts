import { describe, expect, it } from 'vitest';
import { slopedPlaneForward, slopedPlaneInverse } from '../../../src/core/threeAxis/slopedPlane';
import {
  flatFloorStepMm,
  largestValidSlopeDeg,
  rasterWaterlineCrossingDeg,
  type SlopeSweepInput,
  slopeSweep as solveSweep,
} from '../../../src/core/threeAxis/slopeSweep';
import { waterlineForward } from '../../../src/core/threeAxis/waterlineRevolution';
import { seededRandom } from '../../support/bruteForce';
import { bruteGougeDepthMm, brutePair, bruteRasterCusp } from '../../support/reference/threeAxisBruteForce';

/** The sweep of valid input (a test of the points, not of the input errors: see 'no valid slope'). */
function slopeSweep(input: SlopeSweepInput) {
  const r = solveSweep(input);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.value;
}

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

describe('no valid slope is an input error, as the single question is (issue 26 point 2)', () => {
  const bull = { toolRadiusMm: 3, cornerRadiusMm: 1, hMm: 0.01, passes: 'waterline', rasterAngleDeg: 90 } as const;

  it('a surface that gouges at every slope: the gouging error, as --slope gives at each slope (and the brute force sees the tool in the material)', () => {
    const input = { ...bull, feedRadiusMm: -0.5, crossRadiusMm: -0.5 };
    const r = solveSweep(input);
    expect(r.ok).toBe(false);
    if (r.ok) return;
    expect(r.errors).toHaveLength(1);
    expect(r.errors[0]).toMatchObject({ code: 'gouging' });
    expect(r.errors[0]?.message).toContain('at every slope');
    for (let a = 3; a <= 90; a += 3) {
      const c = { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: a, feedRadiusMm: -0.5, crossRadiusMm: -0.5 };
      const single = waterlineForward(c, 0.01);
      expect(!single.ok && single.errors[0]?.code, `slope ${a}`).toBe('gouging');
      if (a % 30 === 0) {
        const tip = brutePair({ R: 3, Rcr: 1 }, c, 0).tip0;
        expect(bruteGougeDepthMm({ R: 3, Rcr: 1 }, c, tip, 100, 180)).toBeGreaterThan(0.1);
      }
    }
  });

  it('a concave meridian tighter than the tool: the radius named lets it fit at some slope, a hair less does not; at least R (the tool inscribed at 90 degrees); the brute force finds the answered pair clear', () => {
    // Rcr above R / 2: at 90 degrees on |Rc| near R the corner, not the shank, forms the cusp.
    const big = { ...bull, cornerRadiusMm: 2 };
    const r = solveSweep({ ...big, crossRadiusMm: -2 });
    expect(!r.ok && r.errors[0]).toMatchObject({ field: 'crossRadius', code: 'gouging', got: -2 });
    const limit = !r.ok ? (r.errors[0]?.limit as number) : Number.NaN;
    expect(!r.ok && r.errors[0]?.message).toMatch(
      /at every slope \(got -2\): a concave meridian must have a radius of at least [\d.]+ mm/,
    );
    // The upper pass alone needs |Rc| >= R (closed form: at 90 degrees both corners touch the circle
    // of radius R); the brute force sees it gouge just inside that.
    expect(limit).toBeLessThanOrEqual(-3);
    const inside = { slopeDeg: 90, feedRadiusMm: null, crossRadiusMm: -3 * (1 - 1e-3) };
    expect(
      bruteGougeDepthMm({ R: 3, Rcr: 2 }, inside, brutePair({ R: 3, Rcr: 2 }, inside, 0).tip0, 200, 360),
    ).toBeGreaterThan(1e-4);
    const tighter = solveSweep({ ...big, crossRadiusMm: limit * (1 - 1e-6) });
    expect(!tighter.ok && tighter.errors[0]?.code).toBe('gouging');
    const fits = solveSweep({ ...big, crossRadiusMm: limit * (1 + 1e-6) });
    if (!fits.ok) throw new Error(JSON.stringify(fits.errors));
    const top = fits.value.points.at(-1);
    if (!top || top.intervalMm === null) throw new Error('the largest slope is not answered');
    const c = { slopeDeg: top.slopeDeg, feedRadiusMm: null, crossRadiusMm: limit * (1 + 1e-6) };
    const pair = brutePair({ R: 3, Rcr: 2 }, c, top.intervalMm);
    for (const tip of [pair.tip0, pair.tip1])
      expect(bruteGougeDepthMm({ R: 3, Rcr: 2 }, c, tip, 200, 360)).toBeLessThan(1e-6);
    // With Rcr = 1 (below |Rc| / 2) the shank forms the cusp at 90 degrees, where the tool fits
    // first: h's error, not gouging.
    const small = solveSweep({ ...bull, crossRadiusMm: -3 * (1 + 1e-6) });
    expect(!small.ok && small.errors[0]).toMatchObject({ field: 'h', code: 'shank-cuts' });
    expect(!small.ok && small.errors[0]?.message).toMatch(/^Scallop height h cannot be answered at any slope/);
  });

  it('h above the limit at every slope: the h error with the largest limit, below which the sweep answers', () => {
    const r = solveSweep({ ...bull, passes: 'raster', rasterAngleDeg: 0, hMm: 5 });
    expect(!r.ok && r.errors[0]).toMatchObject({ field: 'h', code: 'flank-wall', got: 5 });
    const limit = !r.ok ? (r.errors[0]?.limit as number) : Number.NaN;
    expect(limit).toBeLessThan(3);
    expect(solveSweep({ ...bull, passes: 'raster', rasterAngleDeg: 0, hMm: limit * (1 - 1e-9) }).ok).toBe(true);
    const flat = solveSweep({ ...bull, cornerRadiusMm: 0 });
    expect(!flat.ok && flat.errors[0]).toMatchObject({ field: 'h', code: 'wall-only' });
  });

  it('the header never claims what the rows contradict: a sweep answers at its largest slope, a refused one at none of its slopes (seed 41)', () => {
    const rand = seededRandom(41);
    let refused = 0;
    let answered = 0;
    for (let i = 0; i < 60; i++) {
      const R = 0.5 + 5 * rand();
      const Rcr = R * (0.1 + 0.9 * rand());
      const radius = () => (rand() < 0.25 ? null : (rand() < 0.5 ? 1 : -1) * R * 10 ** (-1 + 2.5 * rand()));
      const input = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        hMm: Rcr * 10 ** (-4 + 3 * rand()),
        passes: 'waterline',
        rasterAngleDeg: 90,
        feedRadiusMm: radius(),
        crossRadiusMm: radius(),
      } as const;
      if (input.feedRadiusMm === null && input.crossRadiusMm === null) continue;
      const r = solveSweep({ ...input, count: 31 });
      const single = (a: number) =>
        waterlineForward(
          {
            toolRadiusMm: R,
            cornerRadiusMm: Rcr,
            slopeDeg: a,
            feedRadiusMm: input.feedRadiusMm,
            crossRadiusMm: input.crossRadiusMm,
          },
          input.hMm,
        );
      if (!r.ok) {
        refused += 1;
        for (let a = 0.5; a < 90; a += 3.5) expect(single(a).ok, JSON.stringify([input, a])).toBe(false);
        continue;
      }
      answered += 1;
      const last = r.value.points[30];
      expect(last?.stepMm, JSON.stringify(input)).not.toBeNull();
      expect(single(last?.slopeDeg as number).ok).toBe(true);
      for (const p of r.value.points) if (p.slopeDeg > 0) expect(p.stepMm !== null).toBe(single(p.slopeDeg).ok);
    }
    expect(refused).toBeGreaterThan(5);
    expect(answered).toBeGreaterThan(20);
  });
});
