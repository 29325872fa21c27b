import { describe, expect, it } from 'vitest';
import { autoExaggeration, EXAGGERATION_STEPS, scaleBar } from '../../../src/core/output/drawingScale';

describe('auto vertical exaggeration of the profile view', () => {
  it('picks the largest step that keeps the feature within the fraction of the width', () => {
    // Width 4 mm, feature 0.2 mm: 0.2 k <= 1.4 -> k <= 7 -> 5.
    expect(autoExaggeration(4, 0.2)).toBe(5);
    // Ten times smaller feature: k <= 70 -> 50.
    expect(autoExaggeration(4, 0.02)).toBe(50);
    for (const [w, h] of [
      [4, 0.2],
      [10, 0.001],
      [0.5, 0.3],
    ] as const) {
      const k = autoExaggeration(w, h);
      expect(EXAGGERATION_STEPS).toContain(k);
      if (k > 1) expect(h * k).toBeLessThanOrEqual(0.35 * w);
      const next = EXAGGERATION_STEPS[EXAGGERATION_STEPS.indexOf(k) + 1];
      if (next !== undefined) expect(h * next).toBeGreaterThan(0.35 * w);
    }
  });

  it('true scale for a feature already tall, and for degenerate sizes', () => {
    expect(autoExaggeration(1, 1)).toBe(1);
    expect(autoExaggeration(0, 0.1)).toBe(1);
    expect(autoExaggeration(4, 0)).toBe(1);
    expect(autoExaggeration(Number.NaN, 0.1)).toBe(1);
    expect(autoExaggeration(4, Number.POSITIVE_INFINITY)).toBe(1);
  });
});

describe('profile scale bar', () => {
  it('the largest 1-2-5 length in the user unit, or in um / thou where that reads better', () => {
    expect(scaleBar(1.3, 'mm')).toEqual({ lengthMm: 1, text: '1 mm' });
    expect(scaleBar(3, 'mm')).toEqual({ lengthMm: 2, text: '2 mm' });
    expect(scaleBar(0.07, 'mm')).toEqual({ lengthMm: 0.05, text: '50 µm' });
    expect(scaleBar(250, 'mm')).toEqual({ lengthMm: 200, text: '200 mm' });
    expect(scaleBar(1.3, 'in')).toEqual({ lengthMm: 0.05 * 25.4, text: '0.05 in' });
    expect(scaleBar(0.2, 'in')?.text).toBe('5 thou');
    expect(scaleBar(0, 'mm')).toBeNull();
    expect(scaleBar(Number.NaN, 'mm')).toBeNull();
  });
});
