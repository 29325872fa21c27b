/**
 * The page's question at a doubly curved point (issue 19): the two radii's fields (magnitudes, with
 * their sides) become signed radii in mm; with both straight the question is the plane's, with one
 * straight the cylinder's (so those answers stay exactly what they were), with both curved a doubly
 * curved request, validated here as validate.ts does the tool and posture; this point's own checks
 * (gouging, the flank and shank limits: worker/data/curvedCheck.ts) run once, in the worker, whose
 * refusal describeCurvedError words. Every message in the user's unit on its field. Pure.
 */
import { quotedEntry } from '../core/input/entryMessages';
import { FIELDS, pageKeyOf, TOOL_FIELDS } from '../core/input/fields';
import { passFieldsAnd } from '../core/input/passFields';
import { rawFields } from '../core/input/raw';
import { formatInputNumber, fromMm, toMm, unitSymbol } from '../core/input/units';
import { type InputError, inputError, MIN_LENGTH_MM } from '../core/input/validate';
import type { CurvedError } from '../worker/pageProtocol';
import { catalogue, describeError } from './i18n/words';
import type { BuiltRequest, PageFieldError } from './requestTypes';
import { type CalculatorState, type FieldKey, fieldInMm, parseField, type Unit } from './state';
import { type RadiusKey, sideOf } from './surfaceState';

/** A length in the user's unit, with its symbol (6 significant digits). */
function len(mm: number, unit: Unit): string {
  return `${formatInputNumber(fromMm(mm, unit))} ${unitSymbol(unit)}`;
}

/** The label of each radius's field. */
const LABEL: Readonly<Record<RadiusKey, string>> = { Rf: FIELDS.feedRadius.label, Rc: FIELDS.crossRadius.label };
const SHORT: Readonly<Record<RadiusKey, string>> = { Rf: FIELDS.feedRadius.short, Rc: FIELDS.crossRadius.short };

/** `(got ...)` with the text as typed (shortened). */
function got(text: string): string {
  const t = text.trim();
  return `(got ${quotedEntry(t)})`;
}

/**
 * A radius field's signed value in mm: Infinity when straight, else its magnitude with the side's
 * sign; or the field's own error (missing, not a number, a sign or 0 typed: the side is chosen
 * beside it), in the language in force (a catalogue's radiusField, i18n/curvedText.ts; English here).
 */
export function radiusMm(state: CalculatorState, key: RadiusKey): number | PageFieldError {
  const side = sideOf(state, key);
  if (side === 'straight') return Number.POSITIVE_INFINITY;
  const text = state.fields[key].trim();
  const v = parseField(text);
  if (v === null || !(v > 0) || /^[+-]/.test(text))
    return (
      catalogue()?.radiusField(key, text, v) ?? {
        key,
        message:
          text === ''
            ? `${LABEL[key]} is missing: enter a radius, or choose straight.`
            : v === null
              ? `${LABEL[key]} must be a number (got "${quotedEntry(text)}").`
              : `${LABEL[key]} must be a positive number: convex or concave is chosen beside it ${got(text)}.`,
      }
    );
  const mm = toMm(v, state.unit);
  return side === 'concave' ? -mm : mm;
}

/** The other radius held, in words: `Rc = -40 mm held` (or straight). */
function held(key: RadiusKey, otherMm: number, unit: Unit): string {
  const other = key === 'Rf' ? 'Rc' : 'Rf';
  if (!Number.isFinite(otherMm)) return `with ${SHORT[other]} straight`;
  return `with ${SHORT[other]} = ${otherMm < 0 ? '-' : ''}${len(Math.abs(otherMm), unit)} held`;
}

/** One doubly curved error as one line on its field, lengths in the user's unit. */
export function describeCurvedError(e: CurvedError, state: CalculatorState): PageFieldError {
  const unit = state.unit;
  if (e.field === 'ra') {
    // Worded as the plane's and the cylinder's (the largest Ra, or none when no scallop forms).
    const typed = state.fields.ra.trim();
    const error = inputError('ra', 'beyond-max-ra', typed, e.maxMm);
    return {
      key: 'ra',
      message: describeError(error, unit, { typed }).replace('on this surface', 'at this point'),
    };
  }
  if (e.field === 'h' || e.field === 'interval') {
    const key: FieldKey = e.field === 'h' ? 'h' : 'L';
    if (e.code === 'beyond-max')
      return {
        key,
        message: `${FIELDS.interval.label} must be below ${len(e.maxMm, unit)} at this point ${got(state.fields.L)}: passes this far apart leave a wall.`,
      };
    const shank = e.limitBy === 'shank-right' || e.limitBy === 'shank-left';
    const side = e.limitBy === 'right-flank' || e.limitBy === 'shank-right' ? 'right' : 'left';
    return {
      key,
      message: `${FIELDS.h.label} must be below ${len(e.limitMm, unit)} at this point ${got(state.fields.h)}: above it ${shank ? `the shank (on the ${side}), not the corner, would form the cusp` : `the ${side} flank leaves a wall, not a scallop`}.`,
    };
  }
  const key: RadiusKey = e.field === 'feedRadius' ? 'Rf' : 'Rc';
  const label = LABEL[key];
  const side = sideOf(state, key);
  const typed = got(`${state.fields[key].trim()}${side === 'straight' ? '' : `, ${side}`}`);
  if (e.code === 'out-of-range')
    return {
      key,
      message: `${label} must be a radius from ${len(0.001, unit)} to ${len(1e6, unit)} ${typed}; choose straight for no curvature.`,
    };
  const h = held(key, e.otherMm, unit);
  const r = len(e.limit.radiusMm ?? 0, unit);
  const gouged = 'gouged (the tool reaches into the surface away from the contact).';
  const kind = e.limit.kind;
  return {
    key,
    message:
      kind === 'concave-at-least'
        ? `${label} must be at least ${r} while concave, ${h} ${typed}: a tighter one is ${gouged}`
        : kind === 'convex-at-most'
          ? `${label} must be convex and at most ${r}, ${h} ${typed}: a flatter one is ${gouged}`
          : kind === 'not-concave'
            ? `${label} must be convex or straight, ${h} ${typed}: any concave one is gouged.`
            : `${label}: the tool gouges at any radius, ${h} ${typed}; change the other radius, the tool or its posture.`,
  };
}

/**
 * The request of a doubly curved state with both radii curved, or null when a radius is straight
 * (then the plane's or the cylinder's question answers it: see cylinderState).
 */
export function buildCurvedRequest(state: CalculatorState): BuiltRequest | null {
  const rf = radiusMm(state, 'Rf');
  const rc = radiusMm(state, 'Rc');
  const own: PageFieldError[] = [rf, rc].filter((r): r is PageFieldError => typeof r !== 'number');
  if (own.length === 0 && (rf === Number.POSITIVE_INFINITY || rc === Number.POSITIVE_INFINITY)) return null;
  const forward = state.mode === 'forward';
  const mm = (name: (typeof TOOL_FIELDS)[number] | 'h' | 'interval' | 'ra') => {
    const key = pageKeyOf(name);
    return key === null ? undefined : fieldInMm(state, key);
  };
  const field = forward ? (state.target === 'ra' ? 'ra' : 'h') : 'interval';
  const v = passFieldsAnd({ ...rawFields(TOOL_FIELDS, mm), pattern: state.pattern, [field]: mm(field) }, field);
  const errors: Array<InputError | PageFieldError> = [...own, ...(v.errors as InputError[])];
  const min = forward ? MIN_LENGTH_MM : 2 * MIN_LENGTH_MM;
  if (v.value !== undefined && !(v.value >= min))
    errors.push(inputError(field, v.value > 0 ? 'too-small' : 'not-positive', v.shown, min));
  if (errors.length > 0 || v.pass === null || v.value === undefined || typeof rf !== 'number' || typeof rc !== 'number')
    return { ok: false, errors };
  const radii = { feedRadiusMm: rf, crossRadiusMm: rc };
  const tool = {
    toolRadiusMm: v.pass.toolRadiusMm,
    cornerRadiusMm: v.pass.cornerRadiusMm,
    leadAngleDeg: v.pass.leadAngleDeg,
    tiltAngleDeg: v.pass.tiltAngleDeg,
    pattern: state.pattern,
    ...radii,
  };
  if (field === 'ra') return { ok: true, request: { mode: 'curved-ra', input: { ...tool, targetRaMm: v.value } } };
  return forward
    ? { ok: true, request: { mode: 'curved-forward', input: { ...tool, scallopHeightMm: v.value } } }
    : { ok: true, request: { mode: 'curved-inverse', input: { ...tool, intervalMm: v.value } } };
}

/**
 * The plane's or the cylinder's state that a doubly curved state with a straight radius is: Rf
 * straight is the cylinder with its axis along the feed (radius Rc), Rc straight the one across it
 * (radius Rf), both straight the plane. The cylinder's radius field takes the curved one's text.
 */
export function cylinderState(state: CalculatorState): { state: CalculatorState; radius: RadiusKey | null } {
  const f = state.feedSide;
  const c = state.crossSide;
  if (f === 'straight' && c === 'straight') return { state: { ...state, surface: 'plane' }, radius: null };
  const key: RadiusKey = f === 'straight' ? 'Rc' : 'Rf';
  const side = key === 'Rc' ? c : f;
  return {
    state: {
      ...state,
      surface: side === 'concave' ? 'concave' : 'convex',
      surfaceAxis: key === 'Rc' ? 'feed' : 'cross',
      fields: { ...state.fields, Rs: state.fields[key] },
    },
    radius: key,
  };
}

/** The radius label of a message about the cylinder's radius, renamed to the curved radius it came from. */
export function renameRadius(message: string, key: RadiusKey): string {
  return message.replace(FIELDS.surfaceRadius.label, LABEL[key]);
}
