/**
 * A field's text and its number: parsing as typed (a decimal comma accepted), formatting without
 * float noise, unit conversion by the field's kind (lengths converted, angles in degrees), and the
 * words a switch of the link takes. Pure; re-exported by state.ts.
 */
import { FIELDS, fieldOfPageKey, isLengthField as isLength, type PageFieldKey, urlParamOf } from '../core/input/fields';
import { formatInputNumber, fromMm, type LengthUnit, toMm } from '../core/input/units';

type FieldKey = PageFieldKey;
type Unit = LengthUnit;
const param = urlParamOf;

/** True for the fields that hold a length (converted with the unit); angles are degrees. */
export function isLengthField(key: FieldKey): boolean {
  return isLength(fieldOfPageKey(key));
}

/** Formats a number for a field: up to 6 significant digits, no float noise, no exponent for usual sizes. */
export function formatField(value: number): string {
  return Number.isFinite(value) ? formatInputNumber(value) : '';
}

const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

/**
 * A field's text with a decimal comma read as a decimal point (`0,05` is 0.05, as typed where the
 * comma is the decimal separator). Only a single comma and no point: `1,000.5` stays as it is (and
 * is not a number).
 */
export function withDecimalPoint(text: string): string {
  const t = text.trim();
  return /^[^,.]*,[^,.]*$/.test(t) ? t.replace(',', '.') : t;
}

/** Parses a field's text (a decimal comma accepted); null when it is not a plain finite number. */
export function parseField(text: string): number | null {
  const t = withDecimalPoint(text);
  if (!NUMBER.test(t)) return null;
  const v = Number(t);
  return Number.isFinite(v) ? v : null;
}

/** A value in mm or degrees as the text of a field in `unit`. */
export function fieldText(key: FieldKey, valueMm: number, unit: Unit): string {
  return formatField(isLengthField(key) ? fromMm(valueMm, unit) : valueMm);
}

/** Converts one field's text between units (angles unchanged, invalid text kept as is). */
export function convertField(key: FieldKey, text: string, from: Unit, to: Unit): string {
  if (from === to || !isLengthField(key)) return text;
  const v = parseField(text);
  if (v === null) return text;
  return formatField(fromMm(toMm(v, from), to));
}

/** The words a switch of the link takes (the field registry's values; the first is the default). */
export type ChoiceId = 'unit' | 'mode' | 'pattern' | 'target' | 'surfaceAxis' | 'machine' | 'passes';
type ChoiceOf<I extends ChoiceId> = (typeof FIELDS)[I]['values'][number];

/**
 * A switch's word in the link: one of its values (or an alias of one), else its default (the first
 * value) with a notice; the default when the link leaves it out.
 */
export function choice<I extends ChoiceId>(
  params: URLSearchParams,
  id: I,
  notices: string[],
  aliases: Readonly<Record<string, ChoiceOf<I>>> = {},
): ChoiceOf<I> {
  const values = FIELDS[id].values as readonly ChoiceOf<I>[];
  const fallback = values[0] as ChoiceOf<I>;
  const name = param(id);
  const text = params.get(name);
  if (text === null) return fallback;
  const found = values.find((v) => v === text) ?? aliases[text];
  if (found !== undefined) return found;
  notices.push(`${name}="${text.slice(0, 20)}" is not ${values.join(' or ')}; using ${fallback}.`);
  return fallback;
}
