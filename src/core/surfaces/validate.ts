/**
 * The rules of a forward or inverse question on a registered surface: the tool's fields, the
 * pattern, the surface (a plane, or a cylinder's radius and axis), gouging, and the scallop height or
 * step-over against the surface model's limits (surfaces/registry.ts). Never throws and never yields
 * NaN: every input is accepted as finite numbers inside the solvers' domain or rejected with one
 * structured error per offending field. The parsing of one number, the raw shapes, the field
 * registry, the limits and the wording are the input layer's (input/validate.ts and its neighbours),
 * and so are the checks that ask no surface model (input/passFields.ts, the page's): this file adds
 * gouging and the limits on top of them. It sits above the surface models it asks, they below it.
 */
import type { ForwardInput, InverseInput } from '../domain/pass';
import { PLANE, type Surface } from '../domain/surface';
import type { PassPattern, ToolInput } from '../domain/tool';
import type { FieldName } from '../input/fields';
import { type AnyFieldName, type InputError, inputError, type Validation } from '../input/inputErrors';
import { MIN_LENGTH_MM } from '../input/limits';
import {
  forwardResult,
  inverseResult,
  lengthInRange,
  type PassFields,
  type PassValidation,
  passAnd,
  passFields,
  reject,
} from '../input/passFields';
import type { RawForwardInput, RawInverseInput, RawToolInput } from '../input/validate';
import type { FlankLimits } from '../tool/posture';
import { leavesNoScallop } from './models/plane';
import { type SurfaceDescriptor, surfaceModel } from './registry';

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

/** The opening every validation shares: the fields, the tool, the pattern and the surface, checked. */
interface CheckedPass extends PassFields {
  /** The surface is too tight for the tool (the gouging error is among the errors). */
  readonly gouges: boolean;
}

/**
 * The pass's fields checked (input/passFields.ts), then a surface too tight for the tool (gouging):
 * the errors of the fields and the tool in `c.errors`, then those of the pattern and the surface in
 * `rest` (`c.errors` unless given).
 */
function checkedPass(
  raw: RawToolInput & Readonly<Partial<Record<FieldName, unknown>>>,
  fields: readonly FieldName[],
  rest?: InputError[],
): CheckedPass {
  const p = passFields(raw, fields, rest);
  const { tool, surface } = p;
  const gouge = tool !== null && surface !== null ? gouging(tool, surface, String(raw.surfaceRadius ?? '')) : null;
  if (gouge) (rest ?? p.c.errors).push(gouge);
  return { ...p, gouges: gouge !== null };
}

/** The common part of a validation (input/passFields.ts), re-exported for the callers. */
export type { PassValidation };

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
  const p = checkedPass(raw, ['R', 'Rcr', 'rho', 'tilt'], rest);
  return passAnd(raw, field, p, rest, p.gouges);
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
  const p = checkedPass(raw, ['R', 'Rcr', 'rho', 'tilt', 'h']);
  const { c, tool, surface } = p;
  if (!p.gouges && lengthInRange(c, 'h', MIN_LENGTH_MM) && tool !== null && surface !== null) {
    const h = c.values.h as number;
    if (!surfaceModel(surface).leavesNoScallop(tool, surface)) {
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
  return forwardResult(p);
}

/**
 * Validates the inputs of the inverse problem (step-over `L` to scallop height).
 *
 * Rules: the tool rules of {@link validateForward}, and `0 < L` (at least 2 {@link MIN_LENGTH_MM})
 * below {@link maxIntervalMm} (2R without tilt): at or beyond it adjacent passes leave a wall.
 */
export function validateInverse(raw: RawInverseInput): Validation<InverseInput> {
  const p = checkedPass(raw, ['R', 'Rcr', 'rho', 'tilt', 'interval']);
  const { c, tool, pattern, surface } = p;
  if (
    !p.gouges &&
    lengthInRange(c, 'interval', 2 * MIN_LENGTH_MM) &&
    tool !== null &&
    pattern !== null &&
    surface !== null
  ) {
    const L = c.values.interval as number;
    const noScallop = surfaceModel(surface).leavesNoScallop(tool, surface);
    const limit = scallopHeightLimits(tool, surface).limitMm;
    const max = noScallop || limit >= MIN_LENGTH_MM ? maxIntervalMm(tool, pattern, surface) : Number.NaN;
    const onPlaneNoTilt = tool.tiltAngleDeg === 0 && surface.kind === 'plane';
    if (!(max > 0) || !Number.isFinite(max)) reject(c, 'interval', 'wall-only');
    else if (!(L < max)) reject(c, 'interval', onPlaneNoTilt ? 'beyond-diameter' : 'beyond-interval', max);
  }
  return inverseResult(p);
}
