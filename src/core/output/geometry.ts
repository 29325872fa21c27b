/**
 * Geometry a viewer draws for a solved state: the tool's placement, the section and `P_hp` at
 * each cusp, the curve where the torus meets the plane at the scallop height, and the
 * cross-feed profile. Pure functions returning plain numbers and typed arrays (mm; frame of
 * placement.ts: contact at the origin, X feed, Z up).
 */

import type { ToolInput } from '../domain/tool';
import { bisect } from '../math/rootFinder';
import { cross, dot, norm, type Vec3 } from '../math/vec';
import {
  cutSection,
  type Placement,
  placeTool,
  ringRadial,
  ringTangent,
  sectionCentre,
  sectionPoint,
} from '../tool/placement';
import { type Flank, type FlankPoint, flankAtHeight } from '../tool/posture';
import { profilePolyline } from '../tool/profile';

/** The section circle through one cusp point `P_hp` and the point itself. */
export interface CuspSection {
  readonly flank: Flank;
  /** Ring angle of the section (radians). */
  readonly ringAngleRad: number;
  /** The point of the torus at the cusp height farthest out on this flank (mm). */
  readonly pHp: Vec3;
  readonly sectionCentre: Vec3;
  /** Unit normal of the section's plane (the ring tangent). */
  readonly sectionNormal: Vec3;
  readonly sectionRadiusMm: number;
}

/**
 * The section through the flank point `f` (from posture.ts) and the point itself. For a ball end
 * (Rb = 0) every meridian plane is a section: the one containing the axis and P_hp is used.
 */
export function cuspSection(p: Placement, flank: Flank, f: FlankPoint): CuspSection {
  const sign = flank === 'right' ? 1 : -1;
  const t0 = p.contactRingAngleRad;
  const rcr = p.cornerRadiusMm;
  // Outward normal of the profile at the point, in YZ: (sign sin theta, -cos theta).
  const normal: Vec3 = [0, sign * Math.sin(f.normalAngleRad), -Math.cos(f.normalAngleRad)];
  if (p.ringRadiusMm === 0) {
    const pHp: Vec3 = [p.centre[0] + rcr * normal[0], p.centre[1] + rcr * normal[1], p.centre[2] + rcr * normal[2]];
    const n = cross(p.axis, normal);
    const len = norm(n);
    // The axis along the normal (a point straight below a vertical axis): any meridian; take the XZ one.
    const sectionNormal: Vec3 = len > 1e-12 ? [n[0] / len, n[1] / len, n[2] / len] : [0, 1, 0];
    const d: Vec3 = [normal[0], normal[1], normal[2]];
    const ring = Math.atan2(dot(d, p.v1), dot(d, p.v2));
    return { flank, ringAngleRad: ring, pHp, sectionCentre: p.centre, sectionNormal, sectionRadiusMm: rcr };
  }
  const t = t0 + sign * f.ringOffsetRad;
  const centre = sectionCentre(p, t);
  const pHp: Vec3 = [centre[0] + rcr * normal[0], centre[1] + rcr * normal[1], centre[2] + rcr * normal[2]];
  return { flank, ringAngleRad: t, pHp, sectionCentre: centre, sectionNormal: ringTangent(p, t), sectionRadiusMm: rcr };
}

/** Ring angles where the ring height z(t) = O_z + Rb r_z(t) equals `z` (up to two), radians. */
function ringHeightRoots(p: Placement, z: number): number[] {
  // r_z(t) = sin t v1_z + cos t v2_z = M cos(t - mu)
  const m = Math.hypot(p.v1[2], p.v2[2]);
  if (!(m > 0) || !(p.ringRadiusMm > 0)) return [];
  const mu = Math.atan2(p.v1[2], p.v2[2]);
  const c = (z - p.centre[2]) / (p.ringRadiusMm * m);
  if (!(Math.abs(c) <= 1)) return [];
  const spread = Math.acos(c);
  return [mu - spread, mu + spread];
}

/** Ring angles where the ring height is extreme (t = mu, mu + pi). */
function ringHeightExtremes(p: Placement): number[] {
  const mu = Math.atan2(p.v1[2], p.v2[2]);
  return [mu, mu + Math.PI];
}

const TAU = 2 * Math.PI;

function wrap(t: number): number {
  const w = t % TAU;
  return w < 0 ? w + TAU : w;
}

/** Intervals of ring angle in [0, 2pi) (possibly wrapping) where the sections meet the plane. */
function meetingIntervals(p: Placement, h: number, must: readonly number[]): Array<[number, number]> {
  const k = p.cornerRadiusMm;
  const gap = (t: number) => Math.abs(cutSection(p, t, h).inPlaneDistanceMm) - k;
  // Candidates: a uniform scan, plus every angle where the ring crosses the plane, where a band
  // can be as narrow as a tiny corner, the ring's extremes and the cusp sections themselves.
  const candidates = new Set<number>();
  const steps = 360;
  for (let i = 0; i < steps; i++) candidates.add((TAU * i) / steps);
  for (const t of [...ringHeightRoots(p, h), ...ringHeightRoots(p, h - k), ...ringHeightRoots(p, h + k)])
    candidates.add(wrap(t));
  for (const t of [...ringHeightExtremes(p), ...must]) candidates.add(wrap(t));
  const ts = [...candidates].sort((x, y) => x - y);
  const inside = ts.map((t) => gap(t) <= 0);
  if (inside.every((v) => v)) return [[0, TAU]];
  if (!inside.some((v) => v)) return [];
  const edge = (a: number, b: number, aInside: boolean) => {
    const { lo, hi } = bisect((t) => gap(t) <= 0 === aInside, a, b, 60);
    return aInside ? lo : hi;
  };
  const starts: number[] = [];
  const ends: number[] = [];
  const n = ts.length;
  for (let i = 0; i < n; i++) {
    const a = ts[i] as number;
    const b = i + 1 < n ? (ts[i + 1] as number) : (ts[0] as number) + TAU;
    const ai = inside[i] as boolean;
    const bi = inside[(i + 1) % n] as boolean;
    if (ai && !bi) ends.push(edge(a, b, true));
    else if (!ai && bi) starts.push(edge(a, b, false));
  }
  starts.sort((x, y) => x - y);
  const out: Array<[number, number]> = [];
  for (const s of starts) {
    // The band starting at s ends at the first end after it (mod 2pi).
    let best = Number.POSITIVE_INFINITY;
    for (const e of ends) {
      const d = wrap(e - s);
      if (d < best) best = d;
    }
    out.push([s, s + best]);
  }
  return out;
}

function pushBranch(
  out: number[],
  p: Placement,
  h: number,
  t0: number,
  t1: number,
  n: number,
  side: 0 | 1,
  extra: readonly number[],
): void {
  const ts: number[] = [];
  for (let i = 0; i <= n; i++) {
    // Cosine spacing: crossings move fastest near the single-contact ends.
    const u = i / n;
    ts.push(t0 + (t1 - t0) * 0.5 * (1 - Math.cos(Math.PI * u)));
  }
  for (const t of extra) {
    // The cusp sections (farthest crossings) are included exactly.
    let w = t;
    while (w < t0) w += TAU;
    while (w > t1) w -= TAU;
    if (w >= t0 && w <= t1) ts.push(w);
  }
  ts.sort((x, y) => x - y);
  if (side === 1) ts.reverse();
  for (const t of ts) {
    const cut = cutSection(p, t, h);
    if (cut.psi === null) continue;
    const psi = cut.psi[side];
    // Where the corner is wider than the ring (Rcr > Rb, a near-ball) a section crosses the axis:
    // a crossing beyond it lies inside the tool (nearer the opposite ring point), not on its surface.
    if (p.ringRadiusMm + p.cornerRadiusMm * Math.cos(psi) < 0) continue;
    const q = sectionPoint(p, t, psi);
    out.push(q[0], q[1], q[2]);
  }
}

/**
 * The curve where the torus meets the plane z = h, as closed polylines (flat xyz arrays, mm),
 * with the cusp sections' crossings included exactly (so the curve reaches both P_hp). Crossings
 * that lie beyond the axis (a corner wider than the ring) are inside the tool and left out, so a
 * near-ball's loop may jump across them. For a flat
 * end (Rcr = 0) the ring crosses the plane at two points and the plane cuts the flat bottom
 * along the chord between them: a two-point loop.
 * @param cuspRingAngles ring angles of the sections through P_hp (included in the sampling).
 * @param samples points per branch (8 to 4096).
 */
export function intersectionLoops(
  p: Placement,
  h: number,
  cuspRingAngles: readonly number[],
  samples = 96,
): Float64Array[] {
  const n = Math.max(8, Math.min(4096, Math.round(samples)));
  if (p.cornerRadiusMm === 0) {
    const roots = ringHeightRoots(p, h);
    if (roots.length < 2) return [];
    return [Float64Array.from([...sectionCentre(p, roots[0] as number), ...sectionCentre(p, roots[1] as number)])];
  }
  const intervals = meetingIntervals(p, h, cuspRingAngles);
  if (intervals.length === 1 && (intervals[0] as [number, number])[1] - (intervals[0] as [number, number])[0] >= TAU) {
    // Every section meets the plane: two closed curves, one per crossing.
    const first: number[] = [];
    const second: number[] = [];
    pushBranch(first, p, h, 0, TAU, 2 * n, 0, cuspRingAngles);
    pushBranch(second, p, h, 0, TAU, 2 * n, 1, cuspRingAngles);
    return [Float64Array.from(first), Float64Array.from(second)];
  }
  return intervals.map(([t0, t1]) => {
    const pts: number[] = [];
    pushBranch(pts, p, h, t0, t1, n, 0, cuspRingAngles);
    pushBranch(pts, p, h, t0, t1, n, 1, cuspRingAngles);
    return Float64Array.from(pts);
  });
}

/** What a viewer draws for one pass at a solved state (mm, contact at the origin). */
export interface PassGeometry {
  readonly toolCentre: Vec3;
  readonly toolAxis: Vec3;
  /** Contact offset y0 (Y of the contact minus Y of O). */
  readonly contactOffsetMm: number;
  /** The sections through the cusp points on each flank. */
  readonly right: CuspSection;
  readonly left: CuspSection;
  /** Torus / plane curves at the height of each flank's cusp (one set when the heights agree). */
  readonly loopsRight: Float64Array[];
  readonly loopsLeft: Float64Array[];
  /** The cross-feed profile (y, z) relative to the contact. */
  readonly profile: Float64Array;
}

/**
 * The geometry of a pass whose right cusp stands `rightHeightMm` and left cusp `leftHeightMm`
 * above the contact (equal for one-way passes). @param tool validated tool and posture.
 */
export function passGeometry(tool: ToolInput, rightHeightMm: number, leftHeightMm: number, samples = 96): PassGeometry {
  const p = placeTool(tool);
  const right = cuspSection(p, 'right', flankAtHeight(p.shape, 'right', rightHeightMm));
  const left = cuspSection(p, 'left', flankAtHeight(p.shape, 'left', leftHeightMm));
  const same = rightHeightMm === leftHeightMm;
  const cusps = [right.ringAngleRad, left.ringAngleRad];
  const loopsRight = intersectionLoops(p, rightHeightMm, same ? cusps : [right.ringAngleRad], samples);
  const loopsLeft = same ? loopsRight : intersectionLoops(p, leftHeightMm, [left.ringAngleRad], samples);
  return {
    toolCentre: p.centre,
    toolAxis: p.axis,
    contactOffsetMm: -p.centre[1],
    right,
    left,
    loopsRight,
    loopsLeft,
    profile: profilePolyline(p.shape, samples),
  };
}

export { ringRadial };
