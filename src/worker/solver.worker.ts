/** Module Web Worker entry: exposes the solver API through Comlink, transferring large arrays. */
import * as Comlink from 'comlink';
import { solve, teach, transferables } from './api';
import type { SolveReply, SolveRequest, TeachReply } from './protocol';
import { type SimulateReply, SimulationRunner, simulationTransferables } from './simulate';

/** A newer `simulate` or `cancelSimulation` stops the running simulation between steps. */
const simulations = new SimulationRunner();

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
    const reply = await simulations.run(request, onProgress);
    return Comlink.transfer(reply, simulationTransferables(reply));
  },
  cancelSimulation(): void {
    simulations.cancel();
  },
};

/** The type the page sees: derived from this module, not written twice. */
export type WorkerApi = typeof workerApi;

Comlink.expose(workerApi);
