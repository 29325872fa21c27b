/**
 * The doubly curved solver against the brute-force reference (tests/support/reference/
 * doublyCurvedBruteForce.ts): the sampled tool carried along two passes, the material left in X = 0;
 * the cusp within the reference's stated bound (four levels of local refinement). Part 2 of 2
 * (two files so that the two halves run in parallel).
 */
import { describe, expect, it } from 'vitest';
import { bruteCases, compare } from './bruteForceCases';

describe('doubly curved point against the brute force (part 2)', () => {
  for (const c of bruteCases(1902, 9, 9)) {
    it(c.name, () => {
      for (const { exactMm, bruteMm, boundMm } of compare(c, 4)) {
        expect(boundMm).toBeLessThan(2e-4 * c.tool.toolRadiusMm);
        expect(Math.abs(bruteMm - exactMm)).toBeLessThanOrEqual(boundMm);
      }
    });
  }
});
