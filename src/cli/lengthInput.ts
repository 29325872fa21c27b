/**
 * The command line's lengths as the shop writes them (issue 26 point 9): every length option (the
 * field registry's length fields) is read by the page's one parser (core/input/lengthText.ts:
 * `1/2"`, `.030in`, `5um`, `1 1/4`), a plain number in the chosen unit (`--unit mm|inch`), and
 * handed on as the text of its value in mm, the unit the solvers compute in; the diameter `--D`
 * becomes the radius. A plain decimal in mm is handed on as typed (validation reads it as before);
 * a text the parser refuses is handed on as typed too, so validation words its error. Pure.
 */
import { FIELDS, isLengthField } from '../core/input/fields';
import { parseLengthText } from '../core/input/lengthText';
import { type LengthUnit, toMm } from '../core/input/units';
import { csvNumber, isNumberText } from '../core/output/csvWrite';
import type { CLI_LENGTH_UNITS, ValueOption } from './args';

/** The unit `--unit` names (`mm`, `inch` or `in`), or null for another word. */
export function unitOfText(text: string | undefined): LengthUnit | null {
  if (text === undefined) return 'mm';
  const t = text.trim().toLowerCase();
  return t === 'mm' ? 'mm' : t === 'inch' || t === 'in' ? 'in' : null;
}

/** The unit's word as `--unit` takes it and JSON echoes it. */
export function unitWord(unit: LengthUnit): (typeof CLI_LENGTH_UNITS)[number] {
  return unit === 'mm' ? 'mm' : 'inch';
}

/** A unit suffix at the end of a length's text (`mm`, `in`, `"`, `um`, `thou`...). */
const SUFFIX = /[a-z\u00b5\u03bc"'\u201d]\s*$/i;

/**
 * A length as typed, in mm: a plain number is in `unit`; a suffix names its own unit (read straight
 * into mm, so `12.7mm` is 12.7 in any unit). Null when the page's parser refuses it.
 */
export function lengthMm(text: string, unit: LengthUnit): number | null {
  const suffixed = SUFFIX.test(text.trim());
  const r = parseLengthText(text, suffixed ? 'mm' : unit);
  if (!r.ok) return null;
  return suffixed ? r.value : toMm(r.value, unit);
}

/** The options that give a length (the field registry's length fields that the command line takes). */
const LENGTH_OPTIONS: ReadonlySet<string> = new Set(
  Object.entries(FIELDS).flatMap(([id, spec]) =>
    spec.cli !== null && isLengthField(id as keyof typeof FIELDS) ? [spec.cli] : [],
  ),
);

type Values = Readonly<Partial<Record<ValueOption, string>>>;

/**
 * The options with every length in mm (see the module comment) and `--D` as `--R` (D/2); the other
 * options as they are.
 */
export function valuesInMm(values: Values, unit: LengthUnit): Values {
  const out: Partial<Record<ValueOption, string>> = {};
  for (const [option, text] of Object.entries(values) as [ValueOption, string][]) {
    out[option] = LENGTH_OPTIONS.has(option) ? lengthText(text, unit) : text;
  }
  const d = out[FIELDS.D.cli as ValueOption];
  if (d !== undefined) {
    delete out[FIELDS.D.cli as ValueOption];
    const diameter = Number(d);
    // A diameter that does not read as a number reaches validation as typed (its message names D).
    out[FIELDS.R.cli] = isNumberText(d.trim()) ? csvNumber(diameter / 2) : d;
  }
  return out;
}

/** A length's text handed on: its value in mm, or the text as typed (see the module comment). */
export function lengthText(text: string, unit: LengthUnit): string {
  if (text.trim() === '') return text;
  const plain = parseLengthText(text, unit);
  if (unit === 'mm' && plain.ok && !plain.written) return text;
  const mm = lengthMm(text, unit);
  return mm === null ? text : csvNumber(mm);
}
