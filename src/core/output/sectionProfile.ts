/**
 * The cross-feed section as the profile view draws it, pure: profiles of a pass as flat (s, h)
 * arrays (s across the feed from the contact, measured along the design surface; h above the
 * surface, radially; mm), the height of a pass's profile at a place, and the section's curvature.
 * On a plane s and h are the plain y and z; a surface enters only through its section's signed
 * radius (surfaceGeometry.ts maps (s, h) to the section's y and z).
 */
import type { Surface } from '../domain/surface';

/**
 * The signed radius of the design surface's section across the feed (mm): the cylinder's radius Rs
 * (convex > 0, concave < 0) when its axis runs along the feed, and +infinity for a plane and for a
 * cylinder with its axis across the feed (the section through the contact is then straight).
 */
export function sectionRadiusMm(surface: Surface): number {
  return surface.kind === 'cylinder' && surface.axis === 'feed' ? surface.radiusMm : Number.POSITIVE_INFINITY;
}

/**
 * The height of a profile (flat s, h with s non-decreasing) at `sMm`, linear between samples, or
 * +infinity outside its ends (no material is cut there). At a vertical wall (two samples at the
 * same s) it is the later sample's height, where the profile goes on.
 */
export function profileHeight(pts: ArrayLike<number>, sMm: number): number {
  const n = pts.length / 2;
  if (n < 2 || sMm < (pts[0] as number) || sMm > (pts[2 * (n - 1)] as number)) return Number.POSITIVE_INFINITY;
  let lo = 0;
  let hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if ((pts[2 * mid] as number) <= sMm) lo = mid;
    else hi = mid;
  }
  const s0 = pts[2 * lo] as number;
  const s1 = pts[2 * hi] as number;
  const h0 = pts[2 * lo + 1] as number;
  const h1 = pts[2 * hi + 1] as number;
  return s1 > s0 ? h0 + ((h1 - h0) * (sMm - s0)) / (s1 - s0) : Math.min(h0, h1);
}

/**
 * A profile (flat s, h) from its left end to its right end, keeping from the contact (the point
 * nearest s = 0) outwards only the points that go on outwards: in surface coordinates a flank can
 * turn back near its widest point, and {@link profileHeight} needs s increasing. A profile whose s
 * already increases throughout comes back unchanged (a copy).
 */
export function monotoneProfile(pts: Float64Array): Float64Array {
  const n = pts.length / 2;
  if (n < 2) return pts;
  let j0 = 0;
  for (let i = 1; i < n; i++) if (Math.abs(pts[2 * i] as number) < Math.abs(pts[2 * j0] as number)) j0 = i;
  // The kept run is [first, last] around j0: outwards while s keeps increasing (right) or decreasing (left).
  let last = j0;
  while (last + 1 < n && (pts[2 * last + 2] as number) > (pts[2 * last] as number)) last++;
  let first = j0;
  while (first > 0 && (pts[2 * first - 2] as number) < (pts[2 * first] as number)) first--;
  return pts.slice(2 * first, 2 * last + 2);
}

/**
 * The lowest of several passes' profiles at `sMm`: each pass is the profile `pts` with its contact
 * moved to `centresMm[i]` and mirrored across the feed where `mirrors[i]` is -1 (zigzag), so the
 * height of the material left there (+infinity where no pass reaches).
 */
export function lowestPassHeight(
  pts: ArrayLike<number>,
  centresMm: readonly number[],
  mirrors: readonly (1 | -1)[],
  sMm: number,
): number {
  let lowest = Number.POSITIVE_INFINITY;
  for (let i = 0; i < centresMm.length; i++) {
    const h = profileHeight(pts, (mirrors[i] as 1 | -1) * (sMm - (centresMm[i] as number)));
    if (h < lowest) lowest = h;
  }
  return lowest;
}
