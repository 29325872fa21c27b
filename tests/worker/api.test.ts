import { describe, expect, it } from 'vitest';
import {
  compareForward,
  exactForward,
  exactHalfIntervalMm,
  exactInverse,
  exactScallopHeightMm,
  type ForwardInput,
  forwardInput,
  type InverseInput,
  inverseInput,
  type Surface,
  scallopHeightLimits,
  type ToolInput,
  validateForward,
} from '../../src/core/index';

const scallopHeightLimitMm = (t: ToolInput) => scallopHeightLimits(t).limitMm;

import { solve, teach, traceFrames, transferables } from '../../src/worker/api';
import { type SolveRequest, sameRequest } from '../../src/worker/protocol';
import { seededRandom } from '../support/bruteForce';
import { everyNumberFinite } from '../support/finite';

const TOOL: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const fwd = (input: ForwardInput): SolveRequest => ({ mode: 'forward', input });
const inv = (input: InverseInput): SolveRequest => ({ mode: 'inverse', input });
const tool = (over: Partial<ToolInput>): ToolInput => ({ ...TOOL, ...over });

describe('worker solver API (plain data in, plain data out)', () => {
  it('forward: rows match the solver core, each with the scallop its own L really leaves', () => {
    const request = fwd(forwardInput(TOOL, 'one-way', 0.05));
    const reply = solve(request);
    if (!reply.ok) throw new Error('expected a solution');
    expect(reply.request).toBe(request);
    const c = compareForward(forwardInput(TOOL, 'one-way', 0.05));
    expect(reply.exact.halfIntervalMm).toBe(c.exact.halfIntervalMm);
    expect(reply.exact.intervalMm).toBe(c.exact.intervalMm);
    const sekine = reply.rows.find((r) => r.key === 'sekine');
    const sek = c.approximations.sekine;
    if (!sek.ok || !sekine?.valueMm) throw new Error('sekine applicable here');
    expect(sekine.valueMm).toBe(sek.halfIntervalMm);
    expect(sekine.realScallopMm).toBe(exactScallopHeightMm(inverseInput(TOOL, 'one-way', 2 * sek.halfIntervalMm)));
    expect(reply.scene.toolPositions.length).toBeGreaterThan(0);
    // Every large array is listed for transfer, none twice.
    const buffers = transferables(reply);
    expect(new Set(buffers).size).toBe(buffers.length);
    const loops = (reply.scene.right?.loops.length ?? 0) + (reply.scene.left?.loops.length ?? 0);
    expect(buffers.length).toBe(1 + loops);
  });

  it('the table has every procedure of the registry, deviations of L/2 and in %', () => {
    const reply = solve(fwd(forwardInput(TOOL, 'one-way', 0.05)));
    if (!reply.ok) throw new Error('expected a solution');
    expect(reply.rows.map((r) => r.key)).toEqual(['exact', 'sekine', 'redonnet', 'bedi', 'osculating', 'cornerBall']);
    const c = compareForward(forwardInput(TOOL, 'one-way', 0.05));
    const osc = c.approximations.osculating;
    const row = reply.rows.find((r) => r.key === 'osculating');
    if (!osc.ok || !row) throw new Error('osculating applies here');
    expect(row.deviationMm).toBe(osc.halfIntervalMm - c.exact.halfIntervalMm);
    expect(row.deviationPercent).toBe(osc.deviationPercent);
  });

  it('forward: invalid input is a typed error reply echoing its request, not an exception', () => {
    const bad = fwd(forwardInput(tool({ cornerRadiusMm: 4 }), 'one-way', 0.05));
    const reply = solve(bad);
    expect(reply.ok).toBe(false);
    expect(reply.request).toBe(bad);
    if (!reply.ok) expect(reply.errors[0]?.field).toBe('Rcr');
    expect(solve(fwd(forwardInput(tool({ toolRadiusMm: Number.NaN }), 'one-way', 0.05))).ok).toBe(false);
    expect(teach(bad).ok).toBe(false);
  });

  it('an approximation whose L/2 reaches R leaves a wall, said as data for the page to word', () => {
    // Redonnet's circle at a steep-ish h on a small-corner tool overshoots R.
    const reply = solve(fwd(forwardInput(tool({ cornerRadiusMm: 0.2, leadAngleDeg: 2 }), 'one-way', 0.25)));
    if (!reply.ok) throw new Error('expected a solution');
    const red = reply.rows.find((r) => r.key === 'redonnet');
    expect(red?.valueMm).toBeGreaterThan(3);
    expect(red?.realScallopMm).toBeNull();
    expect(red?.note).toEqual({ kind: 'wall', intervalMm: 2 * (red?.valueMm ?? 0), maxIntervalMm: 6 });
  });

  it('an approximation beyond its own model says by how much, as numbers (mm), not words', () => {
    // The corner ball of Rcr = 0.2 cannot reach h = 0.25.
    const reply = solve(fwd(forwardInput(tool({ cornerRadiusMm: 0.2, leadAngleDeg: 2 }), 'one-way', 0.25)));
    if (!reply.ok) throw new Error('expected a solution');
    const ball = reply.rows.find((r) => r.key === 'cornerBall');
    expect(ball?.valueMm).toBeNull();
    expect(ball?.note).toEqual({ kind: 'beyond-model', shape: 'circle', quantity: 'h', valueMm: 0.25, limitMm: 0.2 });
    // At rho = 0 the paper's models have no answer: the core's reason, which holds no number.
    const flat = solve(fwd(forwardInput(tool({ leadAngleDeg: 0 }), 'one-way', 0.05)));
    if (!flat.ok) throw new Error('expected a solution');
    const sek = flat.rows.find((r) => r.key === 'sekine')?.note;
    expect(sek?.kind).toBe('reason');
    if (sek?.kind === 'reason') expect(sek.text).not.toMatch(/\d\s*mm/);
  });

  it('inverse: L is the full step-over; h = 0 on the flat bottom (rho = 0) has no cusp to draw', () => {
    const reply = solve(inv(inverseInput(TOOL, 'one-way', 2 * 1.443592412967)));
    if (!reply.ok) throw new Error('expected a solution');
    expect(Math.abs(reply.exact.cuspHeightMm - 0.05)).toBeLessThan(1e-9);
    const flat = solve(inv(inverseInput(tool({ leadAngleDeg: 0 }), 'one-way', 3)));
    if (!flat.ok) throw new Error('expected a solution');
    expect(flat.exact.cuspHeightMm).toBe(0);
    expect(flat.scene.right).toBeNull();
    expect(flat.scene.left).toBeNull();
    const views = teach(inv(inverseInput(tool({ leadAngleDeg: 0 }), 'one-way', 3)));
    expect(views.ok).toBe(false);
    if (!views.ok) expect(views.reason).toMatch(/No scallop/);
  });

  it('teaching models give each approximation its L/2 at the state h, in inverse mode too', () => {
    // Regression: the formulas view once read the inverse rows (heights) as L/2.
    const request = inv(inverseInput(TOOL, 'one-way', 3));
    const views = teach(request);
    if (!views.ok) throw new Error('expected teaching data');
    expect(views.request).toBe(request);
    const h = exactScallopHeightMm(inverseInput(TOOL, 'one-way', 3));
    expect(views.forward.scallopHeightMm).toBe(h);
    const c = compareForward(forwardInput(TOOL, 'one-way', h)).approximations;
    const m = views.models;
    if (!c.sekine.ok || !c.redonnet.ok || !c.bedi.ok || !c.osculating.ok) throw new Error('all apply here');
    expect(m.sekine?.halfIntervalMm).toBe(c.sekine.halfIntervalMm);
    expect(m.redonnet?.halfIntervalMm).toBe(c.redonnet.halfIntervalMm);
    expect(m.bedi?.halfIntervalMm).toBe(c.bedi.halfIntervalMm);
    expect(m.osculating?.halfIntervalMm).toBe(c.osculating.halfIntervalMm);
    expect(Math.abs(views.exact.intervalMm - 3)).toBeLessThan(1e-9);
  });

  it('with tilt: wR, wL and y0 of the core; one-way cusps at wR and -wL; sweeps along lead and tilt', () => {
    const t = tool({ tiltAngleDeg: 5 });
    const reply = solve(fwd(forwardInput(t, 'one-way', 0.05)));
    if (!reply.ok) throw new Error('expected a solution');
    const e = exactForward(forwardInput(t, 'one-way', 0.05));
    expect(reply.exact.widthRightMm).toBe(e.halfWidthRightMm);
    expect(reply.exact.widthLeftMm).toBe(e.halfWidthLeftMm);
    expect(reply.exact.contactOffsetMm).toBe(e.contactOffsetMm);
    expect(reply.exact.contactOffsetMm).not.toBe(0);
    expect(reply.exact.right).toEqual({ yMm: e.halfWidthRightMm, heightMm: 0.05 });
    expect(reply.exact.left).toEqual({ yMm: -e.halfWidthLeftMm, heightMm: 0.05 });
    // The scene's cusp points sit where the cusps are, at their heights.
    expect(reply.scene.right?.pHp[1]).toBeCloseTo(e.halfWidthRightMm, 9);
    expect(reply.scene.left?.pHp[1]).toBeCloseTo(-e.halfWidthLeftMm, 9);
    const views = teach(fwd(forwardInput(t, 'one-way', 0.05)));
    if (!views.ok) throw new Error('expected teaching data');
    const i = views.sweeps.tilt.angleDeg.indexOf(5);
    expect(views.sweeps.tilt.values.exact[i]).toBe(e.intervalMm);
    expect(views.sweeps.lead.angleDeg).toContain(5);
  });

  it('zigzag: both cusp heights, at +-L/2, the lower one on the wider flank', () => {
    const t = tool({ tiltAngleDeg: 10 });
    const reply = solve(fwd(forwardInput(t, 'zigzag', 0.05)));
    if (!reply.ok) throw new Error('expected a solution');
    const e = exactForward(forwardInput(t, 'zigzag', 0.05));
    const { right, left } = reply.exact;
    expect(right.yMm).toBe(e.intervalMm / 2);
    expect(left.yMm).toBe(-e.intervalMm / 2);
    expect(Math.max(right.heightMm, left.heightMm)).toBe(0.05);
    expect(Math.min(right.heightMm, left.heightMm)).toBe(e.otherCuspHeightMm);
    // The inverse at this L gives the same two cusps.
    const back = exactInverse(inverseInput(t, 'zigzag', e.intervalMm));
    expect(Math.abs(back.cuspHeightMm - 0.05)).toBeLessThan(1e-9);
    expect(Math.abs((back.otherCuspHeightMm ?? 0) - (e.otherCuspHeightMm ?? 0))).toBeLessThan(1e-9);
  });

  it('sameRequest: equal inputs match; any changed field, the mode or null does not', () => {
    const a = fwd(forwardInput(TOOL, 'one-way', 0.05));
    expect(sameRequest(a, fwd(forwardInput(TOOL, 'one-way', 0.05)))).toBe(true);
    expect(sameRequest(a, fwd(forwardInput(TOOL, 'zigzag', 0.05)))).toBe(false);
    expect(sameRequest(a, fwd(forwardInput(tool({ tiltAngleDeg: 1e-9 }), 'one-way', 0.05)))).toBe(false);
    expect(sameRequest(a, fwd(forwardInput(TOOL, 'one-way', 0.05 + 1e-15)))).toBe(false);
    expect(sameRequest(a, inv(inverseInput(TOOL, 'one-way', 0.05)))).toBe(false);
    const on = (surface: Surface) => fwd(forwardInput(TOOL, 'one-way', 0.05, surface));
    const convex: Surface = { kind: 'cylinder', radiusMm: 50, axis: 'feed' };
    expect(sameRequest(on(convex), on({ ...convex }))).toBe(true);
    expect(sameRequest(a, on(convex))).toBe(false);
    expect(sameRequest(on(convex), a)).toBe(false);
    expect(sameRequest(on(convex), on({ ...convex, radiusMm: -50 }))).toBe(false);
    expect(sameRequest(on(convex), on({ ...convex, axis: 'cross' }))).toBe(false);
    expect(sameRequest(a, null)).toBe(false);
    expect(sameRequest(null, null)).toBe(false);
  });
});

describe('trace frames for the step-through', () => {
  it('start at Eq. 1, pass the single contact, and end on the exact L/2', () => {
    const input = forwardInput(TOOL, 'one-way', 0.1);
    const { frames, traceResult } = traceFrames(input);
    expect(frames[0]?.phase).toBe('approach');
    expect(frames[0]?.approachIndex).toBe(0);
    expect(frames.some((f) => f.phase === 'single-contact')).toBe(true);
    expect(frames.some((f) => f.phase === 'search' && f.candidates.length >= 15)).toBe(true);
    const last = frames[frames.length - 1];
    expect(last?.phase).toBe('converged');
    expect(Math.abs((last?.outMm ?? 0) - exactHalfIntervalMm(input))).toBeLessThan(1e-9);
    expect(Math.abs(traceResult.widthRightMm - traceResult.exactWidthRightMm)).toBeLessThan(1e-9);
    // The numbers themselves: JSON.stringify would turn NaN and Infinity into null and hide them.
    expect(everyNumberFinite(frames)).toBe(true);
  });

  it('both flanks: the right one, then the left one, each converged, then both', () => {
    const input = forwardInput(tool({ tiltAngleDeg: 8 }), 'one-way', 0.05);
    const { frames, traceResult } = traceFrames(input);
    const flanks = frames.map((f) => f.flank);
    const firstLeft = flanks.indexOf('left');
    expect(firstLeft).toBeGreaterThan(0);
    expect(flanks.slice(0, firstLeft).every((f) => f === 'right')).toBe(true);
    expect(frames.filter((f) => f.phase === 'converged').map((f) => f.flank)).toEqual(['right', 'left', null]);
    expect(Math.abs(traceResult.widthLeftMm - traceResult.exactWidthLeftMm)).toBeLessThan(1e-9);
    expect(traceResult.widthLeftMm).not.toBeCloseTo(traceResult.widthRightMm, 3);
  });
});

describe('every number of every reply is finite (issue 7)', () => {
  it('seed 8123: 60 stratified valid cases (flat, tiny, ball corners; lead 0 to 89.9; tilt; both patterns), forward and inverse, solve and teach', () => {
    const rand = seededRandom(8123);
    let checked = 0;
    for (let k = 0; k < 60; k++) {
      const R = 10 ** (-3 + 6 * rand());
      const Rcr = R * ([0, 1e-9, rand(), 1][k % 4] as number);
      const t: ToolInput = {
        toolRadiusMm: R,
        cornerRadiusMm: Rcr,
        leadAngleDeg: [0, 1e-6, 89.9 * rand(), 89.9][(k >> 2) % 4] as number,
        tiltAngleDeg: [0, 60 * rand() - 30][(k >> 4) % 2] as number,
      };
      const pattern = k % 3 === 0 ? 'zigzag' : 'one-way';
      const v = validateForward({
        R: t.toolRadiusMm,
        Rcr: t.cornerRadiusMm,
        rho: t.leadAngleDeg,
        tilt: t.tiltAngleDeg,
        pattern,
        h: Math.max(1e-9, scallopHeightLimitMm(t) * 10 ** (-6 * rand())) * 0.5,
      });
      if (!v.ok) continue;
      const forward = fwd(v.value);
      const reply = solve(forward);
      expect(reply.ok, JSON.stringify(t)).toBe(true);
      expect(everyNumberFinite(reply), `solve ${JSON.stringify(t)}`).toBe(true);
      expect(everyNumberFinite(teach(forward)), `teach ${JSON.stringify(t)}`).toBe(true);
      if (reply.ok) {
        const inverse = inv(inverseInput(v.value, v.value.pattern, reply.exact.intervalMm * 0.9));
        expect(everyNumberFinite(solve(inverse)), `inverse ${JSON.stringify(t)}`).toBe(true);
      }
      checked++;
    }
    expect(checked).toBeGreaterThanOrEqual(45);
  });
});
