/**
 * The doubly curved solver against the polished reference (tests/support/reference/
 * doublyCurvedPolished.ts: the real tool searched continuously over its parameters, each point's
 * sweep meeting X = 0 exactly, the crossing of the two passes' columns by bisection) to 1e-9 mm, on
 * every family crossed with every tool (crossCases, cases 0 to 12), with and without tilt, one-way and
 * zigzag, both zigzag cusps. The polishing starts from the sampled brute force at two levels of
 * refinement, and the polished cusp must lie within that brute force's bound of its sampled cusp. The
 * largest errors per family, tool, tilt and pattern are printed at the end. Part 1 of 2 (two
 * files so that the halves run in parallel).
 */
import { afterAll, describe, expect, it } from 'vitest';
import { compare, crossCases, recordWorst, worstTable } from './bruteForceCases';

const worst = new Map<string, number>();
afterAll(() => {
  console.info(worstTable('Doubly curved (family x tool), largest |polished - exact| (part 1 of 2):', worst));
});

describe('doubly curved point against the polished reference, every family with every tool (part 1)', () => {
  for (const c of crossCases(1903, 13)) {
    it(c.name, () => {
      for (const { exactMm, bruteMm, boundMm, polishedMm } of compare(c, 2, true)) {
        expect(Math.abs(polishedMm - bruteMm)).toBeLessThanOrEqual(boundMm);
        expect(Math.abs(polishedMm - exactMm)).toBeLessThan(1e-9);
        recordWorst(worst, c, Math.abs(polishedMm - exactMm));
      }
    });
  }
});
