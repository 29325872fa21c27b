/**
 * The teeth and their feed on the page (issue 29): the field registry's finish fields as the page's
 * optional text fields (empty: no feed marks). Which are given, their link parameters, and the
 * one check the page makes itself (a text that is not a number is named on its field, as every
 * field's is); the limits (whole teeth, fz up to R, runout up to R/10) are the core's, checked in
 * the worker with the finish (jobs/finish.ts). Pure, small: it loads with the first result.
 */

import { feedPerToothOfRate, MAX_FLUTES, MIN_FEED_PER_TOOTH_MM } from '../core/finish/feedRate';
import { FIELDS, FINISH_FIELD_IDS, type FieldSpec, type PageFieldKey, urlParamOf } from '../core/input/fields';
import { formatInputNumber, type LengthUnit, toMm } from '../core/input/units';
import type { AnyInputError } from '../core/input/validate';
import { parseField } from './fieldText';
import type { PageFieldError } from './requestTypes';
import type { CalculatorState } from './stateTypes';

/** The finish fields' page keys, in the registry's order (z, fz, F, n, runout, runoutPhase, passPhase). */
export const FINISH_KEYS: readonly PageFieldKey[] = FINISH_FIELD_IDS.map(
  (id) => (FIELDS[id] as FieldSpec).page as PageFieldKey,
);

/** The feed rate's and spindle speed's page keys (they give fz while fz is empty). */
const RATE_KEYS: readonly PageFieldKey[] = [FIELDS.feedRate.page, FIELDS.spindleSpeed.page];

/**
 * True for a finish field the page leaves out: the feed rate and spindle speed while fz holds text
 * (fz typed wins; its fields are then disabled, README "Feed rate and spindle speed").
 */
export function finishKeyOff(state: CalculatorState, key: PageFieldKey): boolean {
  return RATE_KEYS.includes(key) && state.fields.fz.trim() !== '';
}

/**
 * The fz field's text while the feed rate or spindle speed holds text and fz does not: the fz they
 * give, F / (n z) in the user's unit (F in mm/min or in/min), or '' while F, n or z is not a
 * positive number (whole teeth, at most 64) or the fz is below 1 nm; null otherwise (fz typed, or F and n empty: the field as typed).
 */
export function rateFzText(state: CalculatorState): string | null {
  const { fz, F, n, z } = state.fields;
  if (fz.trim() !== '' || F.trim() + n.trim() === '') return null;
  const [f, s, t] = [F, n, z].map(parseField) as [number | null, number | null, number | null];
  if (f === null || s === null || t === null || !(f > 0 && s > 0 && Number.isInteger(t) && t >= 1 && t <= MAX_FLUTES))
    return '';
  // Only a feed the finish accepts (at least 1 nm; not 0 from a spindle speed of 1e308).
  const given = feedPerToothOfRate(f, s, t);
  return toMm(given, state.unit) >= MIN_FEED_PER_TOOTH_MM ? formatInputNumber(given) : '';
}

/** True when any finish field holds text (then the page asks for the finish). */
export function finishGiven(state: CalculatorState): boolean {
  return FINISH_KEYS.some((k) => state.fields[k].trim() !== '');
}

/** The link's parameters of the finish fields that hold text, as typed (`z=4&fz=0.08`). */
export function finishSearch(state: CalculatorState): Array<[string, string]> {
  return FINISH_FIELD_IDS.flatMap((id, i) => {
    const key = FINISH_KEYS[i] as PageFieldKey;
    const text = state.fields[key].trim();
    return text === '' || finishKeyOff(state, key) ? [] : [[urlParamOf(id), text] as [string, string]];
  });
}

/**
 * A message on each finish field whose text is not a number (written lengths are plain by now),
 * worded by `describe`: the page's words.ts describeError, in the language in force as the tool's
 * fields' are (handed in: words.ts reaches this module through its types and state.ts; the describers read
 * only the field's label and kind from the registry, which a finish field has too).
 */
export function finishFieldErrors(
  state: CalculatorState,
  describe: (e: AnyInputError, unit: LengthUnit) => string,
): PageFieldError[] {
  return FINISH_FIELD_IDS.flatMap((id, i) => {
    const key = FINISH_KEYS[i] as PageFieldKey;
    const text = state.fields[key].trim();
    if (text === '' || parseField(text) !== null || finishKeyOff(state, key)) return [];
    const e = { field: id, code: 'not-a-number', got: text } as unknown as AnyInputError;
    return [{ key, message: describe(e, state.unit) }];
  });
}
