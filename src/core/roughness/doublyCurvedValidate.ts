/**
 * Validation of a doubly curved point (issue 19): the tool, posture and pattern as validate.ts
 * checks them, the two signed principal radii (`feedRadius` Rf, `crossRadius` Rc: |R| from
 * MIN_SURFACE_RADIUS_MM to MAX_SURFACE_RADIUS_MM, or absent: straight), gouging (gouging.ts) named
 * on the radius that must change with its limit, the other held, and the problem's quantity: a
 * scallop height below the flank and shank limits, a step-over below the widest, or a target Ra
 * below the largest. One structured error per field, worded by validate.ts's describeInputError (in
 * the user's unit). Lengths mm.
 */
import {
  type AnyInputError,
  describeInputError,
  inputError,
  MAX_SURFACE_RADIUS_MM,
  MIN_LENGTH_MM,
  MIN_SURFACE_RADIUS_MM,
  type PassPattern,
  parseNumber,
  type RawToolInput,
  type ToolInput,
  type Validation,
} from '../input/validate';
import { doublyCurvedGouges, doublyCurvedGouging, type RadiusLimit } from '../surfaces/doublyCurved/gouging';
import type { DoublyCurvedPass, PrincipalRadii } from '../surfaces/doublyCurved/types';
import { curvedLimits, curvedMaxIntervalMm, curvedPoint } from '../surfaces/doublyCurvedPoint';
import { validatePassAnd } from '../surfaces/validate';
import { doublyCurvedMaxRaMm } from './doublyCurved';

/** The quantity a doubly curved problem is given: a scallop height, a step-over, or a target Ra. */
export type DoublyCurvedQuantity = 'h' | 'interval' | 'ra';

/** Raw values (as typed; mm and degrees): the tool, posture, pattern, the radii and the quantity. */
export interface RawDoublyCurvedInput extends Omit<RawToolInput, 'surfaceRadius' | 'surfaceAxis'> {
  /** Signed Rf in mm; absent, empty or undefined: straight. */
  readonly feedRadius?: unknown;
  /** Signed Rc in mm; absent, empty or undefined: straight. */
  readonly crossRadius?: unknown;
}

/** A validated doubly curved problem: the pass and the quantity's value (mm). */
export interface DoublyCurvedProblem extends DoublyCurvedPass {
  readonly quantity: DoublyCurvedQuantity;
  /** h, L or the target Ra, mm. */
  readonly valueMm: number;
}

function blank(v: unknown): boolean {
  return v === undefined || v === null || (typeof v === 'string' && v.trim() === '');
}

/** A radius: Infinity when absent, else a signed value in range; or its error. */
function checkRadius(field: 'feedRadius' | 'crossRadius', raw: unknown): number | AnyInputError {
  if (blank(raw)) return Number.POSITIVE_INFINITY;
  const p = parseNumber(raw);
  if (!p.ok) return inputError(field, p.code, p.shown);
  const r = p.value;
  if (!(Math.abs(r) >= MIN_SURFACE_RADIUS_MM && Math.abs(r) <= MAX_SURFACE_RADIUS_MM)) {
    return inputError(field, 'out-of-range', p.shown);
  }
  return r;
}

/** The radius given as text (for messages), or the number. */
function shownOf(raw: unknown): string {
  return typeof raw === 'string' ? raw.trim() : String(raw);
}

/** Which radius to name when the tool gouges: one that a value of it helps, the cross radius first. */
function gougingError(tool: ToolInput, radii: PrincipalRadii, raw: RawDoublyCurvedInput): AnyInputError {
  const g = doublyCurvedGouging(tool, radii);
  const helps = (l: RadiusLimit) => l.kind !== 'none';
  const field: 'feedRadius' | 'crossRadius' = helps(g.cross) || !helps(g.feed) ? 'crossRadius' : 'feedRadius';
  const mine = field === 'crossRadius' ? g.cross : g.feed;
  const other = field === 'crossRadius' ? g.feed : g.cross;
  const kind = mine.kind === 'any' ? 'none' : mine.kind;
  const heldMm = field === 'crossRadius' ? radii.feedRadiusMm : radii.crossRadiusMm;
  // Absent values (no limit, a straight radius held, no magnitude) are left out, never null.
  const data: AnyInputError = {
    field,
    code: 'radius-gouging',
    got: shownOf(field === 'crossRadius' ? raw.crossRadius : raw.feedRadius),
    ...(mine.radiusMm === null ? {} : { limit: mine.kind === 'concave-at-least' ? -mine.radiusMm : mine.radiusMm }),
    radiusLimit: {
      kind,
      ...(Number.isFinite(heldMm) ? { heldMm } : {}),
      other: { kind: other.kind, ...(other.radiusMm === null ? {} : { radiusMm: other.radiusMm }) },
    },
    message: '',
  };
  return { ...data, message: describeInputError(data, 'mm') };
}

/**
 * Validates a doubly curved problem (see the module comment). The quantity is read from `value`
 * (h, L or Ra as typed). Gouging makes the quantity moot (not checked).
 * @param quantity what `value` is.
 */
export function validateDoublyCurved(
  raw: RawDoublyCurvedInput,
  quantity: DoublyCurvedQuantity,
  value: unknown,
): Validation<DoublyCurvedProblem, AnyInputError> {
  const field = quantity;
  const v = validatePassAnd(
    { R: raw.R, Rcr: raw.Rcr, rho: raw.rho, tilt: raw.tilt, pattern: raw.pattern, [field]: value },
    field,
  );
  const errors: AnyInputError[] = [...v.errors];
  const rf = checkRadius('feedRadius', raw.feedRadius);
  const rc = checkRadius('crossRadius', raw.crossRadius);
  if (typeof rf !== 'number') errors.push(rf);
  if (typeof rc !== 'number') errors.push(rc);
  const pass = v.pass;
  if (pass === null || typeof rf !== 'number' || typeof rc !== 'number') return { ok: false, errors };
  const radii = { feedRadiusMm: rf, crossRadiusMm: rc };
  const tool: ToolInput = {
    toolRadiusMm: pass.toolRadiusMm,
    cornerRadiusMm: pass.cornerRadiusMm,
    leadAngleDeg: pass.leadAngleDeg,
    tiltAngleDeg: pass.tiltAngleDeg,
  };
  if (doublyCurvedGouges(tool, radii)) {
    errors.push(gougingError(tool, radii, raw));
    return { ok: false, errors };
  }
  const x = v.value;
  if (x === undefined) return { ok: false, errors };
  const shown = v.shown;
  const pattern: PassPattern = pass.pattern;
  if (x <= 0) errors.push(inputError(field, 'not-positive', shown));
  else if (x < (field === 'interval' ? 2 * MIN_LENGTH_MM : MIN_LENGTH_MM)) {
    errors.push(inputError(field, 'too-small', shown, field === 'interval' ? 2 * MIN_LENGTH_MM : MIN_LENGTH_MM));
  } else {
    const point = curvedPoint(tool, radii, pattern);
    const lim = curvedLimits(point);
    if (!(lim.limitMm >= MIN_LENGTH_MM)) errors.push(inputError(field, 'wall-only', shown));
    else if (field === 'h' && !(x < lim.limitMm)) {
      const shank = lim.limitBy === 'shank-right' || lim.limitBy === 'shank-left';
      const side = lim.limitBy.endsWith('right') ? 'right' : 'left';
      errors.push(inputError('h', shank ? 'shank-cuts' : 'flank-wall', shown, lim.limitMm, side));
    } else if (field === 'interval') {
      const max = curvedMaxIntervalMm(point);
      if (!(x < max)) errors.push(inputError('interval', 'beyond-interval', shown, max));
    } else if (field === 'ra') {
      const max = doublyCurvedMaxRaMm(point);
      if (!(x < max)) errors.push(inputError('ra', 'beyond-max-ra', shown, max));
    }
  }
  if (errors.length > 0) return { ok: false, errors };
  return { ok: true, value: { ...tool, pattern, ...radii, quantity, valueMm: x } };
}
