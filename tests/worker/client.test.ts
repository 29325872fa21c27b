/**
 * The page's worker client against a stand-in worker: a real rpc.ts endpoint (a MessageChannel)
 * whose `solve` and `teach` answer, throw, hang or die when the test says so.
 */
import { afterEach, describe, expect, it } from 'vitest';
import { JobClient, MAX_CONSECUTIVE_RESTARTS, type RestartInfo, type WorkerLike } from '../../src/worker/client';
import { type Endpoint, expose } from '../../src/worker/rpc';

type Req = { readonly n: number };
type Rep = { readonly answers: number; readonly job: string };

interface Call {
  readonly job: 'solve' | 'teach';
  readonly request: Req;
  readonly worker: number;
  answer(): void;
  fail(): void;
}

/** Stand-in workers: each started one is numbered; its calls wait until answered. */
class Workers {
  readonly calls: Call[] = [];
  readonly started: StandIn[] = [];
  /** What a new worker does with a call: wait for the test, throw at once, or die. */
  behaviour: 'wait' | 'throw' | 'die' = 'wait';
  /** How many of the next calls throw whatever the behaviour. */
  throwNext = 0;

  create = (): WorkerLike => {
    const w = new StandIn(this, this.started.length);
    this.started.push(w);
    return w;
  };

  /** Lets pending messages through. */
  async settle(): Promise<void> {
    for (let i = 0; i < 10; i++) await new Promise((r) => setTimeout(r, 1));
  }

  dispose(): void {
    for (const w of this.started) w.terminate();
  }
}

class StandIn implements WorkerLike {
  private readonly channel = new MessageChannel();
  private readonly errorListeners: Array<(e: unknown) => void> = [];
  terminated = false;

  constructor(workers: Workers, index: number) {
    const job =
      (name: 'solve' | 'teach') =>
      (request: Req): Promise<Rep> =>
        new Promise((resolve, reject) => {
          const call: Call = {
            job: name,
            request,
            worker: index,
            answer: () => resolve({ answers: request.n, job: name }),
            fail: () => reject(new Error('boom')),
          };
          workers.calls.push(call);
          if (workers.throwNext > 0) {
            workers.throwNext--;
            call.fail();
          } else if (workers.behaviour === 'throw') call.fail();
          if (workers.behaviour === 'die') setTimeout(() => this.die(), 0);
        });
    expose({ solve: job('solve'), teach: job('teach') }, this.channel.port2 as unknown as Endpoint);
  }

  postMessage(message: unknown, transfer?: unknown[]): void {
    if (!this.terminated) this.channel.port1.postMessage(message, (transfer ?? []) as never);
  }

  addEventListener(type: string, listener: unknown): void {
    if (type === 'error') this.errorListeners.push(listener as (e: unknown) => void);
    else this.channel.port1.addEventListener(type, listener as never);
  }

  removeEventListener(type: string, listener: unknown): void {
    this.channel.port1.removeEventListener(type, listener as never);
  }

  start(): void {
    this.channel.port1.start();
  }

  terminate(): void {
    this.terminated = true;
    this.channel.port1.close();
    this.channel.port2.close();
  }

  /** The worker dies: an error event, as a crashed module worker fires. */
  die(): void {
    for (const l of this.errorListeners) l({ message: 'worker crashed' });
  }
}

let workers = new Workers();
afterEach(() => {
  workers.dispose();
  workers = new Workers();
});

function client(job: 'solve' | 'teach', watchdogMs = 2000) {
  const replies: Rep[] = [];
  const restarts: RestartInfo[] = [];
  const c = new JobClient<Req, Rep>({
    createWorker: workers.create,
    call: (api, r) => (api as unknown as Record<string, (r: Req) => Promise<Rep>>)[job]?.(r) as Promise<Rep>,
    same: (a, b) => a.n === b.n,
    onReply: (reply) => replies.push(reply),
    onRestart: (info) => restarts.push(info),
    watchdogMs,
  });
  return { c, replies, restarts };
}

describe('worker client with a stand-in worker', () => {
  it('latest wins: requests made while one is in flight collapse to the newest, whose reply alone is delivered', async () => {
    const { c, replies } = client('solve');
    c.request({ n: 1 });
    c.request({ n: 2 });
    c.request({ n: 3 });
    await workers.settle();
    expect(workers.calls.map((x) => x.request.n)).toEqual([1]);
    workers.calls[0]?.answer();
    await workers.settle();
    // The reply to 1 is stale: dropped; 3 is sent (2 never is).
    expect(replies).toEqual([]);
    expect(workers.calls.map((x) => x.request.n)).toEqual([1, 3]);
    workers.calls[1]?.answer();
    await workers.settle();
    expect(replies).toEqual([{ answers: 3, job: 'solve' }]);
  });

  it('de-duplicates only against the reply still to come: the same request again after its reply is sent again (issue 17)', async () => {
    const { c, replies } = client('solve');
    c.request({ n: 1 });
    c.request({ n: 1 }); // awaited: nothing new to send
    await workers.settle();
    expect(workers.calls.map((x) => x.request.n)).toEqual([1]);
    expect(c.awaits({ n: 1 })).toBe(true);
    workers.calls[0]?.answer();
    await workers.settle();
    expect(replies.map((r) => r.answers)).toEqual([1]);
    expect(c.awaits({ n: 1 })).toBe(false);
    // The page may have dropped that reply (other inputs were on screen): asking again sends again.
    c.request({ n: 1 });
    await workers.settle();
    expect(workers.calls.map((x) => x.request.n)).toEqual([1, 1]);
    workers.calls[1]?.answer();
    await workers.settle();
    expect(replies.map((r) => r.answers)).toEqual([1, 1]);
  });

  it('stale replies dropped: a reply to an earlier request is never delivered once a newer one was made', async () => {
    const { c, replies } = client('solve');
    c.request({ n: 1 });
    await workers.settle();
    c.request({ n: 2 });
    workers.calls[0]?.answer();
    await workers.settle();
    expect(replies.map((r) => r.answers)).not.toContain(1);
    workers.calls[1]?.answer();
    await workers.settle();
    expect(replies.map((r) => r.answers)).toEqual([2]);
  });

  it('a restart repeats the last request with the same job (the views: teach, not solve), and says so', async () => {
    const { c, replies, restarts } = client('teach');
    c.request({ n: 1 });
    await workers.settle();
    c.request({ n: 2 }); // waiting behind 1 when the worker dies
    workers.started[0]?.die();
    await workers.settle();
    expect(restarts).toEqual([{ reason: 'the solver failed (worker crashed)', gaveUp: false, request: { n: 2 } }]);
    expect(workers.started).toHaveLength(2);
    const repeated = workers.calls.filter((x) => x.worker === 1);
    expect(repeated.map((x) => [x.job, x.request.n])).toEqual([['teach', 2]]);
    repeated[0]?.answer();
    await workers.settle();
    expect(replies).toEqual([{ answers: 2, job: 'teach' }]);
  });

  it('a worker that throws, or stays silent past the watchdog, is restarted and the request repeated', async () => {
    // A watchdog long enough that a loaded machine answers the last call before it fires again.
    const { c, replies, restarts } = client('solve', 300);
    workers.throwNext = 1;
    c.request({ n: 7 });
    await workers.settle();
    expect(restarts[0]?.reason).toMatch(/threw/);
    // The repeated call hangs: the watchdog restarts once more and repeats it again.
    await expect.poll(() => restarts.length, { timeout: 2000, interval: 5 }).toBe(2);
    expect(restarts[1]?.reason).toMatch(/stopped answering/);
    // The third call (on the third worker) arrives through its message channel.
    await expect.poll(() => workers.calls.length, { timeout: 2000, interval: 5 }).toBe(3);
    const last = workers.calls[workers.calls.length - 1];
    expect(last?.worker).toBe(2);
    expect(last?.request.n).toBe(7);
    last?.answer();
    await workers.settle();
    expect(replies.map((r) => r.answers)).toEqual([7]);
  });

  it('gives up after MAX_CONSECUTIVE_RESTARTS, says so, and tries afresh on the next request', async () => {
    const { c, replies, restarts } = client('solve');
    workers.behaviour = 'die';
    c.request({ n: 1 });
    for (let i = 0; i < 5; i++) await workers.settle();
    expect(restarts.map((r) => r.gaveUp)).toEqual([false, false, false, true]);
    expect(workers.started).toHaveLength(MAX_CONSECUTIVE_RESTARTS + 1);
    expect(replies).toEqual([]);
    // Nothing more is tried on its own...
    await workers.settle();
    expect(workers.started).toHaveLength(MAX_CONSECUTIVE_RESTARTS + 1);
    expect(restarts.at(-1)?.request).toEqual({ n: 1 });
    // ...until the next request, even the same one, which starts a new worker.
    workers.behaviour = 'wait';
    c.request({ n: 1 });
    await workers.settle();
    expect(workers.started).toHaveLength(MAX_CONSECUTIVE_RESTARTS + 2);
    workers.calls[workers.calls.length - 1]?.answer();
    await workers.settle();
    expect(replies.map((r) => r.answers)).toEqual([1]);
  });
});
