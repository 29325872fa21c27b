/**
 * The worker's one `solve` job for every question: a plane's or a cylinder's (jobs/solve.ts), a
 * doubly curved point's (jobs/curved.ts), three-axis machining's (jobs/threeAxis.ts), and any other
 * registered machine mode over a registered surface (jobs/question.ts). The reply echoes its request.
 */
import { loadSurfaceModel } from '../../core/surfaces/registry';
import { isQuestionRequest, isSolveRequest, type SolverReplyOf, type SolverRequest } from '../pageProtocol';
import { solveCurved } from './curved';
import { solveQuestion } from './question';
import { solve } from './solve';
import { solveThreeAxisRequest } from './threeAxis';

/**
 * This job once the surface models it asks load (the doubly curved point's loads on first use in
 * the site, registry.ts loadSurfaceModel): what the worker awaits as it loads the job (workerApi.ts);
 * a promise, not a top-level await, so that importing this module never waits for that load.
 */
export const ready: Promise<{ readonly solvePage: typeof solvePage }> = loadSurfaceModel('doublyCurved').then(() => ({
  solvePage,
}));

/** Solves any question. Never throws for any numeric input. */
export function solvePage<R extends SolverRequest>(r: R): SolverReplyOf<R> {
  return answer(r) as SolverReplyOf<R>;
}

function answer(request: SolverRequest): SolverReplyOf<SolverRequest> {
  if (isQuestionRequest(request)) return solveQuestion(request);
  if (isSolveRequest(request)) return solve(request);
  if (request.mode === 'three-axis') return solveThreeAxisRequest(request);
  return solveCurved(request);
}
