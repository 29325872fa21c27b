/**
 * A refusal of the one question (question.ts, worded in mm) in the user's words: the value quoted
 * as typed and every length in the user's unit, as every other refusal of the command line and the
 * page is worded (threeAxis/errors.ts threeAxisMessageInUnit, the one wording). Pure.
 */
import type { LengthUnit } from '../input/units';
import { threeAxisMessageInUnit } from '../threeAxis/errors';
import type { QuestionError } from './mode';

/**
 * The message of a refused question in `unit`, quoting `typed` (the text as given, before its unit
 * was read; absent: the number the message quotes).
 */
export function questionMessageInUnit(e: QuestionError, unit: LengthUnit, typed?: string): string {
  const got = /\(got ([^)]*)\)/.exec(e.message)?.[1] ?? null;
  return threeAxisMessageInUnit({ message: e.message, got }, 'raster', unit, typed ?? String(got));
}
