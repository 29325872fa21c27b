/**
 * What the page shows for a state once its worker has answered: the request is built once
 * (buildRequest: validation only) and, when valid, answered by the worker's own job (solvePage);
 * the messages are then the build's errors or the reply's refusal (stateMessages), as app.ts draws them.
 */
import { buildRequest, stateMessages } from '../../src/ui/request';
import { type SliderRange, sliderRanges } from '../../src/ui/sliders';
import type { CalculatorState, FieldKey } from '../../src/ui/state';
import { solvePage } from '../../src/worker/jobs/page';

/** Each field's message for `state` after the worker's reply (none: the page answers it). */
export function answeredMessages(state: CalculatorState): Map<FieldKey, string> {
  const built = buildRequest(state);
  return stateMessages(state, built, built.ok ? solvePage(built.request) : null);
}

/** True when the page asks `state`'s question and the worker answers it (no refusal). */
export function answered(state: CalculatorState): boolean {
  const built = buildRequest(state);
  return built.ok && solvePage(built.request).ok;
}

/** The sliders' ranges for `state` once its worker has answered (its reply's limits, as app.ts ranges them). */
export function answeredRanges(state: CalculatorState): Readonly<Record<FieldKey, SliderRange>> {
  const built = buildRequest(state);
  return sliderRanges(state, built.ok ? solvePage(built.request).limits : null);
}
