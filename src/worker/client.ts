/**
 * Page-side client of one job of a solver worker (solve, teach, simulate, table): the latest request
 * wins, a reply to an older request is dropped, and a worker that throws, dies or stops answering
 * is restarted and the last request sent again, the same job with the same input. After
 * MAX_CONSECUTIVE_RESTARTS in a row it gives up (and says so) until the next request.
 *
 * A request equal to the latest one whose reply is still to come is not sent twice; that is the
 * only de-duplication on the way to the worker. Once the latest reply is delivered (or given up
 * on), the same request is sent again when asked: the page may have dropped that reply because
 * other inputs were on screen when it came (freshness.ts), so a memory of "already asked" kept
 * past the reply could leave the page waiting for good (issue 17).
 *
 * Replies carry their request, so the page checks them again against the inputs on screen; this
 * client only keeps the worker from doing work nobody waits for.
 *
 * Loading is not a stall (issue 28): the watchdog counts only while the worker can answer: for the
 * client's first worker from its `ready` (its first module graph loaded, rpc.ts expose), and for
 * every worker outside a lazily imported job module's load (rpc.ts lazyModule, which the worker
 * announces); a load gets LOAD_WATCHDOG_MS of its own, so that a worker whose script never arrives
 * is still restarted. A restarted worker's script is cached: its load counts as answering time.
 */
import { type Endpoint, isLoadMessage, type Remote, wrap } from './rpc';
import type { WorkerApi } from './workerApi';

/** What the client needs of a worker: a message endpoint that reports errors and can be terminated. */
export interface WorkerLike extends Endpoint {
  addEventListener(type: 'message' | 'error', listener: (event: { readonly data: unknown }) => void): void;
  terminate(): void;
}

export interface RestartInfo<Req = unknown> {
  /** Why the worker was restarted. */
  readonly reason: string;
  /** True when it failed MAX_CONSECUTIVE_RESTARTS times in a row and the request was not sent again. */
  readonly gaveUp: boolean;
  /** The latest request: sent again, or given up on (null before the first request). */
  readonly request: Req | null;
}

export interface JobClientOptions<Req, Rep> {
  /** Starts a worker (a stand-in in tests). */
  readonly createWorker: () => WorkerLike;
  /** Calls the job on the worker. */
  readonly call: (api: Remote<WorkerApi>, request: Req) => Promise<Rep>;
  /** True when two requests ask the same question (protocol.ts sameRequest, sameTableRequest). */
  readonly same: (a: Req, b: Req) => boolean;
  /** Called with each reply to the latest request. */
  readonly onReply: (reply: Rep, request: Req) => void;
  /** Called when the worker had to be restarted. */
  readonly onRestart: (info: RestartInfo<Req>) => void;
  /** No answer within this time means the worker is dead or stuck (ms). */
  readonly watchdogMs?: number;
  /** The longest a load may take (LOAD_WATCHDOG_MS; a stand-in in tests), ms. */
  readonly loadWatchdogMs?: number;
}

/** No answer within this time means the worker is dead or stuck. */
export const WATCHDOG_MS = 3000;
/** A worker still loading (its first script, or a job's module) after this long is restarted (ms). */
export const LOAD_WATCHDOG_MS = 30000;
/** A request that kills every new worker is not repeated forever. */
export const MAX_CONSECUTIVE_RESTARTS = 3;

export class JobClient<Req, Rep> {
  private worker: WorkerLike | null = null;
  private remote: Remote<WorkerApi> | null = null;
  private inFlight: { readonly request: Req } | null = null;
  private queued: { readonly request: Req } | null = null;
  private latest: { readonly request: Req } | null = null;
  /** The latest request's reply is still to come (neither delivered nor given up on). */
  private awaiting = false;
  private watchdog: ReturnType<typeof setTimeout> | null = null;
  /** The current worker has said it is ready (its first module graph loaded). */
  private ready = false;
  /** Lazily imported modules the current worker is loading now. */
  private loads = 0;
  private consecutiveRestarts = 0;
  /** Number of workers started so far (1 after the first request). */
  started = 0;

  constructor(private readonly options: JobClientOptions<Req, Rep>) {}

  /**
   * Asks for an answer; only the latest request's reply is delivered. A request equal to the
   * latest one, while its reply is still to come, changes nothing (it is not sent twice).
   */
  request(request: Req): void {
    if (this.awaits(request)) return;
    const entry = { request };
    this.latest = entry;
    this.awaiting = true;
    if (this.inFlight !== null) {
      // One in flight: keep only the newest waiting request.
      this.queued = entry;
      return;
    }
    this.send(entry);
  }

  /** True when `request` equals the latest request and its reply is still to come. */
  awaits(request: Req): boolean {
    return this.awaiting && this.latest !== null && this.options.same(this.latest.request, request);
  }

  dispose(): void {
    this.awaiting = false;
    this.stopWatchdog();
    this.worker?.terminate();
    this.worker = null;
    this.remote = null;
    this.inFlight = this.queued = this.latest = null;
  }

  private ensureWorker(): Remote<WorkerApi> {
    if (this.remote !== null) return this.remote;
    const worker = this.options.createWorker();
    worker.addEventListener('error', (e: unknown) => {
      const message = (e as { message?: string }).message;
      if (this.worker === worker) this.restart(`the solver failed (${message || 'worker error'})`);
    });
    worker.addEventListener('message', (e) => {
      if (this.worker === worker && isLoadMessage(e.data)) this.loaded(e.data);
    });
    this.worker = worker;
    // Only the first worker's script load is not counted (a newcomer's first page, a dev server
    // compiling modules): a restarted worker's script is cached, and one that never says it is
    // ready is as stuck as one that never answers.
    this.ready = this.started > 0;
    this.loads = 0;
    this.remote = wrap<WorkerApi>(worker);
    this.started++;
    return this.remote;
  }

  private send(entry: { readonly request: Req }): void {
    this.inFlight = entry;
    const remote = this.ensureWorker();
    this.startWatchdog();
    this.options.call(remote, entry.request).then(
      (reply) => this.settle(entry, reply),
      (error: unknown) => {
        if (this.inFlight === entry) this.restart(`the solver threw (${String(error)})`);
      },
    );
  }

  private settle(entry: { readonly request: Req }, reply: Rep): void {
    if (this.inFlight !== entry) return; // a restart already replaced this request
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
    if (entry !== this.latest) return;
    this.awaiting = false;
    this.options.onReply(reply, entry.request);
  }

  private restart(reason: string): void {
    this.stopWatchdog();
    this.worker?.terminate();
    this.worker = null;
    this.remote = null;
    this.inFlight = null;
    this.queued = null;
    this.consecutiveRestarts++;
    const gaveUp = this.consecutiveRestarts > MAX_CONSECUTIVE_RESTARTS;
    const latest = this.latest;
    if (gaveUp || latest === null) {
      // Nothing is awaited any more; the next request (even the same one) starts afresh.
      this.awaiting = false;
      this.consecutiveRestarts = 0;
    } else {
      // The same job with the same input: the latest request, whatever was in flight.
      this.awaiting = true;
      this.send(latest);
    }
    // Told last, when the client is consistent again: the page may ask at once.
    this.options.onRestart({ reason, gaveUp, request: latest?.request ?? null });
  }

  /** The worker's word on its loading: the watchdog counts again once it is ready and nothing loads. */
  private loaded(m: { readonly rpc: 'ready' } | { readonly rpc: 'loading'; readonly on: boolean }): void {
    if (m.rpc === 'ready') this.ready = true;
    else this.loads = Math.max(0, this.loads + (m.on ? 1 : -1));
    if (this.inFlight !== null) this.startWatchdog();
  }

  /**
   * Arms the watchdog for the call in flight: the stall limit while the worker can answer, the load
   * limit while it loads (its first script, or a job's module).
   */
  private startWatchdog(): void {
    this.stopWatchdog();
    const loading = !this.ready || this.loads > 0;
    this.watchdog = setTimeout(
      () => this.restart(loading ? 'the solver did not load' : 'the solver stopped answering'),
      loading ? (this.options.loadWatchdogMs ?? LOAD_WATCHDOG_MS) : (this.options.watchdogMs ?? WATCHDOG_MS),
    );
  }

  private stopWatchdog(): void {
    if (this.watchdog !== null) clearTimeout(this.watchdog);
    this.watchdog = null;
  }
}
