/** Module Web Worker entry: exposes the solver API through Comlink, transferring large arrays. */
import * as Comlink from 'comlink';
import { solve, teach, transferables } from './api';
import type { SolveReply, SolveRequest, TeachReply } from './protocol';

const workerApi = {
  solve(request: SolveRequest): SolveReply {
    const reply = solve(request);
    return Comlink.transfer(reply, transferables(reply));
  },
  teach(request: SolveRequest): TeachReply {
    const reply = teach(request);
    return Comlink.transfer(reply, transferables(reply));
  },
};

/** The type the page sees: derived from this module, not written twice. */
export type WorkerApi = typeof workerApi;

Comlink.expose(workerApi);
