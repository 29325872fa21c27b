/** The `simulate` job in Node: finite numbers, the request echoed, cancellation, progress. */
import { describe, expect, it } from 'vitest';
import { exactForward, exactRoughness, forwardInput, inverseInput, type ToolInput } from '../../src/core/index';
import { forwardOfRaTarget, validateRaTarget } from '../../src/core/roughness/raTarget';
import type { SolveRequest } from '../../src/worker/protocol';
import { type SimulateReply, SimulationRunner, simulate, simulationTransferables } from '../../src/worker/simulate';

const TOOL: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const fwd = (h: number, tool: ToolInput = TOOL, pattern: 'one-way' | 'zigzag' = 'one-way'): SolveRequest => ({
  mode: 'forward',
  input: forwardInput(tool, pattern, h),
});

function ok(reply: SimulateReply): Extract<SimulateReply, { ok: true }> {
  if (!reply.ok) throw new Error(`expected a simulation, got ${reply.reason ?? reply.errors[0]?.message}`);
  return reply;
}

function expectFinite(values: Iterable<number>, what: string): void {
  let n = 0;
  for (const v of values) {
    if (!Number.isFinite(v)) throw new Error(`${what}[${n}] = ${v}`);
    n++;
  }
  expect(n, what).toBeGreaterThan(0);
}

describe('worker simulate job', () => {
  it('simulates the exact step-over: echoes its request, finite numbers everywhere, cusp within the bound', async () => {
    const request = fwd(0.05);
    const reply = ok(await simulate(request, { cells: 256 }));
    expect(reply.request).toBe(request);
    const s = reply.simulation;
    const e = exactForward(forwardInput(TOOL, 'one-way', 0.05));
    expect(reply.exact.intervalMm).toBe(e.intervalMm);
    expect(reply.exact.cuspHeightMm).toBe(e.cuspHeightMm);
    expect(reply.exact.roughness).toEqual(exactRoughness(forwardInput(TOOL, 'one-way', 0.05)));
    expectFinite(s.heightsMm, 'heightsMm');
    expect(s.heightsMm.length).toBe(256 * 256);
    expectFinite(s.trace, 'trace');
    expectFinite(s.cuspHeightsMm, 'cuspHeightsMm');
    expectFinite(
      [
        s.cuspHeightMm,
        s.resolutionBoundMm,
        s.roughnessBoundMm,
        s.acrossFromMm,
        s.acrossToMm,
        s.alongLengthMm,
        reply.ms,
      ],
      'scalars',
    );
    expectFinite(Object.values(s.roughness), 'roughness');
    expect(s.passes).toBe(5);
    expect(s.resolutionBoundMm).toBeGreaterThan(0);
    expect(Math.abs(s.cuspHeightMm - e.cuspHeightMm)).toBeLessThanOrEqual(s.resolutionBoundMm);
    expect(Math.abs(s.roughness.raMm - reply.exact.roughness.raMm)).toBeLessThanOrEqual(s.roughnessBoundMm);
    // Both large arrays are transferred, not copied.
    expect(simulationTransferables(reply)).toEqual([s.heightsMm.buffer, s.trace.buffer]);
  });

  it('a target Ra simulates the step-over of the h that leaves it; inverse simulates the given L; zigzag 4 passes', async () => {
    const v = validateRaTarget({ R: 3, Rcr: 1, rho: 5, ra: 0.01 });
    if (!v.ok) throw new Error('valid Ra');
    const ra = ok(await simulate({ mode: 'ra', input: v.value }, { cells: 128 }));
    expect(ra.exact.intervalMm).toBe(exactForward(forwardOfRaTarget(v.value)).intervalMm);
    expect(ra.exact.roughness.raMm).toBeCloseTo(0.01, 10);
    const inv = ok(await simulate({ mode: 'inverse', input: inverseInput(TOOL, 'one-way', 2.5) }, { cells: 128 }));
    expect(inv.exact.intervalMm).toBe(2.5);
    const zz = ok(await simulate(fwd(0.05, { ...TOOL, tiltAngleDeg: 4 }, 'zigzag'), { cells: 128 }));
    expect(zz.simulation.passes).toBe(4);
    expect(Math.abs(zz.simulation.cuspHeightMm - zz.exact.cuspHeightMm)).toBeLessThanOrEqual(
      zz.simulation.resolutionBoundMm,
    );
  });

  it('is cancelled between steps when asked to stop, echoing its request; no arrays then', async () => {
    const request = fwd(0.05);
    let steps = 0;
    const reply = await simulate(request, {
      cells: 256,
      shouldStop: () => ++steps > 2,
      pause: async () => undefined,
    });
    expect(reply.ok).toBe(false);
    if (reply.ok) return;
    expect(reply.cancelled).toBe(true);
    expect(reply.request).toBe(request);
    expect(reply.reason).toBeNull();
    expect(simulationTransferables(reply)).toEqual([]);
    expect(steps).toBe(3);
  });

  it('the runner: a newer simulation or a cancel stops the running one (latest wins)', async () => {
    const runner = new SimulationRunner({ cells: 128, pause: () => new Promise((r) => setTimeout(r, 0)) });
    const first = runner.run(fwd(0.05));
    const second = runner.run(fwd(0.04));
    const [a, b] = await Promise.all([first, second]);
    expect(a.ok === false && a.cancelled).toBe(true);
    expect(ok(b).exact.cuspHeightMm).toBe(0.04);
    const third = runner.run(fwd(0.03));
    runner.cancel();
    const c = await third;
    expect(c.ok === false && c.cancelled).toBe(true);
    expect(ok(await runner.run(fwd(0.03))).exact.cuspHeightMm).toBe(0.03);
  });

  it('pauses between steps (a cancel message gets through) and reports progress once past a frame', async () => {
    const progress: number[] = [];
    let pauses = 0;
    ok(
      await simulate(fwd(0.05), {
        cells: 128,
        frameMs: 0,
        onProgress: (f) => progress.push(f),
        pause: async () => {
          pauses++;
        },
      }),
    );
    expect(pauses).toBeGreaterThan(3);
    expect(progress.length).toBe(pauses);
    expectFinite(progress, 'progress');
    for (let i = 1; i < progress.length; i++) expect(progress[i]).toBeGreaterThanOrEqual(progress[i - 1] as number);
    expect(Math.max(...progress)).toBeLessThan(1);
    // A short run reports none.
    const quiet: number[] = [];
    ok(await simulate(fwd(0.05), { cells: 32, frameMs: 1e9, onProgress: (f) => quiet.push(f) }));
    expect(quiet).toEqual([]);
  });

  it('invalid input, a cylinder and a flat surface get a reply with a reason or errors, never an exception', async () => {
    const bad = await simulate(fwd(0.05, { ...TOOL, cornerRadiusMm: 4 }));
    expect(bad.ok === false && bad.errors[0]?.field).toBe('Rcr');
    const cylinder: SolveRequest = {
      mode: 'forward',
      input: forwardInput(TOOL, 'one-way', 0.05, { kind: 'cylinder', radiusMm: 50, axis: 'feed' }),
    };
    const c = await simulate(cylinder);
    expect(c.ok === false && c.reason).toMatch(/planes only/);
    const flat = await simulate(fwd(0.05, { toolRadiusMm: 3, cornerRadiusMm: 0, leadAngleDeg: 0, tiltAngleDeg: 0 }));
    expect(flat.ok === false && flat.reason).toMatch(/No scallop/);
    // Each reason also as a code, for the page to word in its language (none with input errors).
    expect([bad, c, flat].map((r) => (r.ok ? 'ok' : (r.reasonCode ?? null)))).toEqual([
      null,
      'planes-only',
      'no-scallop',
    ]);
    for (const r of [bad, c, flat]) expect(r.ok === false && r.cancelled).toBe(false);
  });
});
