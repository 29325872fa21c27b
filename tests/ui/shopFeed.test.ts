/**
 * "Use the balanced feed" sets fz to fz* rounded down to the step-over's resolution in the unit on
 * screen (src/ui/shopFeed.ts): never above fz* (so hf <= h), within one step of it, a short number.
 */
import { describe, expect, it } from 'vitest';
import { fromMm } from '../../src/core/input/units';
import { shopFeed } from '../../src/ui/shopFeed';

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
