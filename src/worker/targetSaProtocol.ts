/**
 * The target-Sa question between the page and the worker (issue 29; core roughness/targetSa.ts): for
 * a target Sa on the plane of the answer on screen, the pair (step-over L, feed per tooth fz) with the
 * largest L * fz and the curve of all pairs. Plain data (structured-clone safe). The reply echoes its
 * request, and the page shows it only while its request is the question the inputs on screen ask
 * (sameTargetSaRequest). Lengths mm, angles degrees.
 */
import type { FinishField } from '../core/finish/finishInput';
import type { LengthUnit } from '../core/input/units';
import type { PassInput } from '../core/input/validate';
import type { TargetSaAnswer } from '../core/roughness/targetSa';
import type { FinishFieldMessage, FinishValue } from './finishProtocol';

/** The teeth fields a target Sa reads (its feed is the answer). */
export type TargetSaField = Exclude<FinishField, 'fz' | 'feedRate' | 'spindleSpeed'>;

/** A target Sa on a validated plane pass, with the teeth as the page holds them (validated in the worker). */
export interface TargetSaRequest {
  readonly pass: PassInput;
  readonly targetSaMm: number;
  readonly values: Readonly<Record<TargetSaField, FinishValue>>;
  /** The texts as typed (quoted by the messages) and the unit the messages speak. */
  readonly typed: Readonly<Record<TargetSaField, string>>;
  readonly unit: LengthUnit;
}

/**
 * A message on a teeth field: a refusal of the teeth (its data beside its English sentence, as the
 * finish's), or one of the target Sa's own, named for a page to word in its language: runout refused
 * (the inverse takes none), the search stopped past its budget.
 */
export interface TargetSaMessage extends FinishFieldMessage {
  readonly refusal?: 'runout' | 'tooLong';
}

/** The pairs and, at the best pair's step-over, the scallop h the passes leave; or why not. */
export type TargetSaReply =
  | {
      readonly ok: true;
      readonly request: TargetSaRequest;
      readonly answer: TargetSaAnswer;
    }
  | { readonly ok: false; readonly request: TargetSaRequest; readonly errors: readonly TargetSaMessage[] };

/** True when both ask the same question (plain data built in one order by the page: compared as JSON). */
export function sameTargetSaRequest(a: TargetSaRequest | null, b: TargetSaRequest | null): boolean {
  return a !== null && b !== null && JSON.stringify(a) === JSON.stringify(b);
}
