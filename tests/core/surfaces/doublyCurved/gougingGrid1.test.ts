/**
 * The gouging grid of issue 26 point 1 (gougingGrid.ts), part 1 of 4 (run in parallel). The timeout
 * only guards a loaded machine: a few seconds of CPU.
 */
import { describe, expect, it } from 'vitest';
import { checkGougingGrid } from './gougingGrid';

describe('doubly curved gouging grid, tilt 0 (issue 26 point 1)', () => {
  it('bull nose Rcr 0.4 R, leads 0 to 85: every point a finite answer that the sampled tool confirms, or the gouging error', () => {
    const c = checkGougingGrid(0.4, [0, 30, 60, 85], [0]);
    expect(c.answered).toBeGreaterThan(0);
    expect(c.gouging).toBeGreaterThan(0);
  }, 300_000);
});
