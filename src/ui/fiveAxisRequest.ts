/**
 * The page's five-axis question (the mode registry's `fiveAxis`: lead and tilt given): the plane's
 * or the cylinder's, or a doubly curved point's (curvedRequest.ts; with a straight radius the
 * cylinder's or the plane's). The state's text, in the user's unit, becomes one validated request
 * in mm, or the input errors. One of the per-mode builders behind the page's one builder
 * (questionRequest.ts). Pure (no DOM).
 */
import { FIELDS, type FieldName, pageKeyOf, TOOL_FIELDS } from '../core/input/fields';
import { passFieldsAnd, validateForwardFields, validateInverseFields } from '../core/input/passFields';
import { rawFields } from '../core/input/raw';
import { type InputError, inputError } from '../core/input/validate';
import { targetRaFields, targetRaValidation } from '../core/roughness/targetRaFields';
import { buildCurvedRequest, cylinderState, renameRadius } from './curvedRequest';
import { fieldMessages } from './fieldMessages';
import type { BuiltRequest, PageFieldError } from './requestTypes';
import { type CalculatorState, fieldInMm, parseField } from './state';
import type { RadiusKey } from './surfaceState';

/**
 * The five-axis request the state asks, or why it cannot be asked: a doubly curved point's (with a
 * straight radius, the cylinder's or the plane's), or the plane's or cylinder's. Validation only,
 * once per change: the checks that need a solver (gouging, the limits of h, L and Ra, a doubly
 * curved point's) run in the worker, which refuses such a request in its reply (request.ts
 * replyErrors) and brings the sliders' limits with it.
 */
export function buildFiveAxisRequest(state: CalculatorState): BuiltRequest {
  const saRefused = targetSaRefusal(state);
  if (saRefused !== null) return { ok: false, errors: [saRefused] };
  if (state.surface === 'curved') {
    const curved = buildCurvedRequest(state);
    if (curved !== null) return curved;
    const { state: cylinder, radius } = cylinderState(state);
    const built = buildClassic(cylinder);
    return built.ok || radius === null ? built : { ok: false, errors: onRadius(cylinder, built.errors, radius) };
  }
  return buildClassic(state);
}

/** A cylinder's errors on the curved radius it came from (the cylinder's radius field is not shown). */
function onRadius(
  state: CalculatorState,
  errors: readonly (InputError | PageFieldError)[],
  key: RadiusKey,
): Array<InputError | PageFieldError> {
  const messages = fieldMessages(state, errors);
  return errors.map((e) => {
    if ('key' in e || e.field !== 'surfaceRadius') return e;
    return { key, message: renameRadius(messages.get('Rs') ?? e.message, key) };
  });
}

/**
 * A target Sa off a plane: the teeth's surface (and so its Sa) is computed on a plane only
 * (shared/notes/surface-finish.md), so a cylinder or a doubly curved point gets this one line.
 */
function targetSaRefusal(state: CalculatorState): PageFieldError | null {
  if (state.mode !== 'forward' || state.target !== 'sa') return null;
  const straight = state.surface === 'curved' && state.feedSide === 'straight' && state.crossSide === 'straight';
  if (state.surface === 'plane' || straight) return null;
  return { key: 'sa', message: `${FIELDS.targetSa.label} is computed on a plane only: give h or Ra here.` };
}

/** The plane's or the cylinder's request (five-axis). */
function buildClassic(state: CalculatorState): BuiltRequest {
  const built = validated(state);
  const own = [surfaceError(state)].filter((e): e is InputError => e !== null);
  if (own.length === 0) return built;
  // A radius typed with a sign: its own error, beside the others' (the rest validated on a plane).
  return { ok: false, errors: [...own, ...(built.ok ? [] : built.errors)] };
}

function validated(state: CalculatorState): BuiltRequest {
  /** A field's value in mm or degrees (its text when it is not a number), read from its page field. */
  const mm = (name: FieldName) => {
    const key = pageKeyOf(name);
    return key === null ? undefined : fieldInMm(state, key);
  };
  const tool = { ...rawFields(TOOL_FIELDS, mm), pattern: state.pattern, ...surfaceFields(state) };
  if (state.mode === 'forward' && state.target === 'ra') {
    // The fields only: gouging, a posture that leaves a wall only and an Ra beyond the largest are
    // the worker's to find (they need a solve), in its reply (pageMessages.ts replyErrors).
    const v = targetRaValidation(targetRaFields(passFieldsAnd({ ...tool, ra: mm('ra') }, 'ra')));
    // Its errors name the tool, pass and Ra fields only (never a doubly curved point's radii).
    return v.ok
      ? { ok: true, request: { mode: 'ra', input: v.value } }
      : { ok: false, errors: v.errors as InputError[] };
  }
  if (state.mode === 'forward' && state.target === 'sa') {
    // The results answer the curve's end at fz -> 0 (Ra = Sa: L0); the pair is the target-Sa box's
    // (targetSaLazy.ts). The fields only, as a target Ra (the same bound, checked by the worker),
    // each error naming the target Sa field.
    const v = targetRaValidation(targetRaFields(passFieldsAnd({ ...tool, ra: mm('targetSa') }, 'ra')));
    return v.ok
      ? { ok: true, request: { mode: 'ra', input: v.value } }
      : {
          ok: false,
          errors: (v.errors as InputError[]).map((e) => (e.field === 'ra' ? { ...e, field: 'targetSa' } : e)),
        };
  }
  // The fields only, likewise: gouging and the height or step-over limits are the worker's.
  if (state.mode === 'forward') {
    const v = validateForwardFields({ ...tool, h: mm('h') });
    return v.ok ? { ok: true, request: { mode: 'forward', input: v.value } } : v;
  }
  const v = validateInverseFields({ ...tool, interval: mm('interval') });
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
