/**
 * The profile view's section (sectionProfile.ts): the section's signed radius, a profile's height
 * between samples, the monotone part of a profile that turns back, and the material left under
 * three passes, against brute force over the samples.
 */
import { describe, expect, it } from 'vitest';
import {
  lowestPassHeight,
  monotoneProfile,
  profileHeight,
  sectionRadiusMm,
} from '../../../src/core/output/sectionProfile';
import { profileCurves } from '../../../src/core/procedures/teaching';
import { PLANE } from '../../../src/core/surfaces/cylinder';

describe('the cross-feed section', () => {
  it('is curved only on a cylinder with its axis along the feed, with its signed radius', () => {
    expect(sectionRadiusMm(PLANE)).toBe(Number.POSITIVE_INFINITY);
    expect(sectionRadiusMm({ kind: 'cylinder', radiusMm: 12, axis: 'feed' })).toBe(12);
    expect(sectionRadiusMm({ kind: 'cylinder', radiusMm: -40, axis: 'feed' })).toBe(-40);
    expect(sectionRadiusMm({ kind: 'cylinder', radiusMm: 7, axis: 'cross' })).toBe(Number.POSITIVE_INFINITY);
  });

  it('a profile height: linear between samples, the later sample at a vertical wall, +infinity beyond its ends', () => {
    const pts = [-2, 1, -1, 0.25, 0, 0, 1, 0, 1, 0.5, 2, 2];
    expect(profileHeight(pts, -1.5)).toBeCloseTo(0.625, 15);
    expect(profileHeight(pts, 0.5)).toBe(0);
    expect(profileHeight(pts, 1)).toBe(0.5);
    expect(profileHeight(pts, 1.5)).toBeCloseTo(1.25, 15);
    expect(profileHeight(pts, -2)).toBe(1);
    expect(profileHeight(pts, 2)).toBe(2);
    expect(profileHeight(pts, -2.0001)).toBe(Number.POSITIVE_INFINITY);
    expect(profileHeight(pts, 2.0001)).toBe(Number.POSITIVE_INFINITY);
    expect(profileHeight([0, 0], 0)).toBe(Number.POSITIVE_INFINITY);
  });

  it('keeps a profile that goes outwards on both sides, and cuts one where a flank turns back', () => {
    // The plane profiles of a ball, a bull-nose tilted, a flat end with lead: s increases throughout.
    for (const tool of [
      { toolRadiusMm: 3, cornerRadiusMm: 3, leadAngleDeg: 5, tiltAngleDeg: 0 },
      { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 10 },
      { toolRadiusMm: 3, cornerRadiusMm: 0, leadAngleDeg: 5, tiltAngleDeg: 0 },
      { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 0, tiltAngleDeg: 0 },
    ]) {
      const { profile } = profileCurves(tool);
      expect([...monotoneProfile(profile)]).toEqual([...profile]);
    }
    // A flank that turns back at s = 2 (right) and at s = -1.5 (left): cut there.
    const turning = Float64Array.from([-1.2, 3, -1.5, 2, -1, 1, 0.1, 0, 1, 0.5, 2, 1, 1.9, 2, 2.5, 3]);
    expect([...monotoneProfile(turning)]).toEqual([-1.5, 2, -1, 1, 0.1, 0, 1, 0.5, 2, 1]);
  });

  it('the material left under three passes is the lowest pass there, mirrored passes included', () => {
    const { profile } = profileCurves({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 8 });
    const L = 1.6;
    for (const mirror of [1, -1] as const) {
      const centres = [-L, 0, L];
      const mirrors = [mirror, 1, mirror] as const;
      for (let s = -L; s <= L; s += 0.05) {
        // Brute force: each pass's height by its own linear interpolation over its shifted samples.
        let lowest = Number.POSITIVE_INFINITY;
        centres.forEach((c, i) => {
          const m = mirrors[i] as 1 | -1;
          const local = m * (s - c);
          for (let j = 0; j + 3 < profile.length; j += 2) {
            const [s0, h0, s1, h1] = [0, 1, 2, 3].map((k) => profile[j + k] as number) as [
              number,
              number,
              number,
              number,
            ];
            if (s0 <= local && local <= s1 && s1 > s0)
              lowest = Math.min(lowest, h0 + ((h1 - h0) * (local - s0)) / (s1 - s0));
          }
        });
        expect(Math.abs(lowestPassHeight(profile, centres, mirrors, s) - lowest)).toBeLessThan(1e-12);
      }
    }
  });
});
