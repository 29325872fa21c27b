import { describe, expect, it } from 'vitest';
import { compareForward, exactScallopHeightMm, forwardInput, inverseInput } from '../../src/core/index';
import { solve, transferables } from '../../src/worker/api';

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };

describe('worker solver API (plain data in, plain data out)', () => {
  it('forward: rows match the solver core, each with the scallop its own L really leaves', () => {
    const reply = solve({ id: 7, mode: 'forward', R: 3, Rcr: 1, rho: 5, value: 0.05 });
    if (!reply.ok) throw new Error('expected a solution');
    expect(reply.id).toBe(7);
    const c = compareForward(forwardInput(TOOL, 'one-way', 0.05));
    expect(reply.halfIntervalMm).toBe(c.exact.halfIntervalMm);
    const sekine = reply.rows.find((r) => r.key === 'sekine');
    const sek = c.approximations.sekine;
    if (!sek.ok || !sekine?.valueMm) throw new Error('sekine applicable here');
    expect(sekine.valueMm).toBe(sek.halfIntervalMm);
    expect(sekine.realScallopMm).toBe(exactScallopHeightMm(inverseInput(TOOL, 'one-way', 2 * sek.halfIntervalMm)));
    expect(sekine.modelRadiusMm).toBe(sek.effectiveRadiusMm);
    expect(reply.geometry?.toolPositions.length).toBeGreaterThan(0);
    // Every large array is listed for transfer, none twice.
    const buffers = transferables(reply);
    expect(new Set(buffers).size).toBe(buffers.length);
    expect(buffers.length).toBe(2 + (reply.geometry?.intersectionLoops.length ?? 0));
  });

  it('forward: invalid input is a typed error reply, not an exception', () => {
    const reply = solve({ id: 1, mode: 'forward', R: 3, Rcr: 4, rho: 5, value: 0.05 });
    expect(reply.ok).toBe(false);
    if (!reply.ok) expect(reply.errors[0]?.field).toBe('Rcr');
    expect(solve({ id: 2, mode: 'forward', R: Number.NaN, Rcr: 1, rho: 5, value: 0.05 }).ok).toBe(false);
  });

  it('an approximation whose L/2 reaches R leaves a wall, said in the note', () => {
    // Redonnet's circle at a steep-ish h on a small-corner tool overshoots R.
    const reply = solve({ id: 3, mode: 'forward', R: 3, Rcr: 0.2, rho: 2, value: 0.25 });
    if (!reply.ok) throw new Error('expected a solution');
    const red = reply.rows.find((r) => r.key === 'redonnet');
    expect(red?.valueMm).toBeGreaterThan(3);
    expect(red?.realScallopMm).toBeNull();
    expect(red?.note).toMatch(/wall/);
  });

  it('inverse: L is the full step-over; h = 0 on the flat bottom (rho = 0) has no geometry', () => {
    const reply = solve({ id: 4, mode: 'inverse', R: 3, Rcr: 1, rho: 5, value: 2 * 1.443592412967 });
    if (!reply.ok) throw new Error('expected a solution');
    expect(Math.abs(reply.scallopHeightMm - 0.05)).toBeLessThan(1e-9);
    const flat = solve({ id: 5, mode: 'inverse', R: 3, Rcr: 1, rho: 0, value: 3 });
    if (!flat.ok) throw new Error('expected a solution');
    expect(flat.scallopHeightMm).toBe(0);
    expect(flat.geometry).toBeNull();
  });

  it('teaching models give each approximation its L/2 at the state h, in inverse mode too (rows hold heights there)', () => {
    // Regression: the formulas view once read the inverse rows (heights) as L/2.
    const inverse = solve({ id: 6, mode: 'inverse', R: 3, Rcr: 1, rho: 5, value: 3, withViews: true });
    if (!inverse.ok || !inverse.teaching) throw new Error('expected teaching data');
    const c = compareForward(forwardInput(TOOL, 'one-way', inverse.scallopHeightMm)).approximations;
    const m = inverse.teaching.models;
    if (!c.sekine.ok || !c.redonnet.ok || !c.bedi.ok) throw new Error('all three apply here');
    expect(m.sekine?.halfIntervalMm).toBe(c.sekine.halfIntervalMm);
    expect(m.redonnet?.halfIntervalMm).toBe(c.redonnet.halfIntervalMm);
    expect(m.bedi?.halfIntervalMm).toBe(c.bedi.halfIntervalMm);
    expect(Math.abs(inverse.halfIntervalMm - 1.5)).toBeLessThan(1e-12);
  });
});

describe('trace frames for the step-through', () => {
  it('start at Eq. 1, pass the single contact, and end on the exact L/2', async () => {
    const { traceFrames } = await import('../../src/worker/api');
    const { exactHalfIntervalMm } = await import('../../src/core/exact');
    const input = forwardInput(TOOL, 'one-way', 0.1);
    const frames = traceFrames(input);
    expect(frames[0]?.phase).toBe('approach');
    expect(frames.some((f) => f.phase === 'single-contact')).toBe(true);
    expect(frames.some((f) => f.phase === 'search' && f.candidates.length >= 15)).toBe(true);
    const last = frames[frames.length - 1];
    expect(last?.phase).toBe('converged');
    expect(Math.abs((last?.bestY ?? 0) - exactHalfIntervalMm(input))).toBeLessThan(1e-9);
    expect(JSON.stringify(frames)).not.toMatch(/null,"sectionCentre":\[null|NaN|Infinity/);
  });
});
