/**
 * Input validation for the path-interval solvers.
 *
 * Never throws and never yields NaN: every input is either accepted as finite numbers inside
 * the solvers' domain or rejected with one structured error per offending field (field, code,
 * the bound it broke, what was given). Messages are written from that data in one place
 * (describeInputError), in the user's unit.
 */
import type { ForwardInput, InverseInput, PassInput } from '../domain/pass';
import { PLANE, type Surface, type SurfaceAxis } from '../domain/surface';
import { PASS_PATTERNS, type PassPattern, type ToolInput } from '../domain/tool';
import { leavesNoScallop } from '../surfaces/models/plane';
import { type SurfaceDescriptor, surfaceModel } from '../surfaces/registry';
import type { FlankLimits } from '../tool/posture';
import { FIELD_LABELS, FIELDS, type FieldName, isLengthField } from './fields';
import { formatAngleDeg, formatInputNumber, fromMm, type LengthUnit, unitSymbol } from './units';

/** Names of the user-facing inputs (the field registry's, input/fields.ts). */
export type { FieldName };

/**
 * Every field an error can name: the registry's tool, pass and quantity fields, and the two
 * principal radii of a doubly curved point (core/doublyCurved/validate.ts; the registry files them
 * under three-axis machining, where waterline passes take them too).
 */
export type AnyFieldName = FieldName | 'feedRadius' | 'crossRadius';

/** Why a field was rejected. */
export type InputErrorCode =
  | 'missing'
  | 'not-a-number'
  | 'not-finite'
  | 'not-positive'
  | 'negative'
  | 'too-large'
  | 'too-small'
  | 'out-of-range'
  | 'not-a-pattern'
  | 'not-an-axis'
  | 'gouging'
  /** A concave cylinder whose wall the shank crosses below the axis height (limit: the smallest radius, or null: any). */
  | 'shank-gouging'
  | 'corner-exceeds-radius'
  | 'flank-wall'
  | 'shank-cuts'
  | 'beyond-diameter'
  | 'beyond-interval'
  | 'beyond-max-ra'
  | 'wall-only'
  /**
   * A doubly curved point the tool gouges (limit: the signed radius of this field that the
   * nearest admissible value reaches with the other held, or null: none helps; `radiusLimit`).
   */
  | 'radius-gouging'
  /** A target the page does not solve: a target Ra on a cylinder across the feed takes seconds (the command line does). */
  | 'slow-target';

/** One rejected field, as data; `message` is its description in mm (describeInputError). */
export interface InputErrorOf<F extends AnyFieldName> {
  readonly field: F;
  readonly code: InputErrorCode;
  /** The value as given, as text (what the user typed, or the number). */
  readonly got: string;
  /** The bound it broke: mm for lengths, degrees for angles; null when there is none. */
  readonly limit: number | null;
  /** For `flank-wall` and `shank-cuts`: the side (right is +Y, the side the tool tilts to). */
  readonly side: 'right' | 'left' | null;
  /**
   * For `shank-gouging`: the cylinder's axis and the shank's lean from the surface normal seen along
   * it (degrees), which set what would help.
   */
  readonly shankLean?: { readonly axis: SurfaceAxis; readonly leanDeg: number };
  /**
   * For `radius-gouging`: what this radius must be with the other held (`kind` as gouging.ts's
   * RadiusLimit: `concave-at-least`, `convex-at-most`, `not-concave`, `none`), the other radius held
   * (signed mm, Infinity straight), and what the other radius must be with this one held.
   */
  readonly radiusLimit?: {
    readonly kind: 'concave-at-least' | 'convex-at-most' | 'not-concave' | 'none';
    readonly heldMm: number;
    readonly other: {
      readonly kind: 'any' | 'concave-at-least' | 'convex-at-most' | 'not-concave' | 'none';
      readonly radiusMm: number | null;
    };
  };
  /** The message in mm, ready to show as it is. */
  readonly message: string;
}

/** An error of the forward and inverse problems. */
export type InputError = InputErrorOf<FieldName>;

/** An error of the target-roughness problem (its own field `Ra` included). */
export type AnyInputError = InputErrorOf<AnyFieldName>;

/** Either the accepted value or the list of errors (at most one per field). */
export type Validation<T, E extends AnyInputError = InputError> =
  | { readonly ok: true; readonly value: T }
  | { readonly ok: false; readonly errors: readonly E[] };

/** The domain types (domain/): re-exported where they were defined before, for the callers. */
export type { ForwardInput, InverseInput, PassInput, PassPattern, ToolInput };
export { PASS_PATTERNS };

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

/** Smallest and largest |Rs| of a cylinder, mm; beyond the largest a plane answers to 1e-9 mm (and the arithmetic keeps its digits). */
export const MIN_SURFACE_RADIUS_MM = 0.001;
export const MAX_SURFACE_RADIUS_MM = 1e6;

/** Largest tool radius accepted, in mm: keeps every intermediate product far from overflow. */
export const MAX_TOOL_RADIUS_MM = 1000;

/** Smallest tool radius accepted, in mm (the smallest micro end mills are 0.005 mm across). */
export const MIN_TOOL_RADIUS_MM = 0.001;

/**
 * Smallest scallop height accepted, in mm: one nanometre, far below any measurable scallop,
 * so every result stays a normal floating-point number. The step-over's smallest is twice it.
 */
export const MIN_LENGTH_MM = 1e-9;

/** Labels of the fields as messages name them (the field registry's). */
export { FIELD_LABELS };

/** Options of {@link describeInputError}. */
export interface DescribeOptions {
  /** Replaces `got` (for instance by the text exactly as typed in the user's unit). */
  readonly typed?: string;
  /** Name the step-over as its half, `L/2` (a command line given --half-interval). */
  readonly intervalAsHalf?: boolean;
  /**
   * The tool size was given as the diameter `D = 2R` (the page's size switch): the tool radius
   * is named `D` with its limits doubled, and limits set by R are written `D/2`.
   */
  readonly toolSizeAsDiameter?: boolean;
  /**
   * The surface radius was entered as a magnitude, the side chosen apart (the page's convex /
   * concave switch): its messages name |Rs| and leave the sign convention out.
   */
  readonly radiusAsMagnitude?: boolean;
  /**
   * The cylinder was given as one principal radius (the command line's --feed-radius or
   * --cross-radius alone): its messages name that radius instead of Rs.
   */
  readonly surfaceRadiusAs?: 'feedRadius' | 'crossRadius';
}

/**
 * The message of an input error in `unit` (lengths converted; angles stay in degrees). The one
 * place where error data becomes words.
 */
export function describeInputError(e: AnyInputError, unit: LengthUnit, options: DescribeOptions = {}): string {
  const half = e.field === 'interval' && options.intervalAsHalf === true;
  const diameter = options.toolSizeAsDiameter === true;
  const label = half
    ? FIELDS.halfInterval.label
    : diameter && e.field === 'R'
      ? FIELDS.D.label
      : e.field === 'surfaceRadius' && options.surfaceRadiusAs !== undefined
        ? FIELDS[options.surfaceRadiusAs].label
        : FIELDS[e.field].label;
  const u = unitSymbol(unit);
  const scale = half ? 0.5 : diameter && e.field === 'R' ? 2 : 1;
  const length = (mm: number) => `${formatInputNumber(fromMm(mm * scale, unit))} ${u}`;
  const limit = e.limit === null ? '' : isLengthField(e.field) ? length(e.limit) : `${formatAngleDeg(e.limit)} degrees`;
  const shown = options.typed ?? e.got;
  const got = `(got ${shown.length > 24 ? `${shown.slice(0, 21)}...` : shown})`;
  switch (e.code) {
    case 'missing':
      return `${label} is missing: enter a number.`;
    case 'not-a-number':
      return `${label} must be a number ${got.replace('(got ', '(got "').replace(/\)$/, '")')}.`;
    case 'not-finite':
      return `${label} must be a finite number ${got}.`;
    case 'not-positive':
      return `${label} must be greater than 0 ${u} ${got}.`;
    case 'negative':
      return `${label} must be 0 ${u} or more ${got}.`;
    case 'too-small':
      return `${label} must be at least ${limit} ${got}.`;
    case 'too-large':
      return `${label} must be at most ${limit} ${got}.`;
    case 'out-of-range':
      if (e.field === 'surfaceRadius' && options.radiusAsMagnitude === true)
        return `${label} must be a radius from ${length(MIN_SURFACE_RADIUS_MM)} to ${length(MAX_SURFACE_RADIUS_MM)} ${got}.`;
      if (e.field === 'feedRadius' || e.field === 'crossRadius')
        return `${label} must be a radius from ${length(MIN_SURFACE_RADIUS_MM)} to ${length(MAX_SURFACE_RADIUS_MM)}, negative for concave; leave it out for straight ${got}.`;
      if (e.field === 'surfaceRadius')
        return `${label} must be a radius from ${length(MIN_SURFACE_RADIUS_MM)} to ${length(MAX_SURFACE_RADIUS_MM)}, negative for a concave cylinder ${got}.`;
      return e.field === 'rho'
        ? `${label} must be at least 0 and below 90 degrees ${got}.`
        : `${label} must be above -90 and below 90 degrees ${got}.`;
    case 'not-a-pattern':
      return `${label} must be one-way or zigzag ${got.replace('(got ', '(got "').replace(/\)$/, '")')}.`;
    case 'not-an-axis':
      return `${label} must be feed or cross ${got.replace('(got ', '(got "').replace(/\)$/, '")')}.`;
    case 'gouging':
      return e.limit === null || !Number.isFinite(e.limit)
        ? `This tool gouges a concave cylinder of any radius with this axis and posture ${got}: a flat bottom without lead reaches below the surface on both sides of the contact. Add lead or tilt, or use a ball end.`
        : options.radiusAsMagnitude === true
          ? `${label}: a concave cylinder must have a radius of at least ${length(Math.abs(e.limit))} for this tool and posture ${got}; a tighter one is gouged (the tool reaches below the surface away from the contact).`
          : `${label}: a concave cylinder must have a radius of at least ${length(Math.abs(e.limit))} for this tool and posture (Rs at most ${length(e.limit)}) ${got}; a tighter one is gouged (the tool reaches below the surface away from the contact).`;
    case 'shank-gouging': {
      const lean = formatAngleDeg(e.shankLean?.leanDeg ?? 45);
      const help =
        e.shankLean?.axis === 'cross'
          ? 'Less lead would help (seen along the axis the shank leans by the lead; tilt does not matter).'
          : 'Less tilt or lead would help.';
      if (e.limit === null || !Number.isFinite(e.limit))
        return `The shank of this tool crosses the wall of a concave cylinder of any radius with this axis and posture ${got}: seen along the cylinder's axis it leans ${lean} degrees from the surface normal, and at 45 degrees or more it meets the wall below the axis's height. ${help}`;
      const radius =
        options.radiusAsMagnitude === true
          ? `at least ${length(Math.abs(e.limit))}`
          : `at least ${length(Math.abs(e.limit))} (Rs at most ${length(e.limit)})`;
      return `${label}: a concave cylinder must have a radius of ${radius} for this tool and posture ${got}; in a tighter one the shank (the tool's cylindrical side, leaning ${lean} degrees from the surface normal seen along the cylinder's axis) crosses the surface below the axis's height. ${help}`;
    }
    case 'corner-exceeds-radius':
      return diameter
        ? `${label} must be at most D/2 = ${limit} ${got}; Rcr = D/2 is a ball end mill.`
        : `${label} must not exceed the tool radius R = ${limit} ${got}; Rcr = R is a ball end mill.`;
    case 'flank-wall':
      return e.side === null
        ? `${label} must be below the profile's full height (R - Rcr) sin(rho) + Rcr = ${limit} ${got}; at or above it the tool flank leaves a wall, not a scallop.`
        : `${label} must be below ${limit}, the height of the ${e.side} flank's widest point ${got}; at or above it that flank leaves a wall, not a scallop.`;
    case 'shank-cuts':
      return `${label} must be below ${limit} ${got}: above it the shank (the tool's cylindrical side, leaning to the ${e.side ?? 'right'} with the tilt) would cut the surface.`;
    case 'beyond-diameter':
      return `${label} must be below the tool ${half ? 'radius R' : diameter ? 'diameter D' : 'diameter 2R'} = ${limit} ${got}; at or beyond it adjacent passes leave a wall.`;
    case 'wall-only':
      return `${label} cannot be answered ${got}: in this posture the tool cuts a step at any step-over (a flank or the shank rises straight from the contact, as a tilted flat end does), so no scallop forms. Add a corner radius, or lead, or less tilt.`;
    case 'beyond-max-ra':
      return e.limit === null || !(e.limit > 0)
        ? `${label} cannot be reached ${got}: this tool in this posture leaves no scallop (a flat bottom lying on the surface), so Ra = 0 at any step-over up to its diameter.`
        : `${label} must be below ${limit} ${got}, the largest Ra this tool, posture and pattern leave on this surface; passes far enough apart to leave more leave a wall, not a scallop.`;
    case 'radius-gouging':
      return radiusGougingText(e, label, length, got);
    case 'slow-target':
      return `${label} as the target on a cylinder with the axis across the feed takes seconds to solve (each step integrates the revolved profile), longer than the page waits for an answer ${got}: give the scallop height h instead, or use the command line's --ra.`;
    case 'beyond-interval':
      return `${label} must be below ${limit} ${got}, the widest step-over these flanks allow; at or beyond it adjacent passes leave a wall, not a scallop.`;
  }
}

/** The message of a `radius-gouging` error (see describeInputError). */
function radiusGougingText(e: AnyInputError, label: string, length: (mm: number) => string, got: string): string {
  const feed = e.field === 'feedRadius';
  const me = feed ? 'Rf' : 'Rc';
  const them = feed ? 'Rc' : 'Rf';
  const r = e.radiusLimit;
  const held = r === undefined || !Number.isFinite(r.heldMm) ? `${them} straight` : `${them} = ${length(r.heldMm)}`;
  const mag = e.limit === null ? '' : length(Math.abs(e.limit));
  let need: string;
  switch (r?.kind ?? 'none') {
    case 'concave-at-least':
      need = `${label}: a concave ${me} must be at least ${mag} (${me} at most ${length(-Math.abs(e.limit ?? 0))}) for this tool and posture with ${held} held ${got}`;
      break;
    case 'convex-at-most':
      need = `${label} must be convex and at most ${mag} for this tool and posture with ${held} held ${got}`;
      break;
    case 'not-concave':
      need = `${label} must be straight or convex for this tool and posture with ${held} held ${got}: any concave ${me} is gouged`;
      break;
    default:
      need = `This tool gouges the point at any radius ${me} with ${held} held ${got}`;
  }
  const o = r?.other;
  const otherText =
    o === undefined
      ? ''
      : o.kind === 'concave-at-least' && o.radiusMm !== null
        ? `; or, with ${me} held, a concave ${them} of at least ${length(o.radiusMm)}`
        : o.kind === 'convex-at-most' && o.radiusMm !== null
          ? `; or, with ${me} held, a convex ${them} of at most ${length(o.radiusMm)}`
          : o.kind === 'not-concave'
            ? `; or, with ${me} held, a straight or convex ${them}`
            : o.kind === 'none'
              ? `; no ${them} helps with ${me} held`
              : '';
  return `${need}${otherText} (the tool reaches below the surface away from the contact).`;
}

/** An input error as data, with its message in mm. */
export function inputError<F extends AnyFieldName>(
  field: F,
  code: InputErrorCode,
  got: string,
  limit: number | null = null,
  side: 'right' | 'left' | null = null,
  shankLean?: InputErrorOf<F>['shankLean'],
): InputErrorOf<F> {
  const data =
    shankLean === undefined
      ? { field, code, got, limit, side, message: '' }
      : { field, code, got, limit, side, shankLean, message: '' };
  return { ...data, message: describeInputError(data, 'mm') };
}

export type Parsed = { ok: true; value: number; shown: string } | { ok: false; code: InputErrorCode; shown: string };

/** A strict decimal number: optional sign, digits with an optional point, optional exponent. */
const NUMBER_PATTERN = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

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
  if (rho !== undefined && !(rho >= 0 && rho < 90)) reject(c, 'rho', 'out-of-range');
  if (tilt !== undefined && !(tilt > -90 && tilt < 90)) reject(c, 'tilt', 'out-of-range');
}

function checkPattern(raw: unknown, errors: InputError[]): PassPattern | null {
  if (raw === undefined) return 'one-way';
  const text = typeof raw === 'string' ? raw.trim() : String(raw);
  if (text === 'one-way' || text === 'zigzag') return text;
  errors.push(inputError('pattern', 'not-a-pattern', text));
  return null;
}

/**
 * A forward input built property by property: objects made by spreading (`{ ...tool, h }`) get a
 * slow shape in V8 (measured: 7-9 times slower to read in the solvers).
 */
export function forwardInput(
  tool: ToolInput,
  pattern: PassPattern,
  scallopHeightMm: number,
  surface: Surface = PLANE,
): ForwardInput {
  return {
    toolRadiusMm: tool.toolRadiusMm,
    cornerRadiusMm: tool.cornerRadiusMm,
    leadAngleDeg: tool.leadAngleDeg,
    tiltAngleDeg: tool.tiltAngleDeg,
    pattern,
    surface,
    scallopHeightMm,
  };
}

/** An inverse input built property by property (see forwardInput). */
export function inverseInput(
  tool: ToolInput,
  pattern: PassPattern,
  intervalMm: number,
  surface: Surface = PLANE,
): InverseInput {
  return {
    toolRadiusMm: tool.toolRadiusMm,
    cornerRadiusMm: tool.cornerRadiusMm,
    leadAngleDeg: tool.leadAngleDeg,
    tiltAngleDeg: tool.tiltAngleDeg,
    pattern,
    surface,
    intervalMm,
  };
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
  const c = collect(raw, ['R', 'Rcr', 'rho', 'tilt']);
  checkTool(c);
  const parsed = parseNumber(raw[field]);
  const own: AnyInputError[] = parsed.ok ? [] : [inputError(field, parsed.code, parsed.shown)];
  const rest: InputError[] = [];
  const pattern = checkPattern(raw.pattern, rest);
  const surface = checkSurface(raw, rest);
  const tool = toolOf(c.values);
  const gouge = tool !== null && surface !== null ? gouging(tool, surface, String(raw.surfaceRadius ?? '')) : null;
  if (gouge) rest.push(gouge);
  const valid = c.errors.length === 0 && rest.length === 0;
  return {
    errors: [...c.errors, ...own, ...rest],
    pass: valid && tool !== null && pattern !== null && surface !== null ? { ...tool, pattern, surface } : null,
    value: parsed.ok ? parsed.value : undefined,
    shown: parsed.shown,
    gouges: gouge !== null,
  };
}

/** A flat end with neither lead nor tilt (the plane's model, surfaces/models/plane.ts); re-exported for the callers. */
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
  const c = collect(raw, ['R', 'Rcr', 'rho', 'tilt', 'h']);
  checkTool(c);
  const pattern = checkPattern(raw.pattern, c.errors);
  const surface = checkSurface(raw, c.errors);
  const h = c.values.h;
  const tool = toolOf(c.values);
  const gouge = tool !== null && surface !== null ? gouging(tool, surface, String(raw.surfaceRadius ?? '')) : null;
  if (gouge) c.errors.push(gouge);
  if (h !== undefined && gouge === null) {
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
  const c = collect(raw, ['R', 'Rcr', 'rho', 'tilt', 'interval']);
  checkTool(c);
  const pattern = checkPattern(raw.pattern, c.errors);
  const surface = checkSurface(raw, c.errors);
  const L = c.values.interval;
  const tool = toolOf(c.values);
  const gouge = tool !== null && surface !== null ? gouging(tool, surface, String(raw.surfaceRadius ?? '')) : null;
  if (gouge) c.errors.push(gouge);
  if (L !== undefined && gouge === null) {
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
