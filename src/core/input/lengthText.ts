/**
 * Lengths typed as people write them: a decimal (`0.5`, `0,5`, `1e-3`), a fraction (`1/2`, `3/8`),
 * a mixed number (`1 1/4`, `1-1/4`), each with an optional unit suffix (`0.5"`, `0.5 in`,
 * `12.7 mm`, `5 um`, `5 µm`, `0.2 thou`, `200 uin`), read as a number in the field's unit. Pure
 * (no DOM): the page's length fields use it, and anything may. Never returns NaN, Infinity or -0:
 * anything else is refused with one line saying why.
 */

/** A unit a length field shows its number in: mm, inch, or µm. */
export type FieldLengthUnit = 'mm' | 'in' | 'um';

/** The units a typed suffix can name, each in micrometres (exact: 1 in = 25.4 mm by definition). */
const MICROMETRES: Readonly<Record<string, number>> = {
  mm: 1000,
  cm: 10000,
  um: 1,
  in: 25400,
  thou: 25.4,
  uin: 0.0254,
};

/** Each suffix as typed (lower case) and the unit it names. */
const SUFFIXES: Readonly<Record<string, string>> = {
  mm: 'mm',
  millimeter: 'mm',
  millimeters: 'mm',
  millimetre: 'mm',
  millimetres: 'mm',
  cm: 'cm',
  um: 'um',
  '\u00b5m': 'um', // micro sign
  '\u03bcm': 'um', // Greek mu
  micron: 'um',
  microns: 'um',
  '"': 'in',
  '\u201d': 'in', // a right double quote, as phones' keyboards type "
  "''": 'in',
  in: 'in',
  inch: 'in',
  inches: 'in',
  thou: 'thou',
  mil: 'thou',
  mils: 'thou',
  uin: 'uin',
  '\u00b5in': 'uin',
  '\u03bcin': 'uin',
};

/** The longest text read (a length is never longer; a pasted page is refused at once). */
export const LENGTH_TEXT_MAX_CHARS = 40;

/** What reading a typed length gives: its value in the field's unit, or why it cannot be read. */
export type LengthTextResult =
  | { readonly ok: true; readonly value: number; readonly written: boolean }
  | { readonly ok: false; readonly reason: string };

const DECIMAL = /^\d+\.?\d*(?:e[+-]?\d+)?$|^\.\d+(?:e[+-]?\d+)?$/;
const INTEGER = /^\d+$/;
/** sign, the number part, the unit suffix (letters, µ/μ, quotes), after optional spaces. */
const SHAPE = /^([+-]?)([0-9.,/ \-e+]*?[0-9.])\s*([a-z\u00b5\u03bc"'\u201d]*)$/;

function refuse(reason: string): LengthTextResult {
  return { ok: false, reason };
}

/**
 * The number part: a decimal (a single decimal comma accepted), a fraction `n/d` of whole
 * numbers, or a whole number and a fraction (`1 1/4`, `1-1/4`). Null when it is none of these.
 */
function numberPart(text: string): { value: number; fraction: boolean } | 'zero-denominator' | null {
  const t = /^[^,.]*,[^,.]*$/.test(text) ? text.replace(',', '.') : text;
  if (DECIMAL.test(t)) return { value: Number(t), fraction: false };
  const mixed = /^(\d+)(?: +| *- *)(\d+) *\/ *(\d+)$/.exec(t);
  const simple = /^(\d+) *\/ *(\d+)$/.exec(t);
  const [whole, num, den] = mixed ? [mixed[1], mixed[2], mixed[3]] : simple ? ['0', simple[1], simple[2]] : [];
  if (whole === undefined || num === undefined || den === undefined) return null;
  if (!INTEGER.test(den) || Number(den) === 0) return 'zero-denominator';
  return { value: Number(whole) + Number(num) / Number(den), fraction: true };
}

/**
 * Reads a length as typed into a field that shows `fieldUnit`: `1/2`, `1 1/4`, `0.5"`, `12.7 mm`,
 * `5 µm`, `0.2 thou`, `200 uin` (case and spaces free). A number without a suffix is in the
 * field's unit. `written` is true when the text is not a plain decimal (a fraction or a suffix: the
 * page then shows the number it means). Refused, with a reason: an empty text, a text over
 * {@link LENGTH_TEXT_MAX_CHARS} characters, an unknown unit, a zero denominator, `1/2/3`, two
 * signs, hexadecimal, `NaN`, `Infinity`, and a value beyond the range of a double (`1e999`).
 */
export function parseLengthText(text: string, fieldUnit: FieldLengthUnit): LengthTextResult {
  if (text.length > LENGTH_TEXT_MAX_CHARS) return refuse(`too long (over ${LENGTH_TEXT_MAX_CHARS} characters)`);
  const t = text.trim().toLowerCase();
  if (t === '') return refuse('empty');
  const shape = SHAPE.exec(t);
  if (shape === null) return refuse('not a length (a number, a fraction such as 1/2, and a unit such as mm or in)');
  const [, sign = '', digits = '', suffix = ''] = shape;
  const unit = suffix === '' ? fieldUnit : SUFFIXES[suffix];
  if (unit === undefined) return refuse(`unknown unit "${suffix}" (mm, um, in, ", thou, uin)`);
  const number = numberPart(digits.trim());
  if (number === 'zero-denominator') return refuse('a fraction with a zero denominator');
  if (number === null) return refuse('not a length (a number, a fraction such as 1/2, and a unit such as mm or in)');
  const from = MICROMETRES[unit] ?? 1;
  const to = MICROMETRES[fieldUnit] ?? 1;
  // Whole factors first (12.7 mm * 1000 / 25400 is exactly 0.5 in).
  const magnitude = from === to ? number.value : (number.value * from) / to;
  if (!Number.isFinite(magnitude)) return refuse('beyond the range of numbers');
  const value = magnitude === 0 ? 0 : sign === '-' ? -magnitude : magnitude;
  return { ok: true, value, written: number.fraction || suffix !== '' };
}

/** The suffix {@link formatLengthText} writes for each unit. */
const WRITTEN_SUFFIX: Readonly<Record<FieldLengthUnit | 'thou' | 'uin', string>> = {
  mm: 'mm',
  in: 'in',
  um: '\u00b5m',
  thou: 'thou',
  uin: 'uin',
};

/**
 * A length as a person writes it, `0.5 in`: the shortest decimal that reads back as the same
 * double, then the unit. {@link parseLengthText} reads it back exactly (into the same unit).
 */
export function formatLengthText(value: number, unit: FieldLengthUnit | 'thou' | 'uin'): string {
  return `${String(value === 0 ? 0 : value)} ${WRITTEN_SUFFIX[unit]}`;
}
