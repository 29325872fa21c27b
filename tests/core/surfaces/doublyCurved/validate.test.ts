/**
 * Validation of a doubly curved point (core/doublyCurved/validate.ts): the radii's range and
 * gouging in the user's unit (mm and inch), the quantity's limits from the point's own solver.
 */
import { describe, expect, it } from 'vitest';
import { describeInputError } from '../../../../src/core/input/validate';
import { doublyCurvedGouges } from '../../../../src/core/surfaces/doublyCurved/gouging';
import { doublyCurvedLimits } from '../../../../src/core/surfaces/doublyCurved/solve';
import { validateDoublyCurved } from '../../../../src/core/surfaces/doublyCurved/validate';

const TOOL = { R: '3', Rcr: '1', rho: '10', tilt: '5' };

describe('validateDoublyCurved', () => {
  it('radii out of range: the range in the user unit (mm, inch), one error per radius', () => {
    const v = validateDoublyCurved({ ...TOOL, feedRadius: '0.0001', crossRadius: '-2e6' }, 'h', '0.05');
    expect(v.ok).toBe(false);
    if (v.ok) return;
    expect(v.errors.map((e) => e.field)).toEqual(['feedRadius', 'crossRadius']);
    const [f] = v.errors;
    expect(f?.message).toBe(
      'Feed radius Rf must be a radius from 0.001 mm to 1000000 mm, negative for concave; leave it out for straight (got 0.0001).',
    );
    if (f === undefined) return;
    expect(describeInputError(f, 'in', { typed: '0.0000039' })).toBe(
      'Feed radius Rf must be a radius from 0.0000393701 in to 39370.1 in, negative for concave; leave it out for straight (got 0.0000039).',
    );
  });

  it('gouging: named on the radius with its limit (user unit) and the other held; valid just past the limit', () => {
    const v = validateDoublyCurved({ ...TOOL, feedRadius: '40', crossRadius: '-8' }, 'h', '0.05');
    expect(v.ok).toBe(false);
    if (v.ok) return;
    const e = v.errors[0];
    expect(e?.code).toBe('radius-gouging');
    if (e === undefined || e.limit === undefined) throw new Error('no limit');
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 5 };
    expect(doublyCurvedGouges(tool, { feedRadiusMm: 40, crossRadiusMm: e.limit * 0.999 })).toBe(true);
    expect(doublyCurvedGouges(tool, { feedRadiusMm: 40, crossRadiusMm: e.limit * 1.001 })).toBe(false);
    const inch = describeInputError(e, 'in');
    expect(inch).toContain(`at least ${(Math.abs(e.limit) / 25.4).toPrecision(6).replace(/0+$/, '')}`);
    expect(inch).toContain('Rf = 1.5748 in held');
  });

  it('h below the flank limits, L below the widest, Ra below the largest', () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 5 };
    const limit = doublyCurvedLimits({ ...tool, feedRadiusMm: 40, crossRadiusMm: 80 }).limitMm;
    const at = validateDoublyCurved({ ...TOOL, feedRadius: '40', crossRadius: '80' }, 'h', String(limit));
    expect(at.ok).toBe(false);
    const below = validateDoublyCurved({ ...TOOL, feedRadius: '40', crossRadius: '80' }, 'h', String(limit * 0.999));
    expect(below.ok).toBe(true);
    const L = validateDoublyCurved({ ...TOOL, feedRadius: '40', crossRadius: '80' }, 'interval', '100');
    expect(!L.ok && L.errors[0]?.code).toBe('beyond-interval');
    const ra = validateDoublyCurved({ ...TOOL, feedRadius: '40', crossRadius: '80' }, 'ra', '10');
    expect(!ra.ok && ra.errors[0]?.code).toBe('beyond-max-ra');
    const straight = validateDoublyCurved({ ...TOOL, feedRadius: '', crossRadius: undefined }, 'h', '0.05');
    expect(straight.ok && straight.value.feedRadiusMm).toBe(Number.POSITIVE_INFINITY);
  });
});
