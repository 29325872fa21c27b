/**
 * The balanced feed fz* (src/core/finish/feedMarks.ts) and the two shortcuts its search takes without
 * runout: the crest feed in closed form (crestFeed.ts) tried first, and a lower bound of hf read by the
 * scan's probes above the root. Each against what does not share it:
 *
 * - Without tilt the vertical plane y = 0 holds the axis: every tooth crosses it at the front
 *   (psi = 0), and where the crest stays on the corner's arc of radius Rcr around the contact the feed
 *   whose crest stands h high is the arc's chord at that height, 2 sqrt(h (2 Rcr - h)).
 * - With tilt the closed form is checked through feedMarks (the event walk): hf at its feed is h.
 * - The lower bound never exceeds feedMarks' hf, and is hf where one pass shapes the line.
 * - fz* itself: hf(fz*) is h within balancedFeedToleranceMm, and hf - h changes sign across fz*.
 */
import { describe, expect, it } from 'vitest';
import type { PassPattern } from '../../../src/core/domain/tool';
import { crestFeedMm } from '../../../src/core/finish/crestFeed';
import {
  balancedFeed,
  balancedFeedToleranceMm,
  feedMarkLowerBoundMm,
  feedMarks,
  toothModel,
} from '../../../src/core/finish/index';
import { RowEnvelope } from '../../../src/core/finish/rowEnvelope';
import { seededRandom } from '../../../src/core/math/seededRandom';
import { randomBullNose } from '../../support/randomBullNose';
import { teethFinish as finish } from '../../support/teethFinish';

describe('the crest feed in closed form (crestFeed.ts)', () => {
  it('without tilt: the corner arc chord 2 sqrt(h (2 Rcr - h)) to 1e-12 mm (seed 2940)', () => {
    const r = seededRandom(2940);
    for (let n = 0; n < 12; n++) {
      const R = 1 + 8 * r();
      const Rcr = R * (0.1 + 0.9 * r());
      const rho = 3 + 40 * r();
      // Keep the chord's half on the front arc: fz / 2 <= Rcr sin(rho) (the arc meets the flat there).
      const half = Rcr * Math.sin((rho * Math.PI) / 180) * (0.05 + 0.9 * r());
      const h = Rcr - Math.sqrt(Rcr * Rcr - half * half);
      const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: 0 };
      const m = toothModel({ tool, pattern: 'one-way', intervalMm: Rcr, finish: finish(1 + (n % 4), 0.1) });
      expect(
        Math.abs(crestFeedMm(m, h) - 2 * Math.sqrt(h * (2 * Rcr - h))),
        `R ${R} Rcr ${Rcr} rho ${rho}`,
      ).toBeLessThan(1e-12);
    }
  });

  it('with tilt: hf at the feed it gives is h within 1e-12 mm where one pass shapes the CC path (seed 2943)', () => {
    const r = seededRandom(2943);
    let checked = 0;
    for (let n = 0; n < 24; n++) {
      const tool = { ...randomBullNose(r), tiltAngleDeg: (r() < 0.5 ? -1 : 1) * (2 + 8 * r()) };
      const h = tool.cornerRadiusMm * (0.001 + 0.02 * r());
      const flutes = 1 + (n % 4);
      const pattern: PassPattern = n % 2 === 0 ? 'one-way' : 'zigzag';
      const intervalMm = tool.toolRadiusMm * (0.2 + 0.4 * r());
      const fz = crestFeedMm(toothModel({ tool, pattern, intervalMm, finish: finish(flutes, 0.1) }), h);
      expect(fz, JSON.stringify(tool)).toBeGreaterThan(0);
      const m = toothModel({ tool, pattern, intervalMm, finish: finish(flutes, fz) });
      if (new RowEnvelope(m, 0).activePasses().length !== 1) continue;
      checked++;
      expect(Math.abs(feedMarks(m).heightMm - h), `${JSON.stringify(tool)} z ${flutes} h ${h}`).toBeLessThan(1e-12);
    }
    expect(checked).toBeGreaterThanOrEqual(20);
  });
});

describe('the lower bound of hf the scan reads (feedMarkLowerBoundMm)', () => {
  it('never exceeds hf, and is hf where one pass shapes the line; fz up to R (seed 2942)', () => {
    const r = seededRandom(2942);
    let several = 0;
    for (let n = 0; n < 24; n++) {
      const tool = randomBullNose(r);
      const R = tool.toolRadiusMm;
      const fz = R * (n % 3 === 0 ? 0.02 + 0.1 * r() : 0.2 + 0.8 * r());
      const m = toothModel({
        tool,
        pattern: n % 2 === 0 ? 'one-way' : 'zigzag',
        intervalMm: R * (0.2 + 0.5 * r()),
        finish: finish(1 + (n % 4), fz),
      });
      const row = new RowEnvelope(m, 0);
      const bound = feedMarkLowerBoundMm(row);
      const hf = feedMarks(m).heightMm;
      const label = `${JSON.stringify(tool)} fz ${fz}`;
      expect(bound, label).toBeLessThanOrEqual(hf + 1e-15 * R);
      if (row.activePasses().length === 1) expect(bound, label).toBe(hf);
      else several++;
    }
    expect(several).toBeGreaterThanOrEqual(4);
  });
});

describe('the balanced feed fz*', () => {
  it('hf(fz*) is h within its tolerance and hf - h changes sign across fz* (1 +- 1e-9); ball, flat, bull-nose, tilt, zigzag, runout (seed 2941)', () => {
    const r = seededRandom(2941);
    const kinds = ['ball', 'flat', 'bull', 'bull'] as const;
    let answered = 0;
    for (let n = 0; n < 16; n++) {
      const base = randomBullNose(r);
      const R = base.toolRadiusMm;
      const kind = kinds[n % 4] as (typeof kinds)[number];
      const tool = {
        ...base,
        cornerRadiusMm: kind === 'ball' ? R : kind === 'flat' ? 0 : base.cornerRadiusMm,
        leadAngleDeg: kind === 'flat' ? 3 + 10 * r() : base.leadAngleDeg,
        tiltAngleDeg: n % 3 === 0 ? 0 : base.tiltAngleDeg,
      };
      const pattern: PassPattern = n % 2 === 0 ? 'one-way' : 'zigzag';
      const intervalMm = R * (0.1 + 0.6 * r());
      // Two cases with runout (there the scan and the root finder alone).
      const e = 0.002 * R * r();
      const runoutMm = n % 8 === 7 ? e : 0;
      const phaseDeg = 360 * r();
      const fin = (fz: number) => finish(1 + (n % 4), fz, runoutMm, phaseDeg);
      const hfAt = (fz: number) => feedMarks(toothModel({ tool, pattern, intervalMm, finish: fin(fz) })).heightMm;
      const b = balancedFeed(tool, pattern, intervalMm, fin(0.1));
      const label = `${n}: ${kind} ${JSON.stringify(tool)} ${pattern} L ${intervalMm} e ${runoutMm}`;
      if (!b.ok) {
        // A ball near lead 0 drags its low tip along the CC path: the marks stay below h.
        expect(b.reason, label).toBe('marks-below-scallop');
        expect(hfAt(R), label).toBeLessThan(b.scallopHeightMm);
        continue;
      }
      answered++;
      const h = b.scallopHeightMm;
      const fz = b.feedPerToothMm;
      expect(Math.abs(hfAt(fz) - h), label).toBeLessThanOrEqual(balancedFeedToleranceMm(h));
      expect(hfAt(fz * (1 - 1e-9)), label).toBeLessThan(h);
      expect(hfAt(fz * (1 + 1e-9)), label).toBeGreaterThan(h);
    }
    expect(answered).toBeGreaterThanOrEqual(12);
  });

  it('where the closed form misses (hf at its feed is not h), the root finder ends on hf = h', () => {
    // Found by a seeded search (seed 2944): R 4.52 Rcr 4.36 lead 5.4 tilt -2.2, 3 teeth, L 2.75.
    const tool = {
      toolRadiusMm: 4.51897380896844,
      cornerRadiusMm: 4.3550004819423,
      leadAngleDeg: 5.445657231844962,
      tiltAngleDeg: -2.2157227201387286,
    };
    const intervalMm = 2.7482720290443208;
    const hfAt = (fz: number) =>
      feedMarks(toothModel({ tool, pattern: 'one-way', intervalMm, finish: finish(3, fz) })).heightMm;
    const b = balancedFeed(tool, 'one-way', intervalMm, finish(3, 0.1));
    expect(b.ok).toBe(true);
    if (!b.ok) return;
    const h = b.scallopHeightMm;
    const m = toothModel({ tool, pattern: 'one-way', intervalMm, finish: finish(3, 0.1) });
    expect(Math.abs(hfAt(crestFeedMm(m, h)) - h)).toBeGreaterThan(1e-6);
    expect(Math.abs(hfAt(b.feedPerToothMm) - h)).toBeLessThanOrEqual(balancedFeedToleranceMm(h));
    expect(hfAt(b.feedPerToothMm * (1 - 1e-9))).toBeLessThan(h);
    expect(hfAt(b.feedPerToothMm * (1 + 1e-9))).toBeGreaterThan(h);
  });
});
