/**
 * The edge between what the user typed and what the solver is asked: the state's text, in the
 * user's unit, becomes one validated request in mm (the page's one builder, questionRequest.ts), or
 * the input errors; and each field's message, from the build's errors or the worker's refusal
 * (pageMessages.ts). Units are converted here and nowhere else on the way in. This module hands
 * the three-axis builder and wording in statically, for the Node side (the tests, the benches);
 * the page (app.ts) hands them in once it has loaded them. Pure (no DOM).
 */

import type { PageReply } from '../worker/pageProtocol';
import { fieldMessages, fieldOfError } from './fieldMessages';
import { stateMessages as pageStateMessages } from './pageMessages';
import { buildPageRequest } from './questionRequest';
import type { BuiltRequest, PageFieldError } from './requestTypes';
import type { CalculatorState, FieldKey } from './state';
import { buildThreeAxisRequest, threeAxisFieldErrors } from './threeAxisRequest';

export type { BuiltRequest, PageFieldError };

/** The page's one builder (questionRequest.ts buildPageRequest) with every mode's builder at hand. */
export function buildRequest(state: CalculatorState): BuiltRequest {
  return buildPageRequest(state, buildThreeAxisRequest);
}

/** Each field's message (fieldMessages.ts), re-exported for the callers. */
export { fieldMessages, fieldOfError };

/** Each field's message for a state (pageMessages.ts stateMessages). */
export function stateMessages(
  state: CalculatorState,
  built: BuiltRequest,
  reply: PageReply | null,
): Map<FieldKey, string> {
  return pageStateMessages(state, built, reply, threeAxisFieldErrors);
}
