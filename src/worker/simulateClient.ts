/**
 * The page's `simulate` job on its own worker (the same module, solver.worker.ts), so a running
 * simulation never delays the results or the teaching views. Latest wins: a new request first
 * tells the worker to stop the simulation it runs (it checks between steps), then is sent; the
 * client (JobClient) drops any reply but the latest's. A request equal to the one whose reply is
 * still to come changes nothing (and stops nothing).
 */
import { JobClient, type RestartInfo } from './client';
import { type SolveRequest, sameRequest } from './protocol';
import type { Remote } from './rpc';
import type { SimulateReply } from './simulate';
import type { WorkerApi } from './workerApi';
import { startSolverWorker } from './workers';

/**
 * A simulation takes about 0.15 s alone on 2 cores and several times that on a loaded machine;
 * the solver's 3 s watchdog would restart a healthy one there, so this job waits longer.
 */
export const SIMULATION_WATCHDOG_MS = 15_000;

export function createSimulationWorker(): Worker {
  return startSolverWorker('path-interval-simulation');
}

export interface SimulateEvents {
  readonly onReply: (reply: SimulateReply) => void;
  readonly onRestart: (info: RestartInfo<SolveRequest>) => void;
  /** Progress of the simulation of `request` (0 to 1), sent once it runs longer than a frame. */
  readonly onProgress: (request: SolveRequest, fraction: number) => void;
}

export class SimulateClient {
  private remote: Remote<WorkerApi> | null = null;
  private readonly jobs: JobClient<SolveRequest, SimulateReply>;

  constructor(events: SimulateEvents) {
    this.jobs = new JobClient({
      createWorker: createSimulationWorker,
      call: (api, request) => {
        this.remote = api;
        return api.simulate(request, (fraction: number) => events.onProgress(request, fraction));
      },
      same: sameRequest,
      onReply: events.onReply,
      onRestart: events.onRestart,
      watchdogMs: SIMULATION_WATCHDOG_MS,
    });
  }

  /** Simulates `request`, stopping the one running (unless it is the one running). */
  request(request: SolveRequest): void {
    if (this.jobs.awaits(request)) return;
    void this.remote?.cancelSimulation().catch(() => undefined);
    this.jobs.request(request);
  }

  get started(): number {
    return this.jobs.started;
  }
}
