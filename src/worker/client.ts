/**
 * Page-side client of the solver worker: the latest request wins, stale replies are
 * dropped, and a worker that throws, dies or stops answering is restarted and the last
 * request repeated.
 */
import * as Comlink from 'comlink';
import type { SolveReply, SolveRequest } from './protocol';
import type { WorkerApi } from './solver.worker';

export interface SolverClientEvents {
  /** Called with each reply that is still the latest. */
  readonly onReply: (reply: SolveReply) => void;
  /** Called when the worker had to be restarted (with the reason). */
  readonly onRestart: (reason: string) => void;
}

/** No answer within this time means the worker is dead or stuck. */
const WATCHDOG_MS = 3000;
/** A request that kills every new worker is not repeated forever. */
const MAX_CONSECUTIVE_RESTARTS = 3;

export class SolverClient {
  private worker: Worker | null = null;
  private remote: Comlink.Remote<WorkerApi> | null = null;
  private nextId = 1;
  private inFlight: SolveRequest | null = null;
  private queued: Omit<SolveRequest, 'id'> | null = null;
  private latest: SolveRequest | null = null;
  private watchdog: ReturnType<typeof setTimeout> | null = null;
  private consecutiveRestarts = 0;
  /** Number of workers started so far (1 after the first request). */
  started = 0;

  constructor(
    private readonly events: SolverClientEvents,
    private readonly createWorker: () => Worker = () =>
      new Worker(new URL('./solver.worker.ts', import.meta.url), { type: 'module', name: 'path-interval-solver' }),
  ) {}

  /** Asks for a solution; only the latest request's reply is delivered. */
  request(req: Omit<SolveRequest, 'id'>): void {
    if (this.inFlight !== null) {
      // One in flight: keep only the newest waiting request.
      this.queued = req;
      return;
    }
    this.send(req);
  }

  /** Test hook: kills the worker as a crash would. */
  crash(): void {
    void this.remote?.crash().catch(() => undefined);
  }

  dispose(): void {
    this.stopWatchdog();
    this.worker?.terminate();
    this.worker = null;
    this.remote = null;
  }

  private ensureWorker(): Comlink.Remote<WorkerApi> {
    if (this.remote !== null) return this.remote;
    const worker = this.createWorker();
    worker.addEventListener('error', (e) => this.restart(`the solver failed (${e.message || 'worker error'})`));
    this.worker = worker;
    this.remote = Comlink.wrap<WorkerApi>(worker);
    this.started++;
    return this.remote;
  }

  private send(req: Omit<SolveRequest, 'id'>): void {
    const full: SolveRequest = { ...req, id: this.nextId++ };
    this.inFlight = full;
    this.latest = full;
    const remote = this.ensureWorker();
    this.startWatchdog();
    remote.solve(full).then(
      (reply) => this.settle(full, reply),
      (error: unknown) => {
        if (this.inFlight?.id === full.id) this.restart(`the solver threw (${String(error)})`);
      },
    );
  }

  private settle(req: SolveRequest, reply: SolveReply): void {
    if (this.inFlight?.id !== req.id) return; // a restart already replaced this request
    this.stopWatchdog();
    this.consecutiveRestarts = 0;
    this.inFlight = null;
    const next = this.queued;
    this.queued = null;
    if (next !== null) {
      // A newer request is waiting: this reply is stale, drop it.
      this.send(next);
      return;
    }
    if (reply.id === this.latest?.id) this.events.onReply(reply);
  }

  private restart(reason: string): void {
    this.stopWatchdog();
    this.worker?.terminate();
    this.worker = null;
    this.remote = null;
    this.inFlight = null;
    const repeat = this.queued ?? this.latest;
    this.queued = null;
    this.events.onRestart(
      this.consecutiveRestarts >= MAX_CONSECUTIVE_RESTARTS
        ? `${reason}; gave up after ${MAX_CONSECUTIVE_RESTARTS} restarts`
        : reason,
    );
    this.consecutiveRestarts++;
    if (repeat !== null && this.consecutiveRestarts <= MAX_CONSECUTIVE_RESTARTS) {
      this.send({ mode: repeat.mode, R: repeat.R, Rcr: repeat.Rcr, rho: repeat.rho, value: repeat.value });
    }
  }

  private startWatchdog(): void {
    this.stopWatchdog();
    this.watchdog = setTimeout(() => this.restart('the solver stopped answering'), WATCHDOG_MS);
  }

  private stopWatchdog(): void {
    if (this.watchdog !== null) clearTimeout(this.watchdog);
    this.watchdog = null;
  }
}
