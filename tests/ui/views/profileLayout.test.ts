/**
 * The cross-feed profile's layout (profileLayout.ts): the exaggeration a concave section allows,
 * the stretch shown, the band of heights drawn, the home box and the plot's growth.
 */
import { describe, expect, it } from 'vitest';
import {
  foldFreeExaggeration,
  grownHeightPx,
  homeBox,
  type ProfileLayoutInput,
  profileLayout,
} from '../../../src/ui/views/profileLayout';

const ROOM = { widthPx: 800, baseHeightPx: 320, maxHeightPx: 630 };
const BASE: ProfileLayoutInput = {
  toolRadiusMm: 3,
  intervalMm: 2,
  cuspHeightMm: 0.05,
  highestCuspMm: 0.05,
  contactOffsetMm: 0,
  sectionRadiusMm: Number.POSITIVE_INFINITY,
  wantedK: 5,
  room: ROOM,
};

describe('the profile layout', () => {
  it('keeps the exaggeration below folding a concave trough over, to a step, and leaves others alone', () => {
    // Band 0.2 mm in a trough of radius 40: k h <= |Rs| / 2 allows 100, not 200.
    expect(foldFreeExaggeration(100, -40, 0.2)).toBe(100);
    expect(foldFreeExaggeration(200, -40, 0.2)).toBe(100);
    expect(foldFreeExaggeration(200, -30, 0.2)).toBe(50);
    expect(foldFreeExaggeration(1000, 12, 0.2)).toBe(1000);
    expect(foldFreeExaggeration(1000, Number.POSITIVE_INFINITY, 0.2)).toBe(1000);
    // Not even x1 folds free: x1 (true scale) still.
    expect(foldFreeExaggeration(5, -0.1, 0.2)).toBe(1);
  });

  it('shows three passes with a margin, the tool centre, and at most 0.98 of half a turn of a curved section', () => {
    const plane = profileLayout(BASE);
    expect(plane.fromMm).toBeCloseTo(-2.6, 12);
    expect(plane.toMm).toBeCloseTo(2.6, 12);
    expect(plane.d).toBeCloseTo(0.03 * 5.2, 12);
    const offset = profileLayout({ ...BASE, contactOffsetMm: 4 });
    expect(offset.fromMm).toBeCloseTo(-4.3, 12);
    const small = profileLayout({ ...BASE, sectionRadiusMm: 0.5 });
    expect(small.fromMm).toBeCloseTo(-0.98 * Math.PI * 0.5, 12);
    expect(small.toMm).toBeCloseTo(0.98 * Math.PI * 0.5, 12);
    expect(profileLayout({ ...BASE, sectionRadiusMm: -40, wantedK: 200 }).k).toBe(100);
  });

  it('draws heights up to min(R, 4h), less when the exaggerated band would not fit the plot, never below 1.5 cusps', () => {
    expect(profileLayout(BASE).topMm).toBeCloseTo(0.2, 15);
    expect(profileLayout({ ...BASE, cuspHeightMm: 2, highestCuspMm: 2, wantedK: 1 }).topMm).toBe(3);
    // x100: the band that fits the plot's room: (630 / 800 * 5.2 - 6 * 0.156) / 100 mm.
    const fits = ((630 / 800) * 5.2 - 6 * 0.03 * 5.2) / 100;
    expect(profileLayout({ ...BASE, wantedK: 100 }).topMm).toBeCloseTo(Math.max(fits, 0.075), 12);
    expect(profileLayout({ ...BASE, wantedK: 1000 }).topMm).toBeCloseTo(0.075, 15);
  });

  it('home: all of the drawing, d to spare above; the plot grows to fit it, within its room', () => {
    expect(homeBox(-2, 3, -1, 0.5, 0.1)).toEqual({ x: -2, y: -1.1, w: 5, h: 1.6 });
    expect(grownHeightPx(ROOM, { x: 0, y: 0, w: 10, h: 2 }, true)).toBeNull();
    expect(grownHeightPx(ROOM, { x: 0, y: 0, w: 10, h: 5 }, true)).toBe(400);
    expect(grownHeightPx(ROOM, { x: 0, y: 0, w: 10, h: 50 }, true)).toBe(630);
    expect(grownHeightPx(ROOM, { x: 0, y: 0, w: 10, h: 5 }, false)).toBeNull();
  });
});
