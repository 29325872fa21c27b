/**
 * The doubly curved solver against the brute-force reference (tests/support/reference/
 * doublyCurvedBruteForce.ts): the sampled tool carried along two passes, the material left in X = 0;
 * the cusp within the reference's stated bound (four levels of local refinement); and against the
 * polished reference (doublyCurvedPolished.ts: the same real tool searched continuously, the crossing
 * of the two passes' columns by bisection) to 1e-9 mm, the polished cusp itself within the sampled
 * bound of the sampled one. The largest polished errors per family, tool, tilt and pattern are printed
 * at the end. Part 2 of 2 (two files so that the two halves run in parallel).
 */
import { afterAll, describe, expect, it } from 'vitest';
import { bruteCases, compare, recordWorst, worstTable } from './bruteForceCases';

const worst = new Map<string, number>();
afterAll(() => {
  console.info(worstTable('Doubly curved, largest |polished - exact| (part 2 of 2):', worst));
});

describe('doubly curved point against the brute force (part 2)', () => {
  for (const c of bruteCases(1902, 9, 9)) {
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
});
