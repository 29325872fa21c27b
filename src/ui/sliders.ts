/**
 * The sliders' ranges and steps, in the user's unit: steps are round numbers of that unit (0.01 mm
 * or 0.001 in for the tool), so arrow keys move a value by a clean amount instead of a converted
 * millimetre step. The ranges follow the other values (Rcr up to R, h below the limit of the
 * question on screen, L and Ra below the widest and largest there, a concave cylinder's radius from
 * the smallest that does not gouge): limits the worker works out beside its answer or refusal (its
 * reply's SliderLimits, issue 27 point 4: the page solves nothing). Pure (no DOM).
 */

import { fromMm, toMm } from '../core/input/units';
import { MAX_TOOL_RADIUS_MM, MIN_TOOL_RADIUS_MM, type ToolInput } from '../core/input/validate';
import type { SliderLimits } from '../worker/protocol';
import { cylinderState } from './curvedRequest';
import { type CalculatorState, type FieldKey, formatField, parseField, radiusField, sizeIsDiameter } from './state';

export interface SliderRange {
  readonly min: string;
  readonly max: string;
  readonly step: string;
}

/** Steps per unit: round numbers of the unit itself. */
const STEPS: Readonly<Record<'mm' | 'in', Readonly<Record<FieldKey, number>>>> = {
  mm: {
    R: 0.01,
    Rcr: 0.01,
    rho: 0.1,
    tilt: 0.1,
    h: 0.001,
    L: 0.001,
    ra: 0.0001,
    sa: 0.0001,
    Rs: 0.1,
    slope: 0.1,
    psi: 0.1,
    Rf: 0.1,
    Rc: 0.1,
    Lxy: 0.001,
    dz: 0.001,
    z: 1,
    fz: 0.001,
    F: 1,
    n: 10,
    runout: 0.001,
    runoutPhase: 1,
    passPhase: 0.01,
  },
  in: {
    R: 0.001,
    Rcr: 0.001,
    rho: 0.1,
    tilt: 0.1,
    h: 0.0001,
    L: 0.0001,
    ra: 0.00001,
    sa: 0.00001,
    Rs: 0.01,
    slope: 0.1,
    psi: 0.1,
    Rf: 0.01,
    Rc: 0.01,
    Lxy: 0.0001,
    dz: 0.0001,
    z: 1,
    fz: 0.0001,
    F: 0.1,
    n: 10,
    runout: 0.0001,
    runoutPhase: 1,
    passPhase: 0.01,
  },
};

/** A tool for the ranges: the typed values where they make sense, defaults elsewhere. */
function rangeTool(state: CalculatorState): ToolInput {
  const num = (key: FieldKey) => parseField(state.fields[key]);
  const R = radiusField(state);
  const Rcr = num('Rcr');
  const rho = num('rho');
  const tilt = num('tilt');
  const rMm = R !== null && R > 0 ? Math.min(MAX_TOOL_RADIUS_MM, Math.max(MIN_TOOL_RADIUS_MM, toMm(R, state.unit))) : 3;
  const rcrMm = Rcr !== null && Rcr >= 0 ? Math.min(toMm(Rcr, state.unit), rMm) : rMm / 3;
  return {
    toolRadiusMm: rMm,
    cornerRadiusMm: rcrMm,
    leadAngleDeg: rho !== null && rho >= 0 && rho < 90 ? rho : 5,
    tiltAngleDeg: tilt !== null && tilt > -90 && tilt < 90 ? tilt : 0,
  };
}

/** The surface radius slider's top (mm): the field takes up to 1e6 mm, the slider the usual sizes. */
const RADIUS_SLIDER_MAX_MM = 500;

/** Rounds up to a whole number of steps. */
function snapUp(value: number, step: number): number {
  return Math.ceil(value / step - 1e-9) * step;
}

/** Rounds down to a whole number of steps (never below one step above the minimum). */
function snap(value: number, step: number, min: number): number {
  return Math.max(min + step, Math.floor(value / step + 1e-9) * step);
}

/**
 * Every slider's range and step for a state, as the strings a range input takes.
 * @param limits The question's limits, from the worker's last reply (null: none came yet, or its
 *   question has none); each one missing stands in by the tool's size: h below R, L below 2R, Ra
 *   below a quarter of the h limit, no concave limit.
 */
export function sliderRanges(
  state: CalculatorState,
  limits: SliderLimits | null = null,
): Readonly<Record<FieldKey, SliderRange>> {
  const u = state.unit;
  const step = STEPS[u];
  const tool = rangeTool(state);
  const len = (mm: number) => fromMm(mm, u);
  // A doubly curved point with a straight radius is a cylinder's (or the plane's) question.
  const classic = state.machine === '3axis' ? null : state.surface === 'curved' ? cylinderState(state).state : state;
  // A concave cylinder's slider starts at the gouging limit (Infinity: no concave fits; then from 1 step).
  const concaveMin = classic?.surface === 'concave' ? (limits?.concaveMinMm ?? 0) : 0;
  const hLimit = limits?.hMm ?? tool.toolRadiusMm;
  const lMax = limits?.intervalMm ?? 2 * tool.toolRadiusMm;
  const raMax = () => limits?.raMm ?? hLimit / 4;
  const rsMin = Number.isFinite(concaveMin) ? Math.max(step.Rs, snapUp(len(concaveMin), step.Rs)) : step.Rs;
  const ranges: Record<FieldKey, [number, number]> = {
    R: [step.R * 10, snap(len(25), step.R, 0)],
    Rcr: [0, snap(len(tool.toolRadiusMm), step.Rcr, 0)],
    rho: [0, 89.9],
    tilt: [-89.9, 89.9],
    h: [step.h, snap(len(Math.min(0.999 * hLimit, 2)), step.h, step.h)],
    L: [step.L * 10, snap(len(0.999 * lMax), step.L, step.L * 10)],
    // Only drawn (and its maximum worked out) while Ra is the target.
    ra:
      state.mode === 'forward' && state.target === 'ra'
        ? [step.ra, snap(len(Math.min(0.999 * raMax(), 0.5)), step.ra, step.ra)]
        : [step.ra, 10 * step.ra],
    // A target Sa: below the same largest Ra (Sa tends to Ra as fz -> 0); only drawn while it is the target.
    sa:
      state.mode === 'forward' && state.target === 'sa'
        ? [step.sa, snap(len(Math.min(0.999 * raMax(), 0.5)), step.sa, step.sa)]
        : [step.sa, 10 * step.sa],
    Rs: [rsMin, Math.max(rsMin + step.Rs, snap(len(RADIUS_SLIDER_MAX_MM), step.Rs, 0))],
    // Three-axis: the slope below a vertical wall, the raster angle from the fall line to the contour.
    slope: [0, 89.9],
    psi: [0, 90],
    // A doubly curved point's radii (the field takes up to 1e6 mm; gouging is said on the field).
    Rf: [step.Rf, Math.max(2 * step.Rf, snap(len(RADIUS_SLIDER_MAX_MM), step.Rf, 0))],
    Rc: [step.Rc, Math.max(2 * step.Rc, snap(len(RADIUS_SLIDER_MAX_MM), step.Rc, 0))],
    // The programmed steps: up to the tool's diameter (Lxy) or radius (dz); the field says the true limit.
    Lxy: [step.Lxy * 10, snap(len(2 * tool.toolRadiusMm), step.Lxy, step.Lxy * 10)],
    dz: [step.dz, snap(len(tool.toolRadiusMm), step.dz, step.dz)],
    // The teeth and their feed (issue 29): up to 12 teeth, fz up to R (the core's limit: a balanced
    // feed of 2 mm on an R 3 tool stays on the slider) and runout up to R/10.
    z: [1, 12],
    fz: [step.fz, snap(len(tool.toolRadiusMm), step.fz, step.fz)],
    // Feed rate up to 20 m/min, spindle speed up to 40,000 rpm (the fields take any positive value).
    F: [step.F, snap(len(20_000), step.F, step.F)],
    n: [100, 40_000],
    runout: [0, snap(len(tool.toolRadiusMm / 10), step.runout, 0)],
    runoutPhase: [0, 359],
    passPhase: [0, 0.99],
  };
  // The size field in diameter mode: D runs over twice the radius's range.
  if (sizeIsDiameter(state)) ranges.R = [2 * ranges.R[0], 2 * ranges.R[1]];
  const out = {} as Record<FieldKey, SliderRange>;
  for (const key of Object.keys(ranges) as FieldKey[]) {
    const [min, max] = ranges[key];
    out[key] = { min: formatField(min), max: formatField(max), step: formatField(step[key]) };
  }
  return out;
}
