/**
 * Issue 17, item 8 (cylinders without lead but with tilt) and the wall of a convex cylinder along
 * the feed. Every step-over is checked to 1e-9 mm against the polished brute force of
 * tests/support/reference/cylinderReach.ts (the real tool, with its shank, from its 3D surface), and
 * every limit against where that brute force's flank stops growing or the shank starts to shape it
 * (tests/support/cylinderChecks.ts).
 */
import { describe, expect, it } from 'vitest';
import { exactForward, forwardInput, validateForward } from '../../../src/core/index';
import { type CylinderSurface, concaveFit, cylinderSolver } from '../../../src/core/surfaces/cylinder';
import { seededRandom } from '../../support/bruteForce';
import { bruteForceCylinder } from '../../support/cylinderBruteForce';
import { checkCase, cyl, referenceIntervalMm, TOL_MM, tool } from '../../support/cylinderChecks';
import { cylinderReach } from '../../support/reference/cylinderReach';

describe('item 8: cylinders without lead but with tilt (rho = 0, beta != 0)', () => {
  it('the issue case is answered: L against the brute force of the real tool, and the plane nearby', () => {
    const t = tool(3.0451679189546605, 0.47573926862380683, 0, 5.533590864870234);
    const h = 0.02562197304282377;
    const v = validateForward({
      R: t.toolRadiusMm,
      Rcr: t.cornerRadiusMm,
      rho: 0,
      tilt: t.tiltAngleDeg,
      h,
      surfaceRadius: 799.0321707634058,
    });
    expect(v.ok).toBe(true);
    if (!v.ok) return;
    const s = v.value.surface as CylinderSurface;
    const ref = cylinderReach(t, s.radiusMm, s.axis);
    const L = exactForward(v.value).intervalMm;
    expect(Math.abs(L - referenceIntervalMm(ref, s, 'one-way', h))).toBeLessThan(TOL_MM);
    // Rs = 799 mm: within a few micrometres of the plane's 0.4415 mm (issue 17).
    expect(Math.abs(L - exactForward(forwardInput(t, 'one-way', h)).intervalMm)).toBeLessThan(1e-3);
    // The corner circle on the right flank and the circle, then the flat bottom's edge, on the left:
    // the sampled sweep of the real tool (its shank too) leaves cusps of h.
    const b = bruteForceCylinder(t, 'one-way', s.radiusMm, 'feed', L, {
      spacingMm: 0.003,
      bins: 3000,
      shankLengthMm: 1,
    });
    for (const c of b.cuspHeightsMm) expect(Math.abs(c - h)).toBeLessThanOrEqual(b.boundMm);
    expect(b.boundMm).toBeLessThan(0.2 * h);
    checkCase(t, s, 'issue 17 item 8');
  });

  const strata: Array<[string, number, 'feed' | 'cross', 1 | -1]> = [
    ['axis along the feed, convex', 801, 'feed', 1],
    ['axis along the feed, concave', 802, 'feed', -1],
    ['axis across the feed, convex', 803, 'cross', 1],
    ['axis across the feed, concave', 804, 'cross', -1],
  ];
  for (const [name, seed, axis, side] of strata) {
    it(`${name}: random tools and tilts against the brute force (seed ${seed}, 4 cases)`, () => {
      const rand = seededRandom(seed);
      const seenBy = new Set<string>();
      for (let k = 0; k < 4; k++) {
        const R = 0.5 * 20 ** rand();
        // Corner from a sliver to a ball end; tilt either way, 0.5 to 60 degrees.
        const Rcr = R * (k === 0 ? 1 : 0.02 + 0.98 * rand());
        const tilt = (rand() < 0.5 ? -1 : 1) * (0.5 + 59.5 * rand());
        const t = tool(R, Rcr, 0, tilt);
        const fit = concaveFit(t, axis);
        let rs = R * (2 + 150 * rand());
        if (side < 0) {
          // A trough the tool fits (with the shank, when it fits any).
          if (!Number.isFinite(fit.minRadiusMm)) continue;
          rs = -Math.max(rs, 1.05 * fit.minRadiusMm);
        }
        seenBy.add(checkCase(t, cyl(rs, axis), JSON.stringify({ t, rs, axis })).limitBy);
      }
      expect(seenBy.size).toBeGreaterThan(0);
    });
  }

  it('a lead of 1e-320 to 1e-6 degrees: the limits of no lead (no jump), L against the brute force', () => {
    // With b / a below about 1e-9 the section parametrisation's normal is ill-conditioned (the old
    // code refused h there, or cut the shank's height by 1e-4 relative): the limits come from the
    // normal angle (and below b = 1e-14 a from the segment), continuous down to rho = 0.
    for (const [rs, axis] of [
      [40, 'feed'],
      [-60, 'feed'],
      [40, 'cross'],
    ] as const) {
      const s = cyl(rs, axis);
      const at0 = cylinderSolver(tool(3, 0.8, 0, 12), s).limits();
      for (const rho of [1e-320, 1e-200, 1e-14, 1e-12, 1e-9, 1e-6]) {
        const l = cylinderSolver(tool(3, 0.8, rho, 12), s).limits();
        expect(l.limitBy, `${rho} ${axis} ${rs}`).toBe(at0.limitBy);
        expect(Math.abs(l.limitMm - at0.limitMm), `${rho} ${axis} ${rs}`).toBeLessThan(1e-9);
      }
      checkCase(tool(3, 0.8, 1e-10, 12), s, `rho 1e-10 ${axis} ${rs}`);
    }
  });

  it('a tilted flat end (Rcr = 0) without lead is wall-only on a cylinder as on the plane', () => {
    for (const axis of ['feed', 'cross'] as const) {
      const v = validateForward({ R: 3, Rcr: 0, rho: 0, tilt: 10, h: 0.01, surfaceRadius: 50, surfaceAxis: axis });
      expect(!v.ok && v.errors[0]?.code).toBe('wall-only');
    }
    expect(validateForward({ R: 3, Rcr: 0, rho: 0, tilt: 10, h: 0.01 }).ok).toBe(false);
  });

  it('no lead, no tilt (a flat bottom on the surface) and ball ends: against the brute force', () => {
    checkCase(tool(3, 1, 0, 0), cyl(40, 'feed'), 'flat bottom, feed');
    checkCase(tool(3, 1, 0, 0), cyl(40, 'cross'), 'flat bottom, cross');
    checkCase(tool(2, 2, 0, 25), cyl(15, 'feed'), 'ball end, feed');
    checkCase(tool(2, 2, 30, -25), cyl(-15, 'feed'), 'ball end, concave feed');
  });
});

describe('a trough along the feed whose flank dips (nearly flat bottom, a little tilt)', () => {
  it('the flanks hold below the dip, and the limit does not jump between no lead and a tiny one', () => {
    // R 3, Rcr 0.8, tilt 3, Rs -60: away from the tilt the flank runs along the flat bottom's edge,
    // whose foot nearest the axis lies on it: the radial height rises to 0.081 mm there, falls to
    // 0.067 mm at the edge's end, then rises again. Above 0.067 mm a lower point past the first
    // crossing reaches farther (the old limit, the peak, let h = 0.07 mm through with L 2.5 mm short).
    const limits = [0, 1e-9, 0.05, 0.2].map((rho) => {
      const t = tool(3, 0.8, rho, 3);
      const s = cyl(-60, 'feed');
      checkCase(t, s, `rho ${rho}`);
      return cylinderSolver(t, s).limits();
    });
    for (const l of limits) {
      expect(l.limitBy).toBe('left-flank');
      expect(Math.abs(l.limitMm - 0.0668024)).toBeLessThan(1e-5);
    }
    const v = validateForward({ R: 3, Rcr: 0.8, rho: 0.05, tilt: 3, h: 0.07, surfaceRadius: -60 });
    expect(!v.ok && v.errors[0]?.code).toBe('flank-wall');
  });
});

describe('a scallop of a nanometre beside a large corner, along the feed', () => {
  it('ball ends (two circles, closed form): the crossing keeps its digits (the old form lost up to 1.5e-8 mm)', () => {
    for (const [R, rs, rho, tilt] of [
      [115.5, 3512, 0.001, -89],
      [500, -2000, 10, 30],
      [1000, 1e6, 0, 0],
      [1000, -1e6, 45, 10],
    ] as const) {
      const h = 1e-9;
      // Half the angle between the passes at radius |Rs| +- h, the ball's centre at |Rs| +- R from the
      // axis: sin^2(x / 2) = (R^2 - (d - r)^2) / (4 d r), R^2 - (d - r)^2 = h (2 R - h) exactly.
      const d = rs > 0 ? rs + R : -rs - R;
      const r = rs > 0 ? rs + h : -rs - h;
      const expected = 2 * Math.abs(rs) * 2 * Math.asin(Math.sqrt((h * (2 * R - h)) / (4 * d * r)));
      const got = exactForward(forwardInput(tool(R, R, rho, tilt), 'one-way', h, cyl(rs, 'feed'))).intervalMm;
      expect(Math.abs(got - expected) / expected, `R ${R} Rs ${rs}`).toBeLessThan(1e-12);
    }
  });
});

describe('the wall of a convex cylinder along the feed', () => {
  it("is where the flank's polar angle peaks (its tangent through the axis), below the plane's widest point", () => {
    // R 3, Rcr 1, rho 5, no tilt, Rs 10: the plane's widest point is 1.5700 mm up, but the flank's
    // polar angle peaks at 1.3036 mm; between them a pass reaches no farther (the old limit let
    // h = 1.4 through with an L 5e-3 mm short).
    const t = tool(3, 1, 5, 0);
    const s = cyl(10, 'feed');
    const { limitBy } = checkCase(t, s, 'R3 Rcr1 rho5 Rs10');
    expect(limitBy).toBe('right-flank');
    const limit = cylinderSolver(t, s).limits().limitMm;
    expect(limit).toBeCloseTo(1.30357, 5);
    const v = validateForward({ R: 3, Rcr: 1, rho: 5, h: 1.4, surfaceRadius: 10 });
    expect(!v.ok && v.errors[0]?.code).toBe('flank-wall');
    expect(!v.ok && v.errors[0]?.message).toMatch(/below 1\.30357/);
  });

  it('random postures (seed 811, 4 cases): L to the limit and the limit against the brute force', () => {
    const rand = seededRandom(811);
    for (let k = 0; k < 4; k++) {
      const R = 0.5 * 20 ** rand();
      const t = tool(R, R * (0.05 + 0.95 * rand()), 60 * rand(), 70 * rand() - 35);
      checkCase(t, cyl(R * (1.5 + 40 * rand()), 'feed'), JSON.stringify(t));
    }
  });
});
