/** Numbers as the page shows them: at least four significant digits, the user's unit, never -0 or NaN. */
import { describe, expect, it } from 'vitest';
import { formatAngleDeg, formatInputNumber, formatPercent } from '../../src/core/input/units';
import {
  formatDeg,
  formatLen,
  formatLenUnit,
  formatRadAsDeg,
  formatSignedLen,
  formatSignedLenUnit,
  formatSignedPercent,
} from '../../src/ui/format';

describe('page number formatting', () => {
  it('keeps the fixed resolution for usual sizes (0.1 um in mm, 10 uin in inch)', () => {
    expect(formatLen(1.443592412967, 'mm')).toBe('1.4436');
    expect(formatLen(2.168976694, 'in')).toBe('0.08539');
    expect(formatLen(0.0525412, 'mm', 'height')).toBe('0.05254');
    expect(formatLen(1.892088335855, 'mm', 'fine')).toBe('1.892088');
    expect(formatLenUnit(2.887184825934, 'mm')).toBe('2.8872 mm');
  });

  it('shows at least four significant digits for tiny values: the micro tool reads, never 0.0000', () => {
    // R = Rcr = 0.001 mm, h = 1e-6 mm: L/2 = sqrt(2 Rcr h - h^2) = 4.4710e-5 mm.
    const half = Math.sqrt(2 * 0.001 * 1e-6 - 1e-12);
    expect(formatLen(half, 'mm')).toBe('0.00004471');
    expect(formatLen(1e-6, 'mm', 'height')).toBe('0.000001000');
    expect(formatLen(3e-9, 'mm')).toBe('3.000e-9');
    expect(formatLen(half, 'in')).toMatch(/^0\.000001760$|^1\.760e-6$/);
  });

  it('never prints -0, NaN or Infinity; signed values carry their sign', () => {
    expect(formatSignedLen(-0, 'mm')).toBe('0.0000');
    expect(formatSignedLen(-1e-12, 'mm')).toBe('-1.000e-12');
    expect(formatSignedLen(-0, 'in')).toBe('0.00000');
    expect(formatSignedLen(0.103095, 'mm')).toBe('+0.1031');
    expect(formatSignedLen(-0.357855, 'mm')).toBe('-0.3579');
    expect(formatLen(Number.NaN, 'mm')).toBe('\u2014');
    expect(formatLen(null, 'mm')).toBe('\u2014');
    expect(formatLenUnit(Number.POSITIVE_INFINITY, 'in')).toBe('\u2014');
    // Percentages have fixed decimals: a tiny negative deviation rounds to zero, unsigned.
    expect(formatPercent(-0.001)).toBe('0.00');
    expect(formatPercent(-0)).toBe('0.00');
    expect(formatPercent(-0.006)).toBe('-0.01');
    expect(formatPercent(7.1449)).toBe('+7.14');
    expect(formatPercent(Number.NaN)).toBe('\u2014');
  });

  it("a signed percentage (the chart legend's error) that rounds to zero reads 0.00, never -0.00 or +0.00", () => {
    // Bedi's error for R = 0.001, Rcr = 0, rho = 0.5, h = 1e-9 (issue 17): a few 1e-6 % below exact.
    expect(formatSignedPercent(-3e-6)).toBe('0.00');
    expect(formatSignedPercent(-0.004999)).toBe('0.00');
    expect(formatSignedPercent(-0)).toBe('0.00');
    expect(formatSignedPercent(2e-7)).toBe('0.00');
    expect(formatSignedPercent(-0.005001)).toBe('-0.01');
    expect(formatSignedPercent(-29.2812)).toBe('-29.28');
    expect(formatSignedPercent(0.125)).toBe('+0.13');
    expect(formatSignedPercent(null)).toBe('\u2014');
    expect(formatSignedPercent(Number.NaN)).toBe('\u2014');
  });

  it('no page formatter shows -0: negative values from 1e-330 to 100 and -0, in mm and inch', () => {
    const values = [-0];
    for (let e = -330; e <= 2; e += 0.25) for (const m of [1, 4.9999, 5, 5.0001, 9.99]) values.push(-m * 10 ** e);
    /** A text whose number (the part before a unit symbol) is zero yet carries a minus sign. */
    const negativeZero = (text: string) => {
      const number = text.split(' ')[0] ?? '';
      return number.startsWith('-') && Number(number) === 0;
    };
    const bad: string[] = [];
    for (const v of values)
      for (const unit of ['mm', 'in'] as const) {
        const shown = [
          formatLen(v, unit),
          formatLen(v, unit, 'height'),
          formatLen(v, unit, 'fine'),
          formatSignedLen(v, unit),
          formatLenUnit(v, unit),
          formatSignedLenUnit(v, unit, 'height'),
          formatDeg(v),
          formatRadAsDeg(v),
          formatSignedPercent(v),
          formatPercent(v, 1),
          formatInputNumber(v),
          formatAngleDeg(v),
        ];
        for (const text of shown) if (negativeZero(text)) bad.push(`${v} ${unit}: ${text}`);
      }
    expect(bad).toEqual([]);
  });
});

describe('the decimals of a length do not depend on noise below the resolution', () => {
  it('a value just below a power of ten that rounds up to it reads as one just above it (10.000 µm, 1.0000 mm, 0.10000 in)', () => {
    for (const eps of [1e-13, 1e-11, 1e-9]) {
      expect(formatLenUnit(0.01 * (1 - eps), 'mm', 'fine')).toBe('10.000 \u00b5m');
      expect(formatLenUnit(0.01 * (1 + eps), 'mm', 'fine')).toBe('10.000 \u00b5m');
      expect(formatLenUnit(1 - eps, 'mm')).toBe('1.0000 mm');
      expect(formatLenUnit(1 + eps, 'mm')).toBe('1.0000 mm');
      expect(formatLen(2.54 * (1 - eps), 'in')).toBe(formatLen(2.54 * (1 + eps), 'in'));
    }
  });
});
