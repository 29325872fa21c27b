/**
 * The solver worker's API: one function per job, the large arrays of a reply marked for transfer.
 * Exposed by solver.worker.ts; its type is what the page's clients call (rpc.ts `Remote`).
 */
import { sceneTransferables, transferables } from './api';
import { solvePage } from './jobs/page';
import { table } from './jobs/table';
import { teachPage } from './jobs/teachPage';
import { isSolveReply, isSolveRequest, type PageReply, type PageRequest } from './pageProtocol';
import type { SolveRequest, TableReply, TableRequest, TeachReply } from './protocol';
import { transfer } from './rpc';
import { type SimulateReply, SimulationRunner, simulationTransferables } from './simulate';
import type { PageTeachReply } from './teachProtocol';

/** A newer `simulate` or `cancelSimulation` stops the running simulation between steps. */
const simulations = new SimulationRunner();

export const workerApi = {
  solve(request: PageRequest): PageReply {
    const reply = solvePage(request);
    if (isSolveReply(reply)) return transfer(reply, transferables(reply));
    // A doubly curved or three-axis answer: its scene's arrays.
    return reply.ok ? transfer(reply, [...sceneTransferables(reply.scene)]) : reply;
  },
  /** The teaching views' data: a plane's or a cylinder's (its arrays transferred), a doubly curved point's, three-axis'. */
  teach(request: PageRequest): PageTeachReply {
    const reply = teachPage(request);
    return isSolveRequest(reply.request) ? transfer(reply, transferables(reply as TeachReply)) : reply;
  },
  /** The lookup table for the page's download (a string: nothing to transfer). */
  table(request: TableRequest): TableReply {
    return table(request);
  },
  async simulate(request: SolveRequest, onProgress?: (fraction: number) => void): Promise<SimulateReply> {
    const reply = await simulations.run(request, onProgress);
    return transfer(reply, simulationTransferables(reply));
  },
  cancelSimulation(): void {
    simulations.cancel();
  },
};

/** The type the page sees: derived from this module, not written twice. */
export type WorkerApi = typeof workerApi;
