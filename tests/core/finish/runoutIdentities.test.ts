/**
 * Identities of the surface the teeth leave with radial runout (src/core/finish/runout.ts), derived
 * here, each against something that does not share the runout search:
 *
 * - The limit e = 0: the runout search run at e = 0 gives the e = 0 walk's surface (envelope.ts).
 * - Tooth k at spindle position u is tooth 0 at u - k fz (same tooth angle), whose offset is seen at
 *   phi_e - 2 pi k / z from its own half-plane: so z teeth at fz with runout leave the least of one
 *   tooth at z fz with runout phase phi_e - 2 pi k / z, shifted by k fz along the feed (one-way, q = 0).
 * - One tooth whose offset lies in its own half-plane (phi_e = 0) has its edge at radius r + e: it is
 *   the tooth of the tool with R + e and the same corner (Rb + e), the innermost flat part [0, e)
 *   missing (never the lowest at lead, where the corner cuts). Its surface is that tool's e = 0
 *   surface moved by the difference of the two tools' centre points O (placed so that each touches the
 *   design plane): s(x, y) = s_big(x, y - dOy) + dOz; with phi_e = 180 degrees the edge is at r - e,
 *   the tool with R - e. Moved copies have the same areal parameters but the mean.
 * - Continuity as e -> 0: every edge point moves by e, so heights move by about e (the surface's
 *   slope is small on the plane), and hf with it.
 */

import { describe, expect, it } from 'vitest';
import {
  arealParameters,
  envelopeHeightMm,
  feedMarks,
  runoutEnvelopeHeightMm,
  toothModel,
} from '../../../src/core/finish/index';
import { seededRandom } from '../../../src/core/math/seededRandom';
import { randomBullNose } from '../../support/randomBullNose';
import { teethFinish as finish } from '../../support/teethFinish';

describe('runout: the limit e = 0 and the single tooth', () => {
  it('the runout search at e = 0 gives the e = 0 walk within 1e-12 mm (ball, flat, bull-nose; lead, tilt, zigzag; seed 2921)', () => {
    const r = seededRandom(2921);
    let worst = 0;
    for (let n = 0; n < 9; n++) {
      const R = 1 + 5 * r();
      const kind = n % 3;
      const tool = {
        toolRadiusMm: R,
        cornerRadiusMm: kind === 0 ? R : kind === 1 ? 0 : R * (0.2 + 0.6 * r()),
        leadAngleDeg: kind === 1 ? 3 + 20 * r() : 25 * r(),
        tiltAngleDeg: 20 * (r() - 0.5),
      };
      const pattern = n % 2 === 0 ? 'one-way' : 'zigzag';
      const m = toothModel({ tool, pattern, intervalMm: 0.3 * R, finish: finish(1 + (n % 4), 0.02 + 0.1 * r()) });
      for (let p = 0; p < 3; p++) {
        const x = r() * 4 * m.feedPeriodMm;
        const y = r() * m.crossPeriodMm;
        const err = Math.abs(runoutEnvelopeHeightMm(m, x, y) - envelopeHeightMm(m, x, y));
        worst = Math.max(worst, err);
        expect(err, `case ${n} ${JSON.stringify(tool)} (${x}, ${y})`).toBeLessThan(1e-12);
      }
    }
    expect(worst).toBeLessThan(1e-12);
  });

  it('z teeth with runout at fz leave the least of one tooth at z fz with phase phi_e - 2 pi k / z shifted by k fz (seed 2922)', () => {
    const r = seededRandom(2922);
    for (let n = 0; n < 5; n++) {
      const tool = randomBullNose(r);
      const R = tool.toolRadiusMm;
      const z = 2 + (n % 3);
      const fz = 0.02 + 0.1 * r();
      const e = fz * (0.1 + r());
      const phi = 360 * r();
      const L = 0.4 * R;
      const many = toothModel({ tool, pattern: 'one-way', intervalMm: L, finish: finish(z, fz, e, phi) });
      const ones = Array.from({ length: z }, (_, k) =>
        toothModel({ tool, pattern: 'one-way', intervalMm: L, finish: finish(1, z * fz, e, phi - (360 * k) / z) }),
      );
      for (let p = 0; p < 3; p++) {
        const x = r() * z * fz;
        const y = (r() - 0.5) * L;
        let least = Number.POSITIVE_INFINITY;
        for (let k = 0; k < z; k++) least = Math.min(least, envelopeHeightMm(ones[k] as never, x - k * fz, y));
        expect(Math.abs(envelopeHeightMm(many, x, y) - least), `case ${n} (${x}, ${y})`).toBeLessThan(1e-12);
      }
    }
  });

  it('one tooth offset in its own half-plane is the tool with R + e (phi_e = 0) or R - e (phi_e = 180) moved by dO (seed 2923)', () => {
    const r = seededRandom(2923);
    for (let n = 0; n < 6; n++) {
      const R = 2 + 4 * r();
      const Rcr = R * (0.2 + 0.5 * r());
      const e = 0.02 * R * (0.2 + r());
      const phi = n % 2 === 0 ? 0 : 180;
      const lead = 5 + 25 * r();
      const tilt = 16 * (r() - 0.5);
      const L = 0.3 * R;
      const fz = 0.05 + 0.2 * r();
      const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: lead, tiltAngleDeg: tilt };
      const other = { ...tool, toolRadiusMm: phi === 0 ? R + e : R - e };
      const m = toothModel({ tool, pattern: 'one-way', intervalMm: L, finish: finish(1, fz, e, phi) });
      const o = toothModel({ tool: other, pattern: 'one-way', intervalMm: L, finish: finish(1, fz) });
      const dy = m.centreYMm - o.centreYMm;
      const dz = m.centreZMm - o.centreZMm;
      for (let p = 0; p < 4; p++) {
        const x = r() * 2 * fz;
        const y = r() * L;
        const err = Math.abs(envelopeHeightMm(m, x, y) - (envelopeHeightMm(o, x, y - dy) + dz));
        expect(err, `case ${n} phi ${phi} (${x}, ${y})`).toBeLessThan(1e-12);
      }
    }
  });

  it('so the areal parameters of one tooth with phi_e = 0 are those of the tool with R + e (but the mean), Sa and Sq within 1e-6, Ssk and Sku within 1e-5, Sz within 1e-9 mm', () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 6 };
    const e = 0.03;
    const m = toothModel({ tool, pattern: 'one-way', intervalMm: 1, finish: finish(1, 0.15, e, 0) });
    const o = toothModel({
      tool: { ...tool, toolRadiusMm: 3 + e },
      pattern: 'one-way',
      intervalMm: 1,
      finish: finish(1, 0.15),
    });
    const a = arealParameters(m);
    const b = arealParameters(o);
    expect(Math.abs(a.saMm / b.saMm - 1)).toBeLessThan(1e-6);
    expect(Math.abs(a.sqMm / b.sqMm - 1)).toBeLessThan(1e-6);
    expect(Math.abs(a.ssk - b.ssk)).toBeLessThan(1e-5);
    expect(Math.abs(a.sku - b.sku)).toBeLessThan(1e-5);
    expect(Math.abs(a.szMm - b.szMm)).toBeLessThan(1e-9);
    expect(Math.abs(a.meanMm - b.meanMm - (m.centreZMm - o.centreZMm))).toBeLessThan(1e-8);
  });
});

describe('runout: continuity as e -> 0', () => {
  it('heights and hf move by about e (e = 1e-7 mm against e = 0, seed 2924)', () => {
    const r = seededRandom(2924);
    for (const [tool, pattern] of [
      [{ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 5 }, 'one-way'],
      [{ toolRadiusMm: 3, cornerRadiusMm: 3, leadAngleDeg: 0, tiltAngleDeg: 0 }, 'zigzag'],
    ] as const) {
      const at = (e: number) =>
        toothModel({ tool, pattern, intervalMm: 1, finish: finish(3, 0.08, e, 30 + 300 * r()) });
      const m0 = at(0);
      const m1 = at(1e-7);
      for (let p = 0; p < 4; p++) {
        const x = r() * 0.24;
        const y = 0.05 + 0.9 * r();
        expect(Math.abs(envelopeHeightMm(m1, x, y) - envelopeHeightMm(m0, x, y))).toBeLessThan(3e-7);
      }
      // (The ball at lead 0 drags its tip along y = 0, where e = 1e-7 leaves structure at 1e-7 mm
      // that the search resolves slowly: hf is compared on the bull-nose.)
      if (tool.cornerRadiusMm === 3) continue;
      const hf = feedMarks(m1);
      expect(Math.abs(hf.heightMm - feedMarks(m0).heightMm)).toBeLessThan(6e-7);
      expect(hf.periodMm).toBeCloseTo(0.24, 15);
    }
  });
});
