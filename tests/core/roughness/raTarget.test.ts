/** A target Ra: validated against the largest Ra the tool leaves, solved back to h and L. */
import { describe, expect, it } from 'vitest';
import { formatInputNumber, fromMm } from '../../../src/core/input/units';
import { describeInputError } from '../../../src/core/input/validate';
import { forwardOfRaTarget, roughnessSummary, validateRaTarget } from '../../../src/core/roughness/raTarget';
import { exactRoughness, maxRaMm } from '../../../src/core/roughness/roughness';

const TOOL = { R: 3, Rcr: 1, rho: 5 };
const toolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };

describe('target Ra', () => {
  it('a valid Ra comes to the h whose passes leave exactly that Ra', () => {
    const v = validateRaTarget({ ...TOOL, ra: '0.0125' });
    if (!v.ok) throw new Error(v.errors[0]?.message);
    expect(v.value.targetRaMm).toBe(0.0125);
    const f = forwardOfRaTarget(v.value);
    expect(Math.abs(exactRoughness(f).raMm - 0.0125)).toBeLessThan(1e-12);
    expect(f.scallopHeightMm).toBeGreaterThan(0.05); // Tool 1: Ra(h = 0.05) = 0.012417 < 0.0125
  });

  it('Ra at or above the largest reachable is an error naming the limit, in the user unit', () => {
    const max = maxRaMm(toolInput, 'one-way');
    expect(max).toBeGreaterThan(0.1);
    for (const ra of [max, max * 1.01, 0.5, 5]) {
      const v = validateRaTarget({ ...TOOL, ra });
      expect(v.ok, String(ra)).toBe(false);
      if (v.ok) continue;
      expect(v.errors).toHaveLength(1);
      const e = v.errors[0];
      if (!e) continue;
      expect(e.field).toBe('ra');
      expect(e.code).toBe('beyond-max-ra');
      expect(e.limit).toBe(max);
      expect(describeInputError(e, 'in', { typed: '1' })).toContain(
        `below ${formatInputNumber(fromMm(max, 'in'))} in (got 1)`,
      );
    }
    expect(validateRaTarget({ ...TOOL, ra: max * 0.999 }).ok).toBe(true);
  });

  it('the number itself: words of the core, on the Ra field; tool errors stay on their fields', () => {
    const bad = (ra: unknown) => {
      const v = validateRaTarget({ ...TOOL, ra });
      return v.ok ? null : v.errors.map((e) => [e.field, e.code]);
    };
    expect(bad('abc')).toEqual([['ra', 'not-a-number']]);
    expect(bad('')).toEqual([['ra', 'missing']]);
    expect(bad(-1)).toEqual([['ra', 'not-positive']]);
    expect(bad(1e-12)).toEqual([['ra', 'too-small']]);
    const rcr = validateRaTarget({ R: 3, Rcr: 4, rho: 5, ra: 0.01 });
    expect(rcr.ok ? [] : rcr.errors.map((e) => e.field)).toEqual(['Rcr']);
    // A flat end lying flat leaves no scallop: no Ra is reachable, said so.
    const flat = validateRaTarget({ R: 3, Rcr: 0, rho: 0, ra: 0.01 });
    expect(flat.ok).toBe(false);
    if (!flat.ok) expect(flat.errors[0]?.message).toMatch(/no scallop/);
  });

  it('the rule of thumb h/4 beside the exact Ra, with its error', () => {
    const s = roughnessSummary({ rzMm: 0.05, raMm: 0.012417, rqMm: 0.0145, meanMm: 0.0157 }, 0.05);
    expect(s.ruleOfThumbRaMm).toBe(0.0125);
    expect(s.ruleErrorPercent).toBeCloseTo((100 * (0.0125 - 0.012417)) / 0.012417, 12);
    expect(roughnessSummary({ rzMm: 0, raMm: 0, rqMm: 0, meanMm: 0 }, 0).ruleErrorPercent).toBeNull();
  });
});
