/** Module Web Worker entry: exposes the solver API through Comlink, transferring large arrays. */
import * as Comlink from 'comlink';
import { solve, teach, transferables } from './api';
import type { SolveReply, SolveRequest, TeachReply } from './protocol';
import { type SimulateReply, simulate, simulationTransferables } from './simulate';

/** The simulation running now; a newer `simulate` or `cancelSimulation` stops it between steps. */
let simulation = 0;

const workerApi = {
  solve(request: SolveRequest): SolveReply {
    const reply = solve(request);
    return Comlink.transfer(reply, transferables(reply));
  },
  teach(request: SolveRequest): TeachReply {
    const reply = teach(request);
    return Comlink.transfer(reply, transferables(reply));
  },
  async simulate(request: SolveRequest, onProgress?: (fraction: number) => void): Promise<SimulateReply> {
    const mine = ++simulation;
    const reply = await simulate(request, { shouldStop: () => simulation !== mine, onProgress });
    return Comlink.transfer(reply, simulationTransferables(reply));
  },
  cancelSimulation(): void {
    simulation++;
  },
};

/** The type the page sees: derived from this module, not written twice. */
export type WorkerApi = typeof workerApi;

Comlink.expose(workerApi);
