/**
 * Validation of a doubly curved point (core/roughness/doublyCurvedValidate.ts): the radii's range and
 * gouging in the user's unit (mm and inch), the quantity's limits from the point's own solver.
 */
import { describe, expect, it } from 'vitest';
import { describeInputError, MIN_LENGTH_MM } from '../../../../src/core/input/validate';
import { validateDoublyCurved } from '../../../../src/core/roughness/doublyCurvedValidate';
import { doublyCurvedGouges } from '../../../../src/core/surfaces/doublyCurved/gouging';
import { limitOf } from '../../../../src/core/surfaces/doublyCurved/radiusLimitSearch';
import { doublyCurvedLimits } from '../../../../src/core/surfaces/doublyCurved/solve';
import { validateForward } from '../../../../src/core/surfaces/validate';

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

  it('names the cross radius when either radius would help, and when neither does (issue 26 point 7)', () => {
    // Both help: Rf concave of at least 20.6 mm (Rc held), or Rc convex of at most 25.3 mm (Rf held).
    const saddle = {
      R: '3',
      Rcr: '0.417192475637421',
      rho: '44.73893790389411',
      tilt: '5.3511931374669075',
      feedRadius: '-15',
      crossRadius: '1000',
    };
    const both = validateDoublyCurved(saddle, 'h', '0.01');
    expect(!both.ok && both.errors.map((e) => [e.field, e.radiusLimit?.kind, e.radiusLimit?.other.kind])).toEqual([
      ['crossRadius', 'convex-at-most', 'concave-at-least'],
    ]);
    // Neither helps (two tight troughs): still the cross radius, "at any radius".
    const neither = validateDoublyCurved({ ...TOOL, feedRadius: '-8', crossRadius: '-8' }, 'h', '0.05');
    expect(!neither.ok && neither.errors.map((e) => [e.field, e.radiusLimit?.kind])).toEqual([['crossRadius', 'none']]);
    expect(!neither.ok && neither.errors[0]?.message).toMatch(/^This tool gouges the point at any radius Rc/);
    // Only the feed radius helps: it is named (the case: Rf too tight along the feed).
    const feed = validateDoublyCurved(
      { ...TOOL, rho: '60', tilt: '0', feedRadius: '-0.1', crossRadius: '0.5' },
      'h',
      '0.01',
    );
    expect(!feed.ok && feed.errors.map((e) => [e.field, e.code])).toEqual([['feedRadius', 'radius-gouging']]);
  });

  it('the smallest scallop height and step-over accepted are the minimum length (issue 26 point 7)', () => {
    const at = (quantity: 'h' | 'interval' | 'ra', value: number) =>
      validateDoublyCurved({ ...TOOL, feedRadius: '40', crossRadius: '80' }, quantity, value);
    expect(at('h', MIN_LENGTH_MM).ok).toBe(true);
    expect(at('interval', 2 * MIN_LENGTH_MM).ok).toBe(true);
    expect(at('ra', MIN_LENGTH_MM).ok).toBe(true);
    for (const [q, v] of [
      ['h', MIN_LENGTH_MM * 0.999],
      ['interval', 2 * MIN_LENGTH_MM * 0.999],
      ['ra', MIN_LENGTH_MM * 0.999],
    ] as const) {
      const below = at(q, v);
      expect(!below.ok && below.errors.map((e) => e.code)).toEqual(['too-small']);
    }
  });

  it('a limit at or beyond the largest radius (1e6 mm) is "at any radius" (issue 26 point 5)', () => {
    // The doubly curved search: a concave limit of 1e6 mm or more is no concave radius at all.
    expect(limitOf(-1 / 1e6).kind).toBe('not-concave');
    expect(limitOf(-1 / 3.7e15).kind).toBe('not-concave');
    expect(limitOf(-1 / (1e6 * (1 - 1e-9)))).toMatchObject({ kind: 'concave-at-least' });
    expect(limitOf(1 / 1e6).kind).toBe('not-concave');
    // The trough (one radius: a cylinder across the feed): the shank leans 45 degrees, its limit
    // was 3.7309e+15 mm; now no limit and "any radius", as at 46 degrees.
    for (const rho of [45, 46]) {
      const v = validateForward({ R: 3, Rcr: 1, rho, h: 0.01, surfaceRadius: -0.5, surfaceAxis: 'cross' });
      expect(!v.ok && v.errors.map((e) => [e.code, e.limit])).toEqual([['shank-gouging', undefined]]);
      expect(!v.ok && v.errors[0]?.message).toMatch(/of any radius/);
    }
    // With both radii: the concave feed radius is "straight or convex", no limit.
    const both = validateDoublyCurved(
      { ...TOOL, rho: '45', tilt: '0', feedRadius: '-0.5', crossRadius: '1' },
      'h',
      '0.01',
    );
    expect(!both.ok && both.errors.map((e) => [e.field, e.radiusLimit?.kind, e.limit])).toEqual([
      ['feedRadius', 'not-concave', undefined],
    ]);
  });
});
