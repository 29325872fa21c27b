/**
 * Waterline (Z-level) passes on a surface of revolution about a vertical axis, the tool upright
 * (section 2b of shared/notes/doubly-curved-and-3-axis.md): forward (scallop height h to the step
 * L along the meridian and the step-down dz between the tool tips) and inverse (dz or L to h),
 * exact to 1e-9 mm, with the limits as input errors.
 *
 * Decisions:
 * - The step goes DOWN the slope: the answer at a CC point is about the pair (this pass, the next
 *   pass L further down the meridian). On a convex meridian the next pass is steeper, on a
 *   concave one flatter; the cusp above this pass belongs to the pair (previous pass, this pass)
 *   and is this module's answer at the previous pass's CC point (slope alpha - L/Rc), where the
 *   same dz leaves a different cusp: a CAM system's constant dz leaves a different cusp on each
 *   side of a level, and each pair is answered at its upper CC point. {@link waterlineCuspAbove}
 *   gives that up-slope cusp for a constant dz.
 * - Only the meridian radius Rc changes the cusp: the swept section in the meridian plane is the
 *   tool's own profile whatever the distance to the axis (meridianTool.ts), so Rf enters through
 *   gouging (a bowl too tight, the tool reaching across the axis) and the axis bound alone.
 * - Refused, with the limit: h at or above the height where the lower pass's shank (its vertical
 *   side) would form the cusp (steep walls; a flat end, Rcr = 0, at any h); a next pass beyond the
 *   usable surface (past the vertical of a convex meridian, the bottom of a concave one, or the
 *   axis); gouging of either pass (revolutionGouging.ts), naming the radius to change and the
 *   smallest magnitude that fits with the other held; a vertical wall (alpha = 90: no scallop).
 *
 * Lengths mm, angles degrees at the interface.
 */
import { radToDeg } from '../input/units';
import { bracketedRoot, MAX_ITERATIONS, newSearchEnd, newtonRoot } from '../math/rootFinder';
import { cosDeg, sinDeg } from './angles';
import {
  checkHeight,
  checkStep,
  checkTool,
  formatNumber,
  THREE_AXIS_SURFACE_RADIUS_RANGE_MM,
  type ThreeAxisError,
  type ThreeAxisField,
  type ThreeAxisResult,
  threeAxisError,
} from './errors';
import { fillCusp, type MeridianCusp, newMeridianCusp, normalHeightMm } from './meridianCusp';
import {
  fillPassPair,
  intervalOfStepDownMm,
  type Meridian,
  meridian,
  newPassPair,
  type PassPair,
  sinc,
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
  /** Slope alpha at the CC point, degrees, 0 < alpha <= 90 (90 is refused: a vertical wall). */
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
interface Setup {
  readonly tool: MeridianTool;
  readonly mer: Meridian;
  readonly surf: RevolutionSurface;
  /** Largest L (mm, exclusive) keeping the next pass on the usable surface; Infinity if none. */
  readonly maxL: number;
  /** What bounds maxL. */
  readonly maxBy: 'vertical' | 'bottom' | 'axis' | null;
}

function setupOf(c: RevolutionCase): Setup {
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
  return { tool: meridianTool(c.toolRadiusMm, c.cornerRadiusMm), mer, surf, maxL, maxBy };
}

const pairScratch: PassPair = newPassPair();
const cuspScratch: MeridianCusp = newMeridianCusp();

/** Fills the scratch pair and cusp at L; returns the cusp. */
function cuspAt(s: Setup, L: number): MeridianCusp {
  fillPassPair(s.tool, s.mer, L, pairScratch);
  fillCusp(s.tool, s.mer, pairScratch, cuspScratch);
  return cuspScratch;
}

/** The L (mm) where the lower pass's shank starts to form the cusp, searched in (0, hi] (onShank at hi). */
function shankStartL(s: Setup, hi: number): number {
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
function shankHeightAt(s: Setup, L: number): number {
  fillPassPair(s.tool, s.mer, L, pairScratch);
  return normalHeightMm(s.mer, pairScratch.tipS1 - s.tool.R, pairScratch.tipZ1 + s.tool.rcr);
}

/** A value of L (mm) on the usable range where the shank forms the cusp, or null when none does. */
function someShankL(s: Setup): number | null {
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

type Core =
  | { readonly kind: 'ok'; readonly L: number }
  | { readonly kind: 'gouge'; readonly pass: 0 | 1; readonly L: number }
  | { readonly kind: 'shank'; readonly limitL: number }
  | { readonly kind: 'past'; readonly limitL: number }
  | { readonly kind: 'wall-only' };

/** Gouging of the upper pass (0) or the lower one at L (1), or null. */
function gouging(s: Setup, L: number | null): 0 | 1 | null {
  fillPassPair(s.tool, s.mer, L ?? 0, pairScratch);
  if (gougeDepthMm(s.tool, s.surf, pairScratch.tipS0, pairScratch.tipZ0) > 0) return 0;
  if (L === null) return null;
  fillPassPair(s.tool, s.mer, L, pairScratch);
  return gougeDepthMm(s.tool, s.surf, pairScratch.tipS1, pairScratch.tipZ1) > 0 ? 1 : null;
}

/**
 * The L (mm) whose cusp is h high: the shared bracketed root (rootFinder.ts, Illinois) on `sqrt(H(L)) - sqrt(h)`
 * (nearly linear in L), where L past the shank's start counts as too far. Returns the bracket's
 * state: the root, or where the search ran out (shank, end of the usable surface).
 */
function solveInterval(s: Setup, h: number): Core {
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

function forwardCore(s: Setup, h: number): Core {
  if (gouging(s, null) === 0) return { kind: 'gouge', pass: 0, L: 0 };
  const r = solveInterval(s, h);
  if (r.kind !== 'ok') return r;
  if (gouging(s, r.L) === 1) return { kind: 'gouge', pass: 1, L: r.L };
  return r;
}

function inverseCore(s: Setup, step: WaterlineStep): Core {
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
function answerAt(c: RevolutionCase, s: Setup, L: number): WaterlineAnswer {
  const cusp = cuspAt(s, L);
  const p = pairScratch;
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

/** Errors of the case's own inputs (tool, slope, radii). */
function checkCase(c: RevolutionCase): ThreeAxisError[] {
  const errors = checkTool(c.toolRadiusMm, c.cornerRadiusMm);
  const a = c.slopeDeg;
  if (!(a > 0 && a <= 90))
    errors.push(
      threeAxisError(
        'slope',
        a === 0 ? 'needs-slope' : 'out-of-range',
        a,
        null,
        a === 0
          ? 'must be above 0 degrees for waterline passes: on a flat floor every level is the same, so there is no step-down.'
          : `must be above 0 and at most 90 degrees (got ${a}).`,
      ),
    );
  else if (a === 90)
    errors.push(
      threeAxisError(
        'slope',
        'vertical-wall',
        a,
        90,
        'of 90 degrees is a vertical wall: the side of the upright tool cuts it flat, so no scallop forms at any step-down and there is no step to compute.',
      ),
    );
  const [lo, hi] = THREE_AXIS_SURFACE_RADIUS_RANGE_MM;
  for (const [field, r] of [
    ['feedRadius', c.feedRadiusMm],
    ['crossRadius', c.crossRadiusMm],
  ] as const) {
    if (r !== null && !(Math.abs(r) >= lo && Math.abs(r) <= hi))
      errors.push(
        threeAxisError(
          field,
          'out-of-range',
          r,
          null,
          `must be a radius from ${lo} mm to ${hi} mm, negative when concave, or none for a straight line (got ${r}).`,
        ),
      );
  }
  return errors;
}

/** The step of `field` (mm) for L along the meridian. */
function stepOf(s: Setup, field: ThreeAxisField, L: number): number {
  return field === 'stepDown' ? stepDownOfIntervalMm(s.tool, s.mer, L) : L;
}

const PAST_WORDS: Record<NonNullable<Setup['maxBy']>, string> = {
  vertical: 'past the vertical of the convex meridian (an overhang the upright tool cannot reach)',
  bottom: 'past the bottom of the concave meridian',
  axis: 'across the axis of revolution',
};

/** Words an unsuccessful core as the error of `field` (the quantity given: h, dz or L). */
function coreError(c: RevolutionCase, s: Setup, r: Core, field: ThreeAxisField, got: number): ThreeAxisError {
  const gotText = `(got ${got})`;
  switch (r.kind) {
    case 'wall-only':
      return threeAxisError(
        field,
        'wall-only',
        got,
        null,
        'cannot be answered with a flat end (Rcr = 0) in waterline passes: the side of the lower pass rises straight from its contact, so it cuts a step at any step-down, not a scallop. Use a corner radius.',
      );
    case 'shank': {
      const limit = field === 'h' ? shankHeightAt(s, r.limitL) : stepOf(s, field, r.limitL);
      return threeAxisError(
        field,
        'shank-cuts',
        got,
        limit,
        `must be below ${formatNumber(limit)} mm at this slope ${gotText}: beyond it the next pass's shank (its vertical side, above the corner), not its corner, would form the cusp.`,
      );
    }
    case 'past': {
      const where = s.maxBy === null ? 'beyond the surface' : PAST_WORDS[s.maxBy];
      if (field === 'h') {
        // The largest h: the shank's or the end of the surface's, whichever comes first.
        const shankL = someShankL(s);
        if (shankL !== null) {
          const L0 = shankStartL(s, shankL);
          const limit = shankHeightAt(s, L0);
          return threeAxisError(
            'h',
            'shank-cuts',
            got,
            limit,
            `must be below ${formatNumber(limit)} mm at this slope ${gotText}: beyond it the next pass's shank (its vertical side, above the corner), not its corner, would form the cusp.`,
          );
        }
        const limit = cuspAt(s, s.maxL * (1 - 1e-12)).heightMm;
        return threeAxisError(
          'h',
          'past-surface',
          got,
          limit,
          `must be below ${formatNumber(limit)} mm at this slope ${gotText}: a larger scallop needs the next pass ${where}.`,
        );
      }
      const limit = stepOf(s, field, s.maxL);
      return threeAxisError(
        field,
        'past-surface',
        got,
        limit,
        `must be below ${formatNumber(limit)} mm at this slope ${gotText}: a larger step puts the next pass ${where}.`,
      );
    }
    case 'gouge':
      return gougeError(c, r.pass, (cc) => {
        const ss = setupOf(cc);
        return (field === 'h' ? forwardCore(ss, got) : inverseCore(ss, { field: field as 'stepDown', mm: got })).kind;
      });
    case 'ok':
      throw new Error('not an error');
  }
}

/**
 * The gouging error: which radius to change and its smallest magnitude with the other held, found
 * by bisection (on the logarithm of the magnitude) of the whole solve's verdict.
 */
function gougeError(c: RevolutionCase, pass: 0 | 1, kindOf: (c: RevolutionCase) => Core['kind']): ThreeAxisError {
  const which = pass === 0 ? 'at this slope' : 'at the next pass (further down, at its slope)';
  const gouges = (cc: RevolutionCase) => kindOf(cc) === 'gouge';
  const fields = [
    ['crossRadius', c.crossRadiusMm],
    ['feedRadius', c.feedRadiusMm],
  ] as const;
  for (const [field, r] of fields) {
    if (r === null) continue;
    const withRadius = (m: number | null): RevolutionCase =>
      field === 'crossRadius' ? { ...c, crossRadiusMm: m } : { ...c, feedRadiusMm: m };
    if (gouges(withRadius(null))) continue;
    const sign = Math.sign(r);
    const maxMag = THREE_AXIS_SURFACE_RADIUS_RANGE_MM[1];
    let lo = Math.log(Math.abs(r));
    let hi = Math.log(maxMag);
    let limit: number | null = null;
    if (!gouges(withRadius(sign * maxMag))) {
      for (let i = 0; i < 80 && hi - lo > 1e-13; i++) {
        const mid = 0.5 * (lo + hi);
        if (gouges(withRadius(sign * Math.exp(mid)))) lo = mid;
        else hi = mid;
      }
      limit = Math.exp(hi);
    }
    const name = field === 'crossRadius' ? 'meridian' : 'horizontal circle (its normal radius)';
    const kind = sign < 0 ? 'concave' : 'convex';
    return threeAxisError(
      field,
      'gouging',
      r,
      limit === null ? null : sign * limit,
      limit === null
        ? `is too tight for this tool ${which} (got ${r}): only a straight ${name === 'meridian' ? 'meridian (no Rc)' : 'horizontal line (no Rf)'} avoids gouging.`
        : `is too tight for this tool ${which} (got ${r}): a ${kind} ${name} must have a radius of at least ${formatNumber(limit)} mm; a tighter one is gouged (the tool reaches into the surface away from the contact).`,
    );
  }
  return threeAxisError(
    'crossRadius',
    'gouging',
    c.crossRadiusMm ?? Number.POSITIVE_INFINITY,
    null,
    `and the feed radius Rf together are too tight for this tool ${which}: no single one of them, however large, avoids gouging (the tool reaches into the surface away from the contact).`,
  );
}

/**
 * Forward: the step L along the meridian and the step-down dz between the tool tips that leave a
 * cusp of height `hMm` (mm, along the normal) between this pass and the next one down the slope.
 * Errors: the case's inputs, h at least 1e-9 mm and below the shank's limit and the surface's
 * end, gouging of either pass. Exact to 1e-9 mm (closed-form cusp, bracketed root in L).
 */
export function waterlineForward(c: RevolutionCase, hMm: number): ThreeAxisResult<WaterlineAnswer> {
  const errors = checkCase(c);
  errors.push(...checkHeight(hMm));
  if (errors.length > 0) return { ok: false, errors };
  const s = setupOf(c);
  const r = forwardCore(s, hMm);
  if (r.kind !== 'ok') return { ok: false, errors: [coreError(c, s, r, 'h', hMm)] };
  return { ok: true, value: answerAt(c, s, r.L) };
}

/**
 * Inverse: the cusp height (mm, along the normal) that a step-down dz (between the tool tips) or a
 * step L along the meridian leaves between this pass and the next one down. Errors: the case's
 * inputs, the step at least 1e-9 mm and below the shank's limit and the surface's end (in the
 * step's own terms), gouging.
 */
export function waterlineInverse(c: RevolutionCase, step: WaterlineStep): ThreeAxisResult<WaterlineAnswer> {
  const errors = checkCase(c);
  errors.push(...checkStep(step.field, step.mm));
  if (errors.length > 0) return { ok: false, errors };
  const s = setupOf(c);
  const r = inverseCore(s, step);
  if (r.kind !== 'ok') return { ok: false, errors: [coreError(c, s, r, step.field, step.mm)] };
  return { ok: true, value: answerAt(c, s, r.L) };
}

/**
 * The step L (mm) for a cusp of `hMm`, without validation or gouging checks (the fast path for
 * sweeps and benchmarks); NaN where the forward would refuse.
 */
export function waterlineIntervalMm(c: RevolutionCase, hMm: number): number {
  const r = solveInterval(setupOf(c), hMm);
  return r.kind === 'ok' ? r.L : Number.NaN;
}

/**
 * The largest scallop height (mm) waterline passes can leave at this CC point: where the next
 * pass's shank starts to form the cusp, or where the next pass reaches the end of the usable
 * surface; 0 for a flat end. No validation (valid cases only).
 */
export function waterlineHeightLimitMm(c: RevolutionCase): number {
  const s = setupOf(c);
  if (s.tool.rcr === 0) return 0;
  const shankL = someShankL(s);
  if (shankL !== null) return shankHeightAt(s, shankStartL(s, shankL));
  return cuspAt(s, s.maxL * (1 - 1e-12)).heightMm;
}

/**
 * The up-slope cusp at a CC point for a constant step-down (mm): the cusp between the pass `dz`
 * higher (a CAM system's previous level, further up the meridian, at slope `alpha - L_u/Rc`) and
 * this one. It differs from the down-slope answer with the same dz wherever the meridian is curved
 * (the passes are not congruent). Found as the pair answered at the upper pass's CC point: its arc
 * length `L_u` from `dz = (1 + Rcr k) L_u sinc(k L_u / 2) sin(alpha - k L_u / 2)` (Newton, rate
 * `(1 + Rcr k) sin(alpha_u)`), the upper point's normal radius along the feed chosen so that the
 * axis of revolution stays where it is, then {@link waterlineInverse} there with `L_u`. The answer's
 * geometry is in the upper pass's frame. Errors as the inverse's, or `past-surface` when the pass
 * above would lie beyond the top of a convex meridian (slope 0) or the vertical of a concave one.
 */
export function waterlineCuspAbove(c: RevolutionCase, stepDownMm: number): ThreeAxisResult<WaterlineAnswer> {
  const errors = checkCase(c);
  errors.push(...checkStep('stepDown', stepDownMm));
  if (errors.length > 0) return { ok: false, errors };
  const s = setupOf(c);
  const { k, alpha0 } = s.mer;
  const scale = 1 + s.tool.rcr * k;
  const maxL = k > 0 ? alpha0 / k : k < 0 ? (Math.PI / 2 - alpha0) / -k : Number.POSITIVE_INFINITY;
  const dzOf = (L: number) => scale * L * sinc((k * L) / 2) * Math.sin(alpha0 - (k * L) / 2);
  const beyond = () =>
    threeAxisError(
      'stepDown',
      'past-surface',
      stepDownMm,
      Number.isFinite(maxL) ? dzOf(maxL) : null,
      `must be below ${formatNumber(dzOf(maxL))} mm here (got ${stepDownMm}): the pass above would lie beyond ${k > 0 ? 'the top of the convex meridian' : 'the vertical of the concave meridian'}.`,
    );
  if (Number.isFinite(maxL) && !(dzOf(maxL) > stepDownMm)) return { ok: false, errors: [beyond()] };
  const mismatch = {
    slope: 0,
    value(L: number): number {
      this.slope = scale * Math.sin(alpha0 - k * L);
      return dzOf(L) - stepDownMm;
    },
  };
  const start = stepDownMm / (scale * s.mer.sin0);
  const L = newtonRoot(mismatch, 0, maxL, start < maxL ? start : 0.5 * maxL, true, 1e-15, 100);
  const alphaU = alpha0 - k * L;
  // The upper CC point relative to this one, and the axis relative to it.
  const half = (k * L) / 2;
  const chord = L * sinc(half);
  const abar = alpha0 - half;
  const upS = -chord * Math.cos(abar);
  let feedU: number | null = null;
  if (s.surf.axisS !== null) {
    feedU = -(s.surf.axisS - upS) / Math.sin(alphaU);
    if (!(feedU * (c.feedRadiusMm as number) > 0)) {
      return {
        ok: false,
        errors: [
          threeAxisError(
            'stepDown',
            'past-surface',
            stepDownMm,
            null,
            `is too large here (got ${stepDownMm}): the pass above would lie across the axis of revolution.`,
          ),
        ],
      };
    }
  }
  return waterlineInverse({ ...c, slopeDeg: radToDeg(alphaU), feedRadiusMm: feedU }, { field: 'interval', mm: L });
}
