/**
 * Every procedure for one case, side by side with the exact answer: step-overs (forward) or
 * scallop heights (inverse), deviations, the scallop each procedure's own step-over really leaves,
 * and a warning where a procedure's step-over is so wide that the passes would leave a wall.
 * Pure; lengths mm. Never NaN or Infinity: a missing value is null or "not applicable" with a reason.
 */
import {
  type Approximation,
  type BediModel,
  bediHalfInterval,
  bediScallopHeight,
  type CornerBallModel,
  cornerBallHalfInterval,
  cornerBallScallopHeight,
  type HalfInterval,
  type OsculatingModel,
  osculatingHalfInterval,
  osculatingScallopHeight,
  type RedonnetModel,
  redonnetHalfInterval,
  redonnetScallopHeight,
  type ScallopHeight,
  type SekineModel,
  sekineHalfInterval,
  sekineScallopHeight,
} from './approximations';
import { type ExactForward, type ExactInverse, exactForward, exactInverse } from './exact';
import type { ApproximationKey } from './procedures';
import { formatSignificant } from './units';
import {
  type ForwardInput,
  type InverseInput,
  inverseInput,
  maxIntervalMm,
  type RawForwardInput,
  type RawInverseInput,
  type Validation,
  validateForward,
  validateInverse,
} from './validate';

/** An approximation's step-over for a scallop height, beside the exact one. */
export type ForwardEstimate<M> =
  | ({
      readonly ok: true;
      readonly intervalMm: number;
      readonly halfIntervalMm: number;
      /** Signed deviation of its step-over from the exact one: mm and % of the exact. */
      readonly deviationMm: number;
      readonly deviationPercent: number;
      /** The scallop (mm) that its own step-over really leaves (exact inverse); null beyond the wall. */
      readonly realScallopMm: number | null;
      /** Set when its step-over is at or beyond the widest that leaves a scallop. */
      readonly warning: string | null;
    } & M)
  | { readonly ok: false; readonly notApplicable: string };

/** An approximation's scallop height for a step-over, beside the exact one. */
export type InverseEstimate =
  | {
      readonly ok: true;
      readonly scallopHeightMm: number;
      readonly deviationMm: number;
      /** Null where the exact scallop is 0 (a flat bottom covering the step-over). */
      readonly deviationPercent: number | null;
    }
  | { readonly ok: false; readonly notApplicable: string };

export interface ForwardModels {
  readonly sekine: SekineModel;
  readonly redonnet: RedonnetModel;
  readonly bedi: BediModel;
  readonly osculating: OsculatingModel;
  readonly cornerBall: CornerBallModel;
}

/** Step-over of every procedure for one case (mm). */
export interface ForwardComparison {
  readonly input: ForwardInput;
  /** The widest step-over that still leaves a scallop (2R without tilt). */
  readonly maxIntervalMm: number;
  readonly exact: ExactForward;
  readonly approximations: { readonly [K in ApproximationKey]: ForwardEstimate<ForwardModels[K]> };
}

/** Scallop height of every procedure at one step-over (mm). */
export interface InverseComparison {
  readonly input: InverseInput;
  readonly exact: ExactInverse;
  readonly approximations: Readonly<Record<ApproximationKey, InverseEstimate>>;
}

function estimate<M>(
  r: Approximation<HalfInterval & M>,
  input: ForwardInput,
  exact: ExactForward,
  maxMm: number,
): ForwardEstimate<M> {
  if (!r.ok) return r;
  // A symmetric model: its step-over is twice its L/2 for either pattern.
  const L = 2 * r.halfIntervalMm;
  const deviationMm = L - exact.intervalMm;
  const beyond = !(L < maxMm);
  const realScallopMm = beyond ? null : exactInverse(inverseInput(input, input.pattern, L)).cuspHeightMm;
  const warning = beyond
    ? `its step-over L = ${formatSignificant(L, { digits: 6, trimZeros: true })} mm is not below the widest step-over that leaves a scallop (${formatSignificant(maxMm, { digits: 6, trimZeros: true })} mm${input.tiltAngleDeg === 0 ? ', the tool diameter' : ''}): passes this far apart leave a wall.`
    : null;
  return {
    ...r,
    intervalMm: L,
    halfIntervalMm: r.halfIntervalMm,
    deviationMm,
    deviationPercent: (100 * deviationMm) / exact.intervalMm,
    realScallopMm,
    warning,
  };
}

/** Every procedure's step-over for a validated input. */
export function compareForward(input: ForwardInput): ForwardComparison {
  const exact = exactForward(input);
  const maxMm = maxIntervalMm(input, input.pattern);
  return {
    input,
    maxIntervalMm: maxMm,
    exact,
    approximations: {
      sekine: estimate(sekineHalfInterval(input), input, exact, maxMm),
      redonnet: estimate(redonnetHalfInterval(input), input, exact, maxMm),
      bedi: estimate(bediHalfInterval(input), input, exact, maxMm),
      osculating: estimate(osculatingHalfInterval(input), input, exact, maxMm),
      cornerBall: estimate(cornerBallHalfInterval(input), input, exact, maxMm),
    },
  };
}

function heightEstimate(r: Approximation<ScallopHeight>, exactMm: number): InverseEstimate {
  if (!r.ok) return r;
  const deviationMm = r.scallopHeightMm - exactMm;
  return {
    ok: true,
    scallopHeightMm: r.scallopHeightMm,
    deviationMm,
    deviationPercent: exactMm > 0 ? (100 * deviationMm) / exactMm : null,
  };
}

/** Every procedure's scallop height at a validated step-over. */
export function compareInverse(input: InverseInput): InverseComparison {
  const exact = exactInverse(input);
  const h = exact.cuspHeightMm;
  return {
    input,
    exact,
    approximations: {
      sekine: heightEstimate(sekineScallopHeight(input), h),
      redonnet: heightEstimate(redonnetScallopHeight(input), h),
      bedi: heightEstimate(bediScallopHeight(input), h),
      osculating: heightEstimate(osculatingScallopHeight(input), h),
      cornerBall: heightEstimate(cornerBallScallopHeight(input), h),
    },
  };
}

/** Validates raw values and compares every procedure; errors name the fields. */
export function solveForwardRaw(raw: RawForwardInput): Validation<ForwardComparison> {
  const v = validateForward(raw);
  return v.ok ? { ok: true, value: compareForward(v.value) } : v;
}

/** Validates raw values and computes every procedure's scallop height. */
export function solveInverseRaw(raw: RawInverseInput): Validation<InverseComparison> {
  const v = validateInverse(raw);
  return v.ok ? { ok: true, value: compareInverse(v.value) } : v;
}
