/** Which sides of a sideways-scrolling box hide content (src/ui/scrollCue.ts). */
import { describe, expect, it } from 'vitest';
import { hiddenSides } from '../../src/ui/scrollCue';

describe('hiddenSides', () => {
  it('a box that fits hides nothing; scrolled from start to end, the hidden side moves from right to left', () => {
    expect(hiddenSides(0, 300, 300)).toEqual({ left: false, right: false });
    expect(hiddenSides(0, 300, 300.6)).toEqual({ left: false, right: false }); // rounding, not content
    expect(hiddenSides(0, 300, 500)).toEqual({ left: false, right: true });
    expect(hiddenSides(100, 300, 500)).toEqual({ left: true, right: true });
    expect(hiddenSides(200, 300, 500)).toEqual({ left: true, right: false });
    expect(hiddenSides(199.5, 300, 500)).toEqual({ left: true, right: false });
  });
});
