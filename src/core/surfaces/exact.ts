/**
 * The exact step-over of a filleted end mill in any posture on a plane, and its inverse, for
 * one-way and zigzag passes (shared/notes/posture-and-surfaces.md). The flanks come from
 * posture.ts; this module combines them into step-overs and cusp heights. Lengths mm.
 *
 * One-way: every pass has the same profile; the cusp between passes k and k+1 joins the right
 * flank of k and the left flank of k+1, so `L = wR(h) + wL(h)`. Zigzag (posture relative to
 * the feed): every other pass is mirrored, cusps alternate between two right flanks (where
 * `wR = L/2`) and two left flanks (`wL = L/2`); for no cusp above h, `L = 2 min(wR, wL)` and
 * the other cusp is lower. Without tilt both give `L = 2 (L/2)` of the paper.
 */

import type { ForwardInput, InverseInput } from '../input/validate';
import { bracketedRoot } from '../math/rootFinder';
import {
  contactOffsetMm,
  type FlankPoint,
  flankAtHeight,
  flankAtWidth,
  flankLimits,
  flankWidthMm,
  type PostureShape,
  shapeOfTool,
} from '../tool/posture';
import { stepOverFromReaches } from '../tool/stepOverRule';
import { type CylinderSurface, cylinderSolver } from './cylinder';

/** The exact answer of the forward problem (scallop height to step-over), mm. */
export interface ExactForward {
  /** Step-over L between adjacent cutter-contact paths. */
  readonly intervalMm: number;
  /** L / 2. */
  readonly halfIntervalMm: number;
  /** Widths of the right and left flank at the scallop height, from the contact (wR, wL). */
  readonly halfWidthRightMm: number;
  readonly halfWidthLeftMm: number;
  /** Contact offset y0: Y of the contact point minus Y of the tool centre point O. */
  readonly contactOffsetMm: number;
  /** Height of the highest cusp the passes leave: h (0 when no scallop forms at all). */
  readonly cuspHeightMm: number;
  /** Zigzag: the height of the other, lower cusp; null for one-way passes. */
  readonly otherCuspHeightMm: number | null;
  /**
   * True when the tool leaves no scallop at any step-over up to `intervalMm`: a flat end with
   * neither lead nor tilt (its bottom face lies on the plane and has no corner to curve up).
   */
  readonly noScallop: boolean;
  /**
   * The flank points of the plane profile at the cusps (geometry and teaching). On a cylinder they
   * are the plane profile's points at the same height, for drawing only: the cylinder's flanks are
   * measured radially.
   */
  readonly right: FlankPoint;
  readonly left: FlankPoint;
}

/** The exact answer of the inverse problem (step-over to scallop height), mm. */
export interface ExactInverse {
  readonly intervalMm: number;
  /** Height of the highest cusp the passes leave (the scallop height); 0 on a flat bottom. */
  readonly cuspHeightMm: number;
  /** Zigzag: the height of the other, lower cusp; null for one-way passes. */
  readonly otherCuspHeightMm: number | null;
  /** Heights of the cusps formed by right flanks and by left flanks (equal for one-way). */
  readonly rightCuspHeightMm: number;
  readonly leftCuspHeightMm: number;
  /** Widths of the right and left flank at their cusps, from the contact. */
  readonly halfWidthRightMm: number;
  readonly halfWidthLeftMm: number;
  readonly contactOffsetMm: number;
  readonly right: FlankPoint;
  readonly left: FlankPoint;
}

/**
 * Exact step-over L (mm) for a validated forward input: the fast path (no geometry, no
 * allocation beyond the shape). Error below 1e-9 mm over the valid domain.
 */
export function exactIntervalMm(input: ForwardInput): number {
  if (input.surface.kind === 'cylinder') {
    // The reaches alone (no display geometry); without tilt the flanks are mirror images.
    const c = cylinderSolver(input, input.surface);
    const h = input.scallopHeightMm;
    const right = c.reach('right', h);
    const left = input.tiltAngleDeg === 0 ? right : c.reach('left', h);
    return c.intervalFromReach(stepOverFromReaches(input.pattern, right, left));
  }
  const s = shapeOfTool(input);
  if (s.flatOnPlane && s.rcr === 0) return 2 * s.a;
  const h = input.scallopHeightMm;
  const right = flankWidthMm(s, 'right', h);
  if (input.tiltAngleDeg === 0) return 2 * right;
  return stepOverFromReaches(input.pattern, right, flankWidthMm(s, 'left', h));
}

/**
 * Exact half path interval `L/2` in mm (the paper's quantity; L / 2 for either pattern).
 * @param input validated by validateForward.
 */
export function exactHalfIntervalMm(input: ForwardInput): number {
  return exactIntervalMm(input) / 2;
}

/** Exact forward solution: step-over, flank widths, contact offset and cusp heights (mm). */
export function exactForward(input: ForwardInput): ExactForward {
  if (input.surface.kind === 'cylinder') return cylinderForward(input, input.surface);
  const s = shapeOfTool(input);
  const h = input.scallopHeightMm;
  const y0 = contactOffsetMm(s);
  if (s.flatOnPlane && s.rcr === 0) {
    // A flat end lying flat: no scallop at any step-over up to the diameter.
    const edge: FlankPoint = { widthMm: s.a, heightMm: 0, ringOffsetRad: Math.PI / 2, normalAngleRad: 0 };
    return {
      intervalMm: 2 * s.a,
      halfIntervalMm: s.a,
      halfWidthRightMm: s.a,
      halfWidthLeftMm: s.a,
      contactOffsetMm: y0,
      cuspHeightMm: 0,
      otherCuspHeightMm: input.pattern === 'zigzag' ? 0 : null,
      noScallop: true,
      right: edge,
      left: edge,
    };
  }
  const right = flankAtHeight(s, 'right', h);
  const left = flankAtHeight(s, 'left', h);
  const L = stepOverFromReaches(input.pattern, right.widthMm, left.widthMm);
  let other: number | null = null;
  if (input.pattern === 'zigzag') {
    // The wider flank meets its mirror at L/2, lower than h (equal without tilt).
    const wider = right.widthMm > left.widthMm ? 'right' : 'left';
    other = right.widthMm === left.widthMm ? h : Math.min(h, flankAtWidth(s, wider, L / 2).heightMm);
  }
  return {
    intervalMm: L,
    halfIntervalMm: L / 2,
    halfWidthRightMm: right.widthMm,
    halfWidthLeftMm: left.widthMm,
    contactOffsetMm: y0,
    cuspHeightMm: h,
    otherCuspHeightMm: other,
    noScallop: false,
    right,
    left,
  };
}

/**
 * Height z (mm) of the one-way cusp for a step-over L: the root of `wR(z) + wL(z) = L`, found by a
 * bracketed Newton step in `u = sqrt(z)` (both widths grow like sqrt(z) near the contact, so
 * the function is nearly linear in u), with `dw/dz = cot(theta)` on each flank.
 */
function oneWayCuspHeightMm(s: PostureShape, L: number, limitMm: number): number {
  let lo = 0;
  let hi = Math.sqrt(limitMm);
  let u = 0.5 * hi;
  for (let i = 0; i < 200; i++) {
    const z = u * u;
    const r = flankAtHeight(s, 'right', z);
    const l = flankAtHeight(s, 'left', z);
    const f = r.widthMm + l.widthMm - L;
    if (f === 0) return z;
    if (f > 0) hi = u;
    else lo = u;
    // d/du (wR + wL) = 2u (cot thetaR + cot thetaL)
    const slope = 2 * u * (1 / Math.tan(r.normalAngleRad) + 1 / Math.tan(l.normalAngleRad));
    let next = slope > 0 && Number.isFinite(slope) ? u - f / slope : Number.NaN;
    if (Math.abs(next - u) <= 1e-15 * u) {
      u = Math.min(Math.max(next, lo), hi);
      break;
    }
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    u = next;
    if (hi - lo <= 4e-16 * hi) break;
  }
  return u * u;
}

/** Exact inverse: the cusp heights (mm) that passes L apart leave. @param input validated by validateInverse. */
export function exactInverse(input: InverseInput): ExactInverse {
  if (input.surface.kind === 'cylinder') return cylinderInverse(input, input.surface);
  const s = shapeOfTool(input);
  const L = input.intervalMm;
  const y0 = contactOffsetMm(s);
  if (input.pattern === 'zigzag' || input.tiltAngleDeg === 0) {
    // Each cusp is where a flank is L/2 from its contact (one-way without tilt is symmetric).
    const right = flankAtWidth(s, 'right', L / 2);
    const left = input.tiltAngleDeg === 0 ? right : flankAtWidth(s, 'left', L / 2);
    const top = Math.max(right.heightMm, left.heightMm);
    return {
      intervalMm: L,
      cuspHeightMm: top,
      otherCuspHeightMm: input.pattern === 'zigzag' ? Math.min(right.heightMm, left.heightMm) : null,
      rightCuspHeightMm: right.heightMm,
      leftCuspHeightMm: left.heightMm,
      halfWidthRightMm: L / 2,
      halfWidthLeftMm: L / 2,
      contactOffsetMm: y0,
      right,
      left,
    };
  }
  const z = oneWayCuspHeightMm(s, L, flankLimits(s).limitMm);
  const right = flankAtHeight(s, 'right', z);
  const left = flankAtHeight(s, 'left', z);
  return {
    intervalMm: L,
    cuspHeightMm: z,
    otherCuspHeightMm: null,
    rightCuspHeightMm: z,
    leftCuspHeightMm: z,
    halfWidthRightMm: right.widthMm,
    halfWidthLeftMm: left.widthMm,
    contactOffsetMm: y0,
    right,
    left,
  };
}

/**
 * Exact scallop height (mm) left by passes `intervalMm` apart: the highest cusp. 0 when the
 * point lies on a flat bottom lying on the plane (rho = 0 without tilt, L/2 <= R - Rcr).
 */
export function exactScallopHeightMm(input: InverseInput): number {
  return exactInverse(input).cuspHeightMm;
}

/**
 * On a cylinder (cylinder.ts): the step-over from the flanks' reach at the radial height h, one-way
 * `L = |Rs| (A_R + A_L)` (axis = feed, A the polar angles) or `w_R + w_L` (axis = cross, widths
 * along the axis); zigzag twice the smaller reach. "Widths" are reported as the reach converted to
 * length along the surface.
 */
function cylinderForward(input: ForwardInput, surface: CylinderSurface): ExactForward {
  const c = cylinderSolver(input, surface);
  const s = shapeOfTool(input);
  const h = input.scallopHeightMm;
  const reachR = c.reach('right', h);
  const reachL = c.reach('left', h);
  const wR = c.intervalFromReach(reachR);
  const wL = c.intervalFromReach(reachL);
  const L = stepOverFromReaches(input.pattern, wR, wL);
  let other: number | null = null;
  if (input.pattern === 'zigzag') {
    const wider = reachR > reachL ? 'right' : 'left';
    const half = c.reachFromInterval(L / 2);
    other = reachR === reachL ? h : Math.min(h, c.heightAt(wider, half));
  }
  return {
    intervalMm: L,
    halfIntervalMm: L / 2,
    halfWidthRightMm: wR,
    halfWidthLeftMm: wL,
    contactOffsetMm: contactOffsetMm(s),
    cuspHeightMm: h,
    otherCuspHeightMm: other,
    noScallop: false,
    right: flankAtHeight(s, 'right', Math.min(h, flankLimits(s).topRightMm)),
    left: flankAtHeight(s, 'left', Math.min(h, flankLimits(s).topLeftMm)),
  };
}

/** The inverse on a cylinder: cusp heights at a step-over (one-way by a bracketed secant in sqrt(h)). */
function cylinderInverse(input: InverseInput, surface: CylinderSurface): ExactInverse {
  const c = cylinderSolver(input, surface);
  const s = shapeOfTool(input);
  const L = input.intervalMm;
  const reach = c.reachFromInterval(L);
  const plane = (flank: 'right' | 'left', z: number) =>
    flankAtHeight(
      s,
      flank,
      Math.max(0, Math.min(z, flank === 'right' ? flankLimits(s).topRightMm : flankLimits(s).topLeftMm)),
    );
  if (input.pattern === 'zigzag' || input.tiltAngleDeg === 0) {
    // Without tilt the flanks are mirror images (on both axes): each cusp is at half the reach.
    const hR = Math.max(0, c.heightAt('right', reach / 2));
    const hL = input.tiltAngleDeg === 0 ? hR : Math.max(0, c.heightAt('left', reach / 2));
    return {
      intervalMm: L,
      cuspHeightMm: Math.max(hR, hL),
      otherCuspHeightMm: input.pattern === 'zigzag' ? Math.min(hR, hL) : null,
      rightCuspHeightMm: hR,
      leftCuspHeightMm: hL,
      halfWidthRightMm: L / 2,
      halfWidthLeftMm: L / 2,
      contactOffsetMm: contactOffsetMm(s),
      right: plane('right', hR),
      left: plane('left', hL),
    };
  }
  // One-way with tilt (or across the axis): the cusp height z where the two reaches add up to L.
  const limit = c.limits().limitMm;
  const f = { value: (u: number) => c.intervalFromReach(c.reach('right', u * u) + c.reach('left', u * u)) - L };
  const hi = Math.sqrt(limit);
  const fLo = f.value(0);
  const fHi = fLo >= 0 ? fLo : f.value(hi);
  // The flat faces already cover L (a flat bottom lying on the cylinder): no scallop. Past the
  // limit (no sign change) the bracket's top.
  const z = (fLo >= 0 ? 0 : fHi <= 0 ? hi : bracketedRoot(f, 0, hi, fLo, fHi, 1e-16)) ** 2;
  return {
    intervalMm: L,
    cuspHeightMm: z,
    otherCuspHeightMm: null,
    rightCuspHeightMm: z,
    leftCuspHeightMm: z,
    halfWidthRightMm: c.intervalFromReach(c.reach('right', z)),
    halfWidthLeftMm: c.intervalFromReach(c.reach('left', z)),
    contactOffsetMm: contactOffsetMm(s),
    right: plane('right', z),
    left: plane('left', z),
  };
}
