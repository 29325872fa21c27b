/**
 * The solver API that runs inside the Web Worker: one function per job, plain data in and out,
 * so it is tested in Node directly and exposed unchanged (rpc.ts) in solver.worker.ts.
 *  - `solve` (jobs/solve.ts): the exact answer, every procedure beside it, and the 3D scene's geometry;
 *  - `teach` (jobs/teach.ts): the teaching views' data (profiles, sweeps, the traced procedure, formulas' models);
 *  - `table` (jobs/table.ts): the lookup table for the page's download.
 * The data each view needs is built in data/ (one file per view). Every reply echoes its request.
 * Inputs are validated again (jobs/revalidate.ts): a bad request gets a typed error reply, never an
 * exception.
 */
import { sceneGeometry } from './data/scene';
import { traceFrames } from './data/trace';
import { revalidate } from './jobs/revalidate';
import { solve } from './jobs/solve';
import { table } from './jobs/table';
import { teach } from './jobs/teach';
import type { SceneGeometry, SolveReply, TeachReply } from './protocol';

export { revalidate, sceneGeometry, solve, table, teach, traceFrames };

/** Buffers of a scene's geometry that can be transferred instead of copied (added to `out`). */
export function sceneTransferables(g: SceneGeometry | null, out: Set<ArrayBuffer> = new Set()): Set<ArrayBuffer> {
  if (g === null) return out;
  out.add(g.toolPositions.buffer as ArrayBuffer);
  for (const cusp of [g.right, g.left]) for (const l of cusp?.loops ?? []) out.add(l.buffer as ArrayBuffer);
  if (g.machine !== null) out.add(g.machine.step.points.buffer as ArrayBuffer);
  return out;
}

/** Buffers of a reply that can be transferred instead of copied (each listed once). */
export function transferables(reply: SolveReply | TeachReply): ArrayBuffer[] {
  if (!reply.ok) return [];
  const out = new Set<ArrayBuffer>();
  if ('scene' in reply) sceneTransferables(reply.scene, out);
  else {
    const c = reply.curves;
    for (const curve of [c.profile, c.ringEllipse, ...Object.values(c.approximations)])
      if (curve) out.add(curve.buffer as ArrayBuffer);
    if (reply.cylinder !== null) {
      out.add(reply.cylinder.passProfile.buffer as ArrayBuffer);
      out.add(reply.cylinder.ringEllipse.buffer as ArrayBuffer);
    }
  }
  return [...out];
}

/** The worker's API object; its type is what the page sees through rpc.ts. */
export const solverApi = { solve, teach, table };

export type SolverApi = typeof solverApi;
