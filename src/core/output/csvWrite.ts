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

function halfText(r: Approximation<HalfInterval>): string {
  return r.ok ? csvNumber(r.halfIntervalMm) : '';
}

/** compareForward's warning condition: a step-over at or beyond the widest that leaves a scallop. */
function beyondWall(r: Approximation<HalfInterval>, maxMm: number): boolean {
  return r.ok && !(2 * r.halfIntervalMm < maxMm);
}

const NO_SCALLOP_NOTE =
  'exact: a flat end without lead or tilt leaves no scallop at any step-over up to its diameter (L = 2R).';

/**
 * The results of a valid case: the result fields up to `note`, joined (no `error`). Calls the
 * core's functions one by one, not compareForward, which also solves the scallop each
 * approximation really leaves (not written here) and is about 5 times slower; compareForward only
 * words the warnings, on the rare rows that have one.
 */
export function resultFields(input: ForwardInput): string {
  const exact = exactForward(input);
  const maxMm = maxIntervalMm(input, input.pattern, input.surface);
  const half = {} as Record<ApproximationKey, Approximation<HalfInterval>>;
  let beyond = false;
  for (const key of APPROXIMATION_KEYS) {
    const r = APPROXIMATIONS[key].halfInterval(input);
    half[key] = r;
    beyond ||= beyondWall(r, maxMm);
  }
  const noScallop = exact.noScallop ? NO_SCALLOP_NOTE : '';
  const empty = APPROXIMATION_KEYS.flatMap((key) => notApplicable(half[key]));
  const note = [beyond ? warningNotes(input, noScallop) : noScallop, ...empty].filter((n) => n !== '').join(' ');
  return (
    `${csvNumber(exact.halfIntervalMm)},${halfText(half.sekine)},${halfText(half.redonnet)},${halfText(half.bedi)},` +
    `${csvNumber(exact.intervalMm)},${csvNumber(exact.halfWidthRightMm)},${csvNumber(exact.halfWidthLeftMm)},` +
    `${csvNumber(exact.contactOffsetMm)},${exact.otherCuspHeightMm === null ? '' : csvNumber(exact.otherCuspHeightMm)},` +
    `${halfText(half.osculating)},${halfText(half.cornerBall)},${csvText(note)}`
  );
}

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
