/**
 * The page's one builder of its question (issue 27 points 3 and 4): the machine mode (the mode
 * registry's kind, from the machine switch) picks its builder, which reads the surface, the tool,
 * the posture or slope and the target from the state's fields in the user's unit, converts them to
 * mm and validates them once (fiveAxisRequest.ts: the plane, the cylinders, a doubly curved point;
 * threeAxisRequest.ts: the sloped plane, waterline on a surface of revolution). The page calls it
 * once per change and the worker's one `solve` job answers what it builds (jobs/page.ts); nothing
 * is solved here. The three-axis builder is handed in: the page loads it with its first three-axis
 * question (app.ts), so that it is not part of the first result; request.ts's buildRequest hands
 * it in statically (the Node side). A mode or surface registered beside the product's is asked
 * through registryQuestionRequest.ts. Pure (no DOM).
 */
import type { ModeDescriptor } from '../core/surfaces/modes';
import { finishFieldErrors } from './finishFields';
import { buildFiveAxisRequest } from './fiveAxisRequest';
import { describeError } from './i18n/words';
import type { BuiltRequest } from './requestTypes';
import type { CalculatorState } from './state';

/** A machine mode's builder: the state's request, or why it cannot be asked (threeAxisRequest.ts buildThreeAxisRequest). */
export type ModeBuilder = (state: CalculatorState) => BuiltRequest;

/** The mode registry's kind of the machine the state's switch chooses. */
export function pageModeKind(state: CalculatorState): ModeDescriptor['kind'] {
  return state.machine === '3axis' ? 'threeAxis' : 'fiveAxis';
}

/**
 * The request the state asks, or why it cannot be asked (each message on its field, in the user's
 * unit): validation only, once per change; the checks that need a solver run in the worker, which
 * refuses such a request in its reply (pageMessages.ts replyErrors).
 */
export function buildPageRequest(state: CalculatorState, threeAxis: ModeBuilder): BuiltRequest {
  // Each product mode of the mode registry has its builder (tests/ui/requestBuilder.test.ts checks every one).
  const built = pageModeKind(state) === 'threeAxis' ? threeAxis(state) : buildFiveAxisRequest(state);
  // The teeth and their feed (issue 29, optional): a text that is not a number is named on its field.
  const finish = finishFieldErrors(state, describeError);
  return finish.length === 0 ? built : { ok: false, errors: [...(built.ok ? [] : built.errors), ...finish] };
}
