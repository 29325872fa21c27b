/** Lengths typed as people write them: fractions, mixed numbers and unit suffixes, and what is refused. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import {
  type FieldLengthUnit,
  formatLengthText,
  LENGTH_TEXT_MAX_CHARS,
  parseLengthText,
} from '../../../src/core/input/lengthText';

const SEED = 20261125;

/** The value read, or the test fails with the reason. */
function value(text: string, unit: FieldLengthUnit): number {
  const r = parseLengthText(text, unit);
  if (!r.ok) throw new Error(`${text}: ${r.reason}`);
  return r.value;
}

describe('lengths as people write them', () => {
  it.each([
    ['1/2', 'in', 0.5],
    ['3/8', 'in', 0.375],
    ['1 1/4', 'in', 1.25],
    ['1-1/4', 'in', 1.25],
    ['1 / 2', 'mm', 0.5],
    ['0.5"', 'mm', 12.7],
    ['1/2"', 'in', 0.5],
    ['1/2"', 'mm', 12.7],
    ['0.5 in', 'mm', 12.7],
    ['0.5in', 'mm', 12.7],
    ['0.5 IN', 'mm', 12.7],
    ['2 inches', 'mm', 50.8],
    ['12.7 mm', 'in', 0.5],
    ['12.7 mm', 'mm', 12.7],
    ['12,7 mm', 'in', 0.5],
    ['5 um', 'mm', 0.005],
    ['5 \u00b5m', 'mm', 0.005],
    ['5 \u03bcm', 'mm', 0.005],
    ['5 microns', 'um', 5],
    ['0.2 thou', 'in', 0.0002],
    ['0.2 mil', 'in', 0.0002],
    ['200 uin', 'in', 0.0002],
    ['200 \u00b5in', 'in', 0.0002],
    ['1 cm', 'mm', 10],
    ['0.05 mm', 'um', 50],
    ['.5', 'mm', 0.5],
    ['1e-3 in', 'in', 0.001],
    ['  7  ', 'mm', 7],
    ['-1/2"', 'mm', -12.7],
    ['+3', 'mm', 3],
  ] as const)('%s in a %s field is %f', (text, unit, want) => {
    expect(value(text, unit)).toBeCloseTo(want, 12);
  });

  it('whole factors first: 12.7 mm is exactly 0.5 in, 0.5 in exactly 12.7 mm', () => {
    expect(value('12.7 mm', 'in')).toBe(0.5);
    expect(value('0.5"', 'mm')).toBe(12.7);
    expect(value('200 uin', 'in')).toBe(0.0002);
  });

  it('marks written forms (a fraction or a suffix) but not a plain number', () => {
    expect(parseLengthText('0.5', 'mm')).toEqual({ ok: true, value: 0.5, written: false });
    expect(parseLengthText('1/2', 'mm')).toEqual({ ok: true, value: 0.5, written: true });
    expect(parseLengthText('0.5 mm', 'mm')).toEqual({ ok: true, value: 0.5, written: true });
  });

  it('never gives -0', () => {
    expect(Object.is(value('-0', 'mm'), 0)).toBe(true);
    expect(Object.is(value('-0/4 in', 'mm'), 0)).toBe(true);
    expect(Object.is(value('-1e-400', 'mm'), 0)).toBe(true);
  });

  it.each([
    ['1/0', /zero denominator/],
    ['0/0', /zero denominator/],
    ['1 1/0 in', /zero denominator/],
    ['1e999', /beyond the range/],
    ['1e308 in', /beyond the range/],
    ['--1', /not a length/],
    ['+-1', /not a length/],
    ['1/2/3', /not a length/],
    ['1.5/2', /not a length/],
    ['NaN', /not a length/],
    ['nan mm', /not a length/],
    ['Infinity', /not a length/],
    ['-Infinity', /not a length/],
    ['0x10', /not a length/],
    ['', /empty/],
    ['   ', /empty/],
    ['mm', /not a length/],
    ['1 ft', /unknown unit "ft"/],
    ["3'", /unknown unit "'"/],
    ['1..2', /not a length/],
    ['1,000.5', /not a length/],
    ['1 2', /not a length/],
    ['<img src=x onerror=alert(1)>', /not a length/],
  ] as const)('refuses %j with a reason', (text, reason) => {
    const r = parseLengthText(text, 'mm');
    expect(r.ok).toBe(false);
    if (!r.ok) expect(r.reason).toMatch(reason);
  });

  it('refuses long strings at once (a pasted page), without reading them', () => {
    for (const text of ['1'.repeat(LENGTH_TEXT_MAX_CHARS + 1), `1${' '.repeat(10_000)}mm`, '1/'.repeat(1e6)]) {
      const r = parseLengthText(text, 'in');
      expect(r.ok || r.reason).toMatch(/too long \(over 40 characters\)/);
    }
  });

  const units = fc.constantFrom<FieldLengthUnit>('mm', 'in', 'um');
  const written = fc.constantFrom<FieldLengthUnit | 'thou' | 'uin'>('mm', 'in', 'um', 'thou', 'uin');
  const PER_UM = { mm: 1000, in: 25400, um: 1, thou: 25.4, uin: 0.0254 } as const;

  it('property: format then parse gives the value back (same unit exactly, another unit by the factor)', () => {
    fc.assert(
      fc.property(fc.double({ min: -1e6, max: 1e6, noNaN: true }), written, units, (v, from, to) => {
        const text = formatLengthText(v, from);
        const same = from === 'thou' || from === 'uin' ? null : parseLengthText(text, from);
        if (same !== null) expect(same).toEqual({ ok: true, value: v === 0 ? 0 : v, written: true });
        const r = parseLengthText(text, to);
        expect(r.ok).toBe(true);
        if (!r.ok) return;
        const want = (v * PER_UM[from]) / PER_UM[to];
        expect(Math.abs(r.value - want)).toBeLessThanOrEqual(Math.abs(want) * 4e-16);
        expect(Number.isFinite(r.value) && !Object.is(r.value, -0)).toBe(true);
      }),
      { seed: SEED, numRuns: 2000 },
    );
  });

  it('property: a mixed number w n/d reads as w + n/d', () => {
    fc.assert(
      fc.property(fc.nat(1000), fc.nat(1000), fc.integer({ min: 1, max: 1000 }), (w, n, d) => {
        expect(value(`${w} ${n}/${d}`, 'in')).toBe(w + n / d);
        expect(value(`${w}-${n}/${d}"`, 'in')).toBe(w + n / d);
      }),
      { seed: SEED, numRuns: 500 },
    );
  });

  it('property: any string gives a finite value or a reason, never NaN or Infinity', () => {
    const alphabet = fc.constantFrom(...'0123456789./-+ ,e"\'xinmu\u00b5\u03bcthoa'.split(''));
    fc.assert(
      fc.property(fc.oneof(fc.string(), fc.string({ unit: alphabet, maxLength: 20 })), units, (text, unit) => {
        const r = parseLengthText(text, unit);
        if (r.ok) expect(Number.isFinite(r.value) && !Object.is(r.value, -0)).toBe(true);
        else expect(r.reason.length).toBeGreaterThan(0);
      }),
      { seed: SEED, numRuns: 5000 },
    );
  });
});
