/**
 * Why a procedure has no step-over along a sweep, as plain data: the angle ranges without an
 * answer and the reason, in words with no number in them (so the page can show it in any unit).
 * Pure; angles in degrees.
 */

import type { ToolInput } from '../domain/tool';
import { APPROXIMATIONS, modelCurve, type ProcedureKey } from './procedures';

/** A run of consecutive sweep samples where a procedure has no answer, for one reason. */
export interface SweepGap {
  /** First and last sampled angle without an answer (degrees; the true edge lies before the next sample). */
  readonly fromDeg: number;
  readonly toDeg: number;
  /** Why, without the procedure's name and without numbers (e.g. "h is above the widest point of its ellipse"). */
  readonly reason: string;
}

/** The reason the exact solver gives no step-over: h at or above the posture's limit. */
export const EXACT_NO_ANSWER =
  'h is at or above the highest scallop this posture can leave (above it the tool leaves a wall, not a scallop)';

/** The text after a "Who: " prefix, without its final full stop. */
function withoutWho(text: string): string {
  const at = text.indexOf(': ');
  return (at >= 0 ? text.slice(at + 2) : text).replace(/\.$/, '');
}

/**
 * Why procedure `key` has no step-over for `tool` at scallop height h (the caller knows it has
 * none): its model does not apply (that model's own reason), or h is above the widest point of
 * the model's circle or ellipse, or (exact) h is at or above the posture's limit.
 */
export function noAnswerReason(key: ProcedureKey, tool: ToolInput): string {
  if (key === 'exact') return EXACT_NO_ANSWER;
  const model = modelCurve(key, tool);
  if (!model.ok) return withoutWho(model.notApplicable);
  const { shape } = model.curve;
  // The height of a circle's widest point is its radius; an ellipse's, its short semi-axis.
  const widest = `${shape === 'circle' ? 'radius' : 'height'} ${APPROXIMATIONS[key].widestSymbol}`;
  return `h is above the widest point of its ${shape} (its ${widest} is below h)`;
}

/**
 * Groups the samples without an answer into runs with one reason each.
 * @param angleDeg the sampled angles, ascending; @param reasons per sample: null where there is
 * an answer, else why not. Same length.
 */
export function sweepGaps(angleDeg: readonly number[], reasons: ReadonlyArray<string | null>): SweepGap[] {
  const gaps: SweepGap[] = [];
  let open: { fromDeg: number; toDeg: number; reason: string } | null = null;
  angleDeg.forEach((angle, i) => {
    const reason = reasons[i] ?? null;
    if (open !== null && reason === open.reason) {
      open.toDeg = angle;
      return;
    }
    if (open !== null) gaps.push(open);
    open = reason === null ? null : { fromDeg: angle, toDeg: angle, reason };
  });
  if (open !== null) gaps.push(open);
  return gaps;
}
