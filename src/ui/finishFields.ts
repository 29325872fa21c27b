/**
 * The teeth and their feed on the page (issue 29): the field registry's finish fields as the page's
 * optional text fields (empty: no feed marks). Which are given, their link parameters, and the
 * one check the page makes itself (a text that is not a number is named on its field, as every
 * field's is); the limits (whole teeth, fz up to R, runout up to R/10) are the core's, checked in
 * the worker with the finish (jobs/finish.ts). Pure, small: it loads with the first result.
 */

import { entryFaultMessage } from '../core/input/entryMessages';
import { FIELDS, FINISH_FIELD_IDS, type FieldSpec, type PageFieldKey, urlParamOf } from '../core/input/fields';
import { parseField } from './fieldText';
import type { PageFieldError } from './requestTypes';
import type { CalculatorState } from './stateTypes';

/** The finish fields' page keys, in the registry's order (z, fz, runout, runoutPhase, passPhase). */
export const FINISH_KEYS: readonly PageFieldKey[] = FINISH_FIELD_IDS.map(
  (id) => (FIELDS[id] as FieldSpec).page as PageFieldKey,
);

/** True when any finish field holds text (then the page asks for the finish). */
export function finishGiven(state: CalculatorState): boolean {
  return FINISH_KEYS.some((k) => state.fields[k].trim() !== '');
}

/** The link's parameters of the finish fields that hold text, as typed (`z=4&fz=0.08`). */
export function finishSearch(state: CalculatorState): Array<[string, string]> {
  return FINISH_FIELD_IDS.flatMap((id, i) => {
    const text = state.fields[FINISH_KEYS[i] as PageFieldKey].trim();
    return text === '' ? [] : [[urlParamOf(id), text] as [string, string]];
  });
}

/** A message on each finish field whose text is not a number (written lengths are plain by now). */
export function finishFieldErrors(state: CalculatorState): PageFieldError[] {
  return FINISH_FIELD_IDS.flatMap((id, i) => {
    const key = FINISH_KEYS[i] as PageFieldKey;
    const text = state.fields[key].trim();
    if (text === '' || parseField(text) !== null) return [];
    return [{ key, message: entryFaultMessage(FIELDS[id].label, 'not-a-number', text, '') }];
  });
}
