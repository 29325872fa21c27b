/**
 * A runout line's breaks (src/core/finish/runoutLine.ts): where the lowest event passes from one bite
 * to another, located by following both bites (Newton, no search) to the root of their difference,
 * against the same changes located by bisection on the search alone (follow = false), which shares
 * no step of the following but the samples that detect a change.
 */
import { describe, expect, it } from 'vitest';
import { RunoutRow, toothModel } from '../../../src/core/finish/index';
import { runoutLineBreaks } from '../../../src/core/finish/runoutLine';
import { seededRandom } from '../../../src/core/math/seededRandom';
import { teethFinish as finish } from '../../support/teethFinish';

describe('runout line breaks', () => {
  it('the changes of bite found by following the bites are those bisection finds, within 1e-12 of the period (seed 2931)', () => {
    const r = seededRandom(2931);
    let worst = 0;
    let changes = 0;
    for (let n = 0; n < 4; n++) {
      const big = n % 2 === 1;
      const tool = {
        toolRadiusMm: big ? 6 : 3,
        cornerRadiusMm: big ? 2 : 1,
        leadAngleDeg: 2 + 13 * r(),
        tiltAngleDeg: n < 2 ? 0 : 10 * (r() - 0.5),
      };
      const pattern = n % 3 === 0 ? 'zigzag' : 'one-way';
      const fin = finish(2 + (n % 3), 0.05 + 0.15 * r(), 0.002 + 0.008 * r(), 360 * r());
      const m = toothModel({ tool, pattern, intervalMm: 0.4 + 0.6 * r(), finish: fin });
      const P = m.feedPeriodMm;
      for (let k = 0; k < 2; k++) {
        const y = r() * m.crossPeriodMm;
        const followed = runoutLineBreaks(m, new RunoutRow(m, y), 0);
        const bisected = runoutLineBreaks(m, new RunoutRow(m, y), 0, false);
        // Each list's breaks beyond the starting grid (4 a tooth pitch) are the changes; each has its
        // match in the other list.
        for (const [mine, theirs] of [
          [followed, bisected],
          [bisected, followed],
        ] as const) {
          for (const x of mine) {
            const gap = Math.min(...theirs.map((t) => Math.abs(t - x)));
            worst = Math.max(worst, gap / P);
            expect(gap, `case ${n} y ${y} x ${x}`).toBeLessThan(1e-12 * P);
          }
        }
        changes += followed.length - (4 * fin.flutes + 1);
      }
    }
    expect(changes).toBeGreaterThan(8);
    expect(worst).toBeLessThan(1e-12);
  });
});
