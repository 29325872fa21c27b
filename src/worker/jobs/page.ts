/**
 * The page's `solve` job for every question it asks: a plane's or a cylinder's (jobs/solve.ts), a
 * doubly curved point's (jobs/curved.ts) or three-axis machining's (jobs/threeAxis.ts). The reply
 * echoes its request.
 */
import { isSolveRequest, type PageReply, type PageRequest } from '../pageProtocol';
import { solveCurved } from './curved';
import { solve } from './solve';
import { solveThreeAxisRequest } from './threeAxis';

/** Solves any of the page's questions. Never throws for any numeric input. */
export function solvePage(request: PageRequest): PageReply {
  if (isSolveRequest(request)) return solve(request);
  if (request.mode === 'three-axis') return solveThreeAxisRequest(request);
  return solveCurved(request);
}
