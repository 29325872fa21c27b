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
import { sceneTransferables, transferables } from './transferables';

export { revalidate, sceneGeometry, sceneTransferables, solve, table, teach, traceFrames, transferables };

/** The worker's API object; its type is what the page sees through rpc.ts. */
export const solverApi = { solve, teach, table };

export type SolverApi = typeof solverApi;
