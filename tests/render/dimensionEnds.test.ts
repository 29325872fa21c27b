/**
 * Where the step-over's dimension L is drawn (render/drawables/dimensions.ts, render/cameraFit.ts nearerEndFirst): at the end of the
 * drawn passes nearer the isometric camera, in front of the tool, whichever way the machine frame
 * turns the feed; L/2 at the other end.
 */
import { describe, expect, it } from 'vitest';
import { nearerEndFirst } from '../../src/render/cameraFit';

/** A column-major 4 x 4 turning the local feed (x) into `feed` (world). */
const turning = (feed: readonly [number, number, number]) => [...feed, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];

describe('the end of the passes L is drawn at', () => {
  it('five-axis (the local frame is the world): the +x end, which the isometric camera looks from', () => {
    expect(nearerEndFirst(-3.9, 3.9, undefined)).toEqual([3.9, -3.9]);
  });

  it('three-axis, the feed turned away from the camera or towards it: the nearer end first', () => {
    expect(nearerEndFirst(-3.9, 3.9, turning([-1, 0, 0]))).toEqual([-3.9, 3.9]);
    // Along -y the feed runs towards the camera (it looks from -y): +x end.
    expect(nearerEndFirst(-3.9, 3.9, turning([0, -1, 0]))).toEqual([3.9, -3.9]);
    expect(nearerEndFirst(-3.9, 3.9, turning([0, 0.6, -0.8]))).toEqual([-3.9, 3.9]);
  });
});
