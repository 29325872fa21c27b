/**
 * Brute-force cusp heights on a cylinder, sharing nothing with src/core/surfaces/cylinder.ts: points of the
 * real tool surface (the lower outer quarter of the torus, the bottom disk and, on request, the
 * shank, in the tool's posture; placement.ts only places the tool) are swept as the passes run,
 * and the material left is read on bins of the cross-section.
 *
 * Axis along the feed: a pass translates along X, so a point (y, z) of the tool stays at that
 * cross-section position; the next pass is the tool turned about the axis by phi = L / |Rs|
 * (mirrored in y for zigzag). Bins are polar angles about the axis; a convex cylinder keeps the
 * smallest radius per bin (the tool is outside), a concave one the largest.
 * Axis across the feed: a pass turns the tool about the axis (along Y): a point keeps its y and its
 * distance from the axis; the next pass is translated by L along Y. Bins are positions along Y.
 *
 * The cusp between two passes is the highest (convex) or lowest (concave) radius of the material
 * left between their contacts; its radial height is returned. Error: a bin's value can be off by
 * its width times the slope, and by the sample spacing along the surface; both shrink with the
 * resolution.
 */

import type { PassPattern, ToolInput } from '../../src/core/input/validate';
import { placeTool } from '../../src/core/tool/placement';

export interface BruteForceCylinder {
  /** Radial heights of the cusps between pass k and k + 1, mm. */
  readonly cuspHeightsMm: number[];
  /**
   * Error bound on each cusp, mm: the sample spacing (a sample within that distance of the true
   * lowest point along the surface) plus a bin's width (arc length at the cusp's radius, or along
   * the axis) times the largest slope of the material left between neighbouring bins.
   */
  readonly boundMm: number;
}

/** Largest |difference| of neighbouring finite bins divided by their spacing (mm per mm). */
function largestSlope(values: Float64Array, widthMm: number): number {
  let s = 0;
  for (let b = 1; b < values.length; b++) {
    const a = values[b - 1] as number;
    const c = values[b] as number;
    if (Number.isFinite(a) && Number.isFinite(c) && a > 0 && c > 0) s = Math.max(s, Math.abs(c - a) / widthMm);
  }
  return s;
}

export function bruteForceCylinder(
  tool: ToolInput,
  pattern: PassPattern,
  radiusMm: number,
  axis: 'feed' | 'cross',
  intervalMm: number,
  options: {
    readonly spacingMm: number;
    readonly bins: number;
    readonly passes?: number;
    /** Length of shank (radius R, above the corner) sampled too, mm; 0 (default) leaves it out. */
    readonly shankLengthMm?: number;
  },
): BruteForceCylinder {
  const p = placeTool(tool);
  const rs = radiusMm;
  const convex = rs > 0;
  const passes = options.passes ?? 3;
  const ds = options.spacingMm;
  // Tool surface points relative to the contact: (x, y, z).
  const pts: number[] = [];
  const rb = p.ringRadiusMm;
  const rcr = p.cornerRadiusMm;
  const nT = Math.max(64, Math.ceil((2 * Math.PI * (rb + rcr)) / ds));
  for (let i = 0; i < nT; i++) {
    const t = (2 * Math.PI * i) / nT;
    const r = [
      Math.sin(t) * p.v1[0] + Math.cos(t) * p.v2[0],
      Math.sin(t) * p.v1[1] + Math.cos(t) * p.v2[1],
      Math.sin(t) * p.v1[2] + Math.cos(t) * p.v2[2],
    ] as const;
    const nPsi = Math.max(4, Math.ceil(((Math.PI / 2) * rcr) / ds));
    for (let j = 0; j <= nPsi; j++) {
      const psi = -Math.PI / 2 + ((Math.PI / 2) * j) / nPsi;
      const c = rb + rcr * Math.cos(psi);
      const a = rcr * Math.sin(psi);
      pts.push(
        p.centre[0] + c * r[0] + a * p.axis[0],
        p.centre[1] + c * r[1] + a * p.axis[1],
        p.centre[2] + c * r[2] + a * p.axis[2],
      );
    }
    const shankLength = options.shankLengthMm ?? 0;
    const nU = shankLength > 0 ? Math.ceil(shankLength / ds) : 0;
    for (let j = 1; j <= nU; j++) {
      const u = (shankLength * j) / nU;
      pts.push(
        p.centre[0] + (rb + rcr) * r[0] + u * p.axis[0],
        p.centre[1] + (rb + rcr) * r[1] + u * p.axis[1],
        p.centre[2] + (rb + rcr) * r[2] + u * p.axis[2],
      );
    }
    const nR = Math.ceil(rb / ds);
    for (let j = 0; j < nR; j++) {
      const c = (rb * j) / nR;
      pts.push(
        p.centre[0] + c * r[0] - rcr * p.axis[0],
        p.centre[1] + c * r[1] - rcr * p.axis[1],
        p.centre[2] + c * r[2] - rcr * p.axis[2],
      );
    }
  }
  const bins = options.bins;
  const best = new Float64Array(bins).fill(convex ? Number.POSITIVE_INFINITY : 0);
  const keep = (k: number, v: number) => {
    if (k < 0 || k >= bins) return;
    if (convex ? v < (best[k] as number) : v > (best[k] as number)) best[k] = v;
  };
  const abs = Math.abs(rs);
  if (axis === 'feed') {
    // Polar angle about the axis (at y = 0, z = -Rs), from the contact's direction.
    const phi = intervalMm / abs;
    const from = -0.5 * phi;
    const span = passes * phi;
    for (let k = 0; k < passes; k++) {
      const mirror = pattern === 'zigzag' && k % 2 === 1 ? -1 : 1;
      for (let i = 0; i < pts.length; i += 3) {
        const y = mirror * (pts[i + 1] as number);
        const z = pts[i + 2] as number;
        const qz = z + rs;
        const angle = Math.atan2(y, convex ? qz : -qz) + k * phi;
        const radius = Math.sqrt(y * y + qz * qz);
        keep(Math.round(((angle - from) / span) * bins - 0.5), radius);
      }
    }
    const cusps: number[] = [];
    for (let k = 0; k + 1 < passes; k++) {
      let c = convex ? 0 : Number.POSITIVE_INFINITY;
      for (let b = 0; b < bins; b++) {
        const angle = from + ((b + 0.5) / bins) * span;
        if (angle > k * phi && angle < (k + 1) * phi)
          c = convex ? Math.max(c, best[b] as number) : Math.min(c, best[b] as number);
      }
      cusps.push(convex ? c - abs : abs - c);
    }
    const width = (span / bins) * abs;
    return { cuspHeightsMm: cusps, boundMm: ds + width * largestSlope(best, width) };
  }
  // Across the feed: bins along Y; the distance from the axis (along Y at x = 0, z = -Rs).
  const from = -0.5 * intervalMm;
  const span = passes * intervalMm;
  for (let k = 0; k < passes; k++) {
    const mirror = pattern === 'zigzag' && k % 2 === 1 ? -1 : 1;
    for (let i = 0; i < pts.length; i += 3) {
      const x = pts[i] as number;
      const y = mirror * (pts[i + 1] as number) + k * intervalMm;
      const qz = (pts[i + 2] as number) + rs;
      keep(Math.round(((y - from) / span) * bins - 0.5), Math.sqrt(x * x + qz * qz));
    }
  }
  const cusps: number[] = [];
  for (let k = 0; k + 1 < passes; k++) {
    let c = convex ? 0 : Number.POSITIVE_INFINITY;
    for (let b = 0; b < bins; b++) {
      const y = from + ((b + 0.5) / bins) * span;
      if (y > k * intervalMm && y < (k + 1) * intervalMm)
        c = convex ? Math.max(c, best[b] as number) : Math.min(c, best[b] as number);
    }
    cusps.push(convex ? c - abs : abs - c);
  }
  const width = span / bins;
  return { cuspHeightsMm: cusps, boundMm: ds + width * largestSlope(best, width) };
}

/** How far the tool reaches beyond a concave cylinder's wall, by brute force (mm). */
export interface ConcaveOverreach {
  /** Largest distance beyond the wall of a sampled point of the head (corner and bottom), mm; <= 0 inside. */
  readonly headMm: number;
  /** The same for the shank's points up to the height of the cylinder's axis, mm. */
  readonly shankMm: number;
}

/**
 * Samples the tool's surface in its posture with the contact at the origin (placement.ts only
 * places it; nothing else is shared with cylinder.ts) and measures each point's distance from the
 * axis of the concave cylinder of radius `radiusMm` (< 0), which lies |Rs| above the contact, along
 * X (axis = feed) or Y (cross). The head (the torus's outer half and the bottom disk) counts wherever
 * it is, the shank (radius R above the corner) up to the axis height (shared/notes/
 * posture-and-surfaces.md). The head is sampled every `spacingMm`; the shank by its generators (ring
 * angle every `spacingMm` of arc): along a generator, a straight line, the distance from the axis is
 * convex, so its largest value below the axis height lies at an end, the corner or the point at the
 * axis height, which are both taken (and 16 points between, as a check).
 */
export function concaveOverreach(
  tool: ToolInput,
  radiusMm: number,
  axis: 'feed' | 'cross',
  options: { readonly spacingMm: number },
): ConcaveOverreach {
  const p = placeTool(tool);
  const abs = Math.abs(radiusMm);
  const rb = p.ringRadiusMm;
  const rcr = p.cornerRadiusMm;
  const R = rb + rcr;
  const ds = options.spacingMm;
  const beyond = (q: readonly number[]) => {
    const w = (axis === 'feed' ? q[1] : q[0]) as number;
    const z = q[2] as number;
    return Math.sqrt(w * w + (z - abs) * (z - abs)) - abs;
  };
  let headMm = Number.NEGATIVE_INFINITY;
  let shankMm = Number.NEGATIVE_INFINITY;
  const nT = Math.max(64, Math.ceil((2 * Math.PI * R) / ds));
  const nPsi = Math.max(8, Math.ceil((Math.PI * rcr) / ds));
  const nR = Math.max(2, Math.ceil(rb / ds));
  for (let i = 0; i < nT; i++) {
    const t = (2 * Math.PI * i) / nT;
    const r = [0, 1, 2].map((k) => Math.sin(t) * (p.v1[k] as number) + Math.cos(t) * (p.v2[k] as number));
    const point = (radial: number, axial: number) =>
      [0, 1, 2].map((k) => (p.centre[k] as number) + radial * (r[k] as number) + axial * (p.axis[k] as number));
    for (let j = 0; j <= nPsi; j++) {
      const psi = -Math.PI / 2 + (Math.PI * j) / nPsi;
      headMm = Math.max(headMm, beyond(point(rb + rcr * Math.cos(psi), rcr * Math.sin(psi))));
    }
    for (let j = 0; j < nR; j++) headMm = Math.max(headMm, beyond(point((rb * j) / nR, -rcr)));
    // The generator from the corner's top (axial 0) up to the axis height.
    const foot = point(R, 0);
    const top = (abs - (foot[2] as number)) / p.axis[2];
    if (top >= 0) for (let j = 0; j <= 17; j++) shankMm = Math.max(shankMm, beyond(point(R, (top * j) / 17)));
  }
  return { headMm, shankMm };
}
