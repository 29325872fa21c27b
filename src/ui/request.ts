/**
 * The edge between what the user typed and what the solver is asked: the state's text, in the
 * user's unit, becomes one validated request in mm, or the input errors. Units are converted here
 * and nowhere else on the way in. Pure (no DOM).
 */

import { validateRaTarget } from '../core/raTarget';
import {
  describeInputError,
  type FieldName,
  type InputError,
  validateForward,
  validateInverse,
} from '../core/validate';
import type { SolveRequest } from '../worker/protocol';
import { type CalculatorState, type FieldKey, fieldInMm, sizeIsDiameter } from './state';

export type BuiltRequest =
  | { readonly ok: true; readonly request: SolveRequest }
  | { readonly ok: false; readonly errors: readonly InputError[] };

/** The request the state asks, or why it cannot be asked. */
export function buildRequest(state: CalculatorState): BuiltRequest {
  const mm = (key: FieldKey) => fieldInMm(state, key);
  const tool = { R: mm('R'), Rcr: mm('Rcr'), rho: mm('rho'), tilt: mm('tilt'), pattern: state.pattern };
  if (state.mode === 'forward' && state.target === 'ra') {
    const v = validateRaTarget({ ...tool, ra: mm('ra') });
    return v.ok ? { ok: true, request: { mode: 'ra', input: v.value } } : v;
  }
  if (state.mode === 'forward') {
    const v = validateForward({ ...tool, h: mm('h') });
    return v.ok ? { ok: true, request: { mode: 'forward', input: v.value } } : v;
  }
  const v = validateInverse({ ...tool, interval: mm('L') });
  return v.ok ? { ok: true, request: { mode: 'inverse', input: v.value } } : v;
}

/**
 * The page field that shows an error of the core's field. Pattern errors cannot happen here, and
 * the page asks for no surface (a plane), so the surface's fields have no input on the page.
 */
export function fieldOfError(field: FieldName): FieldKey | null {
  if (field === 'interval') return 'L';
  return field === 'pattern' || field === 'surfaceRadius' || field === 'surfaceAxis' ? null : field;
}

/** Each field's message, in the user's unit, quoting the text as typed. */
export function fieldMessages(state: CalculatorState, errors: readonly InputError[]): Map<FieldKey, string> {
  const out = new Map<FieldKey, string>();
  for (const e of errors) {
    const key = fieldOfError(e.field);
    if (key === null || out.has(key)) continue;
    out.set(
      key,
      describeInputError(e, state.unit, { typed: state.fields[key].trim(), toolSizeAsDiameter: sizeIsDiameter(state) }),
    );
  }
  return out;
}
