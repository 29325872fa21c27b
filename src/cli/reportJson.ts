/**
 * One case's answer as a JSON object (report.ts): numbers always finite, a value that does not exist
 * left out. Lengths mm, angles degrees.
 */
import {
  APPROXIMATION_KEYS,
  CORRECTED_KEYS,
  type ExactForward,
  type ForwardComparison,
  type ForwardEstimate,
  type InverseComparison,
  type InverseEstimate,
  type PassInput,
} from '../core/index';
import { PASS_FIELDS } from '../core/input/fields';
import { rawOf } from '../core/input/raw';
import { finishJson } from './finish';
import { type Extras, ruleOfThumb } from './reportExtras';

/** JSON data: numbers are always finite; a value that does not exist is left out, never null. */
export type JsonValue = number | string | boolean | JsonValue[] | { [key: string]: JsonValue };
/** A JSON object of {@link JsonValue}s. */
export type JsonObject = { [key: string]: JsonValue };

/** The tool, posture, pattern and surface as validation reads them (a plane has no surface fields: left out). */
function toolJson(input: PassInput): JsonObject {
  const out = rawOf(input, PASS_FIELDS) as JsonObject;
  // A cylinder is a doubly curved point with one radius straight: its principal radii too.
  const s = input.surface;
  if (s.kind === 'cylinder') out[s.axis === 'feed' ? 'crossRadius' : 'feedRadius'] = s.radiusMm;
  return out;
}

/** The extras as JSON fields: roughness, the rule of thumb beside it, the simulation. */
export function extrasJson(extras: Extras, scallopHeightMm: number): JsonObject {
  const out: JsonObject = {};
  const r = extras.roughness;
  if (r !== undefined) {
    out.roughness = { Rz: r.rzMm, Ra: r.raMm, Rq: r.rqMm };
    const thumb = ruleOfThumb(scallopHeightMm, r.raMm);
    const rule: JsonObject = { Ra: thumb.raMm, deviation: thumb.deviationMm };
    if (thumb.deviationPercent !== null) rule.deviationPercent = thumb.deviationPercent;
    out.raRuleOfThumb = rule;
  }
  if (extras.finish !== undefined) Object.assign(out, finishJson(extras.finish.report, extras.finish.x3p));
  const sim = extras.simulation;
  if (sim !== undefined && !sim.ok) out.simulation = { notApplicable: sim.notApplicable };
  else if (sim !== undefined) {
    const s = sim.result;
    out.simulation = {
      cuspHeight: s.cuspHeightMm,
      Rz: s.roughness.rzMm,
      Ra: s.roughness.raMm,
      Rq: s.roughness.rqMm,
      cells: s.cells,
      placements: s.placements,
      ms: sim.ms,
      cuspHeightBound: s.resolutionBoundMm,
      roughnessBound: s.roughnessBoundMm,
      cellsAcross: s.cellsAcross,
      cellsAlong: s.cellsAlong,
      cellSize: s.cellMm,
    };
  }
  return out;
}

/** Model quantities of the approximations (mm), by their JSON names. */
const MODEL_FIELDS = [
  ['toolCentreHeightMm', 'toolCentreHeight'],
  ['shortRadiusMm', 'shortRadius'],
  ['longRadiusMm', 'longRadius'],
  ['effectiveRadiusMm', 'effectiveRadius'],
  ['combinedRadiusMm', 'combinedRadius'],
] as const;

function forwardEstimateJson(r: ForwardEstimate<unknown>, exact: ExactForward): JsonObject {
  if (!r.ok) return { notApplicable: r.notApplicable };
  const out: JsonObject = {
    halfInterval: r.halfIntervalMm,
    interval: r.intervalMm,
    // As before tilt existed: the deviation of L/2; the step-over's is intervalDeviation.
    deviation: r.halfIntervalMm - exact.halfIntervalMm,
    intervalDeviation: r.deviationMm,
    deviationPercent: r.deviationPercent,
  };
  if (r.realScallopMm !== null) out.realScallopHeight = r.realScallopMm;
  if (r.warning !== null) out.warning = r.warning;
  const model = r as unknown as Record<string, unknown>;
  for (const [from, to] of MODEL_FIELDS) {
    const v = model[from];
    if (typeof v === 'number') out[to] = v;
  }
  return out;
}

/** The forward comparison as the documented JSON object (lengths mm, angles degrees). */
export function forwardJson(c: ForwardComparison, extras: Extras = {}): JsonObject {
  const { exact } = c;
  const exactOut: JsonObject = {
    halfInterval: exact.halfIntervalMm,
    interval: exact.intervalMm,
    halfWidthRight: exact.halfWidthRightMm,
    halfWidthLeft: exact.halfWidthLeftMm,
    contactOffset: exact.contactOffsetMm,
    scallopHeight: exact.cuspHeightMm,
  };
  if (exact.otherCuspHeightMm !== null) exactOut.otherCuspHeight = exact.otherCuspHeightMm;
  exactOut.noScallop = exact.noScallop;
  const target: JsonObject =
    extras.targetRaMm === undefined ? { h: c.input.scallopHeightMm } : { Ra: extras.targetRaMm };
  const out: JsonObject = {
    unit: 'mm',
    input: { ...toolJson(c.input), ...target },
    maxInterval: c.maxIntervalMm,
    exact: exactOut,
  };
  for (const key of APPROXIMATION_KEYS) out[key] = forwardEstimateJson(c.approximations[key], exact);
  if (c.curvature !== null) {
    const k = c.curvature;
    const rows: JsonObject = { plane: forwardEstimateJson(k.plane, exact) };
    for (const key of CORRECTED_KEYS) rows[key] = forwardEstimateJson(k.corrected[key], exact);
    out.curvature = rows;
  }
  return { ...out, ...extrasJson(extras, exact.cuspHeightMm) };
}

function inverseEstimateJson(r: InverseEstimate): JsonObject {
  if (!r.ok) return { notApplicable: r.notApplicable };
  const out: JsonObject = { scallopHeight: r.scallopHeightMm, deviation: r.deviationMm };
  if (r.deviationPercent !== null) out.deviationPercent = r.deviationPercent;
  return out;
}

/** The exact inverse answer's fields (cusp heights, step-over, flank widths, contact offset), in the documented order. */
export function inverseExactJson(e: {
  readonly cuspHeightMm: number;
  readonly rightCuspHeightMm: number;
  readonly leftCuspHeightMm: number;
  readonly otherCuspHeightMm: number | null;
  readonly intervalMm: number;
  readonly halfWidthRightMm: number;
  readonly halfWidthLeftMm: number;
  readonly contactOffsetMm: number;
}): JsonObject {
  const out: JsonObject = {
    scallopHeight: e.cuspHeightMm,
    rightCuspHeight: e.rightCuspHeightMm,
    leftCuspHeight: e.leftCuspHeightMm,
  };
  if (e.otherCuspHeightMm !== null) out.otherCuspHeight = e.otherCuspHeightMm;
  out.interval = e.intervalMm;
  out.halfInterval = e.intervalMm / 2;
  out.halfWidthRight = e.halfWidthRightMm;
  out.halfWidthLeft = e.halfWidthLeftMm;
  out.contactOffset = e.contactOffsetMm;
  return out;
}

/** The inverse comparison as the documented JSON object (lengths mm, angles degrees). */
export function inverseJson(c: InverseComparison, extras: Extras = {}): JsonObject {
  const { exact } = c;
  const exactOut = inverseExactJson(exact);
  const out: JsonObject = {
    unit: 'mm',
    input: { ...toolJson(c.input), interval: c.input.intervalMm, halfInterval: c.input.intervalMm / 2 },
    exact: exactOut,
  };
  for (const key of APPROXIMATION_KEYS) out[key] = inverseEstimateJson(c.approximations[key]);
  if (c.curvature !== null) {
    const k = c.curvature;
    const rows: JsonObject = { plane: inverseEstimateJson(k.plane) };
    for (const key of CORRECTED_KEYS) rows[key] = inverseEstimateJson(k.corrected[key]);
    out.curvature = rows;
  }
  return { ...out, ...extrasJson(extras, exact.cuspHeightMm) };
}
