/**
 * The teaching views' data for three-axis machining (issue 20: the chart "step against slope") and
 * a doubly curved point (issue 19: L against each radius, the profile on the curved section),
 * checked against the core directly: the sweep's steps equal slopedPlaneForward at sampled slopes,
 * the crossing is where raster's Lxy equals waterline's dz, each L equals doublyCurvedForward, the
 * gaps are where the core refuses (gouging, flank limit), the section's profile is the flanks' reach.
 * Their time is a bench figure (`npm run bench`, src/bench/teachPage.ts), not a test.
 */
import { describe, expect, it } from 'vitest';
import { TEACH_BENCH_LINKS } from '../../src/bench/teachPage';
import {
  doublyCurvedForward,
  doublyCurvedGouges,
  doublyCurvedInverse,
  doublyCurvedLimits,
} from '../../src/core/surfaces/doublyCurved';
import { slopedPlaneForward, slopedPlaneInverse } from '../../src/core/threeAxis/slopedPlane';
import { buildRequest } from '../../src/ui/request';
import { parseUrl } from '../../src/ui/state';
import { teachCurved, teachThreeAxis } from '../../src/worker/jobs/teachPage';
import type { CurvedRequest, ThreeAxisRequest } from '../../src/worker/pageProtocol';

function requestOf(query: string) {
  const built = buildRequest(parseUrl(query).state);
  if (!built.ok) throw new Error(`invalid: ${query} ${JSON.stringify(built.errors)}`);
  return built.request;
}

// How long these take is measured by `npm run bench` (src/bench/teachPage.ts, the same links), not here.
function slopeOf(query: string) {
  const reply = teachThreeAxis(requestOf(query) as ThreeAxisRequest);
  if (!reply.ok) throw new Error(`no chart: ${query}`);
  return { slope: reply.slope };
}

describe('the chart "step against slope" (three-axis)', () => {
  const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1 };

  it('raster: each charted step is slopedPlaneForward at that slope and raster angle; the constant step leaves the core inverse cusp', () => {
    const { slope } = slopeOf(TEACH_BENCH_LINKS.slopeChart);
    expect(slope.slopeDeg).toHaveLength(200);
    expect(slope.passes).toBe('raster');
    expect(slope.currentSlopeDeg).toBe(30);
    let checked = 0;
    for (let i = 0; i < 200; i += 13) {
      const a = slope.slopeDeg[i] as number;
      const c = { ...TOOL, slopeDeg: a, passes: 'raster' as const, rasterAngleDeg: 40 };
      const f = slopedPlaneForward(c, 0.01);
      if (!f.ok) throw new Error(`refused at ${a}`);
      expect(slope.stepMm[i]).toBeCloseTo(f.value.horizontalStepMm, 12);
      const w = slopedPlaneForward({ ...c, passes: 'waterline' }, 0.01);
      expect(slope.otherStepMm[i]).toBe(a === 0 ? null : w.ok ? w.value.stepDownMm : null);
      const inv = slopedPlaneInverse(c, { field: 'horizontalStep', mm: slope.constantStepMm });
      expect(slope.cuspAtConstantStepMm[i]).toBe(inv.ok ? inv.value.cuspHeightMm : null);
      checked++;
    }
    expect(checked).toBeGreaterThan(10);
    // The constant step is the flat floor's: 2 (R - Rcr + sqrt(2 Rcr h - h^2)).
    expect(slope.constantStepMm).toBeCloseTo(2 * (2 + Math.sqrt(2 * 1 * 0.01 - 0.01 ** 2)), 12);
    // At slope 0 that step leaves h itself.
    expect(slope.cuspAtConstantStepMm[0]).toBeCloseTo(0.01, 9);
    expect(slope.largestSlopeDeg).toBeGreaterThan(30);
    expect(slope.largestSlopeDeg).toBeLessThanOrEqual(90);
  });

  it('the crossing: raster Lxy = waterline dz there (core slopedPlaneForward), raster larger below, waterline above', () => {
    // psi = 90: raster passes run level as waterline's do, the same posture, so Lxy = L cos(a) and
    // dz = L sin(a): they cross at 45 degrees exactly (closed form).
    const { slope } = slopeOf('?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=90&h=0.01&unit=mm');
    const x = slope.crossingDeg;
    if (x === null) throw new Error('they cross for this tool');
    expect(x).toBeCloseTo(45, 9);
    const at = (a: number, passes: 'raster' | 'waterline') => {
      const r = slopedPlaneForward({ ...TOOL, slopeDeg: a, passes, rasterAngleDeg: 90 }, 0.01);
      if (!r.ok) throw new Error('refused');
      return passes === 'raster' ? r.value.horizontalStepMm : (r.value.stepDownMm as number);
    };
    expect(Math.abs(at(x, 'raster') - at(x, 'waterline'))).toBeLessThan(1e-6);
    expect(at(x - 1, 'raster')).toBeGreaterThan(at(x - 1, 'waterline'));
    expect(at(x + 1, 'raster')).toBeLessThan(at(x + 1, 'waterline'));
    expect(slope.crossingStepMm).toBeCloseTo(at(x, 'raster'), 9);
    // Raster down the fall line (psi = 0) keeps Lxy = L: it never falls to waterline's dz.
    expect(slopeOf('?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=0&h=0.01&unit=mm').slope.crossingDeg).toBeNull();
  });

  it('waterline: dz at each slope; none at slope 0; the other line is raster at psi 0', () => {
    const { slope } = slopeOf('?R=3&Rcr=1&machine=3axis&slope=45&passes=waterline&h=0.01&unit=mm');
    expect(slope.passes).toBe('waterline');
    expect(slope.crossingRasterAngleDeg).toBe(0);
    expect(slope.stepMm[0]).toBe(0);
    for (let i = 5; i < 200; i += 37) {
      const a = slope.slopeDeg[i] as number;
      const w = slopedPlaneForward({ ...TOOL, slopeDeg: a, passes: 'waterline', rasterAngleDeg: 0 }, 0.01);
      const r = slopedPlaneForward({ ...TOOL, slopeDeg: a, passes: 'raster', rasterAngleDeg: 0 }, 0.01);
      if (!w.ok || !r.ok) throw new Error('refused');
      expect(slope.stepMm[i]).toBeCloseTo(w.value.stepDownMm as number, 12);
      expect(slope.otherStepMm[i]).toBeCloseTo(r.value.horizontalStepMm, 12);
    }
  });

  it('a surface of revolution has no plane line beside it', () => {
    const { slope } = slopeOf(
      '?R=3&Rcr=1&machine=3axis&slope=30&passes=waterline&feedRadius=50&crossRadius=50&h=0.01&unit=mm',
    );
    expect(slope.onRevolution).toBe(true);
    expect(slope.otherStepMm.every((v) => v === null)).toBe(true);
    expect(slope.stepMm.some((v) => v !== null && v > 0)).toBe(true);
  });
});

function curvedOf(query: string) {
  const request = requestOf(query) as CurvedRequest;
  const reply = teachCurved(request);
  if (!reply.ok) throw new Error(`no data: ${query}`);
  return { reply, request };
}

describe('L against each radius and the curved section (doubly curved point)', () => {
  const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 0 };

  it('each L is doublyCurvedForward at that radius, the other held; gaps exactly where the core gouges or h is too high', () => {
    const { reply } = curvedOf(TEACH_BENCH_LINKS.curved);
    for (const s of [reply.feed, reply.cross]) {
      expect(s.radiusMm).toContain(Math.abs(s.currentMm));
      for (let i = 0; i < s.radiusMm.length; i += 7) {
        const r = s.radiusMm[i] as number;
        for (const [sign, values] of [
          [1, s.convex],
          [-1, s.concave],
        ] as const) {
          const radii =
            s.which === 'feed'
              ? { feedRadiusMm: sign * r, crossRadiusMm: s.heldMm }
              : { feedRadiusMm: s.heldMm, crossRadiusMm: sign * r };
          const pass = { ...TOOL, ...radii, pattern: 'one-way' as const };
          const ok = !doublyCurvedGouges(TOOL, radii) && 0.05 < doublyCurvedLimits(pass).limitMm;
          const v = values[i];
          if (ok)
            expect(v, `${s.which} ${sign * r}`).toBeCloseTo(
              doublyCurvedForward({ ...pass, scallopHeightMm: 0.05 }).intervalMm,
              9,
            );
          else expect(v, `${s.which} ${sign * r}`).toBeNull();
        }
      }
      const at = s.radiusMm.indexOf(Math.abs(s.currentMm));
      expect((s.currentMm > 0 ? s.convex : s.concave)[at]).toBe(s.currentIntervalMm);
    }
    // A concave radius across the feed smaller than the tool gouges: a labelled gap on that side.
    expect(reply.cross.gaps.some((g) => g.side === 'concave' && g.reason === 'gouging')).toBe(true);
  });

  it('the section: the circle of radius Rc, the pass profile from the flanks, cusps and comparison marks from the core', () => {
    const { reply } = curvedOf('?R=3&Rcr=1&rho=10&tilt=0&h=0.05&feedRadius=40&crossRadius=-20&unit=mm');
    const s = reply.section;
    expect(s.crossRadiusMm).toBe(-20);
    const pass = { ...TOOL, feedRadiusMm: 40, crossRadiusMm: -20, pattern: 'one-way' as const };
    const exact = doublyCurvedForward({ ...pass, scallopHeightMm: 0.05 });
    expect(s.exact.intervalMm).toBe(exact.intervalMm);
    expect(s.exact.cuspHeightMm).toBeCloseTo(0.05, 9);
    expect(s.exact.right.yMm).toBeCloseTo(exact.halfWidthRightMm, 9);
    // The profile's height at the right cusp's reach is h (radial), from the flanks' own inverse.
    const p = s.passProfile;
    for (let i = 2; i + 1 < p.length; i += 2) expect(p[i] as number).toBeGreaterThanOrEqual(p[i - 2] as number);
    const back = doublyCurvedInverse({ ...pass, intervalMm: 2 * (p[p.length - 10] as number) });
    expect(back.cuspHeightMm).toBeCloseTo(p[p.length - 9] as number, 6);
    expect(s.comparison.map((m) => m.key)).toEqual(
      expect.arrayContaining(['plane', 'cylinderAlong', 'cylinderAcross', 'sekineCorrected']),
    );
    const plane = s.comparison.find((m) => m.key === 'plane');
    expect(plane?.intervalMm).toBeCloseTo(
      doublyCurvedForward({ ...pass, feedRadiusMm: Infinity, crossRadiusMm: Infinity, scallopHeightMm: 0.05 })
        .intervalMm,
      9,
    );
  });

  it('inverse mode charts the solved h', () => {
    const { reply } = curvedOf('?R=3&Rcr=1&rho=10&tilt=0&mode=inverse&L=1&feedRadius=40&crossRadius=40&unit=mm');
    expect(reply.section.exact.intervalMm).toBeCloseTo(1, 12);
    expect(reply.feed.currentIntervalMm).toBeCloseTo(1, 6);
  });
});
