/**
 * Closed forms and identities of the surface the teeth leave (src/core/finish), derived here:
 *
 * - Along the CC path of a tool without tilt the vertical plane y = 0 contains the axis: the section
 *   is the tool's own meridian, and every tooth crosses it once a turn at the front (psi = 0), so the
 *   events on the front lie exactly fz apart along it. Where the front meridian is a circular arc of
 *   radius r around the contact (the ball, r = R; the corner of a bull-nose at lead, r = Rcr), the
 *   highest point between two events is the arc's height at fz / 2 from the contact:
 *   hf = r - sqrt(r^2 - fz^2 / 4) (valid while fz / 2 stays on that arc).
 * - A ball end at lead 0 drags its tip, on every tooth's edge, along the CC path: hf = 0 there, where
 *   the shop formula fz^2 / (8 R) says otherwise.
 * - Tooth k sweeps what tooth 0 sweeps, k fz further along the feed; so z teeth at fz leave the
 *   least of one tooth at z fz (a turn per z fz) shifted by k fz, k = 0 .. z - 1 (one-way, q = 0).
 * - As fz -> 0 the areal parameters tend to the continuous cross-feed profile's (roughness.ts).
 */

import { describe, expect, it } from 'vitest';
import {
  arealParameters,
  balancedFeed,
  envelopeHeightMm,
  type FinishInput,
  feedMarks,
  toothModel,
} from '../../../src/core/finish/index';
import { inverseInput } from '../../../src/core/input/validate';
import { seededRandom } from '../../../src/core/math/seededRandom';
import { exactRoughnessAtInterval } from '../../../src/core/roughness/roughness';
import { planeInverse } from '../../../src/core/surfaces/exact';
import { randomBullNose } from '../../support/randomBullNose';

const finish = (flutes: number, fz: number, passPhase = 0): FinishInput => ({
  flutes,
  feedPerToothMm: fz,
  runoutMm: 0,
  runoutPhaseDeg: 0,
  passPhase,
});

const arcMark = (r: number, fz: number) => (fz * fz) / 4 / (r + Math.sqrt(r * r - (fz * fz) / 4));

describe('feed marks along the CC path', () => {
  it('ball end at lead: hf = R - sqrt(R^2 - fz^2/4) to 1e-12 mm (seed 2911)', () => {
    const r = seededRandom(2911);
    for (let n = 0; n < 12; n++) {
      const R = 0.5 + 8 * r();
      const rho = 5 + 50 * r();
      // The tip lies R sin(rho) behind the contact along the meridian: keep fz / 2 before it.
      const fz = 0.9 * R * Math.sin((rho * Math.PI) / 180) * r();
      const tool = { toolRadiusMm: R, cornerRadiusMm: R, leadAngleDeg: rho, tiltAngleDeg: 0 };
      const m = toothModel({
        tool,
        pattern: n % 2 ? 'zigzag' : 'one-way',
        intervalMm: 0.3 * R,
        finish: finish(1 + (n % 5), fz),
      });
      const fm = feedMarks(m);
      expect(Math.abs(fm.heightMm - arcMark(R, fz)), `R ${R} rho ${rho} fz ${fz}`).toBeLessThan(1e-12);
      expect(fm.periodMm).toBe(fz);
    }
  });

  it('bull-nose at lead: hf = Rcr - sqrt(Rcr^2 - fz^2/4) while the crest stays on the corner (seed 2912)', () => {
    const r = seededRandom(2912);
    for (let n = 0; n < 12; n++) {
      const R = 1 + 8 * r();
      const Rcr = R * (0.1 + 0.8 * r());
      const rho = 3 + 40 * r();
      // The corner's front arc runs Rcr sin(rho) back from the contact to the flat bottom.
      const fz = 1.8 * Rcr * Math.sin((rho * Math.PI) / 180) * (0.05 + 0.9 * r());
      const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: 0 };
      const m = toothModel({ tool, pattern: 'one-way', intervalMm: Rcr, finish: finish(1 + (n % 4), fz) });
      expect(Math.abs(feedMarks(m).heightMm - arcMark(Rcr, fz)), `R ${R} Rcr ${Rcr} rho ${rho} fz ${fz}`).toBeLessThan(
        1e-12,
      );
    }
  });

  it('ball end at lead 0 drags its tip along the CC path: hf = 0 at any feed; no balanced feed', () => {
    for (const fz of [0.01, 0.1, 0.5]) {
      const tool = { toolRadiusMm: 3, cornerRadiusMm: 3, leadAngleDeg: 0, tiltAngleDeg: 0 };
      const m = toothModel({ tool, pattern: 'one-way', intervalMm: 1, finish: finish(2, fz) });
      expect(feedMarks(m).heightMm).toBe(0);
    }
    const b = balancedFeed(
      { toolRadiusMm: 3, cornerRadiusMm: 3, leadAngleDeg: 0, tiltAngleDeg: 0 },
      'one-way',
      1,
      finish(2, 0.1),
    );
    expect(b).toMatchObject({ ok: false, reason: 'marks-below-scallop' });
  });

  it("a ball end's tip, on every edge, caps the marks on the CC path at its height R (1 - cos rho)", () => {
    for (const [rho, fz] of [
      [5, 0.6],
      [10, 1.2],
    ] as const) {
      const tool = { toolRadiusMm: 3, cornerRadiusMm: 3, leadAngleDeg: rho, tiltAngleDeg: 0 };
      const m = toothModel({ tool, pattern: 'one-way', intervalMm: 1, finish: finish(2, fz) });
      const tip = 3 * (1 - Math.cos((rho * Math.PI) / 180));
      expect(Math.abs(feedMarks(m).heightMm - tip)).toBeLessThan(1e-12);
    }
  });

  it('the balanced feed makes hf equal the scallop h (bull-nose at lead 10)', () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 0 };
    const b = balancedFeed(tool, 'one-way', 1.2, finish(2, 0.1));
    expect(b.ok).toBe(true);
    if (!b.ok) return;
    const h = planeInverse(inverseInput(tool, 'one-way', 1.2)).cuspHeightMm;
    expect(b.scallopHeightMm).toBe(h);
    // On the corner's arc the balanced feed is in closed form: 2 sqrt(h (2 Rcr - h)).
    expect(Math.abs(b.feedPerToothMm - 2 * Math.sqrt(h * (2 - h)))).toBeLessThan(1e-11);
  });
});

describe('identities of the envelope', () => {
  it('z teeth at fz leave the least of one tooth at z fz shifted by k fz (seed 2913)', () => {
    const r = seededRandom(2913);
    for (let n = 0; n < 6; n++) {
      const tool = randomBullNose(r);
      const R = tool.toolRadiusMm;
      const z = 2 + (n % 3);
      const fz = 0.02 + 0.1 * r();
      const L = 0.4 * R;
      const many = toothModel({ tool, pattern: 'one-way', intervalMm: L, finish: finish(z, fz) });
      const one = toothModel({ tool, pattern: 'one-way', intervalMm: L, finish: finish(1, z * fz) });
      for (let p = 0; p < 4; p++) {
        const x = r() * z * fz;
        const y = (r() - 0.5) * L;
        let least = Number.POSITIVE_INFINITY;
        for (let k = 0; k < z; k++) least = Math.min(least, envelopeHeightMm(one, x - k * fz, y));
        expect(Math.abs(envelopeHeightMm(many, x, y) - least), `case ${n} (${x}, ${y})`).toBeLessThan(1e-12);
      }
    }
  });

  it('as fz -> 0 the areal parameters tend to the cross-feed profile: Sa -> Ra, Sq -> Rq, Sz -> Rz', () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
    const L = 1.4;
    const rough = exactRoughnessAtInterval(tool, 'one-way', planeInverse(inverseInput(tool, 'one-way', L)));
    const fz = 0.004;
    const m = toothModel({ tool, pattern: 'one-way', intervalMm: L, finish: finish(2, fz) });
    const a = arealParameters(m);
    const hf = arcMark(1, fz);
    // The marks add at most hf to any height: every difference is within a few hf.
    expect(Math.abs(a.saMm - rough.raMm)).toBeLessThan(2 * hf);
    expect(Math.abs(a.sqMm - rough.rqMm)).toBeLessThan(2 * hf);
    expect(Math.abs(a.szMm - rough.rzMm)).toBeLessThan(2 * hf);
    expect(a.szMm).toBeGreaterThanOrEqual(rough.rzMm - 1e-12);
    expect(Math.abs(a.meanMm - rough.meanMm)).toBeLessThan(2 * hf);
  });

  it("at fz 3e-5 Sa, Sq meet the continuous profile's Ra, Rq within 1e-6 relative (ball, bull-nose, zigzag with tilt)", () => {
    // p(y) <= s(x, y) <= p(y) + d (d the tallest mark), and the means likewise, so |Sa - Ra| and
    // |Sq - Rq| are at most d: here marks on arcs of radius r >= 1 mm, fz^2 / (8 r) ~ 1.1e-10 mm,
    // below 1e-7 of Ra (>= 1.3e-3 mm). What remains is the quadrature's own error.
    const fz = 3e-5;
    for (const [tool, pattern] of [
      [{ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way'],
      [{ toolRadiusMm: 3, cornerRadiusMm: 3, leadAngleDeg: 15, tiltAngleDeg: 0 }, 'one-way'],
      [{ toolRadiusMm: 3, cornerRadiusMm: 3, leadAngleDeg: 0, tiltAngleDeg: 0 }, 'one-way'],
      [{ toolRadiusMm: 6, cornerRadiusMm: 2, leadAngleDeg: 15, tiltAngleDeg: 10 }, 'zigzag'],
    ] as const) {
      const rough = exactRoughnessAtInterval(tool, pattern, planeInverse(inverseInput(tool, pattern, 1)));
      const a = arealParameters(toothModel({ tool, pattern, intervalMm: 1, finish: finish(2, fz) }));
      const label = `${JSON.stringify(tool)} ${pattern}`;
      expect(Math.abs(a.saMm / rough.raMm - 1), label).toBeLessThan(1e-6);
      expect(Math.abs(a.sqMm / rough.rqMm - 1), label).toBeLessThan(1e-6);
    }
  });
});
