/**
 * Input errors of the three-axis solvers, as data with a one-line message in mm (the same shape
 * as validate.ts's InputError, with the three-axis fields), so that the command line and the
 * page can word them in the user's unit later. Never thrown: every solver returns either an
 * answer or one of these.
 */
import { formatInputNumber, formatSignificant, fromMm, type LengthUnit, unitSymbol } from '../input/units';

/** The inputs a three-axis error can name. */
export type ThreeAxisField =
  | 'R'
  | 'Rcr'
  | 'slope'
  | 'rasterAngle'
  | 'feedRadius'
  | 'crossRadius'
  | 'h'
  | 'interval'
  | 'horizontalStep'
  | 'stepDown';

/** Why it was rejected. */
export type ThreeAxisErrorCode =
  /** Not a finite number, or outside its fixed range (`limit` null; the message says the range). */
  | 'out-of-range'
  /** Below the smallest accepted value (`limit`). */
  | 'too-small'
  /** A vertical wall (slope 90): the tool's side cuts it flat, no scallop at any step. */
  | 'vertical-wall'
  /** Waterline needs a slope: on a flat floor (slope 0) all levels coincide. */
  | 'needs-slope'
  /** Above `limit` (mm) the shank (the tool's cylindrical side), not the corner, forms the cusp. */
  | 'shank-cuts'
  /** At or above `limit` (mm) a flank of the profile is a wall, not a scallop flank. */
  | 'flank-wall'
  /** The shank or a flank rises straight from the contact (a flat end's side): no scallop at any step. */
  | 'wall-only'
  /** The step is at or beyond `limit` (mm, in the step's own terms): adjacent passes leave a wall. */
  | 'beyond-step'
  /** The next pass would lie past the surface's usable part (overhang, bowl bottom, the axis). */
  | 'past-surface'
  /** The tool reaches inside the design surface away from the contact; `limit` the radius that fits. */
  | 'gouging';

/** One rejected input. */
export interface ThreeAxisError {
  readonly field: ThreeAxisField;
  readonly code: ThreeAxisErrorCode;
  /** The value given (mm or degrees). */
  readonly got: number;
  /** The bound it broke, mm for lengths and degrees for angles; null when there is none. */
  readonly limit: number | null;
  /** The message in mm, one line. */
  readonly message: string;
}

/** Labels of the fields as messages name them. */
export const THREE_AXIS_FIELD_LABELS: Readonly<Record<ThreeAxisField, string>> = {
  R: 'Tool radius R',
  Rcr: 'Corner radius Rcr',
  slope: 'Slope alpha',
  rasterAngle: 'Raster angle psi',
  feedRadius: 'Feed radius Rf',
  crossRadius: 'Cross radius Rc',
  h: 'Scallop height h',
  interval: 'Step-over L along the surface',
  horizontalStep: 'Horizontal step Lxy',
  stepDown: 'Step-down dz',
};

/** A number for a message: 8 significant digits, no trailing zeros. */
export function formatNumber(value: number): string {
  return formatSignificant(value, { digits: 8, trimZeros: true, exponentBelow: 1e-5 });
}

/** An error as data with its message (`detail` completes the sentence after the label). */
export function threeAxisError(
  field: ThreeAxisField,
  code: ThreeAxisErrorCode,
  got: number,
  limit: number | null,
  detail: string,
): ThreeAxisError {
  return { field, code, got, limit, message: `${THREE_AXIS_FIELD_LABELS[field]} ${detail}` };
}

/** Either an answer or the errors (at most one per field). */
export type ThreeAxisResult<T> =
  | { readonly ok: true; readonly value: T }
  | { readonly ok: false; readonly errors: readonly ThreeAxisError[] };

/** Smallest scallop height and step accepted, mm (as validate.ts: one nanometre). */
export const MIN_THREE_AXIS_LENGTH_MM = 1e-9;

/** Tool radius range, mm (as validate.ts). */
export const THREE_AXIS_TOOL_RADIUS_RANGE_MM: readonly [number, number] = [0.001, 1000];

/** Range of |Rf| and |Rc|, mm (as validate.ts's cylinder radius); beyond, give no radius (straight). */
export const THREE_AXIS_SURFACE_RADIUS_RANGE_MM: readonly [number, number] = [0.001, 1e6];

/** The tool's errors: R in range, 0 <= Rcr <= R. */
export function checkTool(toolRadiusMm: number, cornerRadiusMm: number): ThreeAxisError[] {
  const out: ThreeAxisError[] = [];
  const [lo, hi] = THREE_AXIS_TOOL_RADIUS_RANGE_MM;
  if (!(toolRadiusMm >= lo && toolRadiusMm <= hi))
    out.push(
      threeAxisError(
        'R',
        'out-of-range',
        toolRadiusMm,
        null,
        `must be from ${lo} mm to ${hi} mm (got ${toolRadiusMm}).`,
      ),
    );
  if (!(cornerRadiusMm >= 0 && cornerRadiusMm <= toolRadiusMm))
    out.push(
      threeAxisError(
        'Rcr',
        'out-of-range',
        cornerRadiusMm,
        Number.isFinite(toolRadiusMm) ? toolRadiusMm : null,
        `must be from 0 to the tool radius R (got ${cornerRadiusMm}); Rcr = R is a ball end mill.`,
      ),
    );
  return out;
}

/** The scallop height's own errors (finite, at least 1 nm). */
export function checkHeight(hMm: number): ThreeAxisError[] {
  if (!Number.isFinite(hMm) || hMm < MIN_THREE_AXIS_LENGTH_MM)
    return [
      threeAxisError(
        'h',
        Number.isFinite(hMm) && hMm > 0 ? 'too-small' : 'out-of-range',
        hMm,
        MIN_THREE_AXIS_LENGTH_MM,
        `must be at least ${MIN_THREE_AXIS_LENGTH_MM} mm (got ${hMm}).`,
      ),
    ];
  return [];
}

/** A step's own errors (finite, at least 1 nm). */
export function checkStep(field: ThreeAxisField, stepMm: number): ThreeAxisError[] {
  if (!Number.isFinite(stepMm) || stepMm < MIN_THREE_AXIS_LENGTH_MM)
    return [
      threeAxisError(
        field,
        Number.isFinite(stepMm) && stepMm > 0 ? 'too-small' : 'out-of-range',
        stepMm,
        MIN_THREE_AXIS_LENGTH_MM,
        `must be at least ${MIN_THREE_AXIS_LENGTH_MM} mm (got ${stepMm}).`,
      ),
    ];
  return [];
}

/**
 * A three-axis solver's message (in mm) in the user's words: the value given quoted as typed
 * (`typed`, as written, in place of the mm number), every "N mm" in `unit`; for waterline passes
 * (they have no raster angle) the slope named alone. The command line's and the lookup table's one wording.
 */
export function threeAxisMessageInUnit(
  e: { readonly message: string; readonly got: unknown },
  passes: string,
  unit: LengthUnit,
  typed: string,
): string {
  const quoted = e.message.replace(`(got ${String(e.got)})`, `(got ${typed})`);
  const words =
    unit === 'mm'
      ? quoted
      : quoted.replace(
          /(-?\d+(?:\.\d+)?(?:e[+-]?\d+)?) mm\b/g,
          (_, n: string) => `${formatInputNumber(fromMm(Number(n), unit))} ${unitSymbol(unit)}`,
        );
  return passes === 'waterline'
    ? words
        .replace('at this slope and raster angle', 'at this slope')
        .replace('the slope and the raster angle set', 'the slope sets')
    : words;
}
