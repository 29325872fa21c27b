/**
 * The results table's data: one row per procedure (exact first), and on a cylinder the rows of the
 * plane's answer and of each procedure corrected for the curvature; a row without a value says why
 * as data (ProcedureNote), which the page words in the user's unit. Mm.
 */

import type { ForwardInput, InverseInput, ToolInput } from '../../core/input/validate';
import { combinedRadiusMm } from '../../core/procedures/approximations';
import type {
  CurvatureComparison,
  ForwardComparison,
  ForwardEstimate,
  InverseComparison,
  InverseCurvatureComparison,
  InverseEstimate,
} from '../../core/procedures/compare';
import {
  APPROXIMATION_KEYS,
  type ApproximationKey,
  CORRECTED_KEYS,
  type CorrectedKey,
  CURVATURE_ROWS,
  correctedRowKey,
  modelCurve,
} from '../../core/procedures/procedures';
import type { CylinderSurface } from '../../core/surfaces/cylinder';
import type { CurvatureRow, ExactSummary, ProcedureNote, ProcedureRow, ResultRow } from '../protocol';

/** Where the forward problem's rows are measured: at h; the inverse's: at L/2. */
interface Asked {
  readonly quantity: 'h' | 'half';
  readonly valueMm: number;
}

function forwardAsked(input: ForwardInput): Asked {
  return { quantity: 'h', valueMm: input.scallopHeightMm };
}

function inverseAsked(input: InverseInput): Asked {
  return { quantity: 'half', valueMm: input.intervalMm / 2 };
}

/** A row without a value, and why. */
function noValueRow<K extends string>(key: K, note: ProcedureNote): ResultRow<K> {
  return { key, valueMm: null, deviationMm: null, deviationPercent: null, realScallopMm: null, note };
}

/** A forward estimate as a row: its L/2 (the deviation halved with it), or its note when it has none. */
function forwardEstimateRow<K extends string>(
  key: K,
  r: ForwardEstimate<unknown>,
  maxIntervalMm: number,
  missing: () => ProcedureNote,
): ResultRow<K> {
  if (!r.ok) return noValueRow(key, missing());
  return {
    key,
    valueMm: r.halfIntervalMm,
    // The table shows L/2: its deviation is half the step-over's.
    deviationMm: r.deviationMm / 2,
    deviationPercent: r.deviationPercent,
    realScallopMm: r.realScallopMm,
    note: r.warning === null ? null : { kind: 'wall', intervalMm: r.intervalMm, maxIntervalMm },
  };
}

/** An inverse estimate as a row: its scallop height, or its note when it has none. */
function inverseEstimateRow<K extends string>(key: K, r: InverseEstimate, missing: () => ProcedureNote): ResultRow<K> {
  if (!r.ok) return noValueRow(key, missing());
  return {
    key,
    valueMm: r.scallopHeightMm,
    deviationMm: r.deviationMm,
    deviationPercent: r.deviationPercent,
    realScallopMm: null,
    note: null,
  };
}

function exactRow(valueMm: number, realScallopMm: number | null): ProcedureRow {
  return { key: 'exact', valueMm, deviationMm: null, deviationPercent: null, realScallopMm, note: null };
}

/**
 * Why an approximation has no value at h (forward) or at L/2 (inverse): the model's own reason, or
 * the quantity beyond the model's widest point (a circle's radius; Bedi's ellipse: Rlong sin(rho)
 * for h, Rlong for L/2).
 */
function noValueNote(key: ApproximationKey, tool: ToolInput, asked: Asked): ProcedureNote {
  const m = modelCurve(key, tool);
  if (!m.ok) return { kind: 'reason', text: m.notApplicable };
  const c = m.curve;
  const limitMm = c.shape === 'circle' ? c.radiusMm : asked.quantity === 'h' ? c.shortRadiusMm : c.longRadiusMm;
  return { kind: 'beyond-model', shape: c.shape, quantity: asked.quantity, valueMm: asked.valueMm, limitMm };
}

/**
 * Why a corrected procedure has no value at h (forward) or L/2 (inverse): the model's own reason, a
 * combined radius that is not positive (a concave surface tighter than Reff), or the quantity beyond
 * the combined circle's widest point.
 */
function curvatureNote(key: CorrectedKey, tool: ToolInput, surface: CylinderSurface, asked: Asked): ProcedureNote {
  const m = modelCurve(key, tool);
  if (!m.ok) return { kind: 'reason', text: m.notApplicable };
  if (m.curve.shape !== 'circle') return { kind: 'reason', text: 'not applicable' };
  const combined = combinedRadiusMm(m.curve.radiusMm, surface);
  if (!(combined > 0) || !Number.isFinite(combined)) {
    return {
      kind: 'reason',
      text: `${CURVATURE_ROWS[correctedRowKey(key)].shortLabel}: its effective radius is not smaller than the concave surface's radius, so the combined radius 1/(1/Reff + 1/Rs) is not positive.`,
    };
  }
  return { kind: 'beyond-model', shape: 'circle', quantity: asked.quantity, valueMm: asked.valueMm, limitMm: combined };
}

/** The plane's row has only its own reason. */
function planeNote(r: { readonly ok: boolean; readonly notApplicable?: string }): ProcedureNote {
  return { kind: 'reason', text: r.notApplicable ?? '' };
}

/** The forward rows: the exact L/2 and the scallop it leaves, then each approximation's. */
export function forwardRows(input: ForwardInput, c: ForwardComparison, exact: ExactSummary): ProcedureRow[] {
  const asked = forwardAsked(input);
  return [
    exactRow(exact.halfIntervalMm, exact.cuspHeightMm),
    ...APPROXIMATION_KEYS.map((key) =>
      forwardEstimateRow(key, c.approximations[key], c.maxIntervalMm, () => noValueNote(key, input, asked)),
    ),
  ];
}

/** The inverse rows: the exact scallop height, then each approximation's. */
export function inverseRows(input: InverseInput, c: InverseComparison, exact: ExactSummary): ProcedureRow[] {
  const asked = inverseAsked(input);
  return [
    exactRow(exact.cuspHeightMm, null),
    ...APPROXIMATION_KEYS.map((key) =>
      inverseEstimateRow(key, c.approximations[key], () => noValueNote(key, input, asked)),
    ),
  ];
}

/** The rows a cylinder adds (forward): the plane's answer and each corrected procedure; null on a plane. */
export function forwardCurvatureRows(input: ForwardInput, c: ForwardComparison): CurvatureRow[] | null {
  const k: CurvatureComparison | null = c.curvature;
  if (k === null) return null;
  const asked = forwardAsked(input);
  return [
    forwardEstimateRow('plane', k.plane, c.maxIntervalMm, () => planeNote(k.plane)),
    ...CORRECTED_KEYS.map((key) =>
      forwardEstimateRow(correctedRowKey(key), k.corrected[key], c.maxIntervalMm, () =>
        curvatureNote(key, input, k.surface, asked),
      ),
    ),
  ];
}

/** The rows a cylinder adds (inverse): the scallop heights of the plane's answer and the corrected circles. */
export function inverseCurvatureRows(input: InverseInput, c: InverseComparison): CurvatureRow[] | null {
  const k: InverseCurvatureComparison | null = c.curvature;
  if (k === null) return null;
  const asked = inverseAsked(input);
  return [
    inverseEstimateRow('plane', k.plane, () => planeNote(k.plane)),
    ...CORRECTED_KEYS.map((key) =>
      inverseEstimateRow(correctedRowKey(key), k.corrected[key], () => curvatureNote(key, input, k.surface, asked)),
    ),
  ];
}
