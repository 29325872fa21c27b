/**
 * Each field's message, from the build's errors or the worker's refusal, on the fields in the
 * user's unit: the page's part of request.ts that the first result needs. Three-axis machining's
 * solver refusals are worded by threeAxisRequest.ts, which the page loads with its first
 * three-axis question and hands in here (request.ts hands it in statically). Pure (no DOM).
 */
import type { InputError } from '../core/input/validate';
import type { ThreeAxisInputError } from '../core/threeAxis/validate';
import {
  type CurvedReply,
  isCurvedRequest,
  isSolveReply,
  type PageReply,
  type ThreeAxisReply,
} from '../worker/pageProtocol';
import { describeCurvedError } from './curvedRequest';
import { fieldMessages } from './fieldMessages';
import { finishFieldErrors } from './finishFields';
import { catalogue, describeError } from './i18n/words';
import type { BuiltRequest, PageFieldError } from './requestTypes';
import type { CalculatorState, FieldKey } from './state';

/** Three-axis errors on their page fields, in the user's unit (threeAxisRequest.ts threeAxisFieldErrors). */
export type ThreeAxisWording = (errors: readonly ThreeAxisInputError[], state: CalculatorState) => PageFieldError[];

/**
 * The errors of a refused reply (none for an answer) as the page shows them, on their fields in the
 * user's unit: a doubly curved point's own checks (describeCurvedError) and three-axis machining's
 * solver refusals (`threeAxis`), which only the worker finds; the tool's and posture's
 * validation errors as they are.
 */
export function replyErrors(
  state: CalculatorState,
  reply: PageReply,
  threeAxis: ThreeAxisWording,
): Array<InputError | PageFieldError> {
  if (reply.ok || isSolveReply(reply)) {
    if (reply.ok) return [];
    // A target Sa is asked as a target Ra (its L0): the worker's Ra bound is the Sa field's.
    return state.mode === 'forward' && state.target === 'sa'
      ? reply.errors.map((e) => (e.field === 'ra' ? { ...e, field: 'targetSa' } : e))
      : [...reply.errors];
  }
  if (isCurvedRequest(reply.request))
    return (reply as Extract<CurvedReply, { ok: false }>).errors.map((e) =>
      // Worded in the language in force (its catalogue's, i18n/curvedText.ts; English here).
      'got' in e ? e : (catalogue()?.curved ?? describeCurvedError)(e, state),
    );
  return threeAxis((reply as Extract<ThreeAxisReply, { ok: false }>).errors, state);
}

/**
 * Each field's message for a state: its own errors (the build's), or, once the worker refused
 * the request it asks, that reply's (replyErrors); none while it is valid and not refused.
 * @param reply The reply to the state's request, or null while none came.
 */
export function stateMessages(
  state: CalculatorState,
  built: BuiltRequest,
  reply: PageReply | null,
  threeAxis: ThreeAxisWording,
): Map<FieldKey, string> {
  const own = !built.ok
    ? fieldMessages(state, built.errors)
    : reply === null || reply.ok
      ? new Map<FieldKey, string>()
      : fieldMessages(state, replyErrors(state, reply, threeAxis));
  // The teeth and their feed (issue 29, optional): a text that is not a number is named on its field,
  // beside the step-over it does not change.
  const finish = finishFieldErrors(state, describeError);
  return finish.length === 0 ? own : new Map([...fieldMessages(state, finish), ...own]);
}
