/**
 * The worker client's watchdog does not count loading as a stall (issue 28, point 12): a worker
 * whose first script is still loading, or a job whose lazily imported module is still loading, is
 * not restarted as "the solver stopped answering"; once loaded, a stall still is, a load that never
 * ends is restarted after the load limit, and a restarted worker (its script cached) that never
 * says it is ready is restarted as stuck. The client's timers are Vitest's fake ones (time
 * advanced by the test); the worker is a real rpc.ts endpoint on a MessageChannel.
 */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { JobClient, type RestartInfo, type WorkerLike } from '../../src/worker/client';
import { type Endpoint, expose, lazyModule } from '../../src/worker/rpc';

const WATCHDOG_MS = 100;
const LOAD_WATCHDOG_MS = 5000;

/** A worker whose script "loads" until the test calls `load()` (only then is its API exposed). */
class LoadingWorker implements WorkerLike {
  private readonly channel = new MessageChannel();
  private readonly errorListeners: Array<(e: unknown) => void> = [];
  constructor(private readonly api: Record<string, (r: number) => Promise<number>>) {}

  /** The script is in: the API is exposed (rpc.ts posts `ready`). */
  load(): void {
    expose(this.api, this.channel.port2 as unknown as Endpoint);
  }
  postMessage(message: unknown, transfer?: unknown[]): void {
    this.channel.port1.postMessage(message, (transfer ?? []) as never);
  }
  addEventListener(type: string, listener: unknown): void {
    if (type === 'error') this.errorListeners.push(listener as (e: unknown) => void);
    else this.channel.port1.addEventListener(type, listener as never);
  }
  start(): void {
    this.channel.port1.start();
  }
  terminate(): void {
    this.channel.port1.close();
    this.channel.port2.close();
  }
}

/** Lets the channel's messages through (macrotasks the fake timers do not hold). */
async function until(condition: () => boolean): Promise<void> {
  for (let i = 0; i < 200 && !condition(); i++) await new Promise((r) => setImmediate(r));
  expect(condition()).toBe(true);
}

async function flush(): Promise<void> {
  for (let i = 0; i < 20; i++) await new Promise((r) => setImmediate(r));
}

function clientOf(worker: LoadingWorker) {
  const replies: number[] = [];
  const restarts: RestartInfo[] = [];
  const workers: LoadingWorker[] = [];
  const c = new JobClient<number, number>({
    createWorker: () => {
      workers.push(worker);
      return worker;
    },
    call: (api, r) => (api as unknown as { solve(r: number): Promise<number> }).solve(r),
    same: (a, b) => a === b,
    onReply: (reply) => replies.push(reply),
    onRestart: (info) => restarts.push(info),
    watchdogMs: WATCHDOG_MS,
    loadWatchdogMs: LOAD_WATCHDOG_MS,
  });
  return { c, replies, restarts, workers };
}

beforeEach(() => {
  vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout'] });
});
afterEach(() => {
  vi.useRealTimers();
});

describe('the watchdog does not count loading as a stall', () => {
  it('a first script loading for 20 watchdog periods is waited for, then answers', async () => {
    const worker = new LoadingWorker({ solve: async (r) => r * 2 });
    const { c, replies, restarts } = clientOf(worker);
    c.request(21);
    vi.advanceTimersByTime(20 * WATCHDOG_MS);
    await flush();
    expect(restarts).toEqual([]);
    worker.load();
    await until(() => replies.length === 1);
    expect(replies).toEqual([42]);
    expect(restarts).toEqual([]);
    c.dispose();
  });

  it('a job module imported lazily for 20 watchdog periods is waited for; once loaded, a stall restarts', async () => {
    let finishLoad: (m: { twice(r: number): number }) => void = () => {};
    const module = lazyModule(() => new Promise<{ twice(r: number): number }>((resolve) => (finishLoad = resolve)));
    let hang = false;
    const worker = new LoadingWorker({
      solve: async (r) => {
        const m = await module();
        return hang ? new Promise<number>(() => {}) : m.twice(r);
      },
    });
    worker.load();
    const { c, replies, restarts } = clientOf(worker);
    c.request(5);
    await flush(); // the call arrived and the load began (the worker said so)
    vi.advanceTimersByTime(20 * WATCHDOG_MS);
    await flush();
    expect(restarts).toEqual([]);
    finishLoad({ twice: (r) => 2 * r });
    await until(() => replies.length === 1);
    expect(replies).toEqual([10]);
    // Loaded: a call that hangs is a stall again.
    hang = true;
    c.request(6);
    await flush();
    vi.advanceTimersByTime(WATCHDOG_MS + 1);
    await until(() => restarts.length === 1);
    expect(restarts[0]?.reason).toBe('the solver stopped answering');
    c.dispose();
  });

  it("a restarted worker's script load counts (cached): one that never says ready is restarted as stuck", async () => {
    const first = new LoadingWorker({ solve: () => new Promise<number>(() => {}) });
    first.load();
    const later: LoadingWorker[] = [];
    const restarts: RestartInfo[] = [];
    const c = new JobClient<number, number>({
      createWorker: () => {
        if (later.length === 0 && restarts.length === 0) {
          later.push(first);
          return first;
        }
        const w = new LoadingWorker({ solve: async (r) => r }); // never exposed: never ready
        later.push(w);
        return w;
      },
      call: (api, r) => (api as unknown as { solve(r: number): Promise<number> }).solve(r),
      same: (a, b) => a === b,
      onReply: () => {},
      onRestart: (info) => restarts.push(info),
      watchdogMs: WATCHDOG_MS,
      loadWatchdogMs: LOAD_WATCHDOG_MS,
    });
    c.request(1);
    await flush(); // the first worker is ready, and its call hangs
    vi.advanceTimersByTime(WATCHDOG_MS + 1);
    await until(() => restarts.length === 1);
    vi.advanceTimersByTime(WATCHDOG_MS + 1); // the restarted worker never says ready
    await until(() => restarts.length === 2);
    expect(restarts.map((r) => r.reason)).toEqual(['the solver stopped answering', 'the solver stopped answering']);
    c.dispose();
  });

  it('a script that never loads is restarted after the load limit, named so', async () => {
    const worker = new LoadingWorker({ solve: async (r) => r });
    const { c, restarts } = clientOf(worker);
    c.request(1);
    vi.advanceTimersByTime(LOAD_WATCHDOG_MS - 1);
    await flush();
    expect(restarts).toEqual([]);
    vi.advanceTimersByTime(2);
    await until(() => restarts.length >= 1);
    expect(restarts[0]?.reason).toBe('the solver did not load');
    c.dispose();
  });
});
