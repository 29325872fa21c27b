/**
 * The solver of waterline passes on a surface of revolution (waterlineRevolution.ts, whose module
 * comment states the decisions): the case's setup and usable range of L, the cusp at L, where the
 * next pass's shank starts to form the cusp, gouging of either pass, and the bracketed solve of the
 * forward and inverse problems. Lengths mm.
 */
import { radToDeg } from '../input/units';
import { bracketedRoot, MAX_ITERATIONS, newSearchEnd } from '../math/rootFinder';
import { cosDeg, sinDeg } from './angles';
import { fillCusp, type MeridianCusp, newMeridianCusp, normalHeightMm } from './meridianCusp';
import {
  fillPassPair,
  intervalOfStepDownMm,
  type Meridian,
  meridian,
  newPassPair,
  type PassPair,
  stepDownOfIntervalMm,
} from './meridianPasses';
import { type MeridianTool, meridianTool } from './meridianTool';
import { gougeDepthMm, type RevolutionSurface, revolutionSurface } from './revolutionGouging';

/** An upright tool at a CC point of a surface of revolution. */
export interface RevolutionCase {
  /** Tool radius R, mm, 0.001 to 1000. */
  readonly toolRadiusMm: number;
  /** Corner radius Rcr, mm, 0 <= Rcr <= R. */
  readonly cornerRadiusMm: number;
  /**
   * Slope alpha at the CC point, degrees, 0 < alpha <= 90 (90 only on a concave meridian: a
   * straight one is a vertical wall, cut flat; below a convex one the surface overhangs).
   */
  readonly slopeDeg: number;
  /**
   * Signed normal radius along the feed (the horizontal circle), mm: > 0 convex (dome, boss),
   * < 0 concave (bowl, pocket); null when infinite (a cone or a plane). |Rf| from 0.001 to 1e6.
   */
  readonly feedRadiusMm: number | null;
  /** Signed meridian radius Rc, mm, signs as Rf; null when the meridian is straight. */
  readonly crossRadiusMm: number | null;
}

/** Points of the pair in the meridian plane (mm; origin at the upper CC point, s down-slope, z up). */
export interface WaterlineGeometry {
  readonly cc0: readonly [number, number];
  readonly cc1: readonly [number, number];
  readonly tip0: readonly [number, number];
  readonly tip1: readonly [number, number];
  readonly cusp: readonly [number, number];
  /** The meridian circle's centre, or null when straight. */
  readonly meridianCentre: readonly [number, number] | null;
  /** s of the axis of revolution, or null (Rf infinite). */
  readonly axisS: number | null;
}

/** The answer of a waterline pair on a surface of revolution. */
export interface WaterlineAnswer {
  /** Step L along the meridian (arc length) between the CC points, mm. */
  readonly intervalMm: number;
  /** Step-down dz between the tool tips (the programmed step), mm. */
  readonly stepDownMm: number;
  /** Horizontal distance between the tool axes (difference of their radii about the axis), mm. */
  readonly radialStepMm: number;
  /** Cusp height along the surface normal (radially from the meridian centre), mm. */
  readonly cuspHeightMm: number;
  /** Slope at the next pass's CC point, degrees. */
  readonly slopeNextDeg: number;
  /** The equivalent posture at the CC point (lead 0, tilt alpha), degrees. */
  readonly leadDeg: number;
  readonly tiltDeg: number;
  readonly geometry: WaterlineGeometry;
}

/** The programmed step of the inverse problem. */
export interface WaterlineStep {
  /** `stepDown` (dz between the tool tips) or `interval` (L along the meridian). */
  readonly field: 'stepDown' | 'interval';
  /** mm, at least 1e-9. */
  readonly mm: number;
}

/** Everything fixed for one case: tool, meridian, surface and the usable range of L. */
export interface Setup {
  readonly tool: MeridianTool;
  readonly mer: Meridian;
  readonly surf: RevolutionSurface;
  /** Largest L (mm, exclusive) keeping the next pass on the usable surface; Infinity if none. */
  readonly maxL: number;
  /** What bounds maxL. */
  readonly maxBy: 'vertical' | 'bottom' | 'axis' | null;
  /**
   * This case's workspace for {@link cuspAt} (the pass pair and the cusp it fills): owned by the
   * setup, so it lives as long as the one solve that made it and is shared with nothing else.
   */
  readonly work: { readonly pair: PassPair; readonly cusp: MeridianCusp };
}

/** The setup of a case: its tool, meridian, surface and usable range of L. */
export function setupOf(c: RevolutionCase): Setup {
  const alpha = (c.slopeDeg * Math.PI) / 180;
  const mer = meridian(alpha, c.crossRadiusMm);
  const sin0 = sinDeg(c.slopeDeg);
  const cos0 = cosDeg(c.slopeDeg);
  const surf = revolutionSurface(sin0, cos0, c.crossRadiusMm, c.feedRadiusMm);
  let maxL = Number.POSITIVE_INFINITY;
  let maxBy: Setup['maxBy'] = null;
  const k = mer.k;
  if (k > 0) {
    maxL = (Math.PI / 2 - alpha) / k;
    maxBy = 'vertical';
  } else if (k < 0) {
    maxL = alpha / -k;
    maxBy = 'bottom';
  }
  // Moving towards the axis (CC side below it in s): the next CC point must stay on its side.
  if (surf.axisS !== null && surf.side < 0) {
    let La: number;
    if (k === 0) La = surf.axisS / cos0;
    else {
      const rhs = sin0 + k * surf.axisS;
      La = rhs >= -1 && rhs <= 1 ? (Math.asin(rhs) - alpha) / k : Number.POSITIVE_INFINITY;
      if (!(La > 0)) La = Number.POSITIVE_INFINITY;
    }
    if (La < maxL) {
      maxL = La;
      maxBy = 'axis';
    }
  }
  const work = { pair: newPassPair(), cusp: newMeridianCusp() };
  return { tool: meridianTool(c.toolRadiusMm, c.cornerRadiusMm), mer, surf, maxL, maxBy, work };
}

/**
 * The cusp at L (mm), filled into the setup's own workspace (no module state): read it before the
 * next call with the same setup.
 */
export function cuspAt(s: Setup, L: number): MeridianCusp {
  fillPassPair(s.tool, s.mer, L, s.work.pair);
  fillCusp(s.tool, s.mer, s.work.pair, s.work.cusp);
  return s.work.cusp;
}

/** The L (mm) where the lower pass's shank starts to form the cusp, searched in (0, hi] (onShank at hi). */
export function shankStartL(s: Setup, hi: number): number {
  let lo = 0;
  let up = hi;
  for (let i = 0; i < 200 && up - lo > 1e-15 * up; i++) {
    const mid = 0.5 * (lo + up);
    if (cuspAt(s, mid).onShank) up = mid;
    else lo = mid;
  }
  return lo;
}

/** Height (mm) of the lower tool's corner top K1 along the normal at L: the shank limit there. */
export function shankHeightAt(s: Setup, L: number): number {
  fillPassPair(s.tool, s.mer, L, s.work.pair);
  return normalHeightMm(s.mer, s.work.pair.tipS1 - s.tool.R, s.work.pair.tipZ1 + s.tool.rcr);
}

/** A value of L (mm) on the usable range where the shank forms the cusp, or null when none does. */
export function someShankL(s: Setup): number | null {
  const t = s.tool;
  // dz >= Rcr puts K1 at or below the upper tip's level: the shank then forms the cusp.
  let L = (2 * t.R) / Math.max(s.mer.sin0, 1e-12);
  for (let i = 0; i < 200; i++) {
    const at = Math.min(L, s.maxL * (1 - 1e-12));
    if (cuspAt(s, at).onShank) return at;
    if (at < L) return null;
    L *= 2;
  }
  return null;
}

/** The verdict of a solve: L, or what stopped it (gouging, the shank, the end of the usable surface, a flat end). */
export type Core =
  | { readonly kind: 'ok'; readonly L: number }
  | { readonly kind: 'gouge'; readonly pass: 0 | 1; readonly L: number }
  | { readonly kind: 'shank'; readonly limitL: number }
  | { readonly kind: 'past'; readonly limitL: number }
  | { readonly kind: 'wall-only' };

/** Gouging of the upper pass (0) or the lower one at L (1), or null. */
function gouging(s: Setup, L: number | null): 0 | 1 | null {
  fillPassPair(s.tool, s.mer, L ?? 0, s.work.pair);
  if (gougeDepthMm(s.tool, s.surf, s.work.pair.tipS0, s.work.pair.tipZ0) > 0) return 0;
  if (L === null) return null;
  fillPassPair(s.tool, s.mer, L, s.work.pair);
  return gougeDepthMm(s.tool, s.surf, s.work.pair.tipS1, s.work.pair.tipZ1) > 0 ? 1 : null;
}

/**
 * The L (mm) whose cusp is h high: the shared bracketed root (rootFinder.ts, Illinois) on `sqrt(H(L)) - sqrt(h)`
 * (nearly linear in L), where L past the shank's start counts as too far. Returns the bracket's
 * state: the root, or where the search ran out (shank, end of the usable surface).
 */
export function solveInterval(s: Setup, h: number): Core {
  const t = s.tool;
  if (t.rcr === 0) return { kind: 'wall-only' };
  const rh = Math.sqrt(h);
  const f = {
    value(L: number): number {
      const c = cuspAt(s, L);
      return c.onShank ? Number.POSITIVE_INFINITY : Math.sqrt(Math.max(0, c.heightMm)) - rh;
    },
  };
  const cap = s.maxL * (1 - 1e-12);
  let lo = 0;
  let fLo = -rh;
  let hi = Math.min(cap, 2 * Math.sqrt(2 * t.rcr * h) + Math.min(2 * t.rb, h / Math.max(s.mer.sin0, 1e-12)));
  let fHi = f.value(hi);
  while (fHi < 0) {
    if (hi >= cap) return { kind: 'past', limitL: s.maxL };
    lo = hi;
    fLo = fHi;
    hi = Math.min(cap, 2 * hi);
    fHi = f.value(hi);
  }
  const end = newSearchEnd();
  const L = bracketedRoot(f, lo, hi, fLo, fHi, 1e-15, MAX_ITERATIONS, end);
  // A bracket still closed by a point on the shank converged onto the shank's start (the sign
  // change is the jump to +Infinity there, not a root): h is at or above the shank limit.
  if (cuspAt(s, L).onShank || (cuspAt(s, end.hi).onShank && f.value(L) !== 0))
    return { kind: 'shank', limitL: shankStartL(s, end.hi) };
  return { kind: 'ok', L };
}

/** The forward problem's verdict at a scallop height h (mm): L, or why not (gouging, shank, past the surface). */
export function forwardCore(s: Setup, h: number): Core {
  if (gouging(s, null) === 0) return { kind: 'gouge', pass: 0, L: 0 };
  const r = solveInterval(s, h);
  if (r.kind !== 'ok') return r;
  if (gouging(s, r.L) === 1) return { kind: 'gouge', pass: 1, L: r.L };
  return r;
}

/** The inverse problem's verdict for a programmed step (dz or L): L, or why not. */
export function inverseCore(s: Setup, step: WaterlineStep): Core {
  if (gouging(s, null) === 0) return { kind: 'gouge', pass: 0, L: 0 };
  if (s.tool.rcr === 0) return { kind: 'wall-only' };
  const L = step.field === 'interval' ? step.mm : intervalOfStepDownMm(s.tool, s.mer, step.mm, s.maxL);
  if (L === null || !(L < s.maxL)) {
    // Beyond the usable surface; if the shank forms the cusp before its end, that limit binds first.
    const cap = Math.min(s.maxL * (1 - 1e-12), L ?? Number.POSITIVE_INFINITY);
    const shankL = Number.isFinite(cap) ? (cuspAt(s, cap).onShank ? cap : null) : someShankL(s);
    return shankL === null ? { kind: 'past', limitL: s.maxL } : { kind: 'shank', limitL: shankStartL(s, shankL) };
  }
  if (gouging(s, L) === 1) return { kind: 'gouge', pass: 1, L };
  if (cuspAt(s, L).onShank) return { kind: 'shank', limitL: shankStartL(s, L) };
  return { kind: 'ok', L };
}

/** The answer at L (mm) of a setup (after a successful core). */
export function answerAt(c: RevolutionCase, s: Setup, L: number): WaterlineAnswer {
  const cusp = cuspAt(s, L);
  const p = s.work.pair;
  return {
    intervalMm: L,
    stepDownMm: stepDownOfIntervalMm(s.tool, s.mer, L),
    radialStepMm: p.dS,
    cuspHeightMm: cusp.heightMm,
    slopeNextDeg: radToDeg(p.alpha1),
    leadDeg: 0,
    tiltDeg: c.slopeDeg,
    geometry: {
      cc0: [0, 0],
      cc1: [p.ccS1, p.ccZ1],
      tip0: [p.tipS0, p.tipZ0],
      tip1: [p.tipS1, p.tipZ1],
      cusp: [cusp.s, cusp.z],
      meridianCentre: s.mer.k === 0 ? null : [s.surf.centreS, s.surf.centreZ],
      axisS: s.surf.axisS,
    },
  };
}
