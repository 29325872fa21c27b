/**
 * The solver worker's API: one function per job, the large arrays of a reply marked for transfer.
 * Exposed by solver.worker.ts; its type is what the page's clients call (rpc.ts `Remote`).
 *
 * Only a plane's or a cylinder's answer is in the worker's first script (jobs/solve.ts: the first
 * result needs no more); every other surface's and mode's solvers (jobs/page.ts), the teaching
 * views' data, the lookup table and the simulation load here when first asked (dynamic imports,
 * each once; the module cache keeps them).
 */

import { loadSurfaceModel } from '../core/surfaces/registry';
import type { FinishReply, FinishRequest } from './finishProtocol';
import { solve } from './jobs/solve';
import {
  isSolveReply,
  isSolveRequest,
  type PageReply,
  type PageRequest,
  type QuestionReply,
  type SolverReplyOf,
  type SolverRequest,
} from './pageProtocol';
import type { SolveRequest, TableReply, TableRequest, TeachReply } from './protocol';
import { lazyModule, transfer } from './rpc';
import type { SimulateReply, SimulationRunner } from './simulate';
import type { TargetSaReply, TargetSaRequest } from './targetSaProtocol';
import type { PageTeachReply } from './teachProtocol';
import { sceneTransferables, transferables } from './transferables';

/**
 * A job's module once the doubly curved point's model is loaded (on first use in the site): the
 * teaching views' and the lookup table's doubly curved data ask the registry for it (core
 * surfaces/doublyCurvedPoint.ts), as jobs/page.ts's `ready` does for the answer.
 */
function withCurvedModel<T>(module: T): Promise<T> {
  return loadSurfaceModel('doublyCurved').then(() => module);
}

/** The jobs' modules beyond the first script, each imported on first use (the page's watchdog told: rpc.ts lazyModule). */
const pageJob = lazyModule(() => import('./jobs/page').then((m) => m.ready));
const teachJob = lazyModule(() => import('./jobs/teachPage').then(withCurvedModel));
const tableJob = lazyModule(() => import('./jobs/table').then(withCurvedModel));
const simulation = lazyModule(() => import('./simulate'));
const finishJob = lazyModule(() => import('./jobs/finish'));
const targetSaJob = lazyModule(() => import('./jobs/targetSa'));

/** Answers any question; the plane's and cylinders' at once, the others' solvers loaded on first use. */
async function solveAny(request: SolverRequest): Promise<PageReply | QuestionReply> {
  if (isSolveRequest(request)) {
    const reply = solve(request);
    return transfer(reply, transferables(reply));
  }
  // Any other surface or mode: its solvers load now (once), then its scene's arrays.
  const reply = (await pageJob()).solvePage(request);
  if (isSolveReply(reply)) return transfer(reply, transferables(reply));
  return reply.ok && 'scene' in reply ? transfer(reply, [...sceneTransferables(reply.scene)]) : reply;
}

/** A newer `simulate` or `cancelSimulation` stops the running simulation between steps (one runner, made on first use). */
let simulations: Promise<SimulationRunner> | null = null;
const runner = (): Promise<SimulationRunner> =>
  (simulations ??= simulation().then(({ SimulationRunner }) => new SimulationRunner()));

export const workerApi = {
  /**
   * The one `solve` job: any question (a page's, or one over the registries of modes and surfaces);
   * the reply's kind follows the request's (SolverReplyOf).
   */
  async solve<R extends SolverRequest>(request: R): Promise<SolverReplyOf<R>> {
    return (await solveAny(request)) as SolverReplyOf<R>;
  },
  /** The teaching views' data: a plane's or a cylinder's (its arrays transferred), any other surface's or mode's. */
  async teach(request: PageRequest): Promise<PageTeachReply> {
    const reply = (await teachJob()).teachPage(request);
    return isSolveRequest(reply.request) ? transfer(reply, transferables(reply as TeachReply)) : reply;
  },
  /** The lookup table for the page's download (a string: nothing to transfer). */
  async table(request: TableRequest): Promise<TableReply> {
    return (await tableJob()).table(request);
  },
  /** The surface the teeth leave (issue 29): feed marks, areal parameters, and the x3p file when asked (transferred). */
  async finish(request: FinishRequest): Promise<FinishReply> {
    const reply = (await finishJob()).finish(request);
    if (!reply.ok) return reply;
    const buffers = [reply.x3p?.buffer, reply.map?.buffer].filter((b) => b !== undefined) as ArrayBuffer[];
    return transfer(reply, buffers);
  },
  /** The best (L, fz) pair for a target Sa and the curve of pairs (issue 29; seconds of work). */
  async targetSa(request: TargetSaRequest): Promise<TargetSaReply> {
    return (await targetSaJob()).targetSa(request);
  },
  async simulate(request: SolveRequest, onProgress?: (fraction: number) => void): Promise<SimulateReply> {
    const r = await runner();
    const reply = await r.run(request, onProgress);
    const { simulationTransferables } = await simulation();
    return transfer(reply, simulationTransferables(reply));
  },
  cancelSimulation(): void {
    // After any simulate call already waiting for the runner (promise callbacks run in order).
    void runner().then((r) => r.cancel());
  },
};

/** The type the page sees: derived from this module, not written twice. */
export type WorkerApi = typeof workerApi;
