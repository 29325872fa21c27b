/**
 * A unit switch (issue 28 point 11): untouched defaults become the new unit's own round defaults,
 * values the user set convert with enough digits to come back exactly as typed, and a field's
 * number never carries float noise nor loses digits.
 */
import { describe, expect, it } from 'vitest';
import { PAGE_FIELD_KEYS } from '../../src/core/input/fields';
import { seededRandom as random } from '../../src/core/math/seededRandom';
import { convertLength } from '../../src/ui/fieldText';
import { buildRequest } from '../../src/ui/request';
import {
  convertState,
  DEFAULT_FIELDS_IN,
  DEFAULT_FIELDS_MM,
  defaultState,
  formatField,
  isLengthField,
  parseUrl,
  withField,
  withSize,
  withValues,
} from '../../src/ui/state';

const SEED = 2812;

/** Typed numbers: every count of significant digits 1 to 11 at every decade 1e-5 to 1e5, 12 of each. */
function typedNumbers(seed: number): string[] {
  const next = random(seed);
  const out: string[] = [];
  for (let digits = 1; digits <= 11; digits++)
    for (let decade = -5; decade <= 5; decade++)
      for (let i = 0; i < 12; i++) {
        // A mantissa of exactly `digits` digits, its last one not 0.
        let m = Math.floor(10 ** (digits - 1) + next() * 9 * 10 ** (digits - 1));
        if (m % 10 === 0) m += 1 + Math.floor(next() * 9);
        if (m >= 10 ** digits) m = 10 ** digits - 1;
        out.push(formatField(Number(`${m}e${decade - digits + 1}`)));
      }
  return out;
}

describe('a field number: no float noise, nothing lost', () => {
  it('writes the fewest digits that give the number', () => {
    expect(formatField(0.1 + 0.2)).toBe('0.3');
    expect(formatField(0.762 * (1 - 1e-16))).toBe('0.762');
    expect(formatField(12.7)).toBe('12.7');
    expect(formatField(0.5)).toBe('0.5');
    expect(formatField(3 / 25.4)).toBe('0.1181102362205');
    expect(formatField(1 / 3)).toBe('0.333333333333');
    expect(formatField(Number.NaN)).toBe('');
    expect(formatField(-0)).toBe('0');
  });
});

describe(`typed lengths switch mm -> in -> mm (and in -> mm -> in) back to what was typed (seed ${SEED})`, () => {
  const typed = typedNumbers(SEED);
  it(`${typed.length} numbers of 1 to 11 significant digits over ten decades, in every length field (seed ${SEED})`, () => {
    const wrong: string[] = [];
    const keys = PAGE_FIELD_KEYS.filter(isLengthField);
    typed.forEach((t, i) => {
      const key = keys[i % keys.length] ?? 'h';
      for (const [from, to] of [
        ['mm', 'in'],
        ['in', 'mm'],
      ] as const) {
        const start = withField(defaultState(from), key, t);
        const there = convertState(start, to);
        const back = convertState(there, from);
        if (back.fields[key] !== t)
          wrong.push(`${key} ${t} ${from} -> ${there.fields[key]} ${to} -> ${back.fields[key]}`);
        // The converted text is the same length to 1e-12 (what the solver is given).
        const v = Number(t);
        const converted = Number(there.fields[key]) * (to === 'in' ? 25.4 : 1 / 25.4);
        if (Math.abs(converted - v) > 1e-12 * v) wrong.push(`${key} ${t} ${from} -> ${there.fields[key]} ${to} is off`);
        // Switched once more, the field reads as the first switch wrote it.
        if (convertState(back, to).fields[key] !== there.fields[key])
          wrong.push(`${key} ${t}: a second switch differs`);
      }
    });
    expect(wrong.slice(0, 5)).toEqual([]);
  });

  it('as typed, to the character: 3.50 mm comes back 3.50; an edit after the switch is converted anew', () => {
    const inch = convertState(withField(defaultState(), 'h', '0.050'), 'in');
    expect(inch.fields.h).toBe('0.001968503937008');
    expect(convertState(inch, 'mm').fields.h).toBe('0.050');
    const edited = withField(inch, 'h', '0.001');
    expect(convertState(edited, 'mm').fields.h).toBe('0.0254');
  });

  it('exact conversions read short: 25.4 mm is 1 in, 12.7 mm 0.5 in, 0.762 mm 0.03 in', () => {
    expect(convertLength(25.4, 'mm', 'in')).toBe('1');
    // A value the page computed in inch and set in mm ("use this pair": 0.00467 in), read back as it was.
    expect(convertLength(0.00467 * 25.4, 'mm', 'in')).toBe('0.00467');
    expect(convertLength(12.7, 'mm', 'in')).toBe('0.5');
    expect(convertLength(0.762, 'mm', 'in')).toBe('0.03');
    expect(convertLength(0.03, 'in', 'mm')).toBe('0.762');
    expect(convertLength(3.5, 'mm', 'in')).toBe('0.1377952755906');
  });
});

describe("untouched defaults become the unit's own round defaults", () => {
  it('h 0.05 mm reads 0.002 in; the tool D6 R1 reads D 0.25 in, Rcr 0.03 in; and back', () => {
    const inch = convertState(parseUrl('').state, 'in');
    expect(inch.size).toBe('D');
    expect(inch.fields.R).toBe('0.25');
    expect(inch.fields.Rcr).toBe('0.03');
    expect(inch.fields.h).toBe('0.002');
    expect(inch.fields.Rf).toBe('3');
    expect(inch.fields.Rc).toBe('1.5');
    expect(convertState(inch, 'mm').fields).toEqual(parseUrl('').state.fields);
  });

  it.each(['R', 'D'] as const)('every field, size %s: lengths to the other defaults, angles kept', (size) => {
    const mm = withSize(defaultState('mm'), size);
    const inch = convertState(mm, 'in');
    for (const key of PAGE_FIELD_KEYS) {
      const factor = key === 'R' && size === 'D' ? 2 : 1;
      const want = isLengthField(key) ? DEFAULT_FIELDS_IN[key] : DEFAULT_FIELDS_MM[key];
      expect(Number(inch.fields[key]), key).toBe(factor * Number(want));
      // Each inch default is within 30 % of its mm default (the same kind of question).
      const ratio = (Number(inch.fields[key]) * (isLengthField(key) ? 25.4 : 1)) / Number(mm.fields[key]);
      if (Number(mm.fields[key]) !== 0) expect(Math.abs(ratio - 1), key).toBeLessThan(0.3);
    }
    expect(convertState(inch, 'mm').fields).toEqual(mm.fields);
    // The inch defaults make a valid question, as the mm ones do.
    expect(buildRequest(inch).ok).toBe(true);
    expect(buildRequest(defaultState('in')).ok).toBe(true);
  });

  it('a value the user set converts exactly, even when it equals the default', () => {
    // Typed: h 0.05 mm is 0.0019685... in (not the inch default 0.002 in = 0.0508 mm).
    const typed = convertState(withField(defaultState(), 'h', '0.05'), 'in');
    expect(Number(typed.fields.h) * 25.4).toBeCloseTo(0.05, 14);
    expect(convertState(typed, 'mm').fields.h).toBe('0.05');
    // A tool chosen (a preset, a library tool) that is D6 R1 stays D6 R1 in inches.
    const tool = convertState(withValues(withSize(defaultState(), 'D'), { R: 3, Rcr: 1 }), 'in');
    expect(Math.abs(Number(tool.fields.R) * 25.4 - 6)).toBeLessThan(6e-12);
    expect(Math.abs(Number(tool.fields.Rcr) * 25.4 - 1)).toBeLessThan(1e-12);
    expect(convertState(tool, 'mm').fields.R).toBe('6');
    // The untouched fields beside it still take the inch defaults.
    expect(tool.fields.h).toBe('0.002');
  });

  it('invalid text and angles are kept as typed', () => {
    const s = convertState(withField(withField(defaultState(), 'h', '0,0x'), 'rho', '7.25'), 'in');
    expect(s.fields.h).toBe('0,0x');
    expect(s.fields.rho).toBe('7.25');
  });
});
