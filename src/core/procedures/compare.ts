/**
 * Every procedure for one case, side by side with the exact answer: step-overs (forward) or
 * scallop heights (inverse), deviations, the scallop each procedure's own step-over really leaves,
 * and a warning where a procedure's step-over is so wide that the passes would leave a wall.
 * Pure; lengths mm. Never NaN or Infinity: a missing value is null or "not applicable" with a reason.
 */

import type { ForwardInput, InverseInput } from '../domain/pass';
import type { CylinderSurface } from '../domain/surface';
import type { ToolInput } from '../domain/tool';
import { formatSignificant } from '../input/units';
import {
  forwardInput,
  inverseInput,
  type RawForwardInput,
  type RawInverseInput,
  type Validation,
} from '../input/validate';
import { type ExactForward, type ExactInverse, exactForward, exactInverse } from '../surfaces/solve';
import { maxIntervalMm, validateForward, validateInverse } from '../surfaces/validate';
import { type Approximation, combinedRadiusMm, type HalfInterval, type ScallopHeight } from './approximations';
import {
  APPROXIMATION_KEYS,
  APPROXIMATIONS,
  type ApproximationKey,
  CORRECTED_KEYS,
  type CorrectedKey,
  type ForwardModels,
  PROCEDURES,
} from './procedures';

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

/** What ignoring or correcting for the curvature gives on a cylinder (forward), mm. */
export interface CurvatureComparison {
  readonly surface: CylinderSurface;
  /** The plane's exact step-over at the same h: the answer that ignores the curvature. */
  readonly plane: ForwardEstimate<{ readonly planeIntervalMm: number }>;
  /**
   * The usual correction: each effective radius Reff combined with the surface's radius across the
   * feed, `1 / rho = 1 / Reff + 1 / Rs` (Rs signed; across the axis the surface is straight across
   * the feed, so rho = Reff), and the circle's `L = 2 sqrt(2 rho h - h^2)`.
   */
  readonly corrected: { readonly [K in CorrectedKey]: ForwardEstimate<{ readonly combinedRadiusMm: number }> };
}

/** Step-over of every procedure for one case (mm). */
export interface ForwardComparison {
  readonly input: ForwardInput;
  /** The widest step-over that still leaves a scallop (2R without tilt). */
  readonly maxIntervalMm: number;
  readonly exact: ExactForward;
  /** The paper's procedures and the circles, as on a plane (on a cylinder they ignore its curvature). */
  readonly approximations: { readonly [K in ApproximationKey]: ForwardEstimate<ForwardModels[K]> };
  /** On a cylinder: the plane's answer and the usual curvature correction; null on a plane. */
  readonly curvature: CurvatureComparison | null;
}

/** What ignoring or correcting for the curvature gives on a cylinder (inverse: heights at the step-over), mm. */
export interface InverseCurvatureComparison {
  readonly surface: CylinderSurface;
  /** The plane's exact scallop height at the same step-over. */
  readonly plane: InverseEstimate;
  /** The usual correction (see CurvatureComparison): `h = rho - sqrt(rho^2 - (L/2)^2)`. */
  readonly corrected: { readonly [K in CorrectedKey]: InverseEstimate };
}

/** Scallop height of every procedure at one step-over (mm). */
export interface InverseComparison {
  readonly input: InverseInput;
  readonly exact: ExactInverse;
  readonly approximations: Readonly<Record<ApproximationKey, InverseEstimate>>;
  /** On a cylinder: the plane's answer and the usual curvature correction; null on a plane. */
  readonly curvature: InverseCurvatureComparison | null;
}

/** `value(key)` for every approximation, keyed by procedure, in the registry's order. */
function eachApproximation<V>(value: (key: ApproximationKey) => V): Record<ApproximationKey, V> {
  const out = {} as Record<ApproximationKey, V>;
  for (const key of APPROXIMATION_KEYS) out[key] = value(key);
  return out;
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
  const realScallopMm = beyond ? null : exactInverse(inverseInput(input, input.pattern, L, input.surface)).cuspHeightMm;
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

/** The radii of a corrected procedure: its own effective radius and the combined one on the cylinder (mm). */
type CorrectedRadii = Approximation<{ readonly effectiveRadiusMm: number; readonly combinedRadiusMm: number }>;

/** Each corrected procedure's effective radius and combined radius on the cylinder, or its model's reason for none. */
function correctedRadii(tool: ToolInput, surface: CylinderSurface): Record<CorrectedKey, CorrectedRadii> {
  const out = {} as Record<CorrectedKey, CorrectedRadii>;
  for (const key of CORRECTED_KEYS) {
    const m = APPROXIMATIONS[key].model(tool);
    out[key] = m.ok
      ? {
          ok: true,
          effectiveRadiusMm: m.effectiveRadiusMm,
          combinedRadiusMm: combinedRadiusMm(m.effectiveRadiusMm, surface),
        }
      : { ok: false, notApplicable: m.notApplicable };
  }
  return out;
}

/** Who a corrected procedure's reasons name. */
function correctedWho(key: CorrectedKey): string {
  return `${PROCEDURES[key].shortLabel}, corrected for the curvature`;
}

/** The plane's answer and the corrected circles on a cylinder (see CurvatureComparison). */
function curvatureRows(
  input: ForwardInput,
  surface: CylinderSurface,
  exact: ExactForward,
  maxMm: number,
): CurvatureComparison {
  const planeL = exactForward(forwardInput(input, input.pattern, input.scallopHeightMm)).intervalMm;
  const plane = estimate<{ planeIntervalMm: number }>(
    { ok: true, halfIntervalMm: planeL / 2, intervalMm: planeL, planeIntervalMm: planeL },
    input,
    exact,
    maxMm,
  );
  const h = input.scallopHeightMm;
  const corrected = {} as { -readonly [K in CorrectedKey]: ForwardEstimate<{ readonly combinedRadiusMm: number }> };
  const radii = correctedRadii(input, surface);
  for (const key of CORRECTED_KEYS) {
    const m = radii[key];
    const who = correctedWho(key);
    if (!m.ok) {
      corrected[key] = m;
      continue;
    }
    const { effectiveRadiusMm: reff, combinedRadiusMm: combined } = m;
    if (!(combined > 0) || !Number.isFinite(combined)) {
      corrected[key] = {
        ok: false,
        notApplicable: `${who}: its effective radius (${formatSignificant(reff, { digits: 5, trimZeros: true })} mm) is not smaller than the concave surface's, so the combined radius is not positive.`,
      };
      continue;
    }
    if (h > combined) {
      corrected[key] = {
        ok: false,
        notApplicable: `${who}: h is above the widest point of the combined circle (${formatSignificant(combined, { digits: 5, trimZeros: true })} mm).`,
      };
      continue;
    }
    const half = Math.sqrt(h) * Math.sqrt(2 * combined - h);
    corrected[key] = estimate<{ combinedRadiusMm: number }>(
      { ok: true, halfIntervalMm: half, intervalMm: 2 * half, combinedRadiusMm: combined },
      input,
      exact,
      maxMm,
    );
  }
  return { surface, plane, corrected };
}

/** Every procedure's step-over for a validated input. */
export function compareForward(input: ForwardInput): ForwardComparison {
  const exact = exactForward(input);
  const maxMm = maxIntervalMm(input, input.pattern, input.surface);
  return {
    input,
    maxIntervalMm: maxMm,
    exact,
    curvature: input.surface.kind === 'cylinder' ? curvatureRows(input, input.surface, exact, maxMm) : null,
    // Each estimate carries its own procedure's model (the registry's functions are typed per key).
    approximations: eachApproximation((key) =>
      estimate(APPROXIMATIONS[key].halfInterval(input), input, exact, maxMm),
    ) as ForwardComparison['approximations'],
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

/** The curvature rows of the inverse (see InverseCurvatureComparison). */
function inverseCurvatureRows(
  input: InverseInput,
  surface: CylinderSurface,
  exactMm: number,
): InverseCurvatureComparison {
  const L = input.intervalMm;
  const planeInput = inverseInput(input, input.pattern, L);
  const planeMax = maxIntervalMm(input, input.pattern);
  const plane: InverseEstimate =
    L < planeMax
      ? heightEstimate({ ok: true, scallopHeightMm: exactInverse(planeInput).cuspHeightMm }, exactMm)
      : { ok: false, notApplicable: 'Plane: the step-over is at or beyond the widest one the tool allows on a plane.' };
  const corrected = {} as { -readonly [K in CorrectedKey]: InverseEstimate };
  const half = L / 2;
  const radii = correctedRadii(input, surface);
  for (const key of CORRECTED_KEYS) {
    const m = radii[key];
    if (!m.ok) {
      corrected[key] = m;
      continue;
    }
    const rho = m.combinedRadiusMm;
    if (!(rho > 0) || !Number.isFinite(rho) || half > rho) {
      corrected[key] = {
        ok: false,
        notApplicable: `${correctedWho(key)}: L/2 is not inside its combined circle (${formatSignificant(rho, { digits: 5, trimZeros: true })} mm).`,
      };
      continue;
    }
    corrected[key] = heightEstimate(
      { ok: true, scallopHeightMm: (half * half) / (rho + Math.sqrt((rho - half) * (rho + half))) },
      exactMm,
    );
  }
  return { surface, plane, corrected };
}

/** Every procedure's scallop height at a validated step-over. */
export function compareInverse(input: InverseInput): InverseComparison {
  const exact = exactInverse(input);
  const h = exact.cuspHeightMm;
  return {
    input,
    exact,
    curvature: input.surface.kind === 'cylinder' ? inverseCurvatureRows(input, input.surface, h) : null,
    approximations: eachApproximation((key) => heightEstimate(APPROXIMATIONS[key].scallopHeight(input), h)),
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
