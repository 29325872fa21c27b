/**
 * Test and benchmark probe, built only into the instrumented site (`vite build --mode e2e`, which
 * the browser tests and `npm run bench:web` use); the production build contains none of it.
 * Exposes `window.__pathInterval`: frames drawn, software rendering, input-to-frame latencies
 * (from each input event to the first frame that answers it), the time of the first result, the
 * active teaching view and the solver workers started; and, so that a test can await an event
 * instead of sleeping, the calls sent to and the replies received from each named worker and the
 * writes of the URL.
 */
import type { SceneFraming } from '../render/scene';
import { type AppObserver, CalculatorApp } from './app';

export interface Probe {
  frames(): number;
  softwareRendering(): boolean;
  latencies(): number[];
  /** The same, from the time stamp of the pointer event behind each input (when the browser got it). */
  pointerLatencies(): number[];
  firstResultMs(): number | null;
  activeView(): string | null;
  workerStarts(): number;
  /** Replies (results or errors) received so far from the workers of this name (workers.ts). */
  replies(worker: string): number;
  /** Calls sent to the live workers of this name (of any name if none) still without a reply (0: idle). */
  pending(worker?: string): number;
  /** Calls posted so far to the workers of this name (restarted ones included). */
  calls(worker: string): number;
  /** Requests the page built so far (app.ts: once per input). */
  requestsBuilt(): number;
  /** URL writes so far (history.replaceState calls: urlState.ts writes once the inputs settle). */
  urlWrites(): number;
  /** The 3D scene's camera and what it frames (null before the scene is built). */
  sceneFraming(): SceneFraming | null;
}

/** rpc.ts messages: a call from the page, and the worker's final answer to one (not progress). */
const isCall = (data: unknown) => (data as { rpc?: unknown } | null)?.rpc === 'call';
const isReply = (data: unknown) => ['ok', 'error'].includes((data as { rpc?: unknown } | null)?.rpc as string);

/**
 * Counts, per worker name, the calls posted to each worker and its replies, by replacing the
 * global Worker with a subclass before the page starts any (the page's own listeners run after
 * the counter's, in the same task). A terminated worker's unanswered calls no longer count.
 */
function countWorkerMessages(): Pick<Probe, 'replies' | 'pending' | 'calls'> {
  const replies = new Map<string, number>();
  const calls = new Map<string, number>();
  const live = new Map<string, Set<{ pending: number }>>();
  const NativeWorker = window.Worker;
  class CountedWorker extends NativeWorker {
    private readonly count = { pending: 0 };
    private readonly workerName: string;
    constructor(url: string | URL, options?: WorkerOptions) {
      super(url, options);
      const name = options?.name ?? '';
      this.workerName = name;
      const mine = live.get(name) ?? new Set();
      live.set(name, mine.add(this.count));
      this.addEventListener('message', (e) => {
        if (!isReply(e.data)) return;
        this.count.pending = Math.max(0, this.count.pending - 1);
        replies.set(name, (replies.get(name) ?? 0) + 1);
      });
    }
    override postMessage(message: unknown, options?: Transferable[] | StructuredSerializeOptions): void {
      if (isCall(message)) {
        this.count.pending++;
        calls.set(this.workerName, (calls.get(this.workerName) ?? 0) + 1);
      }
      super.postMessage(message, options as Transferable[]);
    }
    override terminate(): void {
      live.get(this.workerName)?.delete(this.count);
      super.terminate();
    }
  }
  window.Worker = CountedWorker;
  return {
    replies: (name) => replies.get(name) ?? 0,
    calls: (name) => calls.get(name) ?? 0,
    pending: (name) =>
      [...live.entries()]
        .filter(([n]) => name === undefined || n === name)
        .flatMap(([, counts]) => [...counts])
        .reduce((n, c) => n + c.pending, 0),
  };
}

/** Counts the URL writes (history.replaceState calls). */
function countUrlWrites(): () => number {
  let writes = 0;
  const replace = history.replaceState.bind(history);
  history.replaceState = (...args: Parameters<History['replaceState']>) => {
    writes++;
    replace(...args);
  };
  return () => writes;
}

export function startWithProbe(root: HTMLElement): void {
  const workerMessages = countWorkerMessages();
  const urlWrites = countUrlWrites();
  const latencies: number[] = [];
  const pointerLatencies: number[] = [];
  let pendingInputAt: number | null = null;
  let pendingPointerAt: number | null = null;
  /** Time stamp of the latest pointer event (raw updates included): where a drag's input began. */
  let pointerAt: number | null = null;
  const onPointer = (e: Event) => {
    pointerAt = e.timeStamp;
  };
  for (const type of ['pointerdown', 'pointermove', 'pointerrawupdate']) window.addEventListener(type, onPointer, true);
  let firstResultMs: number | null = null;
  // Capture phase: the time of the event, before the page's own handler runs.
  window.addEventListener(
    'input',
    () => {
      pendingInputAt = performance.now();
      // A pointer event within the last 100 ms caused this input (keys leave none).
      pendingPointerAt = pointerAt !== null && pendingInputAt - pointerAt < 100 ? pointerAt : null;
    },
    true,
  );
  window.addEventListener(
    'change',
    () => {
      pendingInputAt = performance.now();
      pendingPointerAt = null;
    },
    true,
  );
  let requestsBuilt = 0;
  const observer: AppObserver = {
    built() {
      requestsBuilt++;
    },
    resultShown() {
      firstResultMs ??= performance.now();
    },
    frame(current) {
      if (current && pendingInputAt !== null) {
        const now = performance.now();
        latencies.push(now - pendingInputAt);
        if (pendingPointerAt !== null) pointerLatencies.push(now - pendingPointerAt);
        pendingInputAt = null;
        pendingPointerAt = null;
      }
    },
  };
  const app = new CalculatorApp(root, observer);
  const d = app.diagnostics;
  const probe: Probe = {
    frames: d.frames,
    softwareRendering: d.softwareRendering,
    latencies: () => [...latencies],
    pointerLatencies: () => [...pointerLatencies],
    firstResultMs: () => firstResultMs,
    activeView: d.activeView,
    workerStarts: d.workerStarts,
    sceneFraming: d.sceneFraming,
    requestsBuilt: () => requestsBuilt,
    ...workerMessages,
    urlWrites,
  };
  (window as unknown as { __pathInterval: Probe }).__pathInterval = probe;
}
