import { describe, expect, it } from 'vitest';
import { forwardInput, inverseInput, type PassPattern, type ToolInput } from '../../../src/core/input/validate';
import { compareForward } from '../../../src/core/procedures/compare';
import { type CylinderSurface, minConcaveRadiusMm } from '../../../src/core/surfaces/cylinder';
import { exactForward, exactInverse } from '../../../src/core/surfaces/solve';
import { scallopHeightLimits, validateForward } from '../../../src/core/surfaces/validate';
import { seededRandom } from '../../support/bruteForce';
import { bruteForceCylinder } from '../../support/cylinderBruteForce';

const tool = (R: number, Rcr: number, rho: number, tilt: number): ToolInput => ({
  toolRadiusMm: R,
  cornerRadiusMm: Rcr,
  leadAngleDeg: rho,
  tiltAngleDeg: tilt,
});
const cyl = (radiusMm: number, axis: 'feed' | 'cross'): CylinderSurface => ({ kind: 'cylinder', radiusMm, axis });
const L = (t: ToolInput, pattern: PassPattern, h: number, surface?: CylinderSurface) =>
  exactForward(forwardInput(t, pattern, h, surface)).intervalMm;

describe('exact step-over on cylinders', () => {
  it('approaches the plane as |Rs| grows, on both axes and both sides (error falling like 1 / |Rs|)', () => {
    const t = tool(3, 1, 5, 8);
    const plane = L(t, 'one-way', 0.05);
    for (const axis of ['feed', 'cross'] as const) {
      for (const sign of [1, -1]) {
        const errors = [1e2, 1e4, 1e6].map((r) => Math.abs(L(t, 'one-way', 0.05, cyl(sign * r, axis)) - plane));
        expect(errors[1]).toBeLessThan((errors[0] as number) / 50);
        expect(errors[2]).toBeLessThan((errors[1] as number) / 50 + 1e-12);
        expect(errors[2]).toBeLessThan(1e-4);
      }
    }
  });

  it('tiny h on a nearly flat cylinder gives the plane flanks (checked against the 40-digit reference there)', () => {
    for (const t of [tool(3, 1, 5, 8), tool(10, 0.01, 30, -20), tool(1, 0, 45, 0)]) {
      for (const h of [1e-9, 1e-6]) {
        const plane = exactForward(forwardInput(t, 'one-way', h));
        for (const axis of ['feed', 'cross'] as const) {
          const c = exactForward(forwardInput(t, 'one-way', h, cyl(1e6, axis)));
          // The curvature changes the widths by about w Reff / Rs: far below 1e-9 relative here.
          expect(Math.abs(c.halfWidthRightMm / plane.halfWidthRightMm - 1), `${axis} h ${h}`).toBeLessThan(1e-5);
          expect(Math.abs(c.halfWidthLeftMm / plane.halfWidthLeftMm - 1), `${axis} h ${h}`).toBeLessThan(1e-5);
        }
      }
    }
  });

  it('a ball end with the axis along the feed: two circles (closed form), convex and concave', () => {
    for (const [R, rs, h, rho, tilt] of [
      [3, 20, 0.05, 10, 20],
      [3, -20, 0.05, 0, 0],
      [1, 5, 0.2, 45, -30],
      [2, -3, 0.01, 5, 5],
    ] as const) {
      // Ball centre at distance d = |Rs + R| (convex) or |Rs| - R (concave) from the axis; the cusp
      // at radius r = |Rs| +- h; the half angle between passes by the law of cosines.
      const d = rs > 0 ? rs + R : -rs - R;
      const r = rs > 0 ? rs + h : -rs - h;
      const half = Math.acos((d * d + r * r - R * R) / (2 * d * r));
      const expected = 2 * Math.abs(rs) * half;
      const got = L(tool(R, R, rho, tilt), 'one-way', h, cyl(rs, 'feed'));
      expect(Math.abs(got - expected), `R ${R} Rs ${rs} h ${h}`).toBeLessThan(1e-9);
    }
  });

  it('a flat bottom without lead on a convex cylinder across the axis: the plane profile, L = 2 (Rb + sqrt(2 Rcr h - h^2))', () => {
    // It touches along a generator (x = 0): each chord of the bottom disk is nearest the axis at
    // its middle, so the revolved meridian is the plane's cross-feed profile for any Rs > 0.
    for (const [R, Rcr, h, rs] of [
      [3, 1, 0.05, 10],
      [5, 0.5, 0.2, 2],
    ] as const) {
      const expected = 2 * (R - Rcr + Math.sqrt(2 * Rcr * h - h * h));
      expect(Math.abs(L(tool(R, Rcr, 0, 0), 'one-way', h, cyl(rs, 'cross')) - expected)).toBeLessThan(1e-9);
      // Passes closer than the flat face is wide leave no scallop at all.
      for (const pattern of ['one-way', 'zigzag'] as const)
        expect(
          exactInverse(inverseInput(tool(R, Rcr, 0, 0), pattern, R - Rcr, cyl(rs, 'cross'))).cuspHeightMm,
        ).toBeLessThan(1e-12);
    }
  });

  it('a ball end across the axis leaves the plane answer (a revolved ball is the same circle)', () => {
    const plane = L(tool(3, 3, 20, 10), 'one-way', 0.05);
    for (const rs of [5, 20, -20])
      expect(Math.abs(L(tool(3, 3, 20, 10), 'one-way', 0.05, cyl(rs, 'cross')) - plane)).toBeLessThan(1e-12);
  });

  for (const seed of [61, 62]) {
    it(`seed ${seed}: for the same h convex gives less than the plane and concave more; tilt is mirror-symmetric`, () => {
      const rand = seededRandom(seed);
      let checked = 0;
      for (let k = 0; k < 12; k++) {
        const R = 1 + 8 * rand();
        const t = tool(R, R * (0.1 + 0.9 * rand()), 3 + 40 * rand(), 40 * rand() - 20);
        const axis = rand() < 0.5 ? 'feed' : 'cross';
        const radius = R * (10 + 100 * rand());
        const h = 0.2 * scallopHeightLimits(t).limitMm * rand() + 1e-4;
        if (!(radius >= minConcaveRadiusMm(t, axis))) continue;
        const plane = L(t, 'one-way', h);
        expect(L(t, 'one-way', h, cyl(radius, axis))).toBeLessThan(plane);
        expect(L(t, 'one-way', h, cyl(-radius, axis))).toBeGreaterThan(plane);
        const a = exactForward(forwardInput(t, 'one-way', h, cyl(radius, axis)));
        const b = exactForward(forwardInput({ ...t, tiltAngleDeg: -t.tiltAngleDeg }, 'one-way', h, cyl(radius, axis)));
        expect(Math.abs(a.halfWidthRightMm - b.halfWidthLeftMm)).toBeLessThan(1e-9);
        expect(Math.abs(a.halfWidthLeftMm - b.halfWidthRightMm)).toBeLessThan(1e-9);
        checked++;
      }
      expect(checked).toBeGreaterThanOrEqual(8);
    });
  }

  it('the inverse returns h (one-way and zigzag, both axes, both sides)', () => {
    const t = tool(3, 1, 5, 8);
    for (const axis of ['feed', 'cross'] as const)
      for (const rs of [15, -60])
        for (const pattern of ['one-way', 'zigzag'] as const) {
          const f = exactForward(forwardInput(t, pattern, 0.05, cyl(rs, axis)));
          const back = exactInverse(inverseInput(t, pattern, f.intervalMm, cyl(rs, axis)));
          expect(Math.abs(back.cuspHeightMm - 0.05), `${axis} ${rs} ${pattern}`).toBeLessThan(1e-9);
          if (pattern === 'zigzag')
            expect(Math.abs((back.otherCuspHeightMm ?? 0) - (f.otherCuspHeightMm ?? -1))).toBeLessThan(1e-9);
        }
  });

  it('gouging: a concave cylinder tighter than the tool is an input error that names the smallest radius', () => {
    const t = tool(3, 1, 5, 0);
    const min = minConcaveRadiusMm(t, 'feed');
    // Without tilt the profile's curvature radius at the contact is Redonnet's Rb / sin(rho) + Rcr.
    expect(min).toBeCloseTo(2 / Math.sin((5 * Math.PI) / 180) + 1, 6);
    const tight = validateForward({ R: 3, Rcr: 1, rho: 5, h: 0.05, surfaceRadius: -0.9 * min, surfaceAxis: 'feed' });
    expect(tight.ok).toBe(false);
    if (!tight.ok) {
      expect(tight.errors[0]?.code).toBe('gouging');
      expect(tight.errors[0]?.message).toMatch(/at least 23\.947/);
    }
    expect(validateForward({ R: 3, Rcr: 1, rho: 5, h: 0.05, surfaceRadius: -1.01 * min, surfaceAxis: 'feed' }).ok).toBe(
      true,
    );
    // A flat bottom without lead, seen along the axis across the feed, gouges any concave cylinder.
    const flat = validateForward({ R: 3, Rcr: 1, rho: 0, h: 0.05, surfaceRadius: -1e5, surfaceAxis: 'cross' });
    expect(!flat.ok && flat.errors[0]?.message).toMatch(/any radius/);
    // A convex cylinder never gouges.
    expect(validateForward({ R: 3, Rcr: 1, rho: 0, h: 0.05, surfaceRadius: 0.5, surfaceAxis: 'cross' }).ok).toBe(true);
  });

  it('comparison rows: the plane answer and the usual curvature correction, each against exact', () => {
    const c = compareForward(forwardInput(tool(3, 1, 5, 0), 'one-way', 0.05, cyl(20, 'feed')));
    expect(c.curvature).not.toBeNull();
    const plane = c.curvature?.plane;
    expect(plane?.ok && plane.intervalMm).toBeCloseTo(L(tool(3, 1, 5, 0), 'one-way', 0.05), 12);
    const red = c.curvature?.corrected.redonnet;
    // Redonnet's Reff = 23.95 combined with Rs = 20: 1 / rho = 1 / 23.95 + 1 / 20.
    const rho = 1 / (1 / (2 / Math.sin((5 * Math.PI) / 180) + 1) + 1 / 20);
    expect(red?.ok && red.combinedRadiusMm).toBeCloseTo(rho, 10);
    expect(red?.ok && red.intervalMm).toBeCloseTo(2 * Math.sqrt(2 * rho * 0.05 - 0.0025), 12);
    expect(compareForward(forwardInput(tool(3, 1, 5, 0), 'one-way', 0.05)).curvature).toBeNull();
  });
});

describe('cylinders against brute-force sampling of the tool swept along or around the axis', () => {
  for (const seed of [71, 72]) {
    it(`seed ${seed}: 4 random cases agree within the sampler's stated bound`, () => {
      const rand = seededRandom(seed);
      for (let k = 0; k < 4; k++) {
        const R = 1 + 4 * rand();
        const t = tool(R, R * (0.2 + 0.8 * rand()), 2 + 30 * rand(), 30 * rand() - 15);
        const axis = rand() < 0.5 ? 'feed' : 'cross';
        const pattern: PassPattern = rand() < 0.5 ? 'one-way' : 'zigzag';
        const min = minConcaveRadiusMm(t, axis);
        const radius = rand() < 0.5 ? R * (3 + 20 * rand()) : -Math.max(1.2 * min, R * (3 + 20 * rand()));
        const h = 0.02 * R * (0.2 + rand());
        const v = validateForward({
          R,
          Rcr: t.cornerRadiusMm,
          rho: t.leadAngleDeg,
          tilt: t.tiltAngleDeg,
          pattern,
          h,
          surfaceRadius: radius,
          surfaceAxis: axis,
        });
        if (!v.ok) throw new Error(`invalid case: ${v.errors[0]?.message}`);
        const e = exactForward(v.value);
        // The real tool: its shank too (valid heights lie below where it would shape the flanks).
        const b = bruteForceCylinder(t, pattern, radius, axis, e.intervalMm, {
          spacingMm: R / 1000,
          bins: 3000,
          shankLengthMm: R / 2,
        });
        const other = e.otherCuspHeightMm ?? h;
        const rightNarrow = e.halfWidthRightMm <= e.halfWidthLeftMm;
        b.cuspHeightsMm.forEach((c, i) => {
          const expected = pattern === 'one-way' ? h : (i % 2 === 0) === rightNarrow ? h : other;
          expect(
            Math.abs(c - expected),
            `cusp ${i} ${JSON.stringify({ t, pattern, radius, axis, h })}`,
          ).toBeLessThanOrEqual(b.boundMm);
        });
        // The bound is a useful one: a fraction of the scallop (the sampler's errors are far smaller).
        expect(b.boundMm).toBeLessThan(0.3 * h);
      }
    });
  }

  it('the bound and the error shrink as the sampling is refined', () => {
    const t = tool(3, 1, 5, 8);
    const e = exactForward(forwardInput(t, 'one-way', 0.05, cyl(20, 'feed')));
    const coarse = bruteForceCylinder(t, 'one-way', 20, 'feed', e.intervalMm, { spacingMm: 0.02, bins: 300 });
    const fine = bruteForceCylinder(t, 'one-way', 20, 'feed', e.intervalMm, { spacingMm: 0.005, bins: 1200 });
    const err = (b: typeof fine) => Math.max(...b.cuspHeightsMm.map((c) => Math.abs(c - 0.05)));
    expect(fine.boundMm).toBeLessThan(coarse.boundMm / 2);
    expect(err(fine)).toBeLessThan(err(coarse));
    expect(err(fine)).toBeLessThanOrEqual(fine.boundMm);
    expect(err(coarse)).toBeLessThanOrEqual(coarse.boundMm);
  });
});
