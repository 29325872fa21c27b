import { describe, expect, it } from 'vitest';
import { solveForwardRaw } from '../../../src/core/procedures/compare';
import { scallopHeightLimits, validateForward, validateInverse } from '../../../src/core/surfaces/validate';

const good = { R: 3, Rcr: 1, rho: 5, h: 0.05 };

function errorsOf(v: ReturnType<typeof validateForward> | ReturnType<typeof validateInverse>) {
  if (v.ok) throw new Error('expected errors');
  return v.errors;
}

describe('validateForward', () => {
  it('accepts numbers and numeric strings, converting strings once', () => {
    const v = validateForward({ R: '3', Rcr: ' 1 ', rho: '5e0', h: '.05' });
    expect(v).toEqual({
      ok: true,
      value: {
        toolRadiusMm: 3,
        cornerRadiusMm: 1,
        leadAngleDeg: 5,
        tiltAngleDeg: 0,
        pattern: 'one-way',
        surface: { kind: 'plane' },
        scallopHeightMm: 0.05,
      },
    });
  });

  it.each([
    [{ ...good, R: 0 }, 'R', 'not-positive', /greater than 0/],
    [{ ...good, R: -2 }, 'R', 'not-positive', /greater than 0/],
    [{ ...good, R: 5000 }, 'R', 'too-large', /at most 1000/],
    [{ ...good, R: 1e-5 }, 'R', 'too-small', /at least 0.001 mm/],
    [{ ...good, h: 1e-12 }, 'h', 'too-small', /at least 1e-9 mm/],
    [{ ...good, Rcr: -0.1 }, 'Rcr', 'negative', /0 mm or more/],
    [{ ...good, Rcr: 4 }, 'Rcr', 'corner-exceeds-radius', /must not exceed the tool radius R = 3 mm/],
    [{ ...good, rho: 90 }, 'rho', 'out-of-range', /below 90 degrees/],
    [{ ...good, rho: -1 }, 'rho', 'out-of-range', /at least 0/],
    [{ ...good, h: 0 }, 'h', 'not-positive', /greater than 0/],
    [{ ...good, h: 1.2 }, 'h', 'flank-wall', /full height .* = 1\.17431 mm .*wall, not a scallop/],
    [{ ...good, R: Number.NaN }, 'R', 'not-a-number', /must be a number/],
    [{ ...good, h: Number.POSITIVE_INFINITY }, 'h', 'not-finite', /finite/],
    [{ ...good, rho: '' }, 'rho', 'missing', /missing/],
    [{ ...good, rho: undefined }, 'rho', 'missing', /missing/],
    [{ ...good, R: 'abc' }, 'R', 'not-a-number', /must be a number \(got "abc"\)/],
    [{ ...good, R: '3mm' }, 'R', 'not-a-number', /got "3mm"/],
    [{ ...good, h: '1e999' }, 'h', 'not-finite', /finite/],
    [{ ...good, h: {} }, 'h', 'not-a-number', /must be a number/],
  ])('%o is rejected on %s (%s)', (raw, field, code, message) => {
    const errors = errorsOf(validateForward(raw));
    expect(errors).toHaveLength(1);
    expect(errors[0]).toMatchObject({ field, code });
    expect(errors[0]?.message).toMatch(message);
  });

  it('reports every bad field at once, and skips cross-field rules that depend on a bad field', () => {
    const errors = errorsOf(validateForward({ R: 'x', Rcr: 9, rho: 95, h: -1 }));
    expect(errors.map((e) => e.field).sort()).toEqual(['R', 'h', 'rho']);
  });

  it('a flat end without lead or tilt leaves no scallop: any h is valid and answered by L = 2R', () => {
    expect(scallopHeightLimits({ toolRadiusMm: 3, cornerRadiusMm: 0, leadAngleDeg: 0, tiltAngleDeg: 0 }).limitMm).toBe(
      0,
    );
    const v = validateForward({ R: 3, Rcr: 0, rho: 0, h: 0.01 });
    expect(v.ok).toBe(true);
    const fwd = solveForwardRaw({ R: 3, Rcr: 0, rho: 0, h: 0.01 });
    expect(fwd.ok && fwd.value.exact.noScallop && fwd.value.exact.intervalMm).toBe(6);
    // With tilt the same flat end cuts a step with its edge: no h is possible, and the message says why.
    const tilted = errorsOf(validateForward({ R: 3, Rcr: 0, rho: 0, tilt: 5, h: 0.01 }))[0];
    expect(tilted?.code).toBe('wall-only');
    expect(tilted?.message).toMatch(/cuts a step at any step-over/);
    expect(errorsOf(validateInverse({ R: 3, Rcr: 0, rho: 0, tilt: 5, interval: 1 }))[0]?.code).toBe('wall-only');
  });

  it('accepts the edges of the domain: Rcr = 0, Rcr = R, rho = 0', () => {
    expect(validateForward({ R: 3, Rcr: 0, rho: 10, h: 0.1 }).ok).toBe(true);
    expect(validateForward({ R: 3, Rcr: 3, rho: 0, h: 0.1 }).ok).toBe(true);
    expect(validateForward({ R: 3, Rcr: 1, rho: 0, h: 0.1 }).ok).toBe(true);
  });
});

describe('validateInverse', () => {
  it('accepts 0 < L < 2R', () => {
    expect(validateInverse({ R: 3, Rcr: 1, rho: 5, interval: 3 }).ok).toBe(true);
  });
  it('rejects L >= 2R and L <= 0, naming the constraint', () => {
    expect(errorsOf(validateInverse({ R: 3, Rcr: 1, rho: 5, interval: 6 }))[0]?.message).toMatch(
      /Step-over L must be below the tool diameter 2R = 6 mm \(got 6\); .*leave a wall/,
    );
    expect(errorsOf(validateInverse({ R: 3, Rcr: 1, rho: 5, interval: 0 }))[0]?.code).toBe('not-positive');
  });
});
