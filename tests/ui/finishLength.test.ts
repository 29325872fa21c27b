/**
 * The finish box's feed lengths (src/ui/finishLength.ts): the period, fz*, the cell's sides and the
 * profile's x in the user's unit, never a sub-unit (the tester's "period in thou beside fz* in
 * inch"), at the fine resolution; a dash for none.
 */
import { describe, expect, it } from 'vitest';
import { feedLength } from '../../src/ui/finishLength';

describe('feedLength', () => {
  it('keeps the unit on screen where the page rule would switch to thou or µm', () => {
    expect(feedLength(0.001 * 25.4, 'in')).toBe('0.0010000 in');
    expect(feedLength(0.0365123 * 25.4, 'in')).toBe('0.0365123 in');
    expect(feedLength(0.05, 'mm')).toBe('0.050000 mm');
    expect(feedLength(0.927413457, 'mm')).toBe('0.927413 mm');
  });

  it("plain decimals for a tiny feed, 0 for a position's rounding noise (the tester's x = 2.151e-16 mm)", () => {
    expect(feedLength(8.962e-7, 'mm')).toBe('0.0000008962 mm');
    expect(feedLength(2.151e-16, 'mm')).toBe('0.000000 mm');
    expect(feedLength(-2.151e-16, 'in')).toBe('0.0000000 in');
  });

  it('a dash for no value, never NaN or -0', () => {
    expect(feedLength(null, 'mm')).toBe('\u2014');
    expect(feedLength(Number.NaN, 'in')).toBe('\u2014');
    expect(feedLength(-0, 'mm')).toBe('0.000000 mm');
  });
});
