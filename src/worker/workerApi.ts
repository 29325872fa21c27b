/**
 * The solver worker's API: one function per job, the large arrays of a reply marked for transfer.
 * Exposed by solver.worker.ts; its type is what the page's clients call (rpc.ts `Remote`).
 */
import { sceneTransferables, teach, transferables } from './api';
import { solvePage } from './jobs/page';
import { table } from './jobs/table';
import { isSolveReply, type PageReply, type PageRequest } from './pageProtocol';
import type { SolveRequest, TableReply, TableRequest, TeachReply } from './protocol';
import { transfer } from './rpc';
import { type SimulateReply, SimulationRunner, simulationTransferables } from './simulate';

/** A newer `simulate` or `cancelSimulation` stops the running simulation between steps. */
const simulations = new SimulationRunner();

export const workerApi = {
  solve(request: PageRequest): PageReply {
    const reply = solvePage(request);
    if (isSolveReply(reply)) return transfer(reply, transferables(reply));
    // A doubly curved or three-axis answer: its scene's arrays.
    return reply.ok ? transfer(reply, [...sceneTransferables(reply.scene)]) : reply;
  },
  teach(request: SolveRequest): TeachReply {
    const reply = teach(request);
    return transfer(reply, transferables(reply));
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
