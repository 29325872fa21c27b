/**
 * The gouging grid of issue 26 point 1 (gougingGrid.ts), part 3 of 4 (run in parallel). The timeout
 * only guards a loaded machine: a few seconds of CPU.
 */
import { describe, expect, it } from 'vitest';
import { checkGougingGrid } from './gougingGrid';

describe('doubly curved gouging grid, tilt 0 (issue 26 point 1)', () => {
  it('ball end and flat end, leads 0 to 85: every point a finite answer that the sampled tool confirms, or the gouging error', () => {
    const ball = checkGougingGrid(1, [0, 45, 85], [0]);
    const flat = checkGougingGrid(0, [0, 5, 45], [0]);
    expect(ball.answered + flat.answered).toBeGreaterThan(0);
    expect(ball.gouging + flat.gouging).toBeGreaterThan(0);
  }, 300_000);
});
