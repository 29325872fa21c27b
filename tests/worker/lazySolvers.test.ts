/**
 * The worker loads the doubly curved, three-axis and registry solvers only when such a question is
 * asked (issue 27 point 2, the worker's half), seen at run time: the worker's API exposed on a
 * channel announces each lazily imported job module (rpc.ts lazyModule, which the watchdog reads);
 * a plane's and a cylinder's questions announce nothing, the first other question announces one
 * load of the page job, and later ones none (loaded once). The static side (what the first script
 * imports) is tests/build/firstResult.test.ts's.
 */
import { describe, expect, it, vi } from 'vitest';
import type { Endpoint, LoadMessage } from '../../src/worker/rpc';
import type { WorkerApi } from '../../src/worker/workerApi';

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 0 };

describe("the worker's solvers beyond the plane and the cylinders load on first use", () => {
  it('no load for a plane or a cylinder; one for the first doubly curved question; none after', async () => {
    // Fresh modules: the Node project shares modules between files (isolate: false), and another
    // file may have loaded the lazily imported jobs already (then nothing would announce a load).
    vi.resetModules();
    const { forwardInput } = await import('../../src/core/input/validate');
    const { expose, wrap } = await import('../../src/worker/rpc');
    const { workerApi } = await import('../../src/worker/workerApi');
    const channel = new MessageChannel();
    const loads: LoadMessage[] = [];
    channel.port1.addEventListener('message', (e) => {
      const data = (e as MessageEvent).data as { rpc?: string };
      if (data.rpc === 'loading') loads.push(data as LoadMessage);
    });
    const api = wrap<WorkerApi>(channel.port1 as unknown as Endpoint);
    expose(workerApi, channel.port2 as unknown as Endpoint);
    const plane = await api.solve({ mode: 'forward', input: forwardInput(TOOL, 'one-way', 0.01) });
    const cylinder = await api.solve({
      mode: 'forward',
      input: forwardInput(TOOL, 'one-way', 0.01, { kind: 'cylinder', radiusMm: 50, axis: 'feed' }),
    });
    expect([plane.ok, cylinder.ok]).toEqual([true, true]);
    expect(loads).toEqual([]);
    const curved = {
      mode: 'curved-forward',
      input: { ...TOOL, pattern: 'one-way', feedRadiusMm: 40, crossRadiusMm: -200, scallopHeightMm: 0.01 },
    } as const;
    expect((await api.solve(curved)).ok).toBe(true);
    expect(loads).toEqual([
      { rpc: 'loading', on: true },
      { rpc: 'loading', on: false },
    ]);
    const question = {
      mode: 'question',
      input: {
        tool: { toolRadiusMm: 3, cornerRadiusMm: 1 },
        mode: { kind: 'threeAxis', slopeDeg: 30, passes: 'raster', rasterAngleDeg: 20 },
        surface: { kind: 'plane' },
        pattern: 'one-way',
        target: { quantity: 'h', mm: 0.01 },
      },
    } as const;
    expect((await api.solve(question)).ok).toBe(true);
    expect(loads).toHaveLength(2);
    channel.port1.close();
  });
});
