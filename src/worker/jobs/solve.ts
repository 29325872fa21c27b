/**
 * The worker's `solve` job: the exact answer of one request, every procedure beside it (the results
 * table's rows, and a cylinder's comparison rows), the 3D scene's geometry and the roughness. The
 * reply echoes its request; a bad request gets a typed error reply, never an exception.
 */
import { compareForward, compareInverse } from '../../core/procedures/compare';
import { forwardOfRaTarget, roughnessSummary } from '../../core/roughness/raTarget';
import { exactRoughness, exactRoughnessAtInterval, type Roughness } from '../../core/roughness/roughness';
import { exactOfForward, exactOfInverse } from '../data/exact';
import { forwardCurvatureRows, forwardRows, inverseCurvatureRows, inverseRows } from '../data/rows';
import { sceneGeometry } from '../data/scene';
import { classicSliderLimits } from '../data/sliderLimits';
import type { CurvatureRow, ExactSummary, ProcedureRow, SolveReply, SolveRequest } from '../protocol';
import { revalidate } from './revalidate';

/** Solves one request: exact, every procedure, the scene. Never throws for any numeric input. */
export function solve(request: SolveRequest): SolveReply {
  const t0 = performance.now();
  const errors = revalidate(request);
  const limits = classicSliderLimits(request);
  if (errors !== null) return { ok: false, request, errors, limits };
  let exact: ExactSummary;
  let rows: ProcedureRow[];
  let curvature: CurvatureRow[] | null;
  let roughness: Roughness;
  if (request.mode !== 'inverse') {
    const input = request.mode === 'ra' ? forwardOfRaTarget(request.input) : request.input;
    const c = compareForward(input);
    exact = exactOfForward(input, c);
    roughness = exactRoughness(input, c.exact);
    rows = forwardRows(input, c, exact);
    curvature = forwardCurvatureRows(input, c);
  } else {
    const input = request.input;
    const c = compareInverse(input);
    exact = exactOfInverse(input, c);
    roughness = exactRoughnessAtInterval(input, input.pattern, c.exact, input.surface);
    rows = inverseRows(input, c, exact);
    curvature = inverseCurvatureRows(input, c);
  }
  return {
    ok: true,
    request,
    limits,
    exact,
    rows,
    curvature,
    scene: sceneGeometry(request.input, exact, request.input.surface),
    roughness: roughnessSummary(roughness, exact.cuspHeightMm),
    solveMs: performance.now() - t0,
  };
}
