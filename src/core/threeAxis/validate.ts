/**
 * Validation of the three-axis inputs (issue 20) as the command line and the batch give them (text
 * by the field registry's names) into a validated case: a sloped plane (raster, or waterline
 * without radii) or a surface of revolution (waterline with a feed or cross radius), which
 * solve.ts's solveThreeAxis solves (apart, so that validating loads no solver). Text is read as
 * input/validate.ts reads it (the same strict decimal numbers, its isNumberText); the ranges are the solvers' own (errors.ts, slopedPlane.ts,
 * waterlineRevolution.ts), so each message names the constraint and its limit in mm or degrees.
 * The combinations that do not exist are refused here too: a slope with a lead or a tilt (the slope
 * sets them), a raster angle other than 90 degrees with waterline passes (90, the contour, is theirs), a feed or cross radius with raster passes, a
 * horizontal step with waterline passes and a step-down with raster passes.
 */

import { FIELDS } from '../input/fields';
import { isNumberText } from '../input/validate';
import type { ThreeAxisErrorCode, ThreeAxisField } from './errors';
import type { SlopedPlaneAnswer, SlopedPlaneCase, ThreeAxisPasses } from './slopedPlane';
import type { RevolutionCase } from './waterlineRevolution';

/** The fields a three-axis input error can name (the solvers' fields, the strategy, and a lead or tilt given with a slope). */
export type ThreeAxisInputField = ThreeAxisField | 'passes' | 'rho' | 'tilt';

/** A rejected three-axis input: the solvers' error shape, with the parsing and combination codes. */
export interface ThreeAxisInputError {
  readonly field: ThreeAxisInputField;
  readonly code: ThreeAxisErrorCode | 'missing' | 'not-a-number' | 'not-a-strategy' | 'not-with';
  /** The value as given (text), or the number. */
  readonly got: string | number;
  /** The bound it broke (mm or degrees), or null. */
  readonly limit: number | null;
  /** One line, in mm and degrees. */
  readonly message: string;
}

/** The raw three-axis inputs, by registry field name (text as typed; undefined or empty: not given). */
export interface RawThreeAxisInput {
  readonly R?: unknown;
  readonly Rcr?: unknown;
  readonly slope?: unknown;
  readonly passes?: unknown;
  readonly rasterAngle?: unknown;
  readonly feedRadius?: unknown;
  readonly crossRadius?: unknown;
  /** A lead or tilt given beside the slope: an error (the slope sets them). */
  readonly rho?: unknown;
  readonly tilt?: unknown;
}

/** The quantity a three-axis problem is given: h (forward), or a step (inverse: the cusp it leaves). */
export type ThreeAxisQuantity = 'h' | 'interval' | 'horizontalStep' | 'stepDown';

/** A validated three-axis problem. */
export type ThreeAxisProblem =
  | {
      readonly surface: 'plane';
      readonly case: SlopedPlaneCase;
      readonly quantity: ThreeAxisQuantity;
      readonly mm: number;
    }
  | {
      readonly surface: 'revolution';
      readonly case: RevolutionCase;
      readonly quantity: ThreeAxisQuantity;
      readonly mm: number;
    };

/**
 * The answer of a three-axis problem, whichever surface: the sloped plane's fields (on a surface of
 * revolution Lxy is the horizontal distance between the tool axes) but its height limit, and the passes.
 */
export interface ThreeAxisAnswer extends Omit<SlopedPlaneAnswer, 'heightLimitMm'> {
  readonly passes: ThreeAxisPasses;
}

/** The programmed steps that belong to one kind of passes: refused with the other, and why. */
const STEP_NOT_WITH = {
  horizontalStep: {
    passes: 'waterline',
    why: 'is the step of raster passes: waterline passes are programmed by their step-down dz.',
  },
  stepDown: {
    passes: 'raster',
    why: 'is the step of waterline passes: raster passes are programmed by their horizontal step Lxy.',
  },
} as const satisfies Record<'horizontalStep' | 'stepDown', { passes: ThreeAxisPasses; why: string }>;

const STRATEGIES: readonly ThreeAxisPasses[] = ['raster', 'waterline'];

/** The raster angle of waterline passes (they follow the contour), degrees. */
export const WATERLINE_RASTER_ANGLE_DEG = 90;

/** Text of a raw value, trimmed; undefined when not given (absent or empty). */
function textOf(raw: unknown): string | undefined {
  if (raw === undefined || raw === null) return undefined;
  const text = (typeof raw === 'string' ? raw : String(raw)).trim();
  return text === '' ? undefined : text;
}

function labelOf(field: ThreeAxisInputField): string {
  return FIELDS[field].label;
}

function inputError(
  field: ThreeAxisInputField,
  code: ThreeAxisInputError['code'],
  got: string | number,
  detail: string,
  limit: number | null = null,
): ThreeAxisInputError {
  return { field, code, got, limit, message: `${labelOf(field)} ${detail}` };
}

/** A number from its text: the value, or the error (missing, or not a finite decimal number). */
function numberOf(
  field: ThreeAxisInputField,
  raw: unknown,
  errors: ThreeAxisInputError[],
  required: boolean,
): number | undefined {
  if (typeof raw === 'number' && Number.isFinite(raw)) return raw;
  const text = textOf(raw);
  if (text === undefined) {
    if (required) errors.push(inputError(field, 'missing', '', 'is missing.'));
    return undefined;
  }
  const value = Number(text);
  if (!isNumberText(text) || !Number.isFinite(value)) {
    errors.push(inputError(field, 'not-a-number', text, `must be a finite number (got "${text}").`));
    return undefined;
  }
  return value;
}

/**
 * Validates a three-axis problem: the tool, the slope (degrees), the strategy (`raster` by
 * default), the raster angle (raster: degrees, default 0; waterline: 90 or none), the signed feed and cross radii
 * (waterline only; mm; either one makes the surface one of revolution), and the quantity given
 * (`h`, `interval` L along the surface, `horizontalStep` Lxy for raster, `stepDown` dz for
 * waterline; mm). Fixed ranges are checked by the solver ({@link solveThreeAxis}); this checks the
 * text and the combinations.
 */
export function validateThreeAxis(
  raw: RawThreeAxisInput,
  quantity: ThreeAxisQuantity,
  rawValue: unknown,
):
  | { readonly ok: true; readonly value: ThreeAxisProblem }
  | { readonly ok: false; readonly errors: readonly ThreeAxisInputError[] } {
  const errors: ThreeAxisInputError[] = [];
  const R = numberOf('R', raw.R, errors, true);
  const Rcr = numberOf('Rcr', raw.Rcr, errors, true);
  const slope = numberOf('slope', raw.slope, errors, true);
  for (const field of ['rho', 'tilt'] as const) {
    const text = textOf(raw[field]);
    if (text !== undefined)
      errors.push(
        inputError(
          field,
          'not-with',
          text,
          'does not go with a slope: on a three-axis machine the slope and the raster angle set the lead and tilt (leave it empty).',
        ),
      );
  }
  const passesText = textOf(raw.passes) ?? 'raster';
  const passes = STRATEGIES.find((s) => s === passesText);
  if (passes === undefined)
    errors.push(
      inputError('passes', 'not-a-strategy', passesText, `must be raster or waterline (got "${passesText}").`),
    );
  // Waterline passes follow the contour, psi = 90 by definition: a raster angle of 90 (a batch's
  // one rasterAngle column for mixed rows) or none is theirs; any other value is refused.
  const psiText = textOf(raw.rasterAngle);
  const psiGiven = numberOf('rasterAngle', raw.rasterAngle, errors, false);
  if (passes === 'waterline' && psiGiven !== undefined && psiGiven !== WATERLINE_RASTER_ANGLE_DEG)
    errors.push(
      inputError(
        'rasterAngle',
        'not-with',
        psiText ?? psiGiven,
        `must be ${WATERLINE_RASTER_ANGLE_DEG} degrees or left empty for waterline passes (got ${psiText}): they follow the contour, psi = ${WATERLINE_RASTER_ANGLE_DEG}; other raster angles are for raster passes.`,
        WATERLINE_RASTER_ANGLE_DEG,
      ),
    );
  const psi = passes === 'waterline' ? WATERLINE_RASTER_ANGLE_DEG : (psiGiven ?? 0);
  let feed: number | null = null;
  let cross: number | null = null;
  for (const field of ['feedRadius', 'crossRadius'] as const) {
    const text = textOf(raw[field]);
    if (text === undefined) continue;
    if (passes === 'raster') {
      errors.push(
        inputError(
          field,
          'not-with',
          text,
          'is for waterline passes on a surface of revolution only (give --passes waterline, or leave it out for a plane).',
        ),
      );
      continue;
    }
    const value = numberOf(field, text, errors, false);
    if (value === undefined) continue;
    if (!(Math.abs(value) >= FIELDS[field].range.min && Math.abs(value) <= FIELDS[field].range.max))
      errors.push(
        inputError(
          field,
          'out-of-range',
          value,
          `must be from ${FIELDS[field].range.min} mm to ${FIELDS[field].range.max} mm in size, > 0 convex, < 0 concave (got ${value}); leave it out for a straight line.`,
        ),
      );
    else if (field === 'feedRadius') feed = value;
    else cross = value;
  }
  const wrongStep = quantity === 'horizontalStep' || quantity === 'stepDown' ? STEP_NOT_WITH[quantity] : null;
  if (wrongStep !== null && passes === wrongStep.passes)
    errors.push(inputError(quantity, 'not-with', textOf(rawValue) ?? '', wrongStep.why));
  const mm = numberOf(quantity, rawValue, errors, true);
  if (errors.length > 0 || R === undefined || Rcr === undefined || slope === undefined || mm === undefined)
    return { ok: false, errors };
  const onRevolution =
    passes === 'waterline' && (textOf(raw.feedRadius) !== undefined || textOf(raw.crossRadius) !== undefined);
  if (onRevolution)
    return {
      ok: true,
      value: {
        surface: 'revolution',
        case: { toolRadiusMm: R, cornerRadiusMm: Rcr, slopeDeg: slope, feedRadiusMm: feed, crossRadiusMm: cross },
        quantity,
        mm,
      },
    };
  return {
    ok: true,
    value: {
      surface: 'plane',
      case: { toolRadiusMm: R, cornerRadiusMm: Rcr, slopeDeg: slope, passes: passes ?? 'raster', rasterAngleDeg: psi },
      quantity,
      mm,
    },
  };
}
