/**
 * Gouging of a surface of revolution by an upright tool, decided exactly in the meridian plane
 * (frame of meridianTool.ts). The surface is the torus patch of the notes: the meridian circle
 * (centre `M = -Rc n0`, radius `|Rc|`; a line when `Rc` is infinite) turned about the vertical
 * axis at `s = sAxis = -Rf sin alpha0` (none when `Rf` is infinite). Material and tool are both
 * solids of revolution about that axis once the tool is turned along its pass, so gouging in 3D
 * is gouging in a half-plane through the axis: the tool's profile on the CC side of the axis
 * against the meridian, and the part of the profile across the axis mirrored back onto it.
 *
 * Material, in the CC side's half-plane: inside the circle (convex `Rc`), below the line
 * (straight), outside the circle up to the height of its centre (concave: the trough's walls
 * rise to there; the shank counts, as in the notes' troughs). The tool's profile region is
 * convex and touches the meridian at the CC point with the common tangent between them, so on
 * the CC side a convex or straight meridian is never gouged; a concave one is gouged when the
 * region (clipped at the centre's height) reaches farther than `|Rc|` from `M`; across the axis
 * the mirrored region must keep its distance from `M` (convex), stay within it (concave) or
 * stay above the line. The extreme distances of the clipped region are taken over its boundary
 * pieces in closed form (the corners' circles, the flat bottom's ends, the clip corners).
 */
import type { MeridianTool } from './meridianTool';

/** The surface as the gouging test sees it (frame of meridianTool.ts, mm). */
export interface RevolutionSurface {
  /** Signed meridian curvature 1/Rc (1/mm), 0 when straight. */
  readonly k: number;
  /** The meridian's centre (when k != 0), and its radius |Rc|. */
  readonly centreS: number;
  readonly centreZ: number;
  readonly radius: number;
  /** Surface normal at the upper CC point (the line's normal when straight). */
  readonly n0s: number;
  readonly n0z: number;
  /** The axis of revolution `s = sAxis`, or null (Rf infinite). */
  readonly axisS: number | null;
  /** +1 when the CC side is `s > sAxis` (Rf > 0, a dome), -1 when `s < sAxis` (Rf < 0, a bowl). */
  readonly side: 1 | -1;
}

/** The surface of slope alpha0 (sine, cosine), meridian radius `Rc` and feed radius `Rf` (null: infinite), mm. */
export function revolutionSurface(
  sin0: number,
  cos0: number,
  crossRadiusMm: number | null,
  feedRadiusMm: number | null,
): RevolutionSurface {
  const rc = crossRadiusMm;
  return {
    k: rc === null ? 0 : 1 / rc,
    centreS: rc === null ? 0 : -rc * sin0,
    centreZ: rc === null ? 0 : -rc * cos0,
    radius: rc === null ? Number.POSITIVE_INFINITY : Math.abs(rc),
    n0s: sin0,
    n0z: cos0,
    axisS: feedRadiusMm === null ? null : -feedRadiusMm * sin0,
    side: feedRadiusMm !== null && feedRadiusMm < 0 ? -1 : 1,
  };
}

/** Lower boundary of the tool (tip at (ts, tz)) at s, +Infinity outside its footprint. */
function lowerZ(t: MeridianTool, ts: number, tz: number, s: number): number {
  const a = Math.abs(s - ts);
  if (a <= t.rb) return tz;
  if (a > t.R) return Number.POSITIVE_INFINITY;
  const w = Math.min(a - t.rb, t.rcr);
  return tz + (w * w) / (t.rcr + Math.sqrt((t.rcr - w) * (t.rcr + w)));
}

/** Distance (mm) in the meridian plane from (qs, qz) to (s, z), both mm. */
function meridianDistanceMm(qs: number, qz: number, s: number, z: number): number {
  const ds = s - qs;
  const dz = z - qz;
  return Math.sqrt(ds * ds + dz * dz);
}

/** Half-width (mm) of the tool's footprint at height `dzAboveTip` above its tip (the slice radius). */
function sliceRadius(t: MeridianTool, dzAboveTip: number): number {
  if (dzAboveTip < 0) return -1;
  if (dzAboveTip >= t.rcr) return t.R;
  const q = t.rcr - dzAboveTip;
  return t.rb + Math.sqrt((t.rcr - q) * (t.rcr + q));
}

/** The tool region with its tip at (ts, tz), clipped to `sLo <= s <= sHi` (mm). */
interface ClippedTool {
  readonly t: MeridianTool;
  readonly ts: number;
  readonly tz: number;
  readonly sLo: number;
  readonly sHi: number;
}

/**
 * Largest distance (mm) from (qs, qz) over the clipped tool region at `z <= cap`; -Infinity when
 * that part is empty.
 */
function maxDistance(c: ClippedTool, qs: number, qz: number, cap: number): number {
  const { t, ts, tz, sLo, sHi } = c;
  const half = sliceRadius(t, cap - tz);
  if (half < 0) return Number.NEGATIVE_INFINITY;
  const a = Math.max(sLo, ts - half);
  const b = Math.min(sHi, ts + half);
  if (a > b) return Number.NEGATIVE_INFINITY;
  let best = Number.NEGATIVE_INFINITY;
  const take = (s: number, z: number) => {
    const d = meridianDistanceMm(qs, qz, s, z);
    if (d > best) best = d;
  };
  take(a, Math.min(cap, lowerZ(t, ts, tz, a)));
  take(b, Math.min(cap, lowerZ(t, ts, tz, b)));
  if (Number.isFinite(cap)) {
    take(a, cap);
    take(b, cap);
  }
  for (const e of [ts - t.rb, ts + t.rb]) if (e >= a && e <= b) take(e, tz);
  cornerExtremes(t, ts, tz, qs, qz, a, b, cap, true, take);
  return best;
}

/**
 * Hands `take` the point of each corner circle farthest from q (or nearest to it), where it lies on
 * the circle's lower quarter, within `a <= s <= b` and at most `cap` high.
 */
function cornerExtremes(
  t: MeridianTool,
  ts: number,
  tz: number,
  qs: number,
  qz: number,
  a: number,
  b: number,
  cap: number,
  farthest: boolean,
  take: (s: number, z: number) => void,
): void {
  if (!(t.rcr > 0)) return;
  for (const sign of [-1, 1]) {
    const cs = ts + sign * t.rb;
    const cz = tz + t.rcr;
    const ds = farthest ? cs - qs : qs - cs;
    const dz = farthest ? cz - qz : qz - cz;
    const d = Math.sqrt(ds * ds + dz * dz);
    if (!(d > 0)) continue;
    const ps = cs + (t.rcr * ds) / d;
    const pz = cz + (t.rcr * dz) / d;
    if (sign * (ps - cs) >= 0 && pz <= cz && ps >= a && ps <= b && pz <= cap) take(ps, pz);
  }
}

/** Smallest distance (mm) from (qs, qz) to the clipped tool region. */
function minDistance(c: ClippedTool, qs: number, qz: number): number {
  const { t, ts, tz, sLo, sHi } = c;
  const a = Math.max(sLo, ts - t.R);
  const b = Math.min(sHi, ts + t.R);
  if (a > b) return Number.POSITIVE_INFINITY;
  if (qs >= a && qs <= b && qz >= lowerZ(t, ts, tz, qs)) return 0;
  let best = Number.POSITIVE_INFINITY;
  const take = (s: number, z: number) => {
    const d = meridianDistanceMm(qs, qz, s, z);
    if (d < best) best = d;
  };
  // The clip edges (vertical rays up from the lower boundary).
  for (const e of [a, b]) {
    const low = lowerZ(t, ts, tz, e);
    take(e, Math.max(qz, low));
  }
  // The flat bottom.
  const fa = Math.max(a, ts - t.rb);
  const fb = Math.min(b, ts + t.rb);
  if (fa <= fb) take(Math.min(fb, Math.max(fa, qs)), tz);
  for (const e of [ts - t.R, ts + t.R]) if (e >= a && e <= b) take(e, tz + t.rcr);
  cornerExtremes(t, ts, tz, qs, qz, a, b, Number.POSITIVE_INFINITY, false, take);
  return best;
}

/** Smallest value of `ds * s + dz * z` (dz > 0) over the clipped tool region; +Infinity when empty. */
function minLinear(c: ClippedTool, ds: number, dz: number): number {
  const { t, ts, tz, sLo, sHi } = c;
  const a = Math.max(sLo, ts - t.R);
  const b = Math.min(sHi, ts + t.R);
  if (a > b) return Number.POSITIVE_INFINITY;
  let best = Number.POSITIVE_INFINITY;
  const take = (s: number, z: number) => {
    const v = ds * s + dz * z;
    if (v < best) best = v;
  };
  take(a, lowerZ(t, ts, tz, a));
  take(b, lowerZ(t, ts, tz, b));
  for (const e of [ts - t.rb, ts + t.rb]) if (e >= a && e <= b) take(e, tz);
  if (t.rcr > 0) {
    const d = Math.sqrt(ds * ds + dz * dz);
    for (const sign of [-1, 1]) {
      const cs = ts + sign * t.rb;
      const cz = tz + t.rcr;
      const ps = cs - (t.rcr * ds) / d;
      const pz = cz - (t.rcr * dz) / d;
      if (sign * (ps - cs) >= 0 && pz <= cz && ps >= a && ps <= b) take(ps, pz);
    }
  }
  return best;
}

/**
 * How deep (mm) the tool with its tip at (ts, tz) reaches into the material, 0 when it does not
 * (tangency at the CC point counts as not gouging: a relative tolerance of 1e-12 absorbs the
 * rounding of the distances).
 */
export function gougeDepthMm(t: MeridianTool, surf: RevolutionSurface, ts: number, tz: number): number {
  const tol = 1e-12 * (t.R + (Number.isFinite(surf.radius) ? surf.radius : 0) + Math.abs(surf.axisS ?? 0));
  let depth = 0;
  const inf = Number.POSITIVE_INFINITY;
  const axis = surf.axisS;
  // The CC side's and the far side's s ranges.
  const ccLo = axis === null ? -inf : surf.side > 0 ? axis : -inf;
  const ccHi = axis === null ? inf : surf.side > 0 ? inf : axis;
  if (surf.k < 0) {
    const far =
      maxDistance({ t, ts, tz, sLo: ccLo, sHi: ccHi }, surf.centreS, surf.centreZ, surf.centreZ) - surf.radius;
    if (far > depth) depth = far;
  }
  if (axis !== null) {
    const lo = surf.side > 0 ? -inf : axis;
    const hi = surf.side > 0 ? axis : inf;
    // Mirrored centre (distances from the mirrored point are the mirrored region's distances).
    const ms = 2 * axis - surf.centreS;
    const mirrored: ClippedTool = { t, ts, tz, sLo: lo, sHi: hi };
    if (surf.k > 0) {
      const gap = surf.radius - minDistance(mirrored, ms, surf.centreZ);
      if (gap > depth) depth = gap;
    } else if (surf.k < 0) {
      const far = maxDistance(mirrored, ms, surf.centreZ, surf.centreZ) - surf.radius;
      if (far > depth) depth = far;
    } else {
      // Mirrored points Q' = (2 axis - s, z) must satisfy Q'.n0 >= 0: 2 axis n0s + (-n0s) s + n0z z >= 0.
      const below = -(2 * axis * surf.n0s + minLinear(mirrored, -surf.n0s, surf.n0z));
      if (below > depth) depth = below;
    }
  }
  return depth > tol ? depth : 0;
}
