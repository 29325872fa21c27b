/**
 * A sloped plane machined three-axis as the plane question it is (shared/notes/doubly-curved-and-3-axis.md,
 * section 2a): the upright tool at the slope's equivalent lead and tilt, one-way passes (the same
 * upright tool whichever way it feeds), the cusp of the answer. The teaching views draw it (the
 * profile across the passes in the surface's own frame, the formulas, the step-through) and the
 * Machined surface simulates it; the page and the worker build it here, so both ask the same question.
 */
import { forwardInput, MIN_LENGTH_MM } from '../core/input/validate';
import type { ThreeAxisReply } from './pageProtocol';
import type { SolveRequest } from './protocol';

/**
 * The plane question of a three-axis answer on a sloped plane (raster or waterline): forward, at
 * the answer's lead, tilt and cusp, one-way. Null on a surface of revolution (its passes are not
 * congruent) and without a scallop (nothing to draw).
 */
export function equivalentPlaneRequest(reply: ThreeAxisReply): SolveRequest | null {
  if (!reply.ok || reply.request.input.surface !== 'plane') return null;
  const a = reply.answer;
  if (a.noScallop || !(a.cuspHeightMm >= MIN_LENGTH_MM)) return null;
  const c = reply.request.input.case;
  const tool = {
    toolRadiusMm: c.toolRadiusMm,
    cornerRadiusMm: c.cornerRadiusMm,
    leadAngleDeg: a.leadDeg,
    tiltAngleDeg: a.tiltDeg,
  };
  return { mode: 'forward', input: forwardInput(tool, 'one-way', a.cuspHeightMm) };
}
