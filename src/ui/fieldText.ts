/**
 * A field's text and its number: parsing as typed (a decimal comma accepted), formatting without
 * float noise, unit conversion by the field's kind (lengths converted, angles in degrees), and the
 * words a switch of the link takes. Pure; re-exported by state.ts.
 */
import { FIELDS, fieldOfPageKey, isLengthField as isLength, type PageFieldKey, urlParamOf } from '../core/input/fields';
import { fromMm, type LengthUnit, toMm } from '../core/input/units';
import { fieldDigits, formatField } from './format';

export { formatField };

import type { CalculatorState, TypedText } from './stateTypes';
import { defaultFieldText } from './unitDefaults';

type FieldKey = PageFieldKey;
type Unit = LengthUnit;
const param = urlParamOf;

/** True for the fields that hold a length (converted with the unit); angles are degrees. */
export function isLengthField(key: FieldKey): boolean {
  return isLength(fieldOfPageKey(key));
}

/**
 * A length typed in `from` as the text of a field in `to`: the fewest significant digits whose
 * conversion back gives exactly what was typed (as {@link formatField} writes it), so switching
 * mm -> in -> mm gives back `3.5`, and 25.4 mm reads `1`.
 */
export function convertLength(value: number, from: Unit, to: Unit): string {
  const converted = fromMm(toMm(value, from), to);
  for (let digits = 1; digits < 17; digits++) {
    const text = fieldDigits(converted, digits);
    // Compared as numbers: the text converted back, as a field writes it, is the very number given;
    // or that very number before it is written (0.00467 in is the 0.00467 * 25.4 mm a page computed).
    const back = fromMm(toMm(Number(text), to), from);
    if (back === value || Number(formatField(back)) === value) return text;
  }
  return fieldDigits(converted, 17);
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

/** A value in mm or degrees as the text of a field in `unit` (a length converted without loss: {@link convertLength}). */
export function fieldText(key: FieldKey, valueMm: number, unit: Unit): string {
  if (!Number.isFinite(valueMm)) return '';
  return isLengthField(key) ? convertLength(valueMm, 'mm', unit) : formatField(valueMm);
}

/** Converts one field's text between units (angles unchanged, invalid text kept as is; {@link convertLength}). */
export function convertField(key: FieldKey, text: string, from: Unit, to: Unit): string {
  if (from === to || !isLengthField(key)) return text;
  const v = parseField(text);
  if (v === null) return text;
  return convertLength(v, from, to);
}

/**
 * The fields of `state` in `to`, and the texts they were converted from:
 * - a length field that still holds its default (as the page gave it, not set by the user:
 *   `state.edited` leaves it out) becomes `to`'s own default (unitDefaults.ts: h 0.05 mm reads
 *   0.002 in, not 0.0019685);
 * - a field converted before and not changed since, switched back to the unit it was typed in,
 *   reads exactly as it was typed (`3.50` stays `3.50`: `state.typed` keeps it);
 * - every other length converts without loss ({@link convertField}), and its text is kept;
 * - angles and invalid text stay as they are.
 */
export function convertFields(
  state: Pick<CalculatorState, 'fields' | 'unit' | 'size' | 'edited' | 'typed'>,
  to: Unit,
): Pick<CalculatorState, 'fields' | 'typed'> {
  const from = state.unit;
  const fields = { ...state.fields };
  if (from === to) return { fields, typed: state.typed };
  const typed: Partial<Record<FieldKey, TypedText>> = { ...state.typed };
  const size = state.size ?? 'R';
  for (const key of Object.keys(fields) as FieldKey[]) {
    const text = fields[key];
    if (!isLengthField(key)) continue;
    const before = typed[key];
    if (before !== undefined && before.unit === to && before.shown === text) fields[key] = before.text;
    else if (!(state.edited ?? []).includes(key) && text.trim() === defaultFieldText(key, from, size))
      fields[key] = defaultFieldText(key, to, size);
    else {
      fields[key] = convertField(key, text, from, to);
      if (fields[key] !== text) typed[key] = { unit: from, text, shown: fields[key] };
    }
  }
  return { fields, typed: Object.keys(typed).length > 0 ? typed : state.typed };
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
