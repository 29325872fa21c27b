/**
 * "Use the balanced feed" sets fz to fz* rounded down to the step-over's resolution in the unit on
 * screen (src/ui/shopFeed.ts): never above fz* (so hf <= h), within one step of it, a short number.
 */
import { describe, expect, it } from 'vitest';
import { fromMm } from '../../src/core/input/units';
import type { FinishInputs } from '../../src/ui/finishRequest';
import { balancedFeedFields, shopFeed } from '../../src/ui/shopFeed';
import { finishInputsOf } from '../support/finishInputs';

describe('the balanced feed as the page sets it', () => {
  it('mm: 0.1 µm steps, rounded down', () => {
    expect(fromMm(shopFeed(0.92741345796649899, 'mm'), 'mm')).toBe(0.9274);
    expect(shopFeed(2.0702379778358155, 'mm')).toBe(2.0702);
    // 1.13 * 1e4 is 11299.999... in binary: still 1.13, not 1.1299.
    expect(shopFeed(1.13, 'mm')).toBe(1.13);
  });
  it('inch: 10 µin steps, rounded down, never above fz*', () => {
    const fz = 0.92741345796649899;
    const set = shopFeed(fz, 'in');
    expect(set).toBeLessThanOrEqual(fz);
    expect(fz - set).toBeLessThan(25.4e-5);
    expect(String(Math.round(fromMm(set, 'in') * 1e5) / 1e5)).toBe('0.03651');
  });
  it('a feed below the resolution is kept as it is (no zero feed)', () => {
    expect(shopFeed(3e-5, 'mm')).toBe(3e-5);
  });
});

/** The finish fields with 4 teeth (mm, mm/min, rpm). */
const inputs = (values: Partial<FinishInputs['values']>, unit: 'mm' | 'in' = 'mm') =>
  finishInputsOf({ flutes: 4, ...values }, unit);

describe('"use the balanced feed" with the feed rate and spindle speed', () => {
  const fzStar = 0.92741345796649899;
  it('sets F = fz* n z at the spindle speed, rounded down to 1 mm/min (fz then just below fz*)', () => {
    const set = balancedFeedFields(fzStar, inputs({ feedRate: 2400, spindleSpeed: 6000 }));
    expect(set).toEqual({ F: 22257 });
    if (!('F' in set)) throw new Error('F');
    const fz = set.F / (6000 * 4);
    expect(fz).toBeLessThanOrEqual(fzStar);
    expect(fzStar - fz).toBeLessThan(1 / (6000 * 4));
  });
  it('in inches: 0.1 in/min steps', () => {
    const set = balancedFeedFields(fzStar, inputs({ feedRate: 40 * 25.4, spindleSpeed: 10000 }, 'in'));
    if (!('F' in set)) throw new Error('F');
    // fz* n z = 0.0365123 in x 40,000 = 1460.49 in/min: 1460.4.
    expect(fromMm(set.F, 'in')).toBeCloseTo(1460.4, 9);
  });
  it('sets fz while fz is typed (F and n are then off), or when F or n is not a number', () => {
    expect(balancedFeedFields(fzStar, inputs({ fz: 0.1 }))).toEqual({ fz: shopFeed(fzStar, 'mm') });
    expect(balancedFeedFields(fzStar, inputs({ feedRate: 2400, spindleSpeed: 'x' }))).toEqual({
      fz: shopFeed(fzStar, 'mm'),
    });
  });
});
