/**
 * The gouging grid of issue 26 point 1: every combination of signs and principal radii from 0.01 to
 * 100 times the tool radius (and straight), over leads 0 to 85 degrees, with and without tilt, through
 * the validation and solve that every caller shares (validateDoublyCurved, then compareDoublyCurved as
 * the command line, the batch and the worker call them). Each point must be either
 *
 * - a finite answer (step-over, flank reaches and the inverse back to h, all finite and consistent)
 *   where the independent sampled check (tests/support/reference/doublyCurvedGougingSampled.ts) finds
 *   no sample of the swept tool inside the surface, or
 * - the gouging error naming the radius that must change, or "at any radius", with no null and no
 *   non-finite member; the same error for a step-over and a target Ra as for a scallop height; or
 * - the "no scallop forms" or "h beyond the flank's limit" error (a flat end without lead, a ball
 *   end in a groove of its own radius), where the sampled check finds no gouging either.
 *
 * Not only where gouging was expected: every point is checked. Lengths mm (tool radius 1 mm).
 */
import { expect } from 'vitest';
import { compareDoublyCurved } from '../../../../src/core/procedures/compareDoublyCurved';
import { validateDoublyCurved } from '../../../../src/core/roughness/doublyCurvedValidate';
import { doublyCurvedInverse } from '../../../../src/core/surfaces/doublyCurved/index';
import { everyNumberFinite } from '../../../support/finite';
import { sampledLowestRadialHeightMm } from '../../../support/reference/doublyCurvedGougingSampled';

const R = 1;
const H = 1e-4;
const MULTIPLES = [0.01, 0.1, 1, 10, 100];
/** Straight, then convex and concave radii from 0.01 R to 100 R. */
export const GRID_RADII: readonly number[] = [
  Number.POSITIVE_INFINITY,
  ...MULTIPLES.map((m) => m * R),
  ...MULTIPLES.map((m) => -m * R),
];

/** What the grid found, for the test's message. */
export interface GridCounts {
  points: number;
  answered: number;
  gouging: number;
  noScallop: number;
}

const text = (r: number) => (Number.isFinite(r) ? String(r) : '');

/** Checks one tool (corner radius, as a fraction of R) in each lead and tilt over the whole grid of radii. */
export function checkGougingGrid(cornerRatio: number, leads: readonly number[], tilts: readonly number[]): GridCounts {
  const counts: GridCounts = { points: 0, answered: 0, gouging: 0, noScallop: 0 };
  const Rcr = cornerRatio * R;
  for (const rho of leads)
    for (const tilt of tilts)
      for (const rf of GRID_RADII)
        for (const rc of GRID_RADII) {
          counts.points++;
          const label = `Rcr ${Rcr} rho ${rho} tilt ${tilt} Rf ${rf} Rc ${rc}`;
          const raw = { R, Rcr, rho, tilt, feedRadius: text(rf), crossRadius: text(rc) };
          const v = validateDoublyCurved(raw, 'h', H);
          const sampled = () =>
            sampledLowestRadialHeightMm({ R, Rcr, leadDeg: rho, tiltDeg: tilt }, rf, rc, {
              spacingMm: 0.04,
              shankSamples: 60,
              excludeMm: 0,
              shankLengthMm: 2 * R,
            });
          if (v.ok) {
            counts.answered++;
            const c = compareDoublyCurved({ ...v.value, scallopHeightMm: H });
            const e = c.exact;
            const numbers = [e.intervalMm, e.halfWidthRightMm, e.halfWidthLeftMm, e.contactOffsetMm, e.cuspHeightMm];
            expect(everyNumberFinite(numbers), label).toBe(true);
            expect(e.intervalMm, label).toBeGreaterThan(0);
            const back = doublyCurvedInverse({ ...v.value, intervalMm: e.intervalMm });
            expect(Math.abs(back.cuspHeightMm - H), label).toBeLessThan(1e-9);
            // Answered: no sample of the swept tool inside the surface (below the rounding of the samples).
            expect(sampled(), label).toBeGreaterThan(-1e-9);
            continue;
          }
          const [first] = v.errors;
          expect(v.errors.length, label).toBe(1);
          if (first === undefined) continue;
          expect(JSON.stringify(first), label).not.toMatch(/null/);
          expect(everyNumberFinite(first), label).toBe(true);
          if (first.code === 'wall-only' || first.code === 'flank-wall' || first.code === 'shank-cuts') {
            // No scallop of that height forms (a flat end without lead; a ball end in a groove of its own
            // radius): not a gouge, and the sampled tool agrees.
            expect(sampled(), label).toBeGreaterThan(-1e-9);
            counts.noScallop++;
            continue;
          }
          counts.gouging++;
          expect(first.code, label).toBe('radius-gouging');
          expect(first.message, label).toMatch(
            /^(Feed radius Rf|Cross radius Rc)(:| must)|^This tool gouges the point at any radius/,
          );
          expect(first.message, label).not.toMatch(/NaN|Infinity|null|e\+/);
          // A step-over or a target Ra at the same point: the same refusal, before the quantity is read.
          if (counts.gouging % 25 === 1)
            for (const [quantity, value] of [
              ['interval', 0.05],
              ['ra', 0.001],
            ] as const) {
              const w = validateDoublyCurved(raw, quantity, value);
              expect(!w.ok && w.errors.map((x) => x.message), `${label} ${quantity}`).toEqual([first.message]);
            }
        }
  return counts;
}
