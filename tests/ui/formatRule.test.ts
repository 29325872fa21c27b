/**
 * One rule for each kind of number (issue 28 point 11): computed angles at 0.01 deg, always two
 * decimals; roughness at the heights' resolution, so Rz of a scallop reads as the scallop does in
 * the table (50.00 µm both); never NaN, Infinity or -0.
 */
import { describe, expect, it } from 'vitest';
import { seededRandom as random } from '../../src/core/math/seededRandom';
import { ANGLE_DECIMALS, formatAngle, formatLenUnit, formatRadAsDeg, formatRoughness } from '../../src/ui/format';

const SEED = 2811;

describe('computed angles: two decimals, side by side alike', () => {
  it('the equivalent lead and tilt of the issue read 27.31 deg and 12.92 deg', () => {
    expect(formatAngle(27.3117)).toBe('27.31 deg');
    expect(formatAngle(12.921)).toBe('12.92 deg');
    expect(formatAngle(5)).toBe('5.00 deg');
    expect(formatAngle(-3.14159)).toBe('-3.14 deg');
    expect(formatRadAsDeg(Math.atan(1))).toBe('45.00 deg');
  });

  it('never -0, NaN or Infinity', () => {
    expect(formatAngle(-0)).toBe('0.00 deg');
    expect(formatAngle(-0.004)).toBe('0.00 deg');
    expect(formatAngle(null)).toBe('\u2014');
    expect(formatAngle(Number.NaN)).toBe('\u2014');
    expect(formatAngle(Number.NEGATIVE_INFINITY)).toBe('\u2014');
  });

  it(`every angle from -90 to 90 deg has exactly ${ANGLE_DECIMALS} decimals and rounds to 0.01 (seed ${SEED})`, () => {
    const next = random(SEED);
    for (let stratum = 0; stratum < 18; stratum++)
      for (let i = 0; i < 50; i++) {
        const deg = -90 + 10 * stratum + 10 * next();
        const text = formatAngle(deg);
        expect(text, String(deg)).toMatch(/^-?\d{1,2}\.\d{2} deg$/);
        expect(Math.abs(Number.parseFloat(text) - deg), String(deg)).toBeLessThanOrEqual(0.005 + 1e-12);
      }
  });
});

describe('roughness at the resolution of every height', () => {
  it('Rz of a 0.05 mm scallop reads 50.00 µm, as the scallop itself', () => {
    expect(formatRoughness(0.05, 'mm')).toBe('50.00 \u00b5m');
    expect(formatLenUnit(0.05, 'mm', 'height')).toBe('50.00 \u00b5m');
    expect(formatRoughness(0.002 * 25.4, 'in')).toBe('2000 \u00b5in');
    expect(formatLenUnit(0.002 * 25.4, 'in', 'height')).toBe('2.000 thou');
  });

  it(`in mm a roughness in µm reads as a height does (seed ${SEED})`, () => {
    const next = random(SEED);
    // Heights 1 µm to 99 µm: both in µm, at 0.01 µm.
    for (let decade = 0; decade < 2; decade++)
      for (let i = 0; i < 100; i++) {
        const mm = 10 ** (decade - 3) * (1 + 9 * next());
        expect(formatRoughness(mm, 'mm'), String(mm)).toBe(formatLenUnit(mm, 'mm', 'height'));
      }
  });

  it(`in inch a roughness in µin has the resolution of a height in thou, 1 µin (seed ${SEED})`, () => {
    const next = random(SEED + 1);
    for (let i = 0; i < 200; i++) {
      // 1 to 10 thou: both have 4 significant digits at 1 µin.
      const mm = 25.4e-3 * (1 + 9 * next());
      const microInch = Number.parseFloat(formatRoughness(mm, 'in'));
      const thou = Number.parseFloat(formatLenUnit(mm, 'in', 'height'));
      expect(Number.isInteger(microInch), String(mm)).toBe(true);
      expect(microInch, String(mm)).toBe(Math.round(thou * 1000));
    }
  });
});
