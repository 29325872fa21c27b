/**
 * Validation of the finish inputs (src/core/finish/finishInput.ts) and the scope refusal
 * (finishScope.ts): each limit named with its value, in the user's unit.
 */
import { describe, expect, it } from 'vitest';
import {
  describeFinishError,
  finishScopeError,
  MAX_FLUTES,
  MIN_FEED_PER_TOOTH_MM,
  validateFinish,
} from '../../../src/core/finish/index';

const R = 3;

function errorsOf(raw: Parameters<typeof validateFinish>[0]) {
  const v = validateFinish(raw, R);
  return v.ok ? [] : v.errors.map((e) => [e.field, e.code, e.limit ?? null, e.message] as const);
}

describe('validateFinish', () => {
  it('accepts the valid domain, with the optional inputs 0 when missing', () => {
    const v = validateFinish({ flutes: '4', fz: '0.08' }, R);
    expect(v).toEqual({
      ok: true,
      value: { flutes: 4, feedPerToothMm: 0.08, runoutMm: 0, runoutPhaseDeg: 0, passPhase: 0 },
    });
    const w = validateFinish({ flutes: 1, fz: R, runout: R / 10, runoutPhase: -720.5, passPhase: 0.999 }, R);
    expect(w.ok).toBe(true);
    expect(validateFinish({ flutes: MAX_FLUTES, fz: MIN_FEED_PER_TOOTH_MM }, R).ok).toBe(true);
  });

  it('refuses zero, fractional and too many flutes, naming the range', () => {
    for (const z of [0, 2.5, -1, MAX_FLUTES + 1]) {
      const e = errorsOf({ flutes: z, fz: 0.1 });
      expect(e).toHaveLength(1);
      expect(e[0]?.[0]).toBe('flutes');
      expect(e[0]?.[1]).toBe('not-an-integer');
      expect(e[0]?.[3]).toBe(`Flutes z must be a whole number of teeth from 1 to 64 (got ${z}).`);
    }
    expect(errorsOf({ flutes: 'four', fz: 0.1 })[0]?.[3]).toBe('Flutes z must be a number (got "four").');
    expect(errorsOf({ flutes: '', fz: 0.1 })[0]?.[3]).toBe('Flutes z is missing: enter a number.');
  });

  it('refuses fz <= 0, below 1 nm and above the tool radius, with the limit', () => {
    expect(errorsOf({ flutes: 2, fz: 0 })[0]?.[3]).toBe('Feed per tooth fz must be greater than 0 mm (got 0).');
    expect(errorsOf({ flutes: 2, fz: -0.1 })[0]?.[1]).toBe('not-positive');
    expect(errorsOf({ flutes: 2, fz: 1e-7 })[0]).toEqual([
      'fz',
      'too-small',
      MIN_FEED_PER_TOOTH_MM,
      'Feed per tooth fz must be at least 1e-6 mm (got 1e-7).',
    ]);
    expect(errorsOf({ flutes: 2, fz: 3.0001 })[0]).toEqual([
      'fz',
      'too-large',
      3,
      'Feed per tooth fz must be at most the tool radius R = 3 mm (got 3.0001).',
    ]);
    expect(errorsOf({ flutes: 2, fz: 'Infinity' })[0]?.[1]).toBe('not-a-number');
    // A length past a double once in mm (the tester's 1e308 in): too large, with the limit in the user's unit.
    expect(errorsOf({ flutes: 2, fz: Number.POSITIVE_INFINITY })[0]?.slice(0, 3)).toEqual(['fz', 'too-large', 3]);
    expect(errorsOf({ flutes: 2, fz: 0.1, runout: Number.POSITIVE_INFINITY })[0]?.slice(0, 3)).toEqual([
      'runout',
      'too-large',
      0.3,
    ]);
    expect(errorsOf({ flutes: 2, fz: Number.NEGATIVE_INFINITY })[0]?.[1]).toBe('not-positive');
    expect(errorsOf({ flutes: Number.POSITIVE_INFINITY, fz: 0.1 })[0]?.[1]).toBe('not-finite');
  });

  it('refuses negative runout and runout above R/10; any finite phase; pass phase in [0, 1)', () => {
    expect(errorsOf({ flutes: 2, fz: 0.1, runout: -0.001 })[0]?.[3]).toBe(
      'Runout e must be 0 mm or more (got -0.001).',
    );
    expect(errorsOf({ flutes: 2, fz: 0.1, runout: 0.31 })[0]).toEqual([
      'runout',
      'too-large',
      0.3,
      'Runout e must be at most R/10 = 0.3 mm (got 0.31).',
    ]);
    expect(errorsOf({ flutes: 2, fz: 0.1, runoutPhase: Number.NaN })[0]?.[1]).toBe('not-a-number');
    expect(errorsOf({ flutes: 2, fz: 0.1, runoutPhase: 1e6 })).toEqual([]);
    for (const q of [1, -0.1, 1.5]) {
      expect(errorsOf({ flutes: 2, fz: 0.1, passPhase: q })[0]?.[3]).toBe(
        `Pass phase q must be at least 0 and below 1 (a fraction of the feed period) (got ${q}).`,
      );
    }
    expect(errorsOf({ flutes: 2, fz: 0.1, passPhase: 0 })).toEqual([]);
  });

  it('reports every bad field at once and words lengths in the user unit', () => {
    const e = errorsOf({ flutes: 0, fz: 0, runout: -1, passPhase: 2 });
    expect(e.map((x) => x[0])).toEqual(['flutes', 'fz', 'runout', 'passPhase']);
    expect(describeFinishError({ field: 'fz', code: 'too-large', got: '0.2', limit: 25.4 * 0.125 }, 'in')).toBe(
      'Feed per tooth fz must be at most the tool radius R = 0.125 in (got 0.2).',
    );
  });
});

describe('finishScopeError', () => {
  it('computes feed marks on planes only, and says where not yet', () => {
    expect(finishScopeError('plane')).toBeNull();
    expect(finishScopeError('slopedPlane')).toBeNull();
    expect(finishScopeError('cylinder')).toBe(
      'Feed marks are not computed on cylinders yet: only on a plane (any lead and tilt, one-way or zigzag) and the three-axis sloped plane.',
    );
    expect(finishScopeError('doublyCurved')).toMatch(/^Feed marks are not computed on doubly curved points yet:/);
    expect(finishScopeError('waterlineRevolution')).toMatch(
      /^Feed marks are not computed on waterline passes on surfaces of revolution yet:/,
    );
  });
});
