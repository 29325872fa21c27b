/**
 * Calls across the worker boundary: the worker exposes an object of functions (`expose`), the page
 * calls them as async methods (`wrap`). Plain data crosses, as structured clones; a reply's large
 * arrays are transferred when the worker marks them (`transfer`); one trailing function argument
 * becomes a progress callback the worker may call any number of times before it answers. An
 * exception in the worker rejects the page's promise with its message.
 *
 * The page needed only this of Comlink (2 kB gzip): a few lines of our own fit the JavaScript
 * budget and keep every message a plain object of a type written here.
 */

/** Objects moved to the other side instead of copied (ArrayBuffers, MessagePorts). */
export type TransferList = object[];

/** What both ends need of a channel: a Worker, a worker's global scope, or a MessagePort. */
export interface Endpoint {
  postMessage(message: unknown, transfer: TransferList): void;
  addEventListener(type: 'message', listener: (event: { readonly data: unknown }) => void): void;
  start?(): void;
}

type CallMessage = {
  readonly rpc: 'call';
  readonly id: number;
  readonly method: string;
  readonly args: readonly unknown[];
  /** The last argument was a function: the worker passes a progress callback in its place. */
  readonly progress: boolean;
};

type ReplyMessage =
  | { readonly rpc: 'ok'; readonly id: number; readonly value: unknown }
  | { readonly rpc: 'error'; readonly id: number; readonly message: string }
  | { readonly rpc: 'progress'; readonly id: number; readonly value: unknown };

/**
 * What the worker says of its own loading, outside any call (client.ts's watchdog reads it): `ready`
 * once its first module graph is loaded and it answers; `loading` while a lazily imported module of
 * a job loads (`on` true when it starts, false when it is in).
 */
export type LoadMessage = { readonly rpc: 'ready' } | { readonly rpc: 'loading'; readonly on: boolean };

/** True for a LoadMessage. */
export function isLoadMessage(data: unknown): data is LoadMessage {
  const rpc = (data as { rpc?: unknown } | null)?.rpc;
  return rpc === 'ready' || rpc === 'loading';
}

/** The endpoint `expose` answers on (one per worker), told of lazy loads (lazyModule). */
let exposedOn: Endpoint | null = null;

/**
 * A module loaded on first use (a dynamic import), once: the endpoint is told while it loads, so
 * that the page's watchdog does not count the load as a stall. Later calls get the loaded module.
 */
export function lazyModule<M>(load: () => Promise<M>): () => Promise<M> {
  let loaded: Promise<M> | null = null;
  return () => {
    if (loaded !== null) return loaded;
    const endpoint = exposedOn;
    endpoint?.postMessage({ rpc: 'loading', on: true } satisfies LoadMessage, []);
    const done = () => endpoint?.postMessage({ rpc: 'loading', on: false } satisfies LoadMessage, []);
    const pending = load().then(
      (module) => {
        done();
        return module;
      },
      (error: unknown) => {
        done();
        loaded = null; // a failed load is tried again on the next call
        throw error;
      },
    );
    loaded = pending;
    return pending;
  };
}

/** Any function of the exposed object (its arguments are plain data, and maybe a last callback). */
type Method = (...args: never[]) => unknown;

/** The page's view of an exposed object: each method returns a promise of its result. */
export type Remote<Api> = {
  readonly [K in keyof Api]: Api[K] extends (...args: infer A) => infer R ? (...args: A) => Promise<Awaited<R>> : never;
};

const transfers = new WeakMap<object, TransferList>();

/** Marks `value` (a reply) so that `list` (its arrays' buffers) is transferred, not copied. */
export function transfer<T extends object>(value: T, list: TransferList): T {
  transfers.set(value, list);
  return value;
}

/** Answers calls arriving on `endpoint` with the functions of `api` (the worker's side). */
export function expose(api: Readonly<Record<string, Method>>, endpoint: Endpoint): void {
  endpoint.addEventListener('message', async (event) => {
    const call = event.data as CallMessage;
    if (call?.rpc !== 'call') return;
    const reply = (message: ReplyMessage, list: TransferList = []) => endpoint.postMessage(message, list);
    try {
      const method = api[call.method];
      if (method === undefined) throw new Error(`no method ${call.method}`);
      const args = call.progress
        ? [...call.args, (value: unknown) => reply({ rpc: 'progress', id: call.id, value })]
        : call.args;
      const value = await (method as (...a: readonly unknown[]) => unknown)(...args);
      reply(
        { rpc: 'ok', id: call.id, value },
        (value !== null && typeof value === 'object' && transfers.get(value)) || [],
      );
    } catch (error) {
      reply({ rpc: 'error', id: call.id, message: error instanceof Error ? error.message : String(error) });
    }
  });
  endpoint.start?.();
  exposedOn = endpoint;
  // Exposed: the module graph that got here is loaded (the watchdog starts counting now).
  endpoint.postMessage({ rpc: 'ready' } satisfies LoadMessage, []);
}

/** Calls the functions exposed on `endpoint` (the page's side). */
export function wrap<Api>(endpoint: Endpoint): Remote<Api> {
  let nextId = 0;
  const pending = new Map<
    number,
    { resolve(value: unknown): void; reject(error: Error): void; progress: ((value: unknown) => void) | null }
  >();
  endpoint.addEventListener('message', (event) => {
    const m = event.data as ReplyMessage;
    const call = pending.get(m?.id);
    if (call === undefined) return;
    if (m.rpc === 'progress') call.progress?.(m.value);
    else {
      pending.delete(m.id);
      if (m.rpc === 'ok') call.resolve(m.value);
      else call.reject(new Error(m.message));
    }
  });
  endpoint.start?.();
  const method =
    (name: string) =>
    (...args: unknown[]) =>
      new Promise((resolve, reject) => {
        const id = nextId++;
        const last = args[args.length - 1];
        const progress = typeof last === 'function' ? (last as (value: unknown) => void) : null;
        pending.set(id, { resolve, reject, progress });
        const message: CallMessage = {
          rpc: 'call',
          id,
          method: name,
          args: progress === null ? args : args.slice(0, -1),
          progress: progress !== null,
        };
        endpoint.postMessage(message, []);
      });
  // Not a thenable: `then` is no method (awaiting the remote itself must not call the worker).
  return new Proxy({} as Remote<Api>, {
    get: (_target, name) => (typeof name === 'string' && name !== 'then' ? method(name) : undefined),
  });
}
