/**
 * Input validation for the path-interval solvers: the input layer's part. The raw shapes (as they
 * come from a form, a URL or a CSV cell), the strict reading of one number, and the builders of
 * validated inputs; the wording of errors (describeInputError, in inputErrors.ts) and the limits
 * (limits.ts) re-exported for the callers. The rules that ask a surface model (gouging, the height
 * and step-over limits: validateForward, validateInverse, validatePassAnd, scallopHeightLimits,
 * maxIntervalMm) are in surfaces/validate.ts, above the models; this file sits below them.
 */
import type { ForwardInput, InverseInput, PassInput } from '../domain/pass';
import { PLANE, type Surface } from '../domain/surface';
import { PASS_PATTERNS, type PassPattern, type ToolInput } from '../domain/tool';
import { FIELD_LABELS, type FieldName } from './fields';
import {
  type AnyFieldName,
  type AnyInputError,
  type DescribeOptions,
  describeInputError,
  type InputError,
  type InputErrorCode,
  type InputErrorOf,
  inputError,
  type Validation,
} from './inputErrors';
import {
  MAX_SURFACE_RADIUS_MM,
  MAX_TOOL_RADIUS_MM,
  MIN_LENGTH_MM,
  MIN_SURFACE_RADIUS_MM,
  MIN_TOOL_RADIUS_MM,
} from './limits';

/** Names of the user-facing inputs (the field registry's, input/fields.ts). */
/** The wording of input errors (inputErrors.ts), re-exported for the callers. */
/** The domain types (domain/): re-exported where they were defined before, for the callers. */
export type {
  AnyFieldName,
  AnyInputError,
  DescribeOptions,
  FieldName,
  ForwardInput,
  InputError,
  InputErrorCode,
  InputErrorOf,
  InverseInput,
  PassInput,
  PassPattern,
  ToolInput,
  Validation,
};
/** The inputs' limits (limits.ts), re-exported for the callers. */
export {
  describeInputError,
  inputError,
  MAX_SURFACE_RADIUS_MM,
  MAX_TOOL_RADIUS_MM,
  MIN_LENGTH_MM,
  MIN_SURFACE_RADIUS_MM,
  MIN_TOOL_RADIUS_MM,
  PASS_PATTERNS,
};

/** Raw values as they come from a form, a URL or a CSV cell (mm and degrees). */
export interface RawToolInput {
  readonly R: unknown;
  readonly Rcr: unknown;
  readonly rho: unknown;
  /** Missing (undefined) means 0. */
  readonly tilt?: unknown;
  /** Missing (undefined) means one-way. */
  readonly pattern?: unknown;
  /** Signed cylinder radius in mm (convex > 0, concave < 0); missing, empty or 'plane' means a plane. */
  readonly surfaceRadius?: unknown;
  /** 'feed' (default) or 'cross'; only with a surface radius. */
  readonly surfaceAxis?: unknown;
}
export interface RawForwardInput extends RawToolInput {
  readonly h: unknown;
}
export interface RawInverseInput extends RawToolInput {
  readonly interval: unknown;
}

/** Labels of the fields as messages name them (the field registry's). */
export { FIELD_LABELS };

export type Parsed = { ok: true; value: number; shown: string } | { ok: false; code: InputErrorCode; shown: string };

/** A strict decimal number: optional sign, digits with an optional point, optional exponent. */
const NUMBER_PATTERN = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

/** True for text that reads as a number as validation reads it (a strict decimal; see NUMBER_PATTERN). */
export function isNumberText(text: string): boolean {
  return NUMBER_PATTERN.test(text);
}

/** Parses a number as validation does: a strict decimal text or a finite number; else the error code. */
export function parseNumber(raw: unknown): Parsed {
  if (raw === undefined || raw === null) return { ok: false, code: 'missing', shown: '' };
  if (typeof raw === 'number') {
    if (Number.isNaN(raw)) return { ok: false, code: 'not-a-number', shown: 'NaN' };
    if (!Number.isFinite(raw)) return { ok: false, code: 'not-finite', shown: String(raw) };
    return { ok: true, value: raw, shown: String(raw) };
  }
  if (typeof raw !== 'string') return { ok: false, code: 'not-a-number', shown: typeof raw };
  const text = raw.trim();
  if (text === '') return { ok: false, code: 'missing', shown: '' };
  if (!NUMBER_PATTERN.test(text)) return { ok: false, code: 'not-a-number', shown: text };
  const value = Number(text);
  if (!Number.isFinite(value)) return { ok: false, code: 'not-finite', shown: text };
  return { ok: true, value, shown: text };
}

/** Each question's given value by its key, and the input it makes. */
interface GivenInputs {
  readonly scallopHeightMm: ForwardInput;
  readonly intervalMm: InverseInput;
}

/**
 * A builder of one question's input, property by property with the given value last under `key`:
 * objects made by spreading (`{ ...tool, h }`) get a slow shape in V8 (measured: 7-9 times slower
 * to read in the solvers); a literal whose last key is computed reads as fast as one written out
 * (measured in Node 20: 4e7 reads of five fields, 105-196 ms either way, the machine shared).
 */
function inputOf<K extends keyof GivenInputs>(
  key: K,
): (tool: ToolInput, pattern: PassPattern, value: number, surface?: Surface) => GivenInputs[K] {
  return (tool, pattern, value, surface = PLANE) =>
    ({
      toolRadiusMm: tool.toolRadiusMm,
      cornerRadiusMm: tool.cornerRadiusMm,
      leadAngleDeg: tool.leadAngleDeg,
      tiltAngleDeg: tool.tiltAngleDeg,
      pattern,
      surface,
      [key]: value,
    }) as PassInput as GivenInputs[K];
}

/** A forward input: the tool, the pattern, the scallop height h (mm) and the surface (a plane unless given). */
export const forwardInput = inputOf('scallopHeightMm');

/** An inverse input: the tool, the pattern, the step-over L (mm) and the surface (a plane unless given). */
export const inverseInput = inputOf('intervalMm');
