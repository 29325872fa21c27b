/**
 * Issue 26 point 11: an input error leaves out what does not exist (no `limit: null`, `side: null`,
 * `heldMm: null`, `radiusMm: null`), at the source: every error code of the core's validations, as
 * data and as JSON, holds no null and no non-finite number. The table is keyed by the code type, so
 * a new code cannot be added without an example here.
 */
import { describe, expect, it } from 'vitest';
import type { AnyInputError, InputErrorCode } from '../../../src/core/input/validate';
import { validateDoublyCurved } from '../../../src/core/roughness/doublyCurvedValidate';
import { validateTargetRa } from '../../../src/core/roughness/roughness';
import { validateForward, validateInverse } from '../../../src/core/surfaces/validate';
import { everyNumberFinite } from '../../support/finite';

const TOOL = { R: 3, Rcr: 1, rho: 5 };
const errorsOf = (v: { ok: boolean; errors?: readonly AnyInputError[] }) => (v.ok ? [] : (v.errors ?? []));

/** For each code, inputs whose validation gives it (and often others). */
const EXAMPLES: Record<InputErrorCode, () => readonly AnyInputError[]> = {
  missing: () => errorsOf(validateForward({ ...TOOL, h: '' })),
  'not-a-number': () => errorsOf(validateForward({ ...TOOL, h: '5um' })),
  'not-finite': () => errorsOf(validateForward({ ...TOOL, h: Number.POSITIVE_INFINITY })),
  'not-positive': () => errorsOf(validateForward({ ...TOOL, h: 0 })),
  negative: () => errorsOf(validateForward({ ...TOOL, Rcr: -1, h: 0.01 })),
  'too-large': () => errorsOf(validateForward({ ...TOOL, R: 1e9, h: 0.01 })),
  'too-small': () => errorsOf(validateForward({ ...TOOL, h: 1e-12 })),
  'out-of-range': () => errorsOf(validateForward({ ...TOOL, rho: 95, h: 0.01 })),
  'not-a-pattern': () => errorsOf(validateForward({ ...TOOL, pattern: 'spiral', h: 0.01 })),
  'not-an-axis': () => errorsOf(validateForward({ ...TOOL, surfaceRadius: -30, surfaceAxis: 'up', h: 0.01 })),
  // A flat bottom without lead in a trough across the feed: any radius (no limit).
  gouging: () => errorsOf(validateForward({ R: 3, Rcr: 1, rho: 0, h: 0.05, surfaceRadius: -30, surfaceAxis: 'cross' })),
  // The 45-degree shank lean in a trough: at any radius (point 5), and one with a limit.
  'shank-gouging': () => [
    ...errorsOf(validateForward({ R: 3, Rcr: 1, rho: 45, h: 0.01, surfaceRadius: -0.5, surfaceAxis: 'cross' })),
    ...errorsOf(validateForward({ R: 3, Rcr: 1, rho: 5, tilt: 50, h: 0.01, surfaceRadius: -3.7, surfaceAxis: 'feed' })),
  ],
  'corner-exceeds-radius': () => errorsOf(validateForward({ R: 3, Rcr: 4, rho: 5, h: 0.01 })),
  // Without tilt on a plane (no side) and with tilt (a side).
  'flank-wall': () => [
    ...errorsOf(validateForward({ ...TOOL, h: 5 })),
    ...errorsOf(validateForward({ ...TOOL, tilt: 10, h: 5 })),
  ],
  'shank-cuts': () => errorsOf(validateForward({ ...TOOL, tilt: 30, h: 2 })),
  'beyond-diameter': () => errorsOf(validateInverse({ ...TOOL, rho: 0, interval: 7 })),
  'beyond-interval': () => errorsOf(validateInverse({ ...TOOL, tilt: 10, interval: 50 })),
  // Above the largest Ra, and on a flat bottom lying on the plane (Ra 0: no limit).
  'beyond-max-ra': () => [
    ...errorsOf(validateTargetRa({ ...TOOL, ra: 10 })),
    ...errorsOf(validateTargetRa({ R: 3, Rcr: 1, rho: 0, ra: 0.001 })),
  ],
  'wall-only': () => errorsOf(validateForward({ R: 3, Rcr: 0, rho: 0, tilt: 10, h: 0.01 })),
  // A doubly curved point: a limit with the other radius held, the other straight (no heldMm), and
  // "at any radius" (no limit, no magnitude).
  'radius-gouging': () => [
    ...errorsOf(validateDoublyCurved({ ...TOOL, rho: 10, tilt: 5, feedRadius: 40, crossRadius: -8 }, 'h', 0.05)),
    ...errorsOf(validateDoublyCurved({ ...TOOL, rho: 10, tilt: 5, crossRadius: -8 }, 'h', 0.05)),
    ...errorsOf(validateDoublyCurved({ ...TOOL, rho: 10, tilt: 5, feedRadius: -8, crossRadius: -8 }, 'h', 0.05)),
    ...errorsOf(validateDoublyCurved({ ...TOOL, rho: 45, feedRadius: -0.5, crossRadius: 1 }, 'h', 0.01)),
    ...errorsOf(validateDoublyCurved({ ...TOOL, rho: 60, feedRadius: -0.1, crossRadius: 0.5 }, 'ra', 0.001)),
  ],
};

/** Every key path in a value whose value is null or undefined (own enumerable members). */
function absentMembers(value: unknown, path = ''): string[] {
  if (value === null || value === undefined) return [path];
  if (typeof value !== 'object') return [];
  return Object.entries(value).flatMap(([k, v]) => absentMembers(v, `${path}.${k}`));
}

describe('input errors leave out what does not exist (issue 26 point 11)', () => {
  for (const [code, example] of Object.entries(EXAMPLES)) {
    it(`${code}: no null or undefined member, every number finite, the JSON free of null`, () => {
      const errors = example();
      const mine = errors.filter((e) => e.code === code);
      expect(mine.length, JSON.stringify(errors)).toBeGreaterThan(0);
      for (const e of errors) {
        expect(absentMembers(e), e.message).toEqual([]);
        expect(everyNumberFinite(e), e.message).toBe(true);
        expect(JSON.stringify(e)).not.toMatch(/null/);
      }
    });
  }

  it('what exists is kept: a limit, a side, the held radius and the other radius magnitude', () => {
    const [flank] = EXAMPLES['flank-wall']().filter((e) => e.side !== undefined);
    expect(flank?.limit).toBeGreaterThan(0);
    expect(flank?.side).toBe('right');
    const [held] = EXAMPLES['radius-gouging']();
    expect(held?.radiusLimit?.heldMm).toBe(40);
    expect(held?.limit).toBeLessThan(0);
  });
});
