/**
 * The page's two solver workers, one per kind of job, so that the teaching views' heavier data
 * never delays the results: both run the same module (solver.worker.ts). The names tell them
 * apart in the browser's tools (and to tests, through WorkerGlobalScope.name).
 */
import solverWorkerUrl from 'virtual:solver-worker-url';
import { JobClient, type JobClientOptions, type RestartInfo } from './client';
import type { FinishReply, FinishRequest } from './finishProtocol';
import { type PageReply, type PageRequest, samePageRequest } from './pageProtocol';
import { sameTableRequest, type TableReply, type TableRequest } from './protocol';
import type { PageTeachReply } from './teachProtocol';

/** The worker for `solve`: results and the 3D scene. */
export function createSolverWorker(): Worker {
  return startSolverWorker('path-interval-solver');
}

/** The worker for `teach`: the teaching views' data. */
export function createViewsWorker(): Worker {
  return startSolverWorker('path-interval-views');
}

export interface JobEvents<Req, Rep> {
  readonly onReply: (reply: Rep) => void;
  readonly onRestart: (info: RestartInfo<Req>) => void;
}

/**
 * The watchdog time of the `solve` job (ms): undefined (the client's WATCHDOG_MS), except in the
 * instrumented e2e build, where a test may set `window.__pathIntervalSolverWatchdogMs` (read at
 * each request) so that a test of the give-up need not wait 4 x 3 s. The production build
 * compiles this to `undefined` (tests/e2e/trust.test.ts checks it holds no `__pathInterval`).
 */
function solverWatchdogMs(): number | undefined {
  if (import.meta.env.MODE !== 'e2e') return undefined;
  const ms = (globalThis as { __pathIntervalSolverWatchdogMs?: unknown }).__pathIntervalSolverWatchdogMs;
  return typeof ms === 'number' && ms > 0 ? ms : undefined;
}

/** The `solve` job on its own worker. */
export function solveClient(events: JobEvents<PageRequest, PageReply>): JobClient<PageRequest, PageReply> {
  return new JobClient({
    createWorker: createSolverWorker,
    // A page's request gets a page's reply (SolverReplyOf; the remote's type loses the generic).
    call: (api, r) => api.solve(r) as Promise<PageReply>,
    same: samePageRequest,
    ...events,
    // A getter: the client reads it at each request.
    get watchdogMs() {
      return solverWatchdogMs();
    },
  });
}

/** The `teach` job on its own worker. */
export function teachClient(events: JobEvents<PageRequest, PageTeachReply>): JobClient<PageRequest, PageTeachReply> {
  return jobClient(createViewsWorker, (api, r) => api.teach(r), samePageRequest, events);
}

/** The worker for `table`, started on the first download: the lookup table never delays the results. */
export function createTableWorker(): Worker {
  return startSolverWorker('path-interval-table');
}

/** The `table` job on its own worker. */
export function tableClient(events: JobEvents<TableRequest, TableReply>): JobClient<TableRequest, TableReply> {
  return jobClient(createTableWorker, (api, r) => api.table(r), sameTableRequest, events);
}

/**
 * The finish's watchdog (ms): the core's areal parameters take seconds to minutes at large feeds, so
 * only a worker silent this long is stuck; the page stops a computation nobody waits for itself
 * (finishPanel.ts: a new question ends the worker still busy with the old one).
 */
export const FINISH_WATCHDOG_MS = 300_000;

/**
 * The `finish` job (issue 29) on its own worker, started on the first finish question; `same` is
 * finishProtocol.ts sameFinishRequest, passed by the finish box (loaded later) so that this first
 * script does not carry it.
 */
export function finishClient(
  events: JobEvents<FinishRequest, FinishReply>,
  same: (a: FinishRequest, b: FinishRequest) => boolean,
): JobClient<FinishRequest, FinishReply> {
  return new JobClient({
    createWorker: () => startSolverWorker('path-interval-finish'),
    call: (api, r) => api.finish(r),
    same,
    ...events,
    watchdogMs: FINISH_WATCHDOG_MS,
  });
}

/** A solver worker (the module worker built from solver.worker.ts), named for the browser's tools. */
export function startSolverWorker(name: string): Worker {
  return new Worker(solverWorkerUrl, { type: 'module', name });
}

/** A job's client on its own worker, with no watchdog. */
function jobClient<Req, Rep>(
  createWorker: JobClientOptions<Req, Rep>['createWorker'],
  call: JobClientOptions<Req, Rep>['call'],
  same: JobClientOptions<Req, Rep>['same'],
  events: JobEvents<Req, Rep>,
): JobClient<Req, Rep> {
  return new JobClient({ createWorker, call, same, ...events });
}
