/**
 * The wording of input errors: the error data (field, code, the bound it broke, what was given)
 * and the one place where it becomes words in the user's unit (describeInputError). The rules
 * that produce these errors are in validate.ts, which re-exports everything here.
 */
import type { SurfaceAxis } from '../domain/surface';
import { entryFaultMessage, isEntryFault, quotedEntry } from './entryMessages';
import { FIELDS, type FieldName, isLengthField } from './fields';
import { MAX_SURFACE_RADIUS_MM, MIN_SURFACE_RADIUS_MM } from './limits';
import { formatAngleDeg, formatInputNumber, fromMm, type LengthUnit, unitSymbol } from './units';

/**
 * Every field an error can name: the registry's tool, pass and quantity fields, and the two
 * principal radii of a doubly curved point (core/roughness/doublyCurvedValidate.ts; the registry files them
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
  | 'radius-gouging';

/** One rejected field, as data; `message` is its description in mm (describeInputError). */
export interface InputErrorOf<F extends AnyFieldName> {
  readonly field: F;
  readonly code: InputErrorCode;
  /** The value as given, as text (what the user typed, or the number). */
  readonly got: string;
  /** The bound it broke: mm for lengths, degrees for angles; left out when there is none. */
  readonly limit?: number;
  /** For `flank-wall` and `shank-cuts`: the side (right is +Y, the side the tool tilts to); else left out. */
  readonly side?: 'right' | 'left';
  /**
   * For `shank-gouging`: the cylinder's axis and the shank's lean from the surface normal seen along
   * it (degrees), which set what would help.
   */
  readonly shankLean?: { readonly axis: SurfaceAxis; readonly leanDeg: number };
  /**
   * For `radius-gouging`: what this radius must be with the other held (`kind` as gouging.ts's
   * RadiusLimit: `concave-at-least`, `convex-at-most`, `not-concave`, `none`), the other radius held
   * (signed mm; left out when it is straight), and what the other radius must be with this one held
   * (its magnitude, mm, for the two bounded kinds; else left out).
   */
  readonly radiusLimit?: {
    readonly kind: 'concave-at-least' | 'convex-at-most' | 'not-concave' | 'none';
    readonly heldMm?: number;
    readonly other: {
      readonly kind: 'any' | 'concave-at-least' | 'convex-at-most' | 'not-concave' | 'none';
      readonly radiusMm?: number;
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
  const limit =
    e.limit === undefined ? '' : isLengthField(e.field) ? length(e.limit) : `${formatAngleDeg(e.limit)} degrees`;
  const shown = options.typed ?? e.got;
  const got = `(got ${quotedEntry(shown)})`;
  if (isEntryFault(e.code)) return entryFaultMessage(label, e.code, shown, u, limit);
  switch (e.code) {
    case 'not-positive':
      return `${label} must be greater than 0 ${u} ${got}.`;
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
      return e.limit === undefined || !Number.isFinite(e.limit)
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
      if (e.limit === undefined || !Number.isFinite(e.limit))
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
      return e.side === undefined
        ? `${label} must be below the profile's full height (R - Rcr) sin(rho) + Rcr = ${limit} ${got}; at or above it the tool flank leaves a wall, not a scallop.`
        : `${label} must be below ${limit}, the height of the ${e.side} flank's widest point ${got}; at or above it that flank leaves a wall, not a scallop.`;
    case 'shank-cuts':
      return `${label} must be below ${limit} ${got}: above it the shank (the tool's cylindrical side, leaning to the ${e.side ?? 'right'} with the tilt) would cut the surface.`;
    case 'beyond-diameter':
      return `${label} must be below the tool ${half ? 'radius R' : diameter ? 'diameter D' : 'diameter 2R'} = ${limit} ${got}; at or beyond it adjacent passes leave a wall.`;
    case 'wall-only':
      return `${label} cannot be answered ${got}: in this posture the tool cuts a step at any step-over (a flank or the shank rises straight from the contact, as a tilted flat end does), so no scallop forms. Add a corner radius, or lead, or less tilt.`;
    case 'beyond-max-ra':
      return e.limit === undefined || !(e.limit > 0)
        ? `${label} cannot be reached ${got}: this tool in this posture leaves no scallop (a flat bottom lying on the surface), so Ra = 0 at any step-over up to its diameter.`
        : `${label} must be below ${limit} ${got}, the largest Ra this tool, posture and pattern leave on this surface; passes far enough apart to leave more leave a wall, not a scallop.`;
    case 'radius-gouging':
      return radiusGougingText(e, label, length, got);
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
  const held =
    r?.heldMm === undefined || !Number.isFinite(r.heldMm) ? `${them} straight` : `${them} = ${length(r.heldMm)}`;
  const mag = e.limit === undefined ? '' : length(Math.abs(e.limit));
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
      : o.kind === 'concave-at-least' && o.radiusMm !== undefined
        ? `; or, with ${me} held, a concave ${them} of at least ${length(o.radiusMm)}`
        : o.kind === 'convex-at-most' && o.radiusMm !== undefined
          ? `; or, with ${me} held, a convex ${them} of at most ${length(o.radiusMm)}`
          : o.kind === 'not-concave'
            ? `; or, with ${me} held, a straight or convex ${them}`
            : o.kind === 'none'
              ? `; no ${them} helps with ${me} held`
              : '';
  return `${need}${otherText} (the tool reaches below the surface away from the contact).`;
}

/**
 * An input error as data, with its message in mm. A limit or side that is null, undefined or not
 * finite is left out of the object (never a null member).
 */
export function inputError<F extends AnyFieldName>(
  field: F,
  code: InputErrorCode,
  got: string,
  limit: number | null = null,
  side: 'right' | 'left' | null = null,
  shankLean?: InputErrorOf<F>['shankLean'],
): InputErrorOf<F> {
  const data: { -readonly [K in keyof InputErrorOf<F>]: InputErrorOf<F>[K] } = { field, code, got, message: '' };
  if (limit !== null && Number.isFinite(limit)) data.limit = limit;
  if (side !== null) data.side = side;
  if (shankLean !== undefined) data.shankLean = shankLean;
  return { ...data, message: describeInputError(data, 'mm') };
}
