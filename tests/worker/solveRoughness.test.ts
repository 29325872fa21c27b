/** `solve` replies carry the roughness at the exact step-over; a target Ra is a request of its own. */
import { describe, expect, it } from 'vitest';
import {
  exactForward,
  exactInverse,
  exactRoughness,
  exactRoughnessAtInterval,
  forwardInput,
  inverseInput,
  type ToolInput,
} from '../../src/core/index';
import { forwardOfRaTarget, validateRaTarget } from '../../src/core/roughness/raTarget';
import { solve, teach } from '../../src/worker/api';
import { type SolveRequest, sameRequest } from '../../src/worker/protocol';

const TOOL: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };

function raRequest(ra: number): SolveRequest {
  const v = validateRaTarget({ R: 3, Rcr: 1, rho: 5, ra });
  if (!v.ok) throw new Error(v.errors[0]?.message);
  return { mode: 'ra', input: v.value };
}

describe('roughness in the solve reply', () => {
  it('forward: Rz, Ra, Rq of the exact surface and the rule of thumb with its error, all finite', () => {
    const input = forwardInput(TOOL, 'one-way', 0.05);
    const reply = solve({ mode: 'forward', input });
    if (!reply.ok) throw new Error('expected a solution');
    const r = exactRoughness(input);
    expect(reply.roughness.raMm).toBe(r.raMm);
    expect(reply.roughness.rzMm).toBe(r.rzMm);
    expect(reply.roughness.rqMm).toBe(r.rqMm);
    expect(reply.roughness.ruleOfThumbRaMm).toBe(0.0125);
    expect(reply.roughness.ruleErrorPercent).toBeCloseTo((100 * (0.0125 - r.raMm)) / r.raMm, 10);
    for (const v of Object.values(reply.roughness)) expect(Number.isFinite(v)).toBe(true);
    expect(reply.roughness.raMm).toBeCloseTo(0.012417, 6); // the README's figure
  });

  it('inverse: the roughness of the surface the given step-over leaves', () => {
    const input = inverseInput(TOOL, 'zigzag', 2.5);
    const reply = solve({ mode: 'inverse', input });
    if (!reply.ok) throw new Error('expected a solution');
    expect(reply.roughness.raMm).toBe(exactRoughnessAtInterval(TOOL, 'zigzag', exactInverse(input)).raMm);
    expect(reply.roughness.scallopHeightMm).toBe(reply.exact.cuspHeightMm);
  });

  it('target Ra: the reply echoes it, its step-over is that of the solved h, and its Ra is the target', () => {
    const request = raRequest(0.0125);
    const reply = solve(request);
    if (!reply.ok) throw new Error('expected a solution');
    expect(reply.request).toBe(request);
    expect(Math.abs(reply.roughness.raMm - 0.0125)).toBeLessThan(1e-12);
    if (request.mode !== 'ra') throw new Error('ra request');
    const f = forwardOfRaTarget(request.input);
    expect(reply.exact.intervalMm).toBe(exactForward(f).intervalMm);
    expect(reply.roughness.scallopHeightMm).toBe(f.scallopHeightMm);
    const t = teach(request);
    expect(t.ok && t.forward.scallopHeightMm).toBe(f.scallopHeightMm);
  });

  it('a target Ra request equals only the same target; the worker rejects an Ra beyond the maximum', () => {
    expect(sameRequest(raRequest(0.01), raRequest(0.01))).toBe(true);
    expect(sameRequest(raRequest(0.01), raRequest(0.011))).toBe(false);
    expect(sameRequest(raRequest(0.01), { mode: 'forward', input: forwardInput(TOOL, 'one-way', 0.01) })).toBe(false);
    const request = raRequest(0.01);
    if (request.mode !== 'ra') throw new Error('ra request');
    const beyond: SolveRequest = { mode: 'ra', input: { ...request.input, targetRaMm: 5 } };
    const reply = solve(beyond);
    expect(reply.ok).toBe(false);
    expect(reply.request).toBe(beyond);
    if (!reply.ok) expect(reply.errors.map((e) => e.code)).toEqual(['beyond-max-ra']);
  });
});
