/**
 * The checks of a question's fields that need no surface model (issue 27 point 4: the page
 * validates, the worker solves): each number parsed, the tool's rules (R's range, Rcr up to R, the
 * lead and tilt ranges), the pattern, the surface's radius and axis, and a given length positive
 * and at least its smallest. What asks a surface model, gouging and the height and step-over
 * limits, surfaces/validate.ts adds on top of these (validateForward, validateInverse,
 * validatePassAnd), in the same order of errors. The page builds its request with the `...Fields`
 * validations here; the worker, the command line and the batch validate it whole.
 */
import type { ForwardInput, InverseInput, PassInput } from '../domain/pass';
import { PLANE, type Surface, type SurfaceAxis } from '../domain/surface';
import type { PassPattern, ToolInput } from '../domain/tool';
import { leadAngleInRange, tiltAngleInRange } from './angleRanges';
import type { FieldName } from './fields';
// The error shapes and the limits through validate.ts, which re-exports them beside the raw shapes.
import {
  type AnyFieldName,
  type AnyInputError,
  forwardInput,
  type InputError,
  type InputErrorCode,
  inputError,
  inverseInput,
  MAX_SURFACE_RADIUS_MM,
  MAX_TOOL_RADIUS_MM,
  MIN_LENGTH_MM,
  MIN_SURFACE_RADIUS_MM,
  MIN_TOOL_RADIUS_MM,
  parseNumber,
  type RawForwardInput,
  type RawInverseInput,
  type RawToolInput,
  type Validation,
} from './validate';

/** The fields parsed: their numbers, their text as given, and the errors so far. */
export interface Collected {
  values: Partial<Record<FieldName, number>>;
  shown: Partial<Record<FieldName, string>>;
  errors: InputError[];
}

function collect(raw: Readonly<Partial<Record<FieldName, unknown>>>, fields: readonly FieldName[]): Collected {
  const out: Collected = { values: {}, shown: {}, errors: [] };
  for (const field of fields) {
    const given = field === 'tilt' && raw.tilt === undefined ? 0 : raw[field];
    const parsed = parseNumber(given);
    out.shown[field] = parsed.shown;
    if (parsed.ok) out.values[field] = parsed.value;
    else out.errors.push(inputError(field, parsed.code, parsed.shown));
  }
  return out;
}

/** Rejects a parsed field: its error, and its value dropped. */
export function reject(c: Collected, field: FieldName, code: InputErrorCode, limit: number | null = null): void {
  c.errors.push(inputError(field, code, c.shown[field] ?? '', limit));
  delete c.values[field];
}

function checkTool(c: Collected): void {
  const { R, Rcr, rho, tilt } = c.values;
  if (R !== undefined) {
    if (R <= 0) reject(c, 'R', 'not-positive');
    else if (R < MIN_TOOL_RADIUS_MM) reject(c, 'R', 'too-small', MIN_TOOL_RADIUS_MM);
    else if (R > MAX_TOOL_RADIUS_MM) reject(c, 'R', 'too-large', MAX_TOOL_RADIUS_MM);
  }
  if (Rcr !== undefined) {
    if (Rcr < 0) reject(c, 'Rcr', 'negative');
    else if (c.values.R !== undefined && Rcr > c.values.R) reject(c, 'Rcr', 'corner-exceeds-radius', c.values.R);
  }
  // The posture's angle rules, stated once (input/angleRanges.ts; the five-axis mode asks them too).
  if (rho !== undefined && !leadAngleInRange(rho)) reject(c, 'rho', 'out-of-range');
  if (tilt !== undefined && !tiltAngleInRange(tilt)) reject(c, 'tilt', 'out-of-range');
}

function checkPattern(raw: unknown, errors: InputError[]): PassPattern | null {
  if (raw === undefined) return 'one-way';
  const text = typeof raw === 'string' ? raw.trim() : String(raw);
  if (text === 'one-way' || text === 'zigzag') return text;
  errors.push(inputError('pattern', 'not-a-pattern', text));
  return null;
}

/** The surface: a plane when no radius is given; else a cylinder with a valid radius and axis. */
function checkSurface(raw: RawToolInput, errors: InputError[]): Surface | null {
  const given = raw.surfaceRadius;
  const blank =
    given === undefined ||
    given === null ||
    (typeof given === 'string' && (given.trim() === '' || given.trim() === 'plane'));
  const axisText = raw.surfaceAxis === undefined || raw.surfaceAxis === null ? 'feed' : String(raw.surfaceAxis).trim();
  if (blank) return PLANE;
  const parsed = parseNumber(given);
  if (!parsed.ok) {
    errors.push(inputError('surfaceRadius', parsed.code, parsed.shown));
    return null;
  }
  const rs = parsed.value;
  if (!(Math.abs(rs) >= MIN_SURFACE_RADIUS_MM && Math.abs(rs) <= MAX_SURFACE_RADIUS_MM)) {
    errors.push(inputError('surfaceRadius', 'out-of-range', parsed.shown));
    return null;
  }
  if (axisText !== 'feed' && axisText !== 'cross') {
    errors.push(inputError('surfaceAxis', 'not-an-axis', axisText));
    return null;
  }
  return { kind: 'cylinder', radiusMm: rs, axis: axisText as SurfaceAxis };
}

function toolOf(values: Collected['values']): ToolInput | null {
  const { R, Rcr, rho, tilt } = values;
  if (R === undefined || Rcr === undefined || rho === undefined || tilt === undefined) return null;
  return { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt };
}

/** A pass's fields checked: the fields, and the tool, pattern and surface where valid (null where not). */
export interface PassFields {
  readonly c: Collected;
  readonly tool: ToolInput | null;
  readonly pattern: PassPattern | null;
  readonly surface: Surface | null;
}

/**
 * Parses `fields` (the tool's and a problem's own) and checks the tool's rules, then the pattern and
 * the surface: the errors of the fields and the tool in `c.errors`, then those of the pattern and the
 * surface in `rest` (`c.errors` unless given).
 */
export function passFields(
  raw: RawToolInput & Readonly<Partial<Record<FieldName, unknown>>>,
  fields: readonly FieldName[],
  rest?: InputError[],
): PassFields {
  const c = collect(raw, fields);
  checkTool(c);
  const errors = rest ?? c.errors;
  const pattern = checkPattern(raw.pattern, errors);
  const surface = checkSurface(raw, errors);
  return { c, tool: toolOf(c.values), pattern, surface };
}

/**
 * A length's own rules: positive and at least `minMm`. True when it is given and keeps them (its
 * limits on the surface come next); else its error is in `c.errors` (none when it did not parse).
 */
export function lengthInRange(c: Collected, field: FieldName, minMm: number): boolean {
  const v = c.values[field];
  if (v === undefined) return false;
  if (v <= 0) reject(c, field, 'not-positive');
  else if (v < minMm) reject(c, field, 'too-small', minMm);
  else return true;
  return false;
}

/** The common part of a validation: tool, pattern and surface, and one number field, parsed. */
export interface PassValidation {
  /** The errors so far, at most one per field; the field is only parsed, not checked against its range. */
  readonly errors: readonly AnyInputError[];
  /** The tool, pattern and surface when they are valid (whatever the field). */
  readonly pass: PassInput | null;
  /** The field's number, when it parsed. */
  readonly value: number | undefined;
  /** The field as given, for messages. */
  readonly shown: string;
  /** True when the surface is a concave cylinder too tight for the tool (gouging): the field is moot. */
  readonly gouges: boolean;
}

/**
 * The tool, pattern and surface checked (`p`, with `rest` the pattern's and surface's errors), and
 * `field` of `raw` parsed, as one PassValidation (validatePassAnd's and passFieldsAnd's end).
 */
export function passAnd(
  raw: Readonly<Partial<Record<AnyFieldName, unknown>>>,
  field: AnyFieldName,
  p: PassFields,
  rest: readonly InputError[],
  gouges: boolean,
): PassValidation {
  const parsed = parseNumber(raw[field]);
  const own: AnyInputError[] = parsed.ok ? [] : [inputError(field, parsed.code, parsed.shown)];
  const valid = p.c.errors.length === 0 && rest.length === 0;
  const { tool, pattern, surface } = p;
  return {
    errors: [...p.c.errors, ...own, ...rest],
    pass: valid && tool !== null && pattern !== null && surface !== null ? { ...tool, pattern, surface } : null,
    value: parsed.ok ? parsed.value : undefined,
    shown: parsed.shown,
    gouges,
  };
}

/** The tool's fields of every pass. */
const TOOL: readonly FieldName[] = ['R', 'Rcr', 'rho', 'tilt'];

/** validatePassAnd without gouging (which asks the surface model): the page's check of a further problem's field. */
export function passFieldsAnd(
  raw: RawToolInput & Readonly<Partial<Record<AnyFieldName, unknown>>>,
  field: AnyFieldName,
): PassValidation {
  const rest: InputError[] = [];
  return passAnd(raw, field, passFields(raw, TOOL, rest), rest, false);
}

/** A validation's end: the input `build` makes when no field has an error, else the errors. */
function passResult<T>(
  p: PassFields,
  field: 'h' | 'interval',
  build: (tool: ToolInput, pattern: PassPattern, mm: number, surface: Surface) => T,
): Validation<T> {
  const { c, tool, pattern, surface } = p;
  const mm = c.values[field];
  if (c.errors.length > 0 || tool === null || pattern === null || surface === null || mm === undefined)
    return { ok: false, errors: c.errors };
  return { ok: true, value: build(tool, pattern, mm, surface) };
}

/** A forward validation's end: the input when no field has an error, else the errors. */
export function forwardResult(p: PassFields): Validation<ForwardInput> {
  return passResult(p, 'h', forwardInput);
}

/** An inverse validation's end: the input when no field has an error, else the errors. */
export function inverseResult(p: PassFields): Validation<InverseInput> {
  return passResult(p, 'interval', inverseInput);
}

/**
 * validateForward without what asks the surface model (gouging, the height limits): the page's
 * check of a forward question, which the worker validates whole. h positive and at least
 * MIN_LENGTH_MM.
 */
export function validateForwardFields(raw: RawForwardInput): Validation<ForwardInput> {
  const p = passFields(raw, [...TOOL, 'h']);
  lengthInRange(p.c, 'h', MIN_LENGTH_MM);
  return forwardResult(p);
}

/**
 * validateInverse without what asks the surface model (gouging, the widest step-over): the page's
 * check of an inverse question, which the worker validates whole. L positive and at least 2
 * MIN_LENGTH_MM.
 */
export function validateInverseFields(raw: RawInverseInput): Validation<InverseInput> {
  const p = passFields(raw, [...TOOL, 'interval']);
  lengthInRange(p.c, 'interval', 2 * MIN_LENGTH_MM);
  return inverseResult(p);
}
