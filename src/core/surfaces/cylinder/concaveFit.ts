/**
 * Gouging on a concave cylinder (see ../cylinder.ts's module comment): the smallest radius the
 * tool's head and its shank fit in. Lengths mm, angles degrees where named so.
 */

import type { SurfaceAxis } from '../../domain/surface';
import type { ToolInput } from '../../domain/tool';
import { radToDeg } from '../../input/units';
import { goldenMinimum } from '../../math/rootFinder';
import { type Placement, placeTool } from '../../tool/placement';

/**
 * The smallest concave radius |Rs| (mm) the tool end (its head) fits in without gouging: the maximum over the
 * ring of `(E^2 + E_z^2 - Rcr^2) / (2 (E_z - Rcr))`, written `E^2 / (2 rise) + (rise + 2 Rcr) / 2`
 * with `rise = E_z - Rcr` the ring point's height above the contact's ring point (Eq. 1
 * generalised, `2 D0 sin^2(delta/2)`) and E its horizontal offset (the chord: seen along the feed
 * for axis = feed, along the axis for axis = cross), so that the contact's neighbourhood keeps its
 * digits: there the value tends to the curvature radius of the view. Infinity when the tool gouges
 * every concave cylinder (a ring point other than the contact at the contact's height: a flat
 * bottom without lead across the axis). Sampled over the ring, then refined by golden-section search.
 */
function headMinConcaveRadiusMm(p: Placement, axis: SurfaceAxis): number {
  const s = p.shape;
  const rb = p.ringRadiusMm;
  const rcr = p.cornerRadiusMm;
  if (!(rb > 0)) return rcr; // a ball end fits any trough of at least its radius
  const t0 = p.contactRingAngleRad;
  const k = axis === 'feed' ? 1 : 0;
  const ratio = (delta: number): number => {
    const half = Math.sin(delta / 2);
    const rise = 2 * s.d0 * half * half;
    const m = t0 + delta / 2;
    // Chord of the ring from the contact's ring point: 2 sin(delta/2) (cos m v1 - sin m v2), times Rb.
    const e = 2 * half * rb * (Math.cos(m) * p.v1[k] - Math.sin(m) * p.v2[k]);
    if (!(rise > 0)) return e === 0 ? 0 : Number.POSITIVE_INFINITY;
    return (e * e) / (2 * rise) + (rise + 2 * rcr) / 2;
  };
  if (!(s.d0 > 0)) return Number.POSITIVE_INFINITY;
  const n = 720;
  let best = 1;
  let value = 0;
  for (let i = 1; i < n; i++) {
    const v = ratio((2 * Math.PI * i) / n);
    if (v > value) {
      value = v;
      best = i;
    }
  }
  if (!Number.isFinite(value)) return value;
  const a = (2 * Math.PI * (best - 1)) / n;
  const b = (2 * Math.PI * (best + 1)) / n;
  const peak = goldenMinimum({ value: (delta: number) => -ratio(delta) }, a, b, 0, b, 100);
  // Near the contact the ratio tends to the local curvature radius: include that limit.
  return Math.max(value, ratio(peak), ratio(1e-7), ratio(2 * Math.PI - 1e-7));
}

/**
 * The smallest concave radius |Rs| (mm) at and above which the shank stays inside the cylinder up to
 * the height of its axis (shared/notes/posture-and-surfaces.md): 0 when it never meets the wall,
 * Infinity when it does at any radius. Seen along the axis (along the feed for axis = feed, along Y
 * for cross), the shank is a strip of half-width R around the projected tool axis, leaning from the
 * normal by `k = a_w / a_z` (w the horizontal of the view); its edges start on the head at the two
 * equator points `J = O +- R c`, c = a x view / |a x view|. An edge stays inside up to the axis
 * height rho iff, where it reaches that height, `|J_w + k (rho - J_z)| <= rho` (the distance from the
 * axis is convex along the edge, and its start J lies on the head, inside). Each side is a condition
 * `m rho >= q`: with m > 0 it holds from `q / m` up; with m <= 0 and q > 0 it fails at every radius
 * above J_z (a lean of 45 degrees or more towards the wall: the chord from the contact to the wall
 * at the axis height leans 45 degrees). Radii up to J_z, where the edge starts above the axis
 * height, are not needed: the head's own limit lies above them in every posture measured.
 */
function shankMinConcaveRadiusMm(p: Placement, axis: SurfaceAxis): number {
  const a = p.axis;
  const R = p.ringRadiusMm + p.cornerRadiusMm;
  // View along X (feed): w = Y; along Y (cross): w = X. c = a x view, normalised.
  const w = axis === 'feed' ? 1 : 0;
  const cw = axis === 'feed' ? a[2] : -a[2];
  const cz = axis === 'feed' ? -a[1] : a[0];
  const cn = Math.sqrt(cw * cw + cz * cz);
  const k = a[w] / a[2];
  let need = 0;
  for (const edge of [1, -1]) {
    const jw = (p.centre[w] as number) + (edge * R * cw) / cn;
    const jz = (p.centre[2] as number) + (edge * R * cz) / cn;
    const w0 = jw - k * jz;
    for (const s of [1, -1]) {
      // s = 1: w <= rho (the wall at +w); s = -1: w >= -rho.
      const m = 1 - s * k;
      const q = s * w0;
      if (m > 0) {
        if (q / m > jz) need = Math.max(need, q / m);
      } else if (q > 0 || m < 0) return Number.POSITIVE_INFINITY;
    }
  }
  return need;
}

/** What a concave cylinder must be for a tool and posture, and why (mm, degrees). */
export interface ConcaveFit {
  /** Smallest radius |Rs| the head (corner and bottom) fits in; Infinity if none. */
  readonly headMm: number;
  /** Smallest radius from which the shank stays inside up to the axis height; 0 if any, Infinity if none. */
  readonly shankMm: number;
  /** The smallest admissible radius: the larger of both. */
  readonly minRadiusMm: number;
  /** Which of them sets it (the head on a tie). */
  readonly limitedBy: 'head' | 'shank';
  /**
   * The shank's lean from the surface normal seen along the cylinder's axis, degrees (>= 0): the
   * projected lean `atan(tan(beta) / cos(rho))` along the feed, the lead rho across it.
   */
  readonly shankLeanDeg: number;
}

/**
 * Whether and from which radius a concave cylinder takes the tool (gouging by the head or the
 * shank): see headMinConcaveRadiusMm and shankMinConcaveRadiusMm.
 * @param tool validated tool and posture. @param axis the cylinder's axis.
 */
export function concaveFit(tool: ToolInput, axis: SurfaceAxis): ConcaveFit {
  const p = placeTool(tool);
  const headMm = headMinConcaveRadiusMm(p, axis);
  const shankMm = shankMinConcaveRadiusMm(p, axis);
  const a = p.axis;
  const lean = Math.atan2(Math.abs(axis === 'feed' ? a[1] : a[0]), a[2]);
  return {
    headMm,
    shankMm,
    minRadiusMm: Math.max(headMm, shankMm),
    limitedBy: shankMm > headMm ? 'shank' : 'head',
    shankLeanDeg: radToDeg(lean),
  };
}

/**
 * The smallest concave radius |Rs| (mm) that takes the tool in its posture without gouging: the
 * larger of the head's and the shank's limits (concaveFit); Infinity when no radius does.
 * @param tool validated tool and posture. @param axis the cylinder's axis.
 */
export function minConcaveRadiusMm(tool: ToolInput, axis: SurfaceAxis): number {
  return concaveFit(tool, axis).minRadiusMm;
}
