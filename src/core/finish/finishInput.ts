/**
 * The inputs of the surface the teeth leave (shared/notes/surface-finish.md, "The kinematic model"):
 * the number of teeth, the feed per tooth, the radial runout with its phase and the pass phase, their
 * limits, and their validation with one-line messages in the style of input/inputErrors.ts (the
 * constraint and its limit, in the user's unit). Lengths mm, angles degrees.
 */

import { entryFaultMessage, isEntryFault, quotedEntry } from '../input/entryMessages';
import { formatInputNumber, fromMm, type LengthUnit, unitSymbol } from '../input/units';
import { parseNumber } from '../input/validate';
import { feedPerToothOfRate, MAX_FLUTES, MIN_FEED_PER_TOOTH_MM } from './feedRate';

/** A validated finish input. */
export interface FinishInput {
  /** Number of teeth (flutes) `z`: an integer, 1 <= z <= {@link MAX_FLUTES}. */
  readonly flutes: number;
  /** Feed per tooth `fz` along the pass, mm: {@link MIN_FEED_PER_TOOTH_MM} <= fz <= the tool radius R. */
  readonly feedPerToothMm: number;
  /** Radial runout `e`, mm: 0 <= e <= {@link maxRunoutMm} (0: the teeth cut equally). */
  readonly runoutMm: number;
  /** Runout phase `phi_e`: angle of the offset from tooth 0's half-plane, degrees, any finite value. */
  readonly runoutPhaseDeg: number;
  /** Pass phase `q` in [0, 1): pass j is shifted along the feed by `j q` feed periods. */
  readonly passPhase: number;
}

/**
 * Raw values as they come from a form, a URL or a CSV cell (mm, mm/min, rpm and degrees); missing
 * optional ones are 0. The feed per tooth is `fz`, or the feed rate and spindle speed, which give
 * it (fz = F / (n z)); not both.
 */
export interface RawFinishInput {
  readonly flutes: unknown;
  readonly fz?: unknown;
  /** Feed rate F, mm/min (with the spindle speed, instead of fz). */
  readonly feedRate?: unknown;
  /** Spindle speed n, rpm (with the feed rate, instead of fz). */
  readonly spindleSpeed?: unknown;
  readonly runout?: unknown;
  readonly runoutPhase?: unknown;
  readonly passPhase?: unknown;
}

/** The finish fields an error can name. */
export type FinishField = 'flutes' | 'fz' | 'feedRate' | 'spindleSpeed' | 'runout' | 'runoutPhase' | 'passPhase';

/** Why a finish field was rejected. */
export type FinishErrorCode =
  | 'missing'
  | 'not-a-number'
  | 'not-finite'
  | 'not-an-integer'
  | 'not-positive'
  | 'negative'
  | 'too-small'
  | 'too-large'
  | 'out-of-range'
  /** fz given together with the feed rate or the spindle speed (one way only). */
  | 'both-feeds'
  /** The fz that F / (n z) gives is below its least or above R (`got`: that fz, mm). */
  | 'rate-too-small'
  | 'rate-too-large'
  /** The surface is one where feed marks are not computed yet (finishScope.ts words it). */
  | 'not-computed-here';

/** One rejected finish field, as data, with its message in mm. */
export interface FinishError {
  readonly field: FinishField;
  readonly code: FinishErrorCode;
  /** The value as given, as text. */
  readonly got: string;
  /** The bound it broke (mm for lengths, a count for flutes); left out when there is none. */
  readonly limit?: number;
  readonly message: string;
}

export { MAX_FLUTES, MIN_FEED_PER_TOOTH_MM };

/**
 * Largest feed per tooth accepted: the tool radius R. Beyond it one tooth's bite is wider than half
 * the tool, the marks would rise towards the corner's top and the period cell would leave the region
 * where the tool's end (not its shank) cuts; real finishing feeds are a few percent of R.
 */
export function maxFeedPerToothMm(toolRadiusMm: number): number {
  return toolRadiusMm;
}

/**
 * Largest radial runout accepted, mm: a tenth of the tool radius. Measured runout of a held end mill
 * is a few micrometres to some hundredths of a millimetre; a tenth of R is already a broken set-up.
 */
export function maxRunoutMm(toolRadiusMm: number): number {
  return toolRadiusMm / 10;
}

const LABELS: Record<FinishField, string> = {
  flutes: 'Flutes z',
  fz: 'Feed per tooth fz',
  feedRate: 'Feed rate F',
  spindleSpeed: 'Spindle speed n',
  runout: 'Runout e',
  runoutPhase: 'Runout phase',
  passPhase: 'Pass phase q',
};

/** Whether a finish field is a length (converted to the user's unit in messages). */
function isLength(field: FinishField): boolean {
  return field === 'fz' || field === 'runout';
}

/** The message of a finish error in `unit` (lengths converted; angles in degrees; counts as they are). */
export function describeFinishError(e: Omit<FinishError, 'message'>, unit: LengthUnit): string {
  const label = LABELS[e.field];
  const length = unitSymbol(unit);
  // The field's unit: mm/min for F (in/min in inch), rpm for n, the length's for fz and e, none else.
  const u =
    e.field === 'feedRate' ? `${length}/min` : e.field === 'spindleSpeed' ? 'rpm' : isLength(e.field) ? length : '';
  const value = (v: number) =>
    isLength(e.field) ? `${formatInputNumber(fromMm(v, unit))} ${length}` : formatInputNumber(v);
  const limit = e.limit === undefined ? '' : value(e.limit);
  const got = `(got ${quotedEntry(e.got)})`;
  if (isEntryFault(e.code)) return entryFaultMessage(label, e.code, e.got, u, limit);
  switch (e.code) {
    case 'both-feeds':
      return 'Give the feed per tooth fz, or the feed rate F and the spindle speed n, not both.';
    case 'rate-too-small':
    case 'rate-too-large':
      return `Feed per tooth fz = F / (n z) = ${value(Number(e.got))} must be ${e.code === 'rate-too-small' ? 'at least' : 'at most the tool radius R ='} ${limit}.`;
    case 'not-an-integer':
      return `${label} must be a whole number of teeth from 1 to ${MAX_FLUTES} ${got}.`;
    case 'not-positive':
      return `${label} must be greater than 0 ${u === '' ? '' : `${u} `}${got}.`;
    case 'too-large':
      return e.field === 'fz'
        ? `${label} must be at most the tool radius R = ${limit} ${got}.`
        : e.field === 'runout'
          ? `${label} must be at most R/10 = ${limit} ${got}.`
          : `${label} must be at most ${limit} ${got}.`;
    case 'out-of-range':
      return `${label} must be at least 0 and below 1 (a fraction of the feed period) ${got}.`;
    case 'not-computed-here':
      return 'Feed marks are not computed on this surface yet: only on a plane (any lead and tilt, one-way or zigzag) and the three-axis sloped plane.';
  }
}

/** A finish error as data, with its message in mm. */
export function finishError(field: FinishField, code: FinishErrorCode, got: string, limit?: number): FinishError {
  const data = limit === undefined || !Number.isFinite(limit) ? { field, code, got } : { field, code, got, limit };
  return { ...data, message: describeFinishError(data, 'mm') };
}

/** Either the validated finish or its errors (at most one per field). */
export type FinishValidation =
  | { readonly ok: true; readonly value: FinishInput }
  | { readonly ok: false; readonly errors: readonly FinishError[] };

/** True for a value not given (absent, or an empty text). */
function empty(value: unknown): boolean {
  return value === undefined || value === null || (typeof value === 'string' && value.trim() === '');
}

type ReadNumber = (field: FinishField, value: unknown, optional: boolean) => { v: number; shown: string } | null;

/**
 * The feed per tooth, mm: `fz` as given, or F / (n z) from the feed rate (mm/min) and the spindle
 * speed (rpm), each checked (F > 0, n > 0, and the fz they give within fz's own limits, said as
 * that fz); `flutes` null while the teeth are invalid (the rate's fz is then not checked). Both ways
 * at once is refused. Null when refused (the reasons pushed on `errors`).
 */
function feedPerTooth(
  raw: RawFinishInput,
  flutes: number | null,
  toolRadiusMm: number,
  num: ReadNumber,
  errors: FinishError[],
): number | null {
  const maxMm = maxFeedPerToothMm(toolRadiusMm);
  if (empty(raw.feedRate) && empty(raw.spindleSpeed)) {
    const fz = num('fz', raw.fz, false);
    if (fz === null) return null;
    if (!(fz.v > 0)) errors.push(finishError('fz', 'not-positive', fz.shown));
    else if (fz.v < MIN_FEED_PER_TOOTH_MM) errors.push(finishError('fz', 'too-small', fz.shown, MIN_FEED_PER_TOOTH_MM));
    else if (fz.v > maxMm) errors.push(finishError('fz', 'too-large', fz.shown, maxMm));
    else return fz.v;
    return null;
  }
  if (!empty(raw.fz)) {
    errors.push(finishError('fz', 'both-feeds', String(raw.fz)));
    return null;
  }
  const rate = num('feedRate', raw.feedRate, false);
  const speed = num('spindleSpeed', raw.spindleSpeed, false);
  if (rate !== null && !(rate.v > 0)) errors.push(finishError('feedRate', 'not-positive', rate.shown));
  if (speed !== null && !(speed.v > 0)) errors.push(finishError('spindleSpeed', 'not-positive', speed.shown));
  if (rate === null || speed === null || !(rate.v > 0 && speed.v > 0) || flutes === null) return null;
  const fzMm = feedPerToothOfRate(rate.v, speed.v, flutes);
  if (fzMm < MIN_FEED_PER_TOOTH_MM)
    errors.push(finishError('fz', 'rate-too-small', String(fzMm), MIN_FEED_PER_TOOTH_MM));
  else if (fzMm > maxMm) errors.push(finishError('fz', 'rate-too-large', String(fzMm), maxMm));
  else return fzMm;
  return null;
}

/**
 * Validates the finish inputs for a tool of radius `toolRadiusMm` (mm, already validated): flutes an
 * integer in [1, MAX_FLUTES]; fz in [MIN_FEED_PER_TOOTH_MM, R], given or F / (n z); runout in [0, R/10] (missing: 0);
 * runout phase any finite number of degrees (missing: 0); pass phase in [0, 1) (missing: 0).
 */
export function validateFinish(raw: RawFinishInput, toolRadiusMm: number): FinishValidation {
  const errors: FinishError[] = [];
  const num = (field: FinishField, value: unknown, optional: boolean): { v: number; shown: string } | null => {
    if (optional && empty(value)) return { v: 0, shown: '0' };
    // A length beyond a double once in mm (1e308 in) is too large, said with its limit, not "not finite".
    if (isLength(field) && (value === Number.POSITIVE_INFINITY || value === Number.NEGATIVE_INFINITY))
      return { v: value, shown: String(value) };
    const p = parseNumber(value);
    if (!p.ok) {
      errors.push(
        finishError(
          field,
          p.code === 'missing' ? 'missing' : p.code === 'not-finite' ? 'not-finite' : 'not-a-number',
          p.shown,
        ),
      );
      return null;
    }
    return { v: p.value, shown: p.shown };
  };
  const z = num('flutes', raw.flutes, false);
  if (z !== null) {
    if (!Number.isInteger(z.v) || z.v < 1 || z.v > MAX_FLUTES)
      errors.push(finishError('flutes', 'not-an-integer', z.shown));
  }
  const fz = feedPerTooth(raw, z === null || errors.length > 0 ? null : z.v, toolRadiusMm, num, errors);
  const e = num('runout', raw.runout, true);
  if (e !== null) {
    if (e.v < 0) errors.push(finishError('runout', 'negative', e.shown));
    else if (e.v > maxRunoutMm(toolRadiusMm))
      errors.push(finishError('runout', 'too-large', e.shown, maxRunoutMm(toolRadiusMm)));
  }
  const phi = num('runoutPhase', raw.runoutPhase, true);
  const q = num('passPhase', raw.passPhase, true);
  if (q !== null && !(q.v >= 0 && q.v < 1)) errors.push(finishError('passPhase', 'out-of-range', q.shown));
  if (errors.length > 0 || z === null || fz === null || e === null || phi === null || q === null)
    return { ok: false, errors };
  return {
    ok: true,
    value: {
      flutes: z.v,
      feedPerToothMm: fz,
      runoutMm: e.v,
      // 0 - (-0) would print -0 nowhere, but keep the phase free of -0 all the same.
      runoutPhaseDeg: phi.v === 0 ? 0 : phi.v,
      passPhase: q.v === 0 ? 0 : q.v,
    },
  };
}
