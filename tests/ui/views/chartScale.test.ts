import { describe, expect, it } from 'vitest';
import {
  coverRange,
  extent,
  linearScale,
  linePath,
  logScale,
  niceStep,
  tickLabel,
  ticksWithin,
} from '../../../src/ui/views/chartScale';

describe('nice 1-2-5 ticks', () => {
  it('steps are 1, 2 or 5 times a power of ten, near span / count', () => {
    expect(niceStep(10, 5)).toBe(2);
    expect(niceStep(1, 4)).toBe(0.2);
    expect(niceStep(0.003, 5)).toBeCloseTo(0.0005, 15);
    expect(niceStep(700, 5)).toBe(100);
    expect(niceStep(45, 5)).toBe(10);
    for (const span of [1e-7, 0.0042, 0.37, 3, 18, 240, 9e5]) {
      const s = niceStep(span, 5);
      const mantissa = s / 10 ** Math.floor(Math.log10(s) + 1e-9);
      expect(
        [1, 2, 5, 10].some((m) => Math.abs(mantissa - m) < 1e-9),
        `${span}`,
      ).toBe(true);
      expect(span / s).toBeGreaterThanOrEqual(2);
      expect(span / s).toBeLessThanOrEqual(12);
    }
  });

  it('a value axis covers the data: first tick at or below the minimum, last at or above the maximum', () => {
    for (const [lo, hi] of [
      [0.6244998, 3.093375],
      [-78.37, 7.14],
      [0.00004471, 0.00008942],
      [-0.7157108, 0.2061904],
      [0.8, 3.1],
      [2.5, 2.5],
      [0, 0],
    ] as const) {
      const s = linearScale(lo, hi, 300, 0, 5, true);
      expect(s.ticks[0], `${lo}`).toBeLessThanOrEqual(lo);
      expect(s.ticks.at(-1), `${hi}`).toBeGreaterThanOrEqual(hi);
      expect(s.min).toBe(s.ticks[0]);
      expect(s.max).toBe(s.ticks.at(-1));
      expect(s.max).toBeGreaterThan(s.min);
      // No more than a step of empty space beyond the data on either side.
      if (hi > lo) {
        expect(lo - s.min).toBeLessThan(s.step + 1e-12);
        expect(s.max - hi).toBeLessThan(s.step + 1e-12);
      }
    }
  });

  it('an angle axis keeps the charted range exactly, its ticks inside it', () => {
    const s = linearScale(-60, 60, 40, 440, 6, false);
    expect([s.min, s.max]).toEqual([-60, 60]);
    expect(s.ticks).toEqual([-60, -40, -20, 0, 20, 40, 60]);
    expect(s.toPixel(-60)).toBe(40);
    expect(s.toPixel(60)).toBe(440);
    expect(s.toPixel(0)).toBe(240);
  });

  it('ticks carry no float noise', () => {
    expect(ticksWithin(0, 1, 0.1)).toEqual([0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1]);
    expect(ticksWithin(0.29, 0.61, 0.1)).toEqual([0.3, 0.4, 0.5, 0.6]);
    const s = linearScale(0, 0.0003, 0, 100, 3, true);
    for (const t of s.ticks) expect(tickLabel(t, s)).not.toMatch(/\d\.\d*(9{6,}|0{6,}[1-9])/);
    expect(s.ticks.map((t) => tickLabel(t, s))).toEqual(['0', '0.0001', '0.0002', '0.0003']);
  });

  it('a flat or empty series still gets a range around it', () => {
    expect(coverRange(5, 5, 5).min).toBeLessThan(5);
    expect(coverRange(5, 5, 5).max).toBeGreaterThan(5);
    const empty = extent([[null, null]]);
    const r = coverRange(empty.min, empty.max, 5);
    expect(Number.isFinite(r.min) && Number.isFinite(r.max) && r.max > r.min).toBe(true);
  });
});

describe('log axis', () => {
  it('ticks at 1, 2, 5 per decade inside the range, placed by the logarithm', () => {
    const s = logScale(0.5, 89, 0, 600);
    expect(s.ticks).toEqual([0.5, 1, 2, 5, 10, 20, 50]);
    expect(s.toPixel(0.5)).toBeCloseTo(0, 9);
    expect(s.toPixel(89)).toBeCloseTo(600, 9);
    // 5.1 deg sits near the middle of 0.5-89 (log ratio 0.449), far from the linear 0.05.
    expect(s.toPixel(5.1) / 600).toBeCloseTo(Math.log(5.1 / 0.5) / Math.log(89 / 0.5), 9);
    expect(s.toPixel(10) - s.toPixel(1)).toBeCloseTo(s.toPixel(1) - s.toPixel(0.1), 9);
    expect(s.ticks.map((t) => tickLabel(t, s))).toEqual(['0.5', '1', '2', '5', '10', '20', '50']);
  });

  it('only the decades over a wide range', () => {
    expect(logScale(0.001, 50, 0, 100).ticks).toEqual([0.001, 0.01, 0.1, 1, 10]);
  });
});

describe('line paths', () => {
  const id = (v: number) => v;
  it('one stroke through every point when nothing is missing', () => {
    expect(linePath([0, 1, 2], [5, 6, 7], id, id)).toBe('M0.0 5.0L1.0 6.0L2.0 7.0');
  });

  it('a missing value splits the line: a new M after each gap, nothing drawn through it', () => {
    const d = linePath([0, 1, 2, 3, 4, 5], [null, 1, 2, null, 4, 5], id, id);
    expect(d).toBe('M1.0 1.0L2.0 2.0M4.0 4.0L5.0 5.0');
    expect(d.match(/M/g)?.length).toBe(2);
    expect(linePath([0, 1], [null, Number.NaN], id, id)).toBe('');
  });

  it('maps through the scales', () => {
    const x = linearScale(0, 10, 0, 100, 5, false);
    const y = linearScale(0, 1, 50, 0, 5, false);
    expect(linePath([0, 10], [0, 1], x.toPixel, y.toPixel)).toBe('M0.0 50.0L100.0 0.0');
  });

  it('extent skips missing values', () => {
    expect(
      extent([
        [null, 3, 1],
        [7, null],
      ]),
    ).toEqual({ min: 1, max: 7 });
  });
});

describe('tick labels', () => {
  it('decimals from the step, never -0', () => {
    const s = linearScale(-1, 1, 0, 100, 4, true);
    expect(s.ticks.map((t) => tickLabel(t, s))).toEqual(['-1.0', '-0.5', '0', '0.5', '1.0']);
    expect(tickLabel(-0, s)).toBe('0');
    // A float residue of a zero tick (a sum of steps) is shown as 0, not -0.0.
    expect(tickLabel(-1e-13, s)).toBe('0');
    const wide = linearScale(-80, 10, 0, 100, 5, true);
    expect(wide.ticks.map((t) => tickLabel(t, wide))).toEqual(['-80', '-60', '-40', '-20', '0', '20']);
  });
});
