/** The page's slider drag: where the thumb lands for a pointer position (pure part of sliderDrag.ts). */
import { describe, expect, it } from 'vitest';
import { sliderValueAt } from '../../src/ui/sliderDrag';
import { seededRandom } from '../support/bruteForce';

const TRACK = { leftPx: 100, widthPx: 224, thumbPx: 24 }; // the thumb's centre travels 112..312 px

describe('sliderValueAt', () => {
  const range = { min: 0.001, max: 1.001, step: 0.001 };

  it('puts the ends of the thumb travel at min and max, and clamps beyond them', () => {
    expect(sliderValueAt(112, TRACK, range)).toBe(0.001);
    expect(sliderValueAt(312, TRACK, range)).toBe(1.001);
    expect(sliderValueAt(0, TRACK, range)).toBe(0.001);
    expect(sliderValueAt(100, TRACK, range)).toBe(0.001);
    expect(sliderValueAt(5000, TRACK, range)).toBe(1.001);
    expect(sliderValueAt(212, TRACK, range)).toBe(0.501); // the middle
  });

  it('snaps to whole steps from min, never past a max off the step grid, without float noise', () => {
    expect(sliderValueAt(112 + 200 * 0.30004, TRACK, { min: 0, max: 1, step: 0.1 })).toBe(0.3);
    expect(String(sliderValueAt(112 + 200 * 0.7, TRACK, { min: 0, max: 1, step: 0.1 }))).toBe('0.7');
    expect(sliderValueAt(312, TRACK, { min: 0, max: 1.05, step: 0.1 })).toBe(1);
    expect(sliderValueAt(212, TRACK, { min: -89.9, max: 89.9, step: 0.1 })).toBe(0);
  });

  it('gives min when there is no travel or no range', () => {
    expect(sliderValueAt(150, { leftPx: 100, widthPx: 24, thumbPx: 24 }, range)).toBe(0.001);
    expect(sliderValueAt(150, TRACK, { min: 2, max: 2, step: 0.1 })).toBe(2);
  });

  for (const seed of [20261123, 7]) {
    it(`seed ${seed}: any track and range: a value on the step grid inside the range, under the pointer to half a step`, () => {
      const rnd = seededRandom(seed);
      for (let i = 0; i < 2000; i++) {
        const track = { leftPx: 1000 * rnd(), widthPx: 40 + 800 * rnd(), thumbPx: [0, 16, 24][i % 3] as number };
        const step = [0.001, 0.01, 0.1, 0.0001, 0.25][i % 5] as number;
        const min = Math.round((rnd() * 200 - 100) / step) * step;
        const max = min + step * (1 + Math.floor(rnd() * 5000)) + (i % 7 === 0 ? step / 3 : 0);
        const x = track.leftPx - 50 + (track.widthPx + 100) * rnd();
        const v = sliderValueAt(x, track, { min, max, step });
        expect(v).toBeGreaterThanOrEqual(min - 1e-9);
        expect(v).toBeLessThanOrEqual(max + 1e-9);
        const n = (v - min) / step;
        expect(Math.abs(n - Math.round(n))).toBeLessThan(1e-6);
        // Where the thumb's centre is drawn for v, against the pointer clamped to the travel.
        const travel = track.widthPx - track.thumbPx;
        const lastOnGrid = min + Math.floor((max - min) / step + 1e-9) * step;
        const xClamped = Math.min(
          track.leftPx + track.thumbPx / 2 + (travel * (lastOnGrid - min)) / (max - min),
          Math.max(track.leftPx + track.thumbPx / 2, x),
        );
        const drawn = track.leftPx + track.thumbPx / 2 + (travel * (v - min)) / (max - min);
        const halfStepPx = (travel * step) / (max - min) / 2;
        expect(Math.abs(drawn - xClamped)).toBeLessThanOrEqual(halfStepPx + 1e-6);
      }
    });
  }
});
