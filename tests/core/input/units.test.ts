/**
 * Lengths into mm (core/input/units.ts toMm): a finite length stays finite, so that a range check
 * names its limit in the user's unit (the tester's 1e308 in read "must be a finite number").
 */
import { describe, expect, it } from 'vitest';
import { fromMm, toMm } from '../../../src/core/input/units';

describe('toMm', () => {
  it('keeps a finite inch length finite, the largest double at most; Infinity and NaN stay as they are', () => {
    expect(toMm(1e308, 'in')).toBe(Number.MAX_VALUE);
    expect(toMm(-1e308, 'in')).toBe(-Number.MAX_VALUE);
    expect(toMm(Number.POSITIVE_INFINITY, 'in')).toBe(Number.POSITIVE_INFINITY);
    expect(toMm(Number.NaN, 'in')).toBeNaN();
    expect(toMm(1e306, 'in')).toBe(1e306 * 25.4);
    expect(fromMm(toMm(0.125, 'in'), 'in')).toBe(0.125);
  });
});
