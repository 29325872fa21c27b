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
 *   smallest magnitude that fits with the other held; a vertical wall (alpha = 90 on a straight
 *   meridian: the side cuts it flat, no scallop) and alpha = 90 on a convex one (an overhang below).
 *   On a concave meridian alpha = 90 is answered: the passes below are less steep and leave a scallop.
 *
 * Lengths mm, angles degrees at the interface.
 *
 * The parts: the solver (waterlineSolve.ts) and the limits as input errors (waterlineErrors.ts).
 */
import { radToDeg } from '../input/units';
import { newtonRoot } from '../math/rootFinder';
import {
  checkHeight,
  checkStep,
  formatNumber,
  MIN_THREE_AXIS_LENGTH_MM,
  type ThreeAxisResult,
  threeAxisError,
} from './errors';
import { sinc } from './meridianPasses';
import { checkCase, coreError } from './waterlineErrors';
import {
  answerAt,
  cuspAt,
  forwardCore,
  inverseCore,
  type RevolutionCase,
  setupOf,
  shankHeightAt,
  shankStartL,
  solveInterval,
  someShankL,
  type WaterlineAnswer,
  type WaterlineStep,
} from './waterlineSolve';

/** The types of the solver (waterlineSolve.ts), re-exported for the callers. */
export type { RevolutionCase, WaterlineAnswer, WaterlineGeometry, WaterlineStep } from './waterlineSolve';

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
  // A corner at least as round as a concave meridian (Rcr >= |Rc|) fits nowhere on it: the inverse's gouging error.
  if (!(scale > 0)) return waterlineInverse(c, { field: 'stepDown', mm: stepDownMm });
  const maxL = k > 0 ? alpha0 / k : k < 0 ? (Math.PI / 2 - alpha0) / -k : Number.POSITIVE_INFINITY;
  const dzOf = (L: number) => scale * L * sinc((k * L) / 2) * Math.sin(alpha0 - (k * L) / 2);
  const beyond = () => {
    const limit = dzOf(maxL);
    const where = k > 0 ? 'the top of the convex meridian' : 'the vertical of the concave meridian';
    return threeAxisError(
      'stepDown',
      'past-surface',
      stepDownMm,
      limit,
      limit < MIN_THREE_AXIS_LENGTH_MM
        ? `cannot be answered here (got ${stepDownMm}): the contact is at ${where}, so there is no pass above it.`
        : `must be below ${formatNumber(limit)} mm here (got ${stepDownMm}): the pass above would lie beyond ${where}.`,
    );
  };
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
