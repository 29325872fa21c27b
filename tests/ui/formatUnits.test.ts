/**
 * The page's one rule for a shown length (issue 21, "Units everywhere"): every length with its
 * unit, µm (micro sign) below 0.1 mm and thou below 0.01 in, never exponent notation, never -0;
 * roughness in µm in mm and in µin in inch, whatever its size.
 */
import { describe, expect, it } from 'vitest';
import { MICROINCH_SYMBOL, MICROMETRE_SYMBOL, roughnessUnit } from '../../src/core/input/units';
import { formatLenUnit, formatRoughness, formatSignedLenUnit } from '../../src/ui/format';

const UNIT_AFTER_NUMBER = /^[+-]?\d+(\.\d+)? (mm|in|\u00b5m|thou)$/;

describe('a shown length carries its unit', () => {
  it('reads in mm or in, and in µm or thou when small, with the micro sign', () => {
    expect(MICROMETRE_SYMBOL).toBe('\u00b5m');
    expect(MICROINCH_SYMBOL).toBe('\u00b5in');
    expect(formatLenUnit(0.4861, 'mm')).toBe('0.4861 mm');
    expect(formatLenUnit(0.05, 'mm', 'height')).toBe('50.00 \u00b5m');
    expect(formatLenUnit(25.4 * 0.0002, 'in', 'height')).toBe('0.2000 thou');
    expect(formatLenUnit(25.4, 'in')).toBe('1.00000 in');
  });

  it('tiny values are in the sub-unit in plain decimals, never exponent notation (the inverse table)', () => {
    // Bedi's deviation in inverse mode, R = 3, Rcr = 1, rho = 5, L = 0.5 mm: +1.981e-7 mm.
    expect(formatSignedLenUnit(1.981e-7, 'mm', 'height')).toBe('+0.0001981 \u00b5m');
    expect(formatSignedLenUnit(1.981e-7, 'mm')).toBe('+0.0001981 \u00b5m');
    expect(formatLenUnit(6.287e-7, 'mm', 'fine')).toBe('0.0006287 \u00b5m');
    expect(formatLenUnit(3e-9, 'mm')).toBe('0.000003000 \u00b5m');
    expect(formatLenUnit(3e-9, 'in')).toBe('0.0000001181 thou');
    for (let e = -15; e <= 6; e += 0.5)
      for (const unit of ['mm', 'in'] as const)
        for (const v of [10 ** e, -(10 ** e)]) {
          const text = formatLenUnit(v, unit, 'height');
          expect(text, `${v} ${unit}`).toMatch(UNIT_AFTER_NUMBER);
          expect(text).not.toMatch(/e[+-]?\d/);
        }
  });

  it('zero and negative zero read in the user unit, unsigned; huge values in plain decimals', () => {
    expect(formatLenUnit(0, 'mm')).toBe('0.0000 mm');
    expect(formatLenUnit(-0, 'mm')).toBe('0.0000 mm');
    expect(formatSignedLenUnit(-0, 'in')).toBe('0.00000 in');
    expect(formatSignedLenUnit(-1e-30, 'mm')).not.toMatch(/^-0(\.0*)? /);
    expect(formatLenUnit(123456.789, 'mm')).toBe('123456.7890 mm');
    expect(formatLenUnit(2.54e7, 'in')).toBe('1000000.00000 in');
  });
});

describe('roughness reads in µm in mm and in µin in inch, whatever its size', () => {
  it('µm in mm', () => {
    expect(roughnessUnit('mm')).toEqual({ symbol: '\u00b5m', perMm: 1000 });
    expect(formatRoughness(0.005, 'mm')).toBe('5.000 \u00b5m');
    expect(formatRoughness(0.00128, 'mm')).toBe('1.280 \u00b5m');
    expect(formatRoughness(0.3, 'mm')).toBe('300.00 \u00b5m');
    expect(formatRoughness(3.358e-7, 'mm')).toBe('0.0003358 \u00b5m');
  });

  it('µin in inch (the US convention)', () => {
    expect(formatRoughness(25.4 * 0.0002, 'in')).toBe('200.0 \u00b5in');
    expect(formatRoughness(25.4 * 0.00005119, 'in')).toBe('51.19 \u00b5in');
    expect(formatRoughness(25.4 * 1e-9, 'in')).toBe('0.001000 \u00b5in');
  });

  it('zero, negative zero, null and non-finite values', () => {
    expect(formatRoughness(0, 'mm')).toBe('0.00 \u00b5m');
    expect(formatRoughness(-0, 'in')).toBe('0 \u00b5in');
    expect(formatRoughness(-1e-40, 'mm')).not.toMatch(/^-/);
    expect(formatRoughness(null, 'mm')).toBe('\u2014');
    expect(formatRoughness(Number.NaN, 'in')).toBe('\u2014');
    expect(formatRoughness(Number.POSITIVE_INFINITY, 'mm')).toBe('\u2014');
  });
});
