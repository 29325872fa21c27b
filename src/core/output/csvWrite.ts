/**
 * Writing CSV, shared by the command line's batch output and the page's lookup table (computed in
 * a worker), so both follow the same conventions: RFC 4180 quoting, a guard against spreadsheet
 * formulas, numbers in full precision (the shortest text that reads back to the same double; never
 * `-0`), a value that does not exist as an empty field, and the same result columns. Pure (no I/O,
 * no DOM); lengths in mm, angles in degrees.
 */

import type { ForwardInput } from '../domain/pass';
import { isNumberText } from '../input/validate';
import type { Approximation, HalfInterval } from '../procedures/approximations';
import { compareForward } from '../procedures/compare';
import { APPROXIMATION_KEYS, APPROXIMATIONS, type ApproximationKey, PROCEDURES } from '../procedures/procedures';
import { exactForward } from '../surfaces/solve';
import { maxIntervalMm } from '../surfaces/validate';

/** Text that reads as a number: validation's own test (re-exported for the command line's CSV). */
export { isNumberText };

/** One output field, quoted when it holds a comma, a quote or a line break (RFC 4180). */
export function csvField(text: string): string {
  return /[",\r\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

/**
 * Text written back to a CSV that a spreadsheet may open: text that is not a number and begins
 * with `=`, `+`, `-`, `@` (or a tab or carriage return) gets a leading `'`, so that it is shown
 * as text and never evaluated as a formula; then it is quoted where needed.
 */
export function csvText(text: string): string {
  const guarded = /^[=+\-@\t\r]/.test(text) && !isNumberText(text) ? `'${text}` : text;
  return csvField(guarded);
}

/**
 * Result columns after the echoed input: L/2 of the exact solution and of the paper's three
 * procedures (as before tilt existed), the exact step-over and its geometry, L/2 of the two
 * other approximations, the notes (warnings) and the error.
 */
export const RESULT_COLUMNS = [
  'exact',
  'sekine',
  'redonnet',
  'bedi',
  'interval',
  'halfWidthRight',
  'halfWidthLeft',
  'contactOffset',
  'otherCuspHeight',
  'osculating',
  'cornerBall',
  'note',
  'error',
] as const;

/** A number in full precision: the shortest text that reads back to the same double; never `-0`. */
export function csvNumber(value: number): string {
  return value === 0 ? '0' : String(value);
}

/** A length result as a CSV field: its text in the table's unit (csvNumber of the mm value by default). */
export type LengthText = (lengthMm: number) => string;

function halfText(r: Approximation<HalfInterval>, length: LengthText): string {
  return r.ok ? length(r.halfIntervalMm) : '';
}

/**
 * Below this step-over (mm) no approximation can be at or beyond the wall on a plane without
 * tilt: there the widest step-over (maxIntervalMm) is 2R (the flanks reach R at the height limit),
 * which its solver gives within 1e-9 mm (measured: within 5e-16 relative); the margin here is a
 * thousand times that. A row at or above it gets maxIntervalMm computed, as every other row.
 */
function surelyBelowWallMm(input: ForwardInput): number {
  if (input.tiltAngleDeg !== 0 || input.surface.kind !== 'plane') return 0;
  return 2 * input.toolRadiusMm * (1 - 1e-9) - 1e-6;
}

/** compareForward's warning condition: a step-over at or beyond the widest that leaves a scallop. */
function beyondWall(r: Approximation<HalfInterval>, maxMm: number): boolean {
  return r.ok && !(2 * r.halfIntervalMm < maxMm);
}

const NO_SCALLOP_NOTE =
  'exact: a flat end without lead or tilt leaves no scallop at any step-over up to its diameter (L = 2R).';

/** The approximations of a row, in APPROXIMATION_KEYS order (filled and read within one call). */
const halves: Approximation<HalfInterval>[] = [];

/**
 * The results of a valid case: the result fields up to `note`, joined (no `error`); each length
 * written by `length` (in mm by default; the batch's inch runs convert). Calls the core's
 * functions one by one, not compareForward, which also solves the scallop each approximation
 * really leaves (not written here) and is about 5 times slower; compareForward only words the
 * warnings, on the rare rows that have one. The widest step-over (for those warnings) is solved
 * only where an approximation may reach it ({@link surelyBelowWallMm}).
 */
export function resultFields(input: ForwardInput, length: LengthText = csvNumber): string {
  const exact = exactForward(input);
  const surelyBelow = surelyBelowWallMm(input);
  let maxMm = Number.NaN;
  let beyond = false;
  let allOk = true;
  for (let i = 0; i < APPROXIMATION_KEYS.length; i++) {
    const r = APPROXIMATIONS[APPROXIMATION_KEYS[i] as ApproximationKey].halfInterval(input);
    halves[i] = r;
    if (!r.ok) allOk = false;
    else if (!beyond && !(2 * r.halfIntervalMm < surelyBelow)) {
      if (Number.isNaN(maxMm)) maxMm = maxIntervalMm(input, input.pattern, input.surface);
      beyond = beyondWall(r, maxMm);
    }
  }
  const noScallop = exact.noScallop ? NO_SCALLOP_NOTE : '';
  let note = beyond ? warningNotes(input, noScallop) : noScallop;
  if (!allOk) {
    const empty = halves.flatMap((r) => notApplicable(r));
    note = [note, ...empty].filter((n) => n !== '').join(' ');
  }
  const half = exact.halfIntervalMm;
  const halfText0 = length(half);
  // The same double is the same text: without tilt both reaches are L/2, and the osculating
  // circle is Redonnet's.
  const same = (x: number, as: number, text: string) => (x === as ? text : length(x));
  const at = (i: number) => halves[i] as Approximation<HalfInterval>;
  const redonnet = at(REDONNET);
  const osculating = at(OSCULATING);
  const redonnetText = halfText(redonnet, length);
  const osculatingText =
    osculating.ok && redonnet.ok && osculating.halfIntervalMm === redonnet.halfIntervalMm
      ? redonnetText
      : halfText(osculating, length);
  return (
    `${halfText0},${halfText(at(SEKINE), length)},${redonnetText},${halfText(at(BEDI), length)},` +
    `${length(exact.intervalMm)},${same(exact.halfWidthRightMm, half, halfText0)},${same(exact.halfWidthLeftMm, half, halfText0)},` +
    `${length(exact.contactOffsetMm)},${exact.otherCuspHeightMm === null ? '' : length(exact.otherCuspHeightMm)},` +
    `${osculatingText},${halfText(at(CORNER_BALL), length)},${csvText(note)}`
  );
}

/** Where each approximation is in APPROXIMATION_KEYS (its columns' order differs). */
const SEKINE = APPROXIMATION_KEYS.indexOf('sekine');
const REDONNET = APPROXIMATION_KEYS.indexOf('redonnet');
const BEDI = APPROXIMATION_KEYS.indexOf('bedi');
const OSCULATING = APPROXIMATION_KEYS.indexOf('osculating');
const CORNER_BALL = APPROXIMATION_KEYS.indexOf('cornerBall');

/** Why an approximation's cell is empty (at rho 0 the paper's models have no answer), or nothing. */
function notApplicable(r: Approximation<HalfInterval>): string[] {
  return r.ok ? [] : [r.notApplicable];
}

/**
 * The notes of the approximations' empty cells of a case (each one's reason), as {@link resultFields}
 * writes them after its warnings: for rows whose other cells are computed elsewhere (a doubly
 * curved point's approximations are the plane's).
 */
export function emptyCellNotes(input: ForwardInput): string[] {
  return APPROXIMATION_KEYS.flatMap((key) => notApplicable(APPROXIMATIONS[key].halfInterval(input)));
}

/** The warnings of every approximation, as compareForward words them, after `note`. */
function warningNotes(input: ForwardInput, note: string): string {
  const notes = note === '' ? [] : [note];
  const c = compareForward(input);
  for (const key of APPROXIMATION_KEYS) {
    const r = c.approximations[key];
    if (r.ok && r.warning !== null) notes.push(`${PROCEDURES[key].shortLabel}: ${r.warning}`);
  }
  return notes.join(' ');
}
