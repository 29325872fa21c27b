/** Target roughness: validation of a target Ra (issue 11) and the simulation's size guard. */
import { describe, expect, it } from 'vitest';
import {
  describeInputError,
  exactRoughness,
  forwardInput,
  MAX_SIMULATION_TRIANGLES,
  maxRaMm,
  SimulationTooLargeError,
  scallopHeightForRaMm,
  simulatePasses,
  validateTargetRa,
} from '../../../src/core/index';

const base = { R: '3', Rcr: '1', rho: '5' };

describe('validateTargetRa', () => {
  it('accepts a target Ra up to maxRaMm; the scallop height found leaves it (round trip)', () => {
    for (const [surfaceRadius, surfaceAxis] of [
      [undefined, undefined],
      ['40', 'feed'],
      ['-60', 'cross'],
    ] as const) {
      for (const pattern of ['one-way', 'zigzag'] as const) {
        const v = validateTargetRa({ ...base, tilt: '4', pattern, surfaceRadius, surfaceAxis, ra: '0.01' });
        if (!v.ok) throw new Error(v.errors.map((e) => e.message).join(' '));
        expect(v.value).toMatchObject({
          toolRadiusMm: 3,
          cornerRadiusMm: 1,
          tiltAngleDeg: 4,
          pattern,
          targetRaMm: 0.01,
        });
        const p = v.value;
        const h = scallopHeightForRaMm(p, p.pattern, p.targetRaMm, p.surface);
        expect(Math.abs(exactRoughness(forwardInput(p, p.pattern, h, p.surface)).raMm - 0.01)).toBeLessThan(1e-9);
      }
    }
  });

  it('rejects a target at or beyond the largest Ra (a supremum: reached only where a wall starts) with that limit; just below it is accepted', () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
    const max = maxRaMm(tool, 'one-way');
    expect(validateTargetRa({ ...base, ra: String(max * 0.999999) }).ok).toBe(true);
    expect(validateTargetRa({ ...base, ra: String(max) }).ok).toBe(false);
    const v = validateTargetRa({ ...base, ra: String(max * 1.000001) });
    expect(v.ok).toBe(false);
    if (v.ok) return;
    expect(v.errors).toHaveLength(1);
    expect(v.errors[0]).toMatchObject({ field: 'ra', code: 'beyond-max-ra', limit: max });
    expect(v.errors[0]?.message).toMatch(/^Roughness Ra must be below 0\.151513 mm \(got 0\.151513/);
  });

  it.each([
    [{ ra: undefined }, 'missing', /Roughness Ra is missing/],
    [{ ra: 'abc' }, 'not-a-number', /Roughness Ra must be a number \(got "abc"\)/],
    [{ ra: '0' }, 'not-positive', /greater than 0 mm/],
    [{ ra: '-0.01' }, 'not-positive', /greater than 0 mm/],
    [{ ra: '1e-10' }, 'too-small', /at least 1e-9 mm/],
    [{ Rcr: '0', rho: '0', ra: '0.01' }, 'beyond-max-ra', /cannot be reached .*leaves no scallop/],
  ])('%j is refused (%s)', (raw, code, message) => {
    const v = validateTargetRa({ ...base, ...raw });
    expect(v.ok).toBe(false);
    if (v.ok) return;
    const e = v.errors.find((x) => x.field === 'ra');
    expect(e?.code).toBe(code);
    expect(e?.message).toMatch(message);
    if (e) expect(describeInputError(e, 'mm')).toBe(e.message);
  });

  it('a gouged concave cylinder is the error, not the Ra; tool errors come with the Ra error', () => {
    const g = validateTargetRa({ ...base, surfaceRadius: '-2', ra: '5' });
    expect(g.ok).toBe(false);
    if (!g.ok) expect(g.errors.map((e) => [e.field, e.code])).toEqual([['surfaceRadius', 'gouging']]);
    // As for h: on a gouged cylinder the Ra's own range is moot.
    const negative = validateTargetRa({ ...base, surfaceRadius: '-2', ra: '-1' });
    expect(negative.ok || negative.errors.map((e) => e.code)).toEqual(['gouging']);
    const t = validateTargetRa({ R: '3', Rcr: '4', rho: '5', ra: '-1', surfaceAxis: 'x', surfaceRadius: '5' });
    expect(t.ok).toBe(false);
    if (!t.ok) {
      expect(t.errors.map((e) => [e.field, e.code])).toEqual([
        ['Rcr', 'corner-exceeds-radius'],
        ['surfaceAxis', 'not-an-axis'],
        ['ra', 'not-positive'],
      ]);
    }
  });
});

describe('simulation size guard', () => {
  it(`a tool far larger than its step-over stops with SimulationTooLargeError (more than ${MAX_SIMULATION_TRIANGLES} triangles), not an exhausted heap`, () => {
    // R = 1000 mm leaving 1 nm: L is about 0.5 um, so the field's cells are 5 nm wide.
    const tool = { toolRadiusMm: 1000, cornerRadiusMm: 1e-9, leadAngleDeg: 89.99, tiltAngleDeg: -80 };
    const L = 0.0004911512087413608;
    expect(() => simulatePasses({ tool, pattern: 'one-way', intervalMm: L })).toThrow(SimulationTooLargeError);
  });
});

describe('validateTargetRa: tools that leave no scallop', () => {
  it('a tilted flat end cuts a step (wall-only, as for h); a flat end lying on a plane leaves Ra = 0', () => {
    const step = validateTargetRa({ R: '3', Rcr: '0', rho: '0', tilt: '10', ra: '0.01' });
    const flat = validateTargetRa({ R: '3', Rcr: '0', rho: '0', ra: '0.01' });
    expect(step.ok || step.errors.map((e) => [e.field, e.code])).toEqual([['ra', 'wall-only']]);
    expect(flat.ok || flat.errors.map((e) => [e.field, e.code, e.limit])).toEqual([['ra', 'beyond-max-ra', 0]]);
  });
});
