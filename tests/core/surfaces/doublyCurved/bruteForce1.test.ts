/**
 * The doubly curved solver against the brute-force reference (tests/support/reference/
 * doublyCurvedBruteForce.ts): the sampled tool carried along two passes, the material left in X = 0;
 * the cusp within the reference's stated bound (four levels of local refinement); and against the
 * polished reference (doublyCurvedPolished.ts: the same real tool searched continuously, the crossing
 * of the two passes' columns by bisection) to 1e-9 mm, the polished cusp itself within the sampled
 * bound of the sampled one. The largest polished errors per family, tool, tilt and pattern are printed
 * at the end. Part 1 of 2 (two files so that the two halves run in parallel).
 */
import { afterAll, describe, expect, it } from 'vitest';
import { bruteCases, compare, recordWorst, worstTable } from './bruteForceCases';

const worst = new Map<string, number>();
afterAll(() => {
  console.info(worstTable('Doubly curved, largest |polished - exact| (part 1 of 2):', worst));
});

describe('doubly curved point against the brute force (part 1)', () => {
  for (const c of bruteCases(1901, 9)) {
    it(c.name, () => {
      for (const { exactMm, bruteMm, boundMm, polishedMm } of compare(c, 4, true)) {
        expect(boundMm).toBeLessThan(2e-4 * c.tool.toolRadiusMm);
        expect(Math.abs(bruteMm - exactMm)).toBeLessThanOrEqual(boundMm);
        expect(Math.abs(polishedMm - bruteMm)).toBeLessThanOrEqual(boundMm);
        expect(Math.abs(polishedMm - exactMm)).toBeLessThan(1e-9);
        recordWorst(worst, c, Math.abs(polishedMm - exactMm));
      }
    });
  }

  it('the bound and the error shrink as the sampling is refined (a saddle, bull-nose, tilt, one-way; seed 1999)', () => {
    const c = bruteCases(1999, 1, 29)[0];
    if (c === undefined) throw new Error('no case');
    const runs = [1, 2, 3].map(
      (levels) => compare(c, levels)[0] as { exactMm: number; bruteMm: number; boundMm: number },
    );
    for (const r of runs) expect(Math.abs(r.bruteMm - r.exactMm), c.name).toBeLessThanOrEqual(r.boundMm);
    expect(runs[1]?.boundMm).toBeLessThan((runs[0]?.boundMm as number) / 4);
    expect(runs[2]?.boundMm).toBeLessThan((runs[1]?.boundMm as number) / 4);
  });
});
