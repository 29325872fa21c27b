/** Calls across the worker boundary (src/worker/rpc.ts), over a real MessageChannel. */
import { afterEach, describe, expect, it } from 'vitest';
import { type Endpoint, expose, transfer, wrap } from '../../src/worker/rpc';

const channels: InstanceType<typeof MessageChannel>[] = [];
afterEach(() => {
  for (const c of channels.splice(0)) {
    c.port1.close();
    c.port2.close();
  }
});

function connect<Api extends Record<string, (...args: never[]) => unknown>>(api: Api) {
  const channel = new MessageChannel();
  channels.push(channel);
  expose(api, channel.port2 as unknown as Endpoint);
  return wrap<Api>(channel.port1 as unknown as Endpoint);
}

describe('rpc', () => {
  it('calls a method with plain data and resolves with its (awaited) result', async () => {
    const remote = connect({
      add: (a: number, b: number) => a + b,
      later: async (s: { text: string }) => ({ echoed: s.text.toUpperCase() }),
    });
    expect(await remote.add(2, 3)).toBe(5);
    expect(await remote.later({ text: 'ok' })).toEqual({ echoed: 'OK' });
    // Calls in flight at once each get their own answer.
    expect(await Promise.all([remote.add(1, 1), remote.add(2, 2), remote.add(3, 3)])).toEqual([2, 4, 6]);
  });

  it('a throw in the worker rejects with its message; an unknown method rejects', async () => {
    const remote = connect({
      fail: () => {
        throw new Error('h must be a number');
      },
    });
    await expect(remote.fail()).rejects.toThrow('h must be a number');
    await expect((remote as unknown as Record<string, () => Promise<unknown>>).nothing?.()).rejects.toThrow(
      'no method nothing',
    );
  });

  it('a trailing function becomes a progress callback, called before the answer', async () => {
    const remote = connect({
      run: async (steps: number, onProgress?: (f: number) => void) => {
        for (let i = 1; i <= steps; i++) onProgress?.(i / steps);
        return 'done';
      },
    });
    const seen: number[] = [];
    expect(await remote.run(4, (f: number) => seen.push(f))).toBe('done');
    expect(seen).toEqual([0.25, 0.5, 0.75, 1]);
    expect(await remote.run(2)).toBe('done'); // without a callback
  });

  it('transfers the buffers a reply marks (the worker keeps none), and copies the others', async () => {
    const kept: ArrayBuffer[] = [];
    const remote = connect({
      arrays: (moved: boolean) => {
        const a = new Float64Array([1, 2, 3]);
        kept.push(a.buffer);
        const reply = { a };
        return moved ? transfer(reply, [a.buffer]) : reply;
      },
    });
    const moved = await remote.arrays(true);
    expect([...moved.a]).toEqual([1, 2, 3]);
    expect(kept[0]?.byteLength).toBe(0); // detached: moved, not copied
    const copied = await remote.arrays(false);
    expect([...copied.a]).toEqual([1, 2, 3]);
    expect(kept[1]?.byteLength).toBe(24);
  });

  it('the remote is not a thenable (awaiting it does not call the worker)', async () => {
    // Even when the worker exposes a function of that name.
    const remote = connect(Object.fromEntries([['then', () => 'called']]) as Record<string, () => string>);
    expect((remote as unknown as { then?: unknown }).then).toBeUndefined();
    expect(await Promise.resolve(remote)).toBe(remote);
  });
});
