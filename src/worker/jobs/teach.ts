/**
 * The worker's `teach` job: the teaching views' data for one request (in inverse mode, for the
 * forward state at the solved h): the profile's curves, the chart's sweeps, the step-through's
 * frames, the formulas' models and the paper's tables. The reply echoes its request.
 */

import { type ForwardInput, forwardInput, MIN_LENGTH_MM } from '../../core/input/validate';
import { compareForward, compareInverse } from '../../core/procedures/compare';
import { type PaperTableRow, paperTables, profileCurves } from '../../core/procedures/teaching';
import { forwardOfRaTarget } from '../../core/roughness/raTarget';
import { exactOfForward, exactOfInverse } from '../data/exact';
import { formulaModels } from '../data/models';
import { cylinderCurves, profileCurveSet } from '../data/profile';
import { sweeps } from '../data/sweeps';
import { traceFrames } from '../data/trace';
import type { ExactSummary, SolveRequest, TeachReply } from '../protocol';
import { revalidate } from './revalidate';

/** Fixed conditions: computed once per worker. */
let tables: readonly PaperTableRow[] | null = null;

/** The teaching views' data for one request (in inverse mode: the forward state at the solved h). */
export function teach(request: SolveRequest): TeachReply {
  const errors = revalidate(request);
  if (errors !== null) return { ok: false, request, errors, reason: null };
  let forward: ForwardInput;
  let exact: ExactSummary;
  /** The forward comparison, when it is at hand (its curvature rows feed the profile on a cylinder). */
  let compared: ReturnType<typeof compareForward> | null = null;
  if (request.mode !== 'inverse') {
    forward = request.mode === 'ra' ? forwardOfRaTarget(request.input) : request.input;
    compared = compareForward(forward);
    exact = exactOfForward(forward, compared);
  } else {
    const input = request.input;
    exact = exactOfInverse(input, compareInverse(input));
    if (exact.cuspHeightMm < MIN_LENGTH_MM) {
      return {
        ok: false,
        request,
        errors: [],
        reason:
          'No scallop: the flat bottom lying on the plane covers this step-over, so there is no profile to compare.',
      };
    }
    forward = forwardInput(input, input.pattern, exact.cuspHeightMm, input.surface);
  }
  const c = profileCurves(forward);
  tables ??= paperTables();
  const cylinder =
    forward.surface.kind === 'cylinder'
      ? cylinderCurves(forward, forward.surface, c, (compared ?? compareForward(forward)).curvature)
      : null;
  const trace = traceFrames(forward);
  return {
    ok: true,
    request,
    forward,
    exact,
    curves: profileCurveSet(c),
    sweeps: sweeps(forward),
    // The paper's procedure works against the h pseudo plane: it has no frames on a cylinder.
    frames: cylinder === null ? trace.frames : [],
    traceResult: trace.traceResult,
    models: formulaModels(forward),
    tables,
    cylinder,
  };
}
