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
 *
 * The same rule serves every surface whose passes are congruent (surface.ts's CongruentPasses: the
 * cylinders, as cylinder.ts prepares them): `congruentForward` and `congruentInverse` combine the
 * flanks' reaches there. Which of them answers a surface is the registry's choice
 * (surfaces/registry.ts, models/*); the public entry is surfaces/solve.ts.
 */

import type { ForwardInput, InverseInput } from '../domain/pass';
import type { SurfaceDescriptorBase } from '../domain/surface';
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
import { cuspsAtHalfInterval, oneWayCusps, stepOverFromReaches } from '../tool/stepOverRule';
import type { CongruentPasses, ExactForward, ExactInverse } from './surface';

/** The answers' types, defined with the surface interface (surface.ts); re-exported for the callers. */
export type { ExactForward, ExactInverse };

/** An input whose surface these solvers ignore or take as prepared passes (any registered kind). */
type AnyForward = ForwardInput<SurfaceDescriptorBase>;
type AnyInverse = InverseInput<SurfaceDescriptorBase>;

/**
 * Exact step-over L (mm) for congruent passes (`c` prepared for the input's tool and surface): the
 * reaches alone, no display geometry. @param input validated.
 */
export function congruentIntervalMm(input: AnyForward, c: CongruentPasses): number {
  // Without tilt the flanks are mirror images.
  const h = input.scallopHeightMm;
  const right = c.reach('right', h);
  const left = input.tiltAngleDeg === 0 ? right : c.reach('left', h);
  return c.intervalFromReach(stepOverFromReaches(input.pattern, right, left));
}

/**
 * Exact step-over L (mm) on a plane for a validated forward input: the fast path (no geometry, no
 * allocation beyond the shape). Error below 1e-9 mm over the valid domain.
 */
export function planeIntervalMm(input: AnyForward): number {
  const s = shapeOfTool(input);
  if (s.flatOnPlane && s.rcr === 0) return 2 * s.a;
  const h = input.scallopHeightMm;
  const right = flankWidthMm(s, 'right', h);
  if (input.tiltAngleDeg === 0) return 2 * right;
  return stepOverFromReaches(input.pattern, right, flankWidthMm(s, 'left', h));
}

/** Exact forward solution on a plane: step-over, flank widths, contact offset and cusp heights (mm). */
export function planeForward(input: AnyForward): ExactForward {
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

/** Exact inverse on a plane: the cusp heights (mm) that passes L apart leave. @param input validated by validateInverse. */
export function planeInverse(input: AnyInverse): ExactInverse {
  const s = shapeOfTool(input);
  const L = input.intervalMm;
  const y0 = contactOffsetMm(s);
  if (input.pattern === 'zigzag' || input.tiltAngleDeg === 0) {
    // Each cusp is where a flank is L/2 from its contact (one-way without tilt is symmetric).
    const right = flankAtWidth(s, 'right', L / 2);
    const left = input.tiltAngleDeg === 0 ? right : flankAtWidth(s, 'left', L / 2);
    const cusps = cuspsAtHalfInterval(L, right.heightMm, left.heightMm, input.pattern === 'zigzag', y0);
    return { ...cusps, right, left };
  }
  const z = oneWayCuspHeightMm(s, L, flankLimits(s).limitMm);
  const right = flankAtHeight(s, 'right', z);
  const left = flankAtHeight(s, 'left', z);
  return { ...oneWayCusps(L, z, right.widthMm, left.widthMm, y0), right, left };
}

/**
 * For congruent passes (`c` prepared for the input's tool and surface), as on a cylinder (cylinder.ts): the step-over from the flanks' reach at the radial height h, one-way
 * `L = |Rs| (A_R + A_L)` (axis = feed, A the polar angles) or `w_R + w_L` (axis = cross, widths
 * along the axis); zigzag twice the smaller reach. "Widths" are reported as the reach converted to
 * length along the surface.
 */
export function congruentForward(input: AnyForward, c: CongruentPasses): ExactForward {
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

/**
 * The inverse for congruent passes, as on a cylinder: cusp heights at a step-over (one-way by a
 * bracketed secant in sqrt(h)). `c` prepared for the input's tool and surface.
 */
export function congruentInverse(input: AnyInverse, c: CongruentPasses): ExactInverse {
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
    const cusps = cuspsAtHalfInterval(L, hR, hL, input.pattern === 'zigzag', contactOffsetMm(s));
    return { ...cusps, right: plane('right', hR), left: plane('left', hL) };
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
  const wR = c.intervalFromReach(c.reach('right', z));
  const wL = c.intervalFromReach(c.reach('left', z));
  return { ...oneWayCusps(L, z, wR, wL, contactOffsetMm(s)), right: plane('right', z), left: plane('left', z) };
}
