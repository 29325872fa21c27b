/**
 * The rules of a forward or inverse question on a registered surface: the tool's fields, the
 * pattern, the surface (a plane, or a cylinder's radius and axis), gouging, and the scallop height or
 * step-over against the surface model's limits (surfaces/registry.ts). Never throws and never yields
 * NaN: every input is accepted as finite numbers inside the solvers' domain or rejected with one
 * structured error per offending field. The parsing of one number, the raw shapes, the field
 * registry, the limits and the wording are the input layer's (input/validate.ts and its neighbours):
 * this file sits above the surface models it asks, they below it.
 */
import type { ForwardInput, InverseInput, PassInput } from '../domain/pass';
import { PLANE, type Surface, type SurfaceAxis } from '../domain/surface';
import type { PassPattern, ToolInput } from '../domain/tool';
import { leadAngleInRange, tiltAngleInRange } from '../input/angleRanges';
import type { FieldName } from '../input/fields';
import {
  type AnyFieldName,
  type AnyInputError,
  type InputError,
  type InputErrorCode,
  inputError,
  type Validation,
} from '../input/inputErrors';
import {
  MAX_SURFACE_RADIUS_MM,
  MAX_TOOL_RADIUS_MM,
  MIN_LENGTH_MM,
  MIN_SURFACE_RADIUS_MM,
  MIN_TOOL_RADIUS_MM,
} from '../input/limits';
import {
  forwardInput,
  inverseInput,
  parseNumber,
  type RawForwardInput,
  type RawInverseInput,
  type RawToolInput,
} from '../input/validate';
import type { FlankLimits } from '../tool/posture';
import { leavesNoScallop } from './models/plane';
import { type SurfaceDescriptor, surfaceModel } from './registry';

type Collected = {
  values: Partial<Record<FieldName, number>>;
  shown: Partial<Record<FieldName, string>>;
  errors: InputError[];
};

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

function reject(c: Collected, field: FieldName, code: InputErrorCode, limit: number | null = null): void {
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

/**
 * A surface too tight for the tool and posture (its model's fit: on a concave cylinder the head, or
 * the shank up to the axis height): the gouging error naming the nearest admissible radius (or "any
 * radius"), else null.
 */
function gouging(tool: ToolInput, surface: Surface, shown: string): InputError | null {
  const fit = surfaceModel(surface).fit(tool, surface);
  if (!fit.gouges) return null;
  if (fit.by === 'head') return inputError('surfaceRadius', 'gouging', shown, fit.limitRadiusMm);
  return inputError('surfaceRadius', 'shank-gouging', shown, fit.limitRadiusMm, null, fit.shankLean);
}

function toolOf(values: Collected['values']): ToolInput | null {
  const { R, Rcr, rho, tilt } = values;
  if (R === undefined || Rcr === undefined || rho === undefined || tilt === undefined) return null;
  return { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt };
}

/** The opening every validation shares: the fields, the tool, the pattern and the surface, checked. */
interface CheckedPass {
  readonly c: Collected;
  readonly tool: ToolInput | null;
  readonly pattern: PassPattern | null;
  readonly surface: Surface | null;
  /** The surface is too tight for the tool (the gouging error is among the errors). */
  readonly gouges: boolean;
}

/**
 * Parses `fields` (the tool's and a problem's own) and checks the tool's rules, then the pattern and
 * the surface, a surface too tight for the tool included (gouging): the errors of the fields and the
 * tool in `c.errors`, then those of the pattern and the surface in `rest` (`c.errors` unless given).
 */
function checkedPass(
  raw: RawToolInput & Readonly<Partial<Record<FieldName, unknown>>>,
  fields: readonly FieldName[],
  rest?: InputError[],
): CheckedPass {
  const c = collect(raw, fields);
  checkTool(c);
  const errors = rest ?? c.errors;
  const pattern = checkPattern(raw.pattern, errors);
  const surface = checkSurface(raw, errors);
  const tool = toolOf(c.values);
  const gouge = tool !== null && surface !== null ? gouging(tool, surface, String(raw.surfaceRadius ?? '')) : null;
  if (gouge) errors.push(gouge);
  return { c, tool, pattern, surface, gouges: gouge !== null };
}

/** The common part of a validation: tool, pattern and surface (gouging included), and one number field, parsed. */
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
 * Validates the tool, pattern and surface as validateForward does, and parses `field` (a further
 * problem's own quantity, such as a target roughness `Ra`); the caller checks its range and
 * words its errors with {@link inputError}. Errors come in validateForward's order.
 */
export function validatePassAnd(
  raw: RawToolInput & Readonly<Partial<Record<AnyFieldName, unknown>>>,
  field: AnyFieldName,
): PassValidation {
  const rest: InputError[] = [];
  const { c, tool, pattern, surface, gouges } = checkedPass(raw, ['R', 'Rcr', 'rho', 'tilt'], rest);
  const parsed = parseNumber(raw[field]);
  const own: AnyInputError[] = parsed.ok ? [] : [inputError(field, parsed.code, parsed.shown)];
  const valid = c.errors.length === 0 && rest.length === 0;
  return {
    errors: [...c.errors, ...own, ...rest],
    pass: valid && tool !== null && pattern !== null && surface !== null ? { ...tool, pattern, surface } : null,
    value: parsed.ok ? parsed.value : undefined,
    shown: parsed.shown,
    gouges,
  };
}

/** A flat end with neither lead nor tilt (the plane's model, models/plane.ts); re-exported for the callers. */
export { leavesNoScallop };

/**
 * The scallop heights a tool in a posture can leave on a surface: below `limitMm` (flankLimits on a
 * plane; measured radially on a cylinder); mm. On a plane without tilt it is `(R - Rcr) sin(rho) + Rcr`.
 * Any registered surface (surfaces/registry.ts).
 */
export function scallopHeightLimits(tool: ToolInput, surface: SurfaceDescriptor = PLANE): FlankLimits {
  return surfaceModel(surface).limits(tool, surface);
}

/**
 * The widest step-over (mm) that still leaves a scallop, for a tool, posture, pattern and surface:
 * the flanks' reach at the height limit; 2R on a plane without tilt. Any registered surface.
 */
export function maxIntervalMm(tool: ToolInput, pattern: PassPattern, surface: SurfaceDescriptor = PLANE): number {
  return surfaceModel(surface).maxIntervalMm(tool, pattern, surface);
}

/**
 * Validates the inputs of the forward problem (scallop height `h` to step-over).
 *
 * Rules: `R` from {@link MIN_TOOL_RADIUS_MM} to {@link MAX_TOOL_RADIUS_MM} mm, `0 <= Rcr <= R`,
 * `0 <= rho < 90`, `-90 < tilt < 90` degrees, pattern one-way or zigzag, `h` at least
 * {@link MIN_LENGTH_MM} and below both flanks' widest points and the height where the shank
 * starts to cut (scallopHeightLimits), except for a flat end lying flat (leavesNoScallop), which
 * accepts any h. Accepts numbers and numeric strings; NaN, Infinity,
 * empty and non-numeric values are rejected.
 */
export function validateForward(raw: RawForwardInput): Validation<ForwardInput> {
  const { c, tool, pattern, surface, gouges } = checkedPass(raw, ['R', 'Rcr', 'rho', 'tilt', 'h']);
  const h = c.values.h;
  if (h !== undefined && !gouges) {
    if (h <= 0) reject(c, 'h', 'not-positive');
    else if (h < MIN_LENGTH_MM) reject(c, 'h', 'too-small', MIN_LENGTH_MM);
    else if (tool !== null && surface !== null && !surfaceModel(surface).leavesNoScallop(tool, surface)) {
      const limits = scallopHeightLimits(tool, surface);
      if (!(limits.limitMm >= MIN_LENGTH_MM)) c.errors.push(inputError('h', 'wall-only', c.shown.h ?? ''));
      else if (h >= limits.limitMm) {
        const by = limits.limitBy;
        const shank = by === 'shank-right' || by === 'shank-left';
        const side = by === 'right-flank' || by === 'shank-right' ? 'right' : 'left';
        c.errors.push(
          inputError(
            'h',
            shank ? 'shank-cuts' : 'flank-wall',
            c.shown.h ?? '',
            limits.limitMm,
            tool.tiltAngleDeg === 0 && surface.kind === 'plane' && !shank ? null : side,
          ),
        );
      }
    }
  }
  if (c.errors.length > 0 || tool === null || pattern === null || surface === null || h === undefined) {
    return { ok: false, errors: c.errors };
  }
  return { ok: true, value: forwardInput(tool, pattern, h, surface) };
}

/**
 * Validates the inputs of the inverse problem (step-over `L` to scallop height).
 *
 * Rules: the tool rules of {@link validateForward}, and `0 < L` (at least 2 {@link MIN_LENGTH_MM})
 * below {@link maxIntervalMm} (2R without tilt): at or beyond it adjacent passes leave a wall.
 */
export function validateInverse(raw: RawInverseInput): Validation<InverseInput> {
  const { c, tool, pattern, surface, gouges } = checkedPass(raw, ['R', 'Rcr', 'rho', 'tilt', 'interval']);
  const L = c.values.interval;
  if (L !== undefined && !gouges) {
    if (L <= 0) reject(c, 'interval', 'not-positive');
    else if (L < 2 * MIN_LENGTH_MM) reject(c, 'interval', 'too-small', 2 * MIN_LENGTH_MM);
    else if (tool !== null && pattern !== null && surface !== null) {
      const noScallop = surfaceModel(surface).leavesNoScallop(tool, surface);
      const limit = scallopHeightLimits(tool, surface).limitMm;
      const max = noScallop || limit >= MIN_LENGTH_MM ? maxIntervalMm(tool, pattern, surface) : Number.NaN;
      const onPlaneNoTilt = tool.tiltAngleDeg === 0 && surface.kind === 'plane';
      if (!(max > 0) || !Number.isFinite(max)) reject(c, 'interval', 'wall-only');
      else if (!(L < max)) reject(c, 'interval', onPlaneNoTilt ? 'beyond-diameter' : 'beyond-interval', max);
    }
  }
  if (c.errors.length > 0 || tool === null || pattern === null || surface === null || L === undefined) {
    return { ok: false, errors: c.errors };
  }
  return { ok: true, value: inverseInput(tool, pattern, L, surface) };
}
