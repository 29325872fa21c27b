/** Module Web Worker entry: exposes the solver API through Comlink, transferring large arrays. */
import * as Comlink from 'comlink';
import { solverApi, transferables } from './api';
import type { SolveReply, SolveRequest } from './protocol';

const workerApi = {
  solve(request: SolveRequest): SolveReply {
    const reply = solverApi.solve(request);
    return Comlink.transfer(reply, transferables(reply));
  },
  crash: solverApi.crash,
};

/** The type the page sees: derived from this module, not written twice. */
export type WorkerApi = typeof workerApi;

Comlink.expose(workerApi);
