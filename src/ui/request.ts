/**
 * The edge between what the user typed and what the solver is asked: the state's text, in the
 * user's unit, becomes one validated request in mm, or the input errors. Units are converted here
 * and nowhere else on the way in. Pure (no DOM).
 */

import { type FieldName, pageKeyOf, TOOL_FIELDS } from '../core/input/fields';
import { rawFields } from '../core/input/raw';
import {
  describeInputError,
  type InputError,
  inputError,
  validateForward,
  validateInverse,
} from '../core/input/validate';
import { validateRaTarget } from '../core/roughness/raTarget';
import type { SolveRequest } from '../worker/protocol';
import { type CalculatorState, type FieldKey, fieldInMm, parseField, sizeIsDiameter } from './state';

export type BuiltRequest =
  | { readonly ok: true; readonly request: SolveRequest }
  | { readonly ok: false; readonly errors: readonly InputError[] };

/** The request the state asks, or why it cannot be asked. */
export function buildRequest(state: CalculatorState): BuiltRequest {
  const built = validated(state);
  const own = [surfaceError(state), slowTarget(state)].filter((e): e is InputError => e !== null);
  if (own.length === 0) return built;
  // A radius typed with a sign: its own error, beside the others' (the rest validated on a plane).
  return { ok: false, errors: [...own, ...(built.ok ? [] : built.errors)] };
}

/**
 * A target Ra on a cylinder across the feed: solving it takes seconds (about 3 s: each secant step
 * integrates the revolved profile), beyond the worker's watchdog, so the page asks for h there.
 */
function slowTarget(state: CalculatorState): InputError | null {
  if (state.mode !== 'forward' || state.target !== 'ra' || state.surface === 'plane') return null;
  if (state.surfaceAxis !== 'cross') return null;
  return inputError('ra', 'slow-target', state.fields.ra.trim());
}

function validated(state: CalculatorState): BuiltRequest {
  /** A field's value in mm or degrees (its text when it is not a number), read from its page field. */
  const mm = (name: FieldName) => {
    const key = pageKeyOf(name);
    return key === null ? undefined : fieldInMm(state, key);
  };
  const tool = { ...rawFields(TOOL_FIELDS, mm), pattern: state.pattern, ...surfaceFields(state) };
  if (state.mode === 'forward' && state.target === 'ra') {
    const v = validateRaTarget({ ...tool, ra: mm('ra') });
    return v.ok ? { ok: true, request: { mode: 'ra', input: v.value } } : v;
  }
  if (state.mode === 'forward') {
    const v = validateForward({ ...tool, h: mm('h') });
    return v.ok ? { ok: true, request: { mode: 'forward', input: v.value } } : v;
  }
  const v = validateInverse({ ...tool, interval: mm('interval') });
  return v.ok ? { ok: true, request: { mode: 'inverse', input: v.value } } : v;
}

/**
 * The surface as the core's raw fields: none for a plane; for a cylinder the signed radius in mm
 * (the field's magnitude, negative when concave) and the axis. A radius that is not a positive
 * number goes as typed (the core words a missing or non-numeric one), or not at all when it has a
 * sign or is 0 (surfaceError words that).
 */
function surfaceFields(state: CalculatorState): { surfaceRadius?: number | string; surfaceAxis?: string } {
  if (state.surface === 'plane') return {};
  const v = parseField(state.fields.Rs);
  if (surfaceError(state) !== null || (v !== null && v <= 0)) return {};
  const mm = fieldInMm(state, 'Rs');
  return {
    surfaceRadius: typeof mm === 'number' && state.surface === 'concave' ? -mm : mm,
    surfaceAxis: state.surfaceAxis,
  };
}

/** The radius field's own rule: a positive magnitude, without a sign (convex or concave is the switch). */
function surfaceError(state: CalculatorState): InputError | null {
  if (state.surface === 'plane') return null;
  const v = parseField(state.fields.Rs);
  const typed = state.fields.Rs.trim();
  // The core reads a blank radius, or the word plane, as a plane: here a cylinder is chosen.
  if (typed === '') return inputError('surfaceRadius', 'missing', typed);
  if (typed === 'plane') return inputError('surfaceRadius', 'not-a-number', typed);
  if (v !== null && v <= 0) return inputError('surfaceRadius', 'not-positive', typed);
  return null;
}

/**
 * The page field that shows an error of the core's field. Pattern and axis errors cannot happen
 * here (switches offer only valid values); the surface radius's errors (gouging included) show on
 * the radius field.
 */
export function fieldOfError(field: FieldName): FieldKey | null {
  return pageKeyOf(field);
}

/** Each field's message, in the user's unit, quoting the text as typed. */
export function fieldMessages(state: CalculatorState, errors: readonly InputError[]): Map<FieldKey, string> {
  const out = new Map<FieldKey, string>();
  for (const e of errors) {
    const key = fieldOfError(e.field);
    if (key === null || out.has(key)) continue;
    out.set(
      key,
      describeInputError(e, state.unit, {
        typed: state.fields[key].trim(),
        toolSizeAsDiameter: sizeIsDiameter(state),
        radiusAsMagnitude: true,
      }),
    );
  }
  return out;
}
