/**
 * The worker's doubly curved and three-axis jobs take their exact answer through the registries
 * (issue 27 point 3: every surface through its SurfaceModel, a machine mode a posture supplier):
 * the model the surface registry holds for the kind, at the posture the mode registry's mode
 * supplies. Each test replaces one registered method for a moment (a spy returning a marked
 * number) and finds the mark in the job's reply: a job with its own solver call would not see it.
 */
import { afterEach, describe, expect, it, vi } from 'vitest';
import { doublyCurvedSolver, inverseWith } from '../../src/core/surfaces/doublyCurved';
import { findMode } from '../../src/core/surfaces/modes';
import { findSurfaceModel } from '../../src/core/surfaces/registry';
import { solvePage } from '../../src/worker/jobs/page';
import type { CurvedReply, CurvedRequest, ThreeAxisReply, ThreeAxisRequest } from '../../src/worker/pageProtocol';
import { bruteForceCylinder } from '../support/cylinderBruteForce';

/** A number no solver gives here (mm or degrees), to find in a reply. */
const MARK = 0.123456789;

/** A tool at a five-axis posture over a saddle point (Rf convex, Rc concave), mm and degrees. */
const POINT = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 5 } as const;
const SADDLE = { ...POINT, pattern: 'one-way', feedRadiusMm: 40, crossRadiusMm: -200 } as const;

const SLOPE = { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 40 } as const;

function curved(request: CurvedRequest): Extract<CurvedReply, { ok: true }> {
  const reply = solvePage(request) as CurvedReply;
  if (!reply.ok) throw new Error(JSON.stringify(reply.errors));
  return reply;
}

function threeAxis(request: ThreeAxisRequest): Extract<ThreeAxisReply, { ok: true }> {
  const reply = solvePage(request) as ThreeAxisReply;
  if (!reply.ok) throw new Error(JSON.stringify(reply.errors));
  return reply;
}

function registered(kind: string) {
  const model = findSurfaceModel(kind);
  if (model === null) throw new Error(`no ${kind} model`);
  return model;
}

afterEach(() => {
  vi.restoreAllMocks();
});

describe("the doubly curved job answers by the registry's doubly curved model", () => {
  it('forward: the step-over is the registered forward, the limits the registered limits', () => {
    const model = registered('doublyCurved');
    const forward = model.forward.bind(model);
    const limits = model.limits.bind(model);
    vi.spyOn(model, 'forward').mockImplementation((input) => ({ ...forward(input), intervalMm: MARK }));
    vi.spyOn(model, 'limits').mockImplementation((tool, surface) => ({ ...limits(tool, surface), limitMm: MARK }));
    const reply = curved({ mode: 'curved-forward', input: { ...SADDLE, scallopHeightMm: 0.01 } });
    expect([reply.exact.intervalMm, reply.exact.limits.limitMm]).toEqual([MARK, MARK]);
    // The comparison rows measure their deviations from the registered forward too.
    const row = reply.comparison?.corrected.redonnet;
    if (row === undefined || !row.ok) throw new Error('a corrected row');
    expect(row.deviationMm).toBe(row.intervalMm - MARK);
  });

  it('inverse: the cusps are the registered inverse, at the five-axis posture', () => {
    const model = registered('doublyCurved');
    const inverse = model.inverse.bind(model);
    const spy = vi.spyOn(model, 'inverse').mockImplementation((input) => ({ ...inverse(input), cuspHeightMm: MARK }));
    const posture = vi.spyOn(findMode('fiveAxis') as NonNullable<ReturnType<typeof findMode>>, 'posture');
    const reply = curved({ mode: 'curved-inverse', input: { ...SADDLE, intervalMm: 1 } });
    expect(reply.exact.cuspHeightMm).toBe(MARK);
    expect(posture).toHaveBeenCalled();
    for (const [mode] of posture.mock.calls) expect(mode).toMatchObject({ leadAngleDeg: 10, tiltAngleDeg: 5 });
    expect(spy.mock.calls[0]?.[0]).toMatchObject({ leadAngleDeg: 10, tiltAngleDeg: 5, intervalMm: 1 });
  });
});

describe('a doubly curved request with a straight radius is answered by the cylinder the model names', () => {
  it("its cusp is the cylinder's (a brute force agrees), not the point's own solver's above its flank limit", () => {
    // Found by the seeded random requests of this change: Rf straight is the cylinder along the feed
    // with Rs = Rc (models/doublyCurved.ts straightSurface), which the job now asks; the point's own
    // solver, which the job called before, gave a cusp of 2.57 mm here, above its own 1.46 mm limit
    // (its ray read the flank's far side: equatorFlank.ts heightAtMm, since fixed, and it agrees now).
    const tool = { toolRadiusMm: 2.33, cornerRadiusMm: 0.63, leadAngleDeg: 74.35, tiltAngleDeg: 0 };
    const point = {
      ...tool,
      pattern: 'one-way',
      feedRadiusMm: Number.NEGATIVE_INFINITY,
      crossRadiusMm: 1.217,
    } as const;
    const L = 1.6545;
    const reply = curved({ mode: 'curved-inverse', input: { ...point, intervalMm: L } });
    const brute = bruteForceCylinder(tool, 'one-way', 1.217, 'feed', L, { spacingMm: 0.01, bins: 800 });
    const own = inverseWith(doublyCurvedSolver(point, point), 'one-way', L).cuspHeightMm;
    expect(reply.exact.cuspHeightMm).toBeLessThan(reply.exact.limits.limitMm);
    expect(Math.abs(reply.exact.cuspHeightMm - (brute.cuspHeightsMm[0] as number))).toBeLessThan(brute.boundMm);
    expect(own).toBeLessThan(reply.exact.limits.limitMm);
    expect(Math.abs(own - (brute.cuspHeightsMm[0] as number))).toBeLessThan(brute.boundMm);
  });
});

describe("the three-axis job answers a sloped plane by the plane's model at the three-axis mode's posture", () => {
  it("forward: L is the plane model's, the lead and tilt the mode's posture, Lxy follows L", () => {
    const mode = findMode('threeAxis') as NonNullable<ReturnType<typeof findMode>>;
    const posture = mode.posture.bind(mode);
    vi.spyOn(mode, 'posture').mockImplementation((m, pattern) => ({ ...posture(m, pattern), leadAngleDeg: MARK }));
    const plane = registered('plane');
    const forward = plane.forward.bind(plane);
    const spy = vi.spyOn(plane, 'forward').mockImplementation((input) => ({ ...forward(input), intervalMm: 2 }));
    const reply = threeAxis({ mode: 'three-axis', input: { surface: 'plane', case: SLOPE, quantity: 'h', mm: 0.01 } });
    expect([reply.answer.intervalMm, reply.answer.leadDeg]).toEqual([2, MARK]);
    expect(spy.mock.calls[0]?.[0]).toMatchObject({
      leadAngleDeg: MARK,
      pattern: 'one-way',
      surface: { kind: 'plane' },
    });
    // Lxy = L D, D = sqrt(cos^2 psi + cos^2 alpha sin^2 psi) (threeAxis/slopePosture.ts).
    const rad = Math.PI / 180;
    const d = Math.sqrt(Math.cos(40 * rad) ** 2 + (Math.cos(30 * rad) * Math.sin(40 * rad)) ** 2);
    expect(reply.answer.horizontalStepMm).toBeCloseTo(2 * d, 12);
  });

  it("inverse (waterline, a step-down): the cusp is the plane model's inverse at L = dz / sin alpha", () => {
    const plane = registered('plane');
    const inverse = plane.inverse.bind(plane);
    const spy = vi.spyOn(plane, 'inverse').mockImplementation((input) => ({ ...inverse(input), cuspHeightMm: MARK }));
    const waterline = { ...SLOPE, passes: 'waterline', rasterAngleDeg: 90 } as const;
    const reply = threeAxis({
      mode: 'three-axis',
      input: { surface: 'plane', case: waterline, quantity: 'stepDown', mm: 0.5 },
    });
    expect(reply.answer.cuspHeightMm).toBe(MARK);
    expect(spy.mock.calls[0]?.[0].intervalMm).toBeCloseTo(0.5 / Math.sin(Math.PI / 6), 12);
  });
});
