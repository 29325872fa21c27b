/** The labels' leader lines (src/render/labelLayout.ts leaderLine): from the point to the label's nearest edge. */
import { describe, expect, it } from 'vitest';
import { leaderLine } from '../../src/render/labelLayout';

describe('leaderLine', () => {
  it('a label to the right of its point: a horizontal line to its left edge', () => {
    const line = leaderLine(60, 0, 40, 14);
    expect(line?.lengthPx).toBeCloseTo(40, 9);
    expect(line?.angleDeg).toBe(0);
  });

  it('a label above-left: the line meets the edge it crosses first, pointing up-left on screen', () => {
    const line = leaderLine(-30, -30, 40, 14);
    // The top/bottom edge is crossed first (half height 7 of 30): 7/30 of the way lies inside.
    expect(line?.lengthPx).toBeCloseTo(Math.hypot(30, 30) * (1 - 7 / 30), 9);
    expect(line?.angleDeg).toBeCloseTo(-135, 9);
  });

  it('no line when the point lies inside the label, or the gap is too small to see', () => {
    expect(leaderLine(0, 0, 40, 14)).toBeNull();
    expect(leaderLine(10, 3, 40, 14)).toBeNull();
    expect(leaderLine(22, 0, 40, 14)).toBeNull();
    expect(leaderLine(26, 0, 40, 14)?.lengthPx).toBeCloseTo(6, 9);
  });
});
