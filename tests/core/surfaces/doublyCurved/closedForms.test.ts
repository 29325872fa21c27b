/**
 * Closed forms, symmetry and ordering of the doubly curved solver (issue 19): a ball end on a sphere
 * (and on any patch: its section is its own circle whatever Rf), a flat bottom lying flat on a dome,
 * tilt mirrored, convex below plane below concave, inverse after forward.
 */
import { describe, expect, it } from 'vitest';
import type { PassPattern, ToolInput } from '../../../../src/core/input/validate';
import { doublyCurvedGouges } from '../../../../src/core/surfaces/doublyCurved/gouging';
import {
  doublyCurvedForward,
  doublyCurvedInverse,
  doublyCurvedLimits,
} from '../../../../src/core/surfaces/doublyCurved/solve';
import type { DoublyCurvedForwardInput } from '../../../../src/core/surfaces/doublyCurved/types';
import { doublyCurvedModel } from '../../../../src/core/surfaces/models/doublyCurved';
import { seededRandom } from '../../../support/bruteForce';

const I = Number.POSITIVE_INFINITY;
const tool = (R: number, Rcr: number, rho: number, tilt: number): ToolInput => ({
  toolRadiusMm: R,
  cornerRadiusMm: Rcr,
  leadAngleDeg: rho,
  tiltAngleDeg: tilt,
});
const fwd = (t: ToolInput, rf: number, rc: number, h: number, pattern: PassPattern = 'one-way') =>
  doublyCurvedForward({ ...t, pattern, feedRadiusMm: rf, crossRadiusMm: rc, scallopHeightMm: h });

/**
 * Two circles of radius R whose centres lie d from C, the cusp at radius r: L = 2 |Rs| acos((d^2 + r^2 -
 * R^2) / (2 d r)), written `2 asin(sqrt(h (2R - h) / (4 d r)))` per half (d - r = +-(R - h)) so that
 * it keeps its digits on a large sphere.
 */
function circlesInterval(R: number, rs: number, h: number): number {
  const d = rs > 0 ? rs + R : -rs - R;
  const r = Math.abs(rs + h);
  return 4 * Math.abs(rs) * Math.asin(Math.sqrt((h * (2 * R - h)) / (4 * d * r)));
}

describe('doubly curved point: closed forms', () => {
  it('a ball end on a sphere, convex and concave, any posture: two circles about the centre', () => {
    for (const [R, rs, h, rho, tilt] of [
      [3, 20, 0.05, 10, 20],
      [3, -20, 0.05, 0, 0],
      [1, 5, 0.2, 45, -30],
      [2, -3, 0.01, 5, 5],
      [0.5, 1e3, 1e-4, 30, 10],
    ] as const) {
      const expected = circlesInterval(R, rs, h);
      for (const pattern of ['one-way', 'zigzag'] as const) {
        const got = fwd(tool(R, R, rho, tilt), rs, rs, h, pattern);
        expect(Math.abs(got.intervalMm - expected), `R ${R} Rs ${rs} h ${h} ${pattern}`).toBeLessThan(1e-9);
        if (pattern === 'zigzag') expect(Math.abs((got.otherCuspHeightMm as number) - h)).toBeLessThan(1e-9);
      }
    }
  });

  it('a ball end leaves the same step-over whatever Rf (its section is its own circle)', () => {
    for (const rf of [I, 7, -9, 40, -300]) {
      for (const rc of [I, 12, -15]) {
        const expected = Number.isFinite(rc) ? circlesInterval(2, rc, 0.03) : 2 * Math.sqrt(2 * 2 * 0.03 - 0.03 * 0.03);
        expect(
          Math.abs(fwd(tool(2, 2, 15, -10), rf, rc, 0.03).intervalMm - expected),
          `Rf ${rf} Rc ${rc}`,
        ).toBeLessThan(1e-9);
      }
    }
  });

  it('a flat bottom lying flat (no lead, no tilt) on a dome: its face, then the corner ball at the ring edge', () => {
    for (const [R, k, rf, rc, h] of [
      [3, 1, 20, 30, 0.05],
      [3, 1, 20, 30, 0.2],
      [5, 0.5, I, 12, 0.2],
      [5, 0.5, I, 12, 0.9],
      [4, 2, 6, 8, 0.5],
    ] as const) {
      const rb = R - k;
      // The face z = 0 rises radially to sqrt(Rb^2 + Rc^2) - Rc at its edge; above it the ball at (Rb, k).
      const edge = (rb * rb) / (Math.hypot(rb, rc) + rc);
      let expected: number;
      if (h <= edge) expected = 2 * rc * Math.atan2(Math.sqrt(h * (2 * rc + h)), rc);
      else {
        const d = Math.hypot(rb, rc + k);
        const r = rc + h;
        expected = 2 * rc * (Math.atan2(rb, rc + k) + Math.acos((d * d + r * r - k * k) / (2 * d * r)));
      }
      const label = `R ${R} k ${k} Rf ${rf} Rc ${rc} h ${h} (edge ${edge})`;
      expect(Math.abs(fwd(tool(R, k, 0, 0), rf, rc, h).intervalMm - expected), label).toBeLessThan(1e-9);
    }
  });
});

describe('doubly curved point: symmetry, ordering and round trips', () => {
  for (const seed of [191, 192, 193]) {
    it(`tilt mirrored swaps the flanks and keeps L and the other cusp (seed ${seed})`, () => {
      const rand = seededRandom(seed);
      for (let n = 0; n < 8; n++) {
        const R = 1 + 5 * rand();
        const t = tool(R, R * rand(), 40 * rand(), 5 + 40 * rand());
        const m = { ...t, tiltAngleDeg: -t.tiltAngleDeg };
        const rf = (rand() < 0.5 ? 1 : -1) * R * (15 + 30 * rand());
        const rc = (rand() < 0.5 ? 1 : -1) * R * (15 + 30 * rand());
        if (doublyCurvedGouges(t, { feedRadiusMm: rf, crossRadiusMm: rc })) continue;
        const h = 0.3 * doublyCurvedLimits({ ...t, feedRadiusMm: rf, crossRadiusMm: rc }).limitMm;
        for (const pattern of ['one-way', 'zigzag'] as const) {
          const a = fwd(t, rf, rc, h, pattern);
          const b = fwd(m, rf, rc, h, pattern);
          const label = `R ${R} Rcr ${t.cornerRadiusMm} rho ${t.leadAngleDeg} tilt ${t.tiltAngleDeg} Rf ${rf} Rc ${rc}`;
          expect(Math.abs(a.halfWidthRightMm - b.halfWidthLeftMm), label).toBeLessThan(1e-9);
          expect(Math.abs(a.halfWidthLeftMm - b.halfWidthRightMm), label).toBeLessThan(1e-9);
          expect(Math.abs(a.intervalMm - b.intervalMm), label).toBeLessThan(1e-9);
          expect(Math.abs(a.contactOffsetMm + b.contactOffsetMm), label).toBeLessThan(1e-12);
          if (pattern === 'zigzag')
            expect(Math.abs((a.otherCuspHeightMm as number) - (b.otherCuspHeightMm as number)), label).toBeLessThan(
              1e-9,
            );
        }
      }
    });

    it(`convex below straight below concave, in each radius, the other held (seed ${seed})`, () => {
      const rand = seededRandom(seed + 100);
      let checked = 0;
      for (let n = 0; n < 10; n++) {
        const R = 1 + 5 * rand();
        const t = tool(R, R * rand(), 40 * rand(), 60 * rand() - 30);
        const mag = R * (20 + 40 * rand());
        const other = (rand() < 0.5 ? 1 : -1) * R * (20 + 40 * rand());
        const pattern: PassPattern = rand() < 0.5 ? 'one-way' : 'zigzag';
        for (const which of ['feed', 'cross'] as const) {
          const radii = (r: number) => (which === 'feed' ? { rf: r, rc: other } : { rf: other, rc: r });
          const all = [mag, I, -mag].map(radii);
          if (all.some(({ rf, rc }) => doublyCurvedGouges(t, { feedRadiusMm: rf, crossRadiusMm: rc }))) continue;
          const limit = Math.min(
            ...all.map(({ rf, rc }) => doublyCurvedLimits({ ...t, feedRadiusMm: rf, crossRadiusMm: rc }).limitMm),
          );
          const h = 0.3 * limit;
          const [convex, straight, concave] = all.map(({ rf, rc }) =>
            doublyCurvedModel.intervalMm({
              ...t,
              pattern,
              surface: { kind: 'doublyCurved', feedRadiusMm: rf, crossRadiusMm: rc },
              scallopHeightMm: h,
            }),
          ) as [number, number, number];
          const label = `${which} R ${R} Rcr ${t.cornerRadiusMm} rho ${t.leadAngleDeg} tilt ${t.tiltAngleDeg} |R| ${mag} other ${other}`;
          // A ball end ignores Rf (equal), otherwise strictly ordered.
          expect(convex, label).toBeLessThanOrEqual(straight + 1e-12);
          expect(straight, label).toBeLessThanOrEqual(concave + 1e-12);
          if (which === 'cross') expect(convex, label).toBeLessThan(concave);
          checked++;
        }
      }
      expect(checked).toBeGreaterThan(5);
    });

    it(`the inverse gives back h, both patterns (seed ${seed})`, () => {
      const rand = seededRandom(seed + 200);
      for (let n = 0; n < 8; n++) {
        const R = 1 + 5 * rand();
        const t = tool(R, R * rand(), 40 * rand(), 60 * rand() - 30);
        const rf = (rand() < 0.5 ? 1 : -1) * R * (15 + 30 * rand());
        const rc = rand() < 0.2 ? rf : (rand() < 0.5 ? 1 : -1) * R * (15 + 30 * rand());
        if (doublyCurvedGouges(t, { feedRadiusMm: rf, crossRadiusMm: rc })) continue;
        const limit = doublyCurvedLimits({ ...t, feedRadiusMm: rf, crossRadiusMm: rc }).limitMm;
        for (const h of [limit * 1e-5, limit * 0.2, limit * 0.7]) {
          for (const pattern of ['one-way', 'zigzag'] as const) {
            const input: DoublyCurvedForwardInput = {
              ...t,
              pattern,
              feedRadiusMm: rf,
              crossRadiusMm: rc,
              scallopHeightMm: h,
            };
            const f = doublyCurvedForward(input);
            const inv = doublyCurvedInverse({ ...input, intervalMm: f.intervalMm });
            const label = `R ${R} Rcr ${t.cornerRadiusMm} rho ${t.leadAngleDeg} tilt ${t.tiltAngleDeg} Rf ${rf} Rc ${rc} h ${h} ${pattern}`;
            expect(Math.abs(inv.cuspHeightMm - h), label).toBeLessThan(1e-9);
            if (pattern === 'zigzag')
              expect(Math.abs((inv.otherCuspHeightMm as number) - (f.otherCuspHeightMm as number)), label).toBeLessThan(
                1e-9,
              );
          }
        }
      }
    });
  }
});
