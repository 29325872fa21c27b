/**
 * Three-axis machining of a sloped plane (section 2a of shared/notes/doubly-curved-and-3-axis.md):
 * the tool upright, raster passes at plan angle `psi` to the fall line, or waterline passes
 * (`psi = 90`). The slope gives the posture at the CC point in closed form (slopePosture.ts);
 * on a plane the answer is then the posture answer (posture.ts, one-way: the upright tool is the
 * same whichever way it feeds, so one-way equals zigzag), and the programmed steps follow:
 * `Lxy = L sqrt(cos^2 psi + cos^2 alpha sin^2 psi)` (raster) and `dz = L sin alpha` (waterline).
 * Lengths mm, angles degrees at the interface.
 *
 * Limits, as the posture solver gives them: the scallop height must stay below the binding
 * flank or shank limit (flankLimits); on the uphill side the shank starts at
 * `Rcr (1 - sin alpha)` above the contact for waterline, so steep walls refuse large h (and a
 * flat end, Rcr = 0, has no scallop flank on the uphill side at any h once it is tilted). A
 * vertical wall (alpha = 90) is cut flat by the side: no scallop, no step.
 */
import { bracketedRoot } from '../math/rootFinder';
import { type FlankLimits, flankLimits, flankWidthMm, type PostureShape, postureShape } from '../tool/posture';
import { sinDeg } from './angles';
import {
  checkHeight,
  checkStep,
  checkTool,
  formatNumber,
  type ThreeAxisError,
  type ThreeAxisField,
  type ThreeAxisResult,
  threeAxisError,
} from './errors';
import { type SlopePosture, slopePosture } from './slopePosture';

/** How the passes run on the slope. */
export type ThreeAxisPasses = 'raster' | 'waterline';

/** A tool on a sloped plane with a pass strategy. */
export interface SlopedPlaneCase {
  /** Tool radius R, mm, 0.001 to 1000. */
  readonly toolRadiusMm: number;
  /** Corner radius Rcr, mm, 0 <= Rcr <= R. */
  readonly cornerRadiusMm: number;
  /** Slope alpha of the plane, degrees, 0 <= alpha <= 90 (90 is refused: a vertical wall). */
  readonly slopeDeg: number;
  /** Raster (parallel) or waterline (Z-level) passes. */
  readonly passes: ThreeAxisPasses;
  /** Raster angle psi in plan from the fall line, degrees, 0 to 90; ignored for waterline (90). */
  readonly rasterAngleDeg: number;
}

/** The answer on a sloped plane. */
export interface SlopedPlaneAnswer {
  /** Step-over L between adjacent CC paths, along the plane, mm. */
  readonly intervalMm: number;
  /** Lxy: horizontal distance between the vertical planes of adjacent passes, mm. */
  readonly horizontalStepMm: number;
  /** dz: height between adjacent levels (waterline), mm; null for raster. */
  readonly stepDownMm: number | null;
  /** The cusp height the passes leave (h, measured along the plane's normal), mm; 0 without scallop. */
  readonly cuspHeightMm: number;
  /** The equivalent posture at the CC point, degrees (lead >= 0: the feed climbs; tilt >= 0: uphill on +Y). */
  readonly leadDeg: number;
  readonly tiltDeg: number;
  /** True when the tool leaves no scallop at all (a flat end on a flat floor: L = 2R). */
  readonly noScallop: boolean;
  /** The largest scallop height this slope and raster angle allow (shank or flank limit), mm. */
  readonly heightLimitMm: number;
}

/** The step a CAM system programs for the inverse problem. */
export interface ProgrammedStep {
  /** `horizontalStep` (Lxy), `stepDown` (dz, waterline only) or `interval` (L along the surface). */
  readonly field: 'horizontalStep' | 'stepDown' | 'interval';
  /** The step, mm, at least 1e-9. */
  readonly mm: number;
}

/** The raster angle the passes use: psi for raster, 90 for waterline. */
export function effectiveRasterAngleDeg(c: SlopedPlaneCase): number {
  return c.passes === 'waterline' ? 90 : c.rasterAngleDeg;
}

/** Errors of the tool, slope and raster angle; the posture when they are valid. */
function checkCase(c: SlopedPlaneCase): { errors: ThreeAxisError[]; posture: SlopePosture | null } {
  const errors = [...checkTool(c.toolRadiusMm, c.cornerRadiusMm), ...slopeErrors(c)];
  return { errors, posture: errors.length === 0 ? slopePosture(c.slopeDeg, effectiveRasterAngleDeg(c)) : null };
}

/**
 * Errors of the slope (0 to 90; 90 a vertical wall; 0 for waterline passes) and the raster angle
 * (0 to 90) on a sloped plane: the rule the three-axis mode's check gives too (surfaces/modes).
 */
export function slopeErrors(c: Pick<SlopedPlaneCase, 'slopeDeg' | 'passes' | 'rasterAngleDeg'>): ThreeAxisError[] {
  const errors: ThreeAxisError[] = [];
  const a = c.slopeDeg;
  if (!(a >= 0 && a <= 90))
    errors.push(threeAxisError('slope', 'out-of-range', a, null, `must be from 0 to 90 degrees (got ${a}).`));
  else if (a === 90)
    errors.push(
      threeAxisError(
        'slope',
        'vertical-wall',
        a,
        90,
        'of 90 degrees is a vertical wall: the side of the upright tool cuts it flat, so no scallop forms at any step and there is no step to compute.',
      ),
    );
  else if (c.passes === 'waterline' && a === 0)
    errors.push(
      threeAxisError(
        'slope',
        'needs-slope',
        a,
        0,
        'must be above 0 degrees for waterline passes: on a flat floor every level is the same, so there is no step-down.',
      ),
    );
  if (c.passes === 'raster' && !(c.rasterAngleDeg >= 0 && c.rasterAngleDeg <= 90))
    errors.push(
      threeAxisError(
        'rasterAngle',
        'out-of-range',
        c.rasterAngleDeg,
        null,
        `must be from 0 to 90 degrees from the fall line (got ${c.rasterAngleDeg}).`,
      ),
    );
  return errors;
}

/** The posture shape (posture.ts) of the upright tool on the slope. */
function shapeOf(c: SlopedPlaneCase, p: SlopePosture): PostureShape {
  return postureShape(c.toolRadiusMm, c.cornerRadiusMm, p.leadRad, p.tiltRad);
}

/** True for a flat end on a flat floor: no scallop, L = 2R (the posture solver's flat case). */
function flatOnFloor(s: PostureShape): boolean {
  return s.flatOnPlane && s.rcr === 0;
}

/** Which side a flank limit is on, in words (right = +Y = uphill). */
function sideWord(limitBy: string): string {
  return limitBy.endsWith('right') || limitBy === 'right-flank' ? 'uphill' : 'downhill';
}

/**
 * Step-over L (mm) along the plane for scallop height `hMm`, without validation (the fast path:
 * `L = wR(h) + wL(h)` of the posture solver at the slope's posture). Valid inputs only: see
 * {@link slopedPlaneForward}.
 */
export function slopedPlaneIntervalMm(c: SlopedPlaneCase, hMm: number): number {
  const p = slopePosture(c.slopeDeg, effectiveRasterAngleDeg(c));
  const s = shapeOf(c, p);
  if (flatOnFloor(s)) return 2 * s.a;
  const right = flankWidthMm(s, 'right', hMm);
  return p.tiltRad === 0 ? 2 * right : right + flankWidthMm(s, 'left', hMm);
}

/**
 * The forward problem's refusals (see {@link slopedPlaneForward}) without solving it: empty when it
 * is answered. For a caller that takes the answer from the plane's model at the slope's posture (the
 * worker's three-axis job: surfaces/question.ts posturedModel).
 */
export function slopedPlaneForwardErrors(c: SlopedPlaneCase, hMm: number): ThreeAxisError[] {
  return checkedForward(c, hMm).errors;
}

/** A case checked once: its refusals, or (none) the posture, its shape and flank limits the answer reads. */
interface Checked {
  readonly errors: ThreeAxisError[];
  readonly valid: { readonly posture: SlopePosture; readonly shape: PostureShape; readonly limits: FlankLimits } | null;
}

/** The forward problem checked once (slopedPlaneForwardErrors's refusals; slopedPlaneForward's answer reads the rest). */
function checkedForward(c: SlopedPlaneCase, hMm: number): Checked {
  const { errors, posture } = checkCase(c);
  errors.push(...checkHeight(hMm));
  if (errors.length > 0 || posture === null) return { errors, valid: null };
  const shape = shapeOf(c, posture);
  const limits = flankLimits(shape);
  const limitError = flatOnFloor(shape) ? null : heightLimitError(limits.limitMm, limits.limitBy, hMm);
  return limitError ? { errors: [limitError], valid: null } : { errors: [], valid: { posture, shape, limits } };
}

/**
 * Forward: the steps that leave a scallop of height `hMm` (mm, along the plane's normal) on the
 * slope. Errors: tool, slope (0..90; 90 a vertical wall; 0 for waterline), raster angle (0..90),
 * h at least 1e-9 mm and below the shank or flank limit of the slope's posture. Exact to the
 * posture solver's 1e-9 mm.
 */
export function slopedPlaneForward(c: SlopedPlaneCase, hMm: number): ThreeAxisResult<SlopedPlaneAnswer> {
  const checked = checkedForward(c, hMm);
  if (checked.valid === null) return { ok: false, errors: checked.errors };
  const { posture, shape: s, limits } = checked.valid;
  if (flatOnFloor(s)) return { ok: true, value: answer(c, posture, 2 * s.a, 0, true, Number.POSITIVE_INFINITY) };
  const right = flankWidthMm(s, 'right', hMm);
  const L = posture.tiltRad === 0 ? 2 * right : right + flankWidthMm(s, 'left', hMm);
  return { ok: true, value: answer(c, posture, L, hMm, false, limits.limitMm) };
}

function heightLimitError(limitMm: number, limitBy: string, hMm: number): ThreeAxisError | null {
  if (!(limitMm >= 1e-9))
    return threeAxisError(
      'h',
      'wall-only',
      hMm,
      null,
      'cannot be answered at this slope and raster angle: the side of the tool rises straight from the contact (a flat end has no corner to curve up), so it cuts a step at any spacing, not a scallop. Use a corner radius.',
    );
  if (hMm < limitMm) return null;
  const shank = limitBy.startsWith('shank');
  return threeAxisError(
    'h',
    shank ? 'shank-cuts' : 'flank-wall',
    hMm,
    limitMm,
    shank
      ? `must be below ${formatNumber(limitMm)} mm at this slope and raster angle (got ${hMm}): above it the shank (the tool's cylindrical side, on the uphill side), not the corner, would form the cusp.`
      : `must be below ${formatNumber(limitMm)} mm at this slope and raster angle (got ${hMm}): at or above it the ${sideWord(limitBy)} flank of the profile leaves a wall, not a scallop.`,
  );
}

function answer(
  c: SlopedPlaneCase,
  p: SlopePosture,
  L: number,
  cusp: number,
  noScallop: boolean,
  limit: number,
): SlopedPlaneAnswer {
  // Each field written out: programmedSteps spread here made the answer about four times slower to
  // build and read (the bench's sloped plane, 1.2 -> 5.4 us per validated forward answer).
  return {
    intervalMm: L,
    horizontalStepMm: L * p.horizontalStepPerInterval,
    stepDownMm: stepDownMm(c, L),
    cuspHeightMm: cusp,
    leadDeg: p.leadDeg,
    tiltDeg: p.tiltDeg,
    noScallop,
    heightLimitMm: limit,
  };
}

/** The step-over L along the plane and the steps programmed for it (mm): Lxy, and dz for waterline passes. */
export function programmedSteps(
  c: SlopedPlaneCase,
  p: SlopePosture,
  L: number,
): Pick<SlopedPlaneAnswer, 'intervalMm' | 'horizontalStepMm' | 'stepDownMm'> {
  return { intervalMm: L, horizontalStepMm: L * p.horizontalStepPerInterval, stepDownMm: stepDownMm(c, L) };
}

/** The step-down dz (mm) of waterline passes L apart along the plane; null for raster passes. */
function stepDownMm(c: SlopedPlaneCase, L: number): number | null {
  return c.passes === 'waterline' ? L * sinDeg(c.slopeDeg) : null;
}

/** Converts a programmed step to L along the plane (mm). */
export function intervalOfStep(c: SlopedPlaneCase, p: SlopePosture, step: ProgrammedStep): number {
  if (step.field === 'interval') return step.mm;
  if (step.field === 'stepDown') return step.mm / sinDeg(c.slopeDeg);
  return step.mm / p.horizontalStepPerInterval;
}

/** A step in the field's own terms from L along the plane (mm). */
function stepOfInterval(c: SlopedPlaneCase, p: SlopePosture, field: ThreeAxisField, L: number): number {
  if (field === 'stepDown') return L * sinDeg(c.slopeDeg);
  if (field === 'horizontalStep') return L * p.horizontalStepPerInterval;
  return L;
}

/**
 * Inverse: the cusp height (mm, along the plane's normal) that a programmed step leaves: `Lxy`
 * (raster or waterline), `dz` (waterline) or `L`. Errors: as the forward, and the step at least
 * 1e-9 mm and below the widest step whose cusp the corner still forms (`shank-cuts`: beyond it the
 * shank would; on a waterline plane `dz < Rcr` up to 45 degrees, `Rcr sin 2 alpha` above) or that
 * still leaves a scallop (`beyond-step`), named in the step's own terms; `dz` only for waterline.
 */
export function slopedPlaneInverse(c: SlopedPlaneCase, step: ProgrammedStep): ThreeAxisResult<SlopedPlaneAnswer> {
  const checked = checkedInverse(c, step);
  if (checked.valid === null) return { ok: false, errors: checked.errors };
  const { posture, shape: s, limits } = checked.valid;
  const L = intervalOfStep(c, posture, step);
  if (flatOnFloor(s)) return { ok: true, value: answer(c, posture, L, 0, true, Number.POSITIVE_INFINITY) };
  const limitMm = limits.limitMm;
  return { ok: true, value: answer(c, posture, L, oneWayCuspHeightMm(s, L, limitMm), false, limitMm) };
}

/**
 * The inverse problem's refusals (see {@link slopedPlaneInverse}) without solving it: empty when it
 * is answered (as {@link slopedPlaneForwardErrors}).
 */
export function slopedPlaneInverseErrors(c: SlopedPlaneCase, step: ProgrammedStep): ThreeAxisError[] {
  return checkedInverse(c, step).errors;
}

/** The inverse problem checked once (as checkedForward). */
function checkedInverse(c: SlopedPlaneCase, step: ProgrammedStep): Checked {
  const { errors, posture } = checkCase(c);
  errors.push(...checkStep(step.field, step.mm));
  if (step.field === 'stepDown' && c.passes !== 'waterline')
    errors.push(
      threeAxisError(
        'stepDown',
        'out-of-range',
        step.mm,
        null,
        'is the step of waterline passes: give raster passes a horizontal step Lxy.',
      ),
    );
  if (errors.length > 0 || posture === null) return { errors, valid: null };
  const s = shapeOf(c, posture);
  const L = intervalOfStep(c, posture, step);
  const limits = flankLimits(s);
  const maxL = flatOnFloor(s)
    ? 2 * s.a
    : limits.limitMm >= 1e-9
      ? flankWidthMm(s, 'right', limits.limitMm) + flankWidthMm(s, 'left', limits.limitMm)
      : 0;
  if (!(maxL > 0)) {
    const e = heightLimitError(limits.limitMm, limits.limitBy, 0);
    return { errors: e ? [{ ...e, field: step.field, got: step.mm }] : [], valid: null };
  }
  if (L < maxL || (flatOnFloor(s) && L <= maxL)) return { errors: [], valid: { posture, shape: s, limits } };
  const limitStep = stepOfInterval(c, posture, step.field, maxL);
  const why = flatOnFloor(s)
    ? 'the tool diameter: beyond it adjacent passes leave a ridge of uncut floor'
    : limits.limitBy.startsWith('shank')
      ? 'the widest step at this slope whose cusp the corner still forms; beyond it the shank (the tool side, uphill) forms the cusp'
      : `the widest step at this slope that still leaves a scallop; beyond it the ${sideWord(limits.limitBy)} flank leaves a wall`;
  return {
    errors: [
      threeAxisError(
        step.field,
        !flatOnFloor(s) && limits.limitBy.startsWith('shank') ? 'shank-cuts' : 'beyond-step',
        step.mm,
        limitStep,
        `must be below ${formatNumber(limitStep)} mm (got ${step.mm}), ${why}.`,
      ),
    ],
    valid: null,
  };
}

/**
 * Height (mm) of the one-way cusp that CC paths `L` apart leave: the root of `wR(z) + wL(z) = L`
 * below `limitMm` (the widths are the posture solver's flanks), by the shared bracketed root
 * (rootFinder.ts, Illinois) in `u = sqrt(z)`, where the widths grow nearly linearly. (exact.ts's inverse gives the
 * same root by Newton steps; it was measured at 0.06 to 4.5 ms on some steep tilted postures, too
 * slow for a 200-slope sweep, so the sweep solves it here from the forward widths.)
 */
function oneWayCuspHeightMm(s: PostureShape, L: number, limitMm: number): number {
  const f = { value: (u: number) => flankWidthMm(s, 'right', u * u) + flankWidthMm(s, 'left', u * u) - L };
  const hi = Math.sqrt(limitMm);
  // The flat bottom of a tool lying flat covers up to 2 (R - Rcr) without a cusp.
  const fLo = f.value(0);
  if (fLo >= 0) return 0;
  const fHi = f.value(hi);
  return (fHi <= 0 ? hi : bracketedRoot(f, 0, hi, fLo, fHi, 1e-16)) ** 2;
}
