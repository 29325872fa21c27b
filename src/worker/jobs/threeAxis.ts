/**
 * The worker's `solve` job for three-axis machining (issue 20): the programmed step (Lxy or dz), L
 * along the surface, the cusp and the equivalent lead and tilt; on a surface of revolution the pair
 * of passes in the meridian plane; and the slope sweep the chart draws. On a sloped plane the step-
 * over and the cusp are the surface registry's plane model's at the posture the three-axis mode
 * supplies (core surfaces/question.ts posturedModel: issue 27 point 3, a machine mode a posture
 * supplier), the refusals and the programmed steps the sloped plane's own (threeAxis/slopedPlane.ts);
 * waterline passes on a surface of revolution are the waterline solver's (core solveThreeAxis, the
 * mode's own answer's solver: their passes are not congruent, and dz is not a question's target).
 * The request is validated again from its numbers (core validateThreeAxis): a bad request gets a
 * typed error reply, never an exception.
 */

import type { PlaneSurface } from '../../core/domain/surface';
import { roughnessSummary } from '../../core/roughness/raTarget';
import { slopedPlaneRoughness } from '../../core/roughness/slopedPlane';
import type { ThreeAxisMode } from '../../core/surfaces/modes/threeAxis';
import { posturedModel } from '../../core/surfaces/question';
import {
  effectiveRasterAngleDeg,
  intervalOfStep,
  programmedSteps,
  type SlopedPlaneCase,
  slopedPlaneForwardErrors,
  slopedPlaneInverseErrors,
} from '../../core/threeAxis/slopedPlane';
import { slopePosture } from '../../core/threeAxis/slopePosture';
import { rasterWaterlineCrossingDeg, slopeSweep } from '../../core/threeAxis/slopeSweep';
import { fromSolver, solveThreeAxis } from '../../core/threeAxis/solve';
import {
  type RawThreeAxisInput,
  type ThreeAxisAnswer,
  type ThreeAxisInputError,
  type ThreeAxisProblem,
  validateThreeAxis,
} from '../../core/threeAxis/validate';
import { waterlineForward, waterlineHeightLimitMm, waterlineInverse } from '../../core/threeAxis/waterlineRevolution';
import { flankLimits } from '../../core/tool/posture';
import { postureShape } from '../../core/tool/postureShape';
import { threeAxisSceneGeometry } from '../data/curvedScene';
import { finiteLimits } from '../data/sliderLimits';
import type { ThreeAxisReply, ThreeAxisRequest } from '../pageProtocol';
import type { SliderLimits } from '../protocol';

/** The raw inputs (by registry field name) a validated problem came from. */
export function rawOfThreeAxis(p: ThreeAxisProblem): RawThreeAxisInput {
  const tool = { R: p.case.toolRadiusMm, Rcr: p.case.cornerRadiusMm, slope: p.case.slopeDeg };
  if (p.surface === 'plane') {
    const c = p.case;
    return c.passes === 'raster'
      ? { ...tool, passes: 'raster', rasterAngle: c.rasterAngleDeg }
      : { ...tool, passes: 'waterline' };
  }
  return {
    ...tool,
    passes: 'waterline',
    feedRadius: p.case.feedRadiusMm ?? undefined,
    crossRadius: p.case.crossRadiusMm ?? undefined,
  };
}

const PLANE: PlaneSurface = { kind: 'plane' };

/**
 * A sloped plane's answer: the plane's model (the surface registry's) at the posture the
 * three-axis mode supplies (the mode registry's), one-way; the steps programmed for its L. Null
 * when the sloped plane refuses the problem (slopedPlaneForwardErrors, slopedPlaneInverseErrors).
 */
export function slopedPlaneByModel(
  c: SlopedPlaneCase,
  quantity: ThreeAxisProblem['quantity'],
  mm: number,
): { ok: true; value: ThreeAxisAnswer } | { ok: false; errors: readonly ThreeAxisInputError[] } {
  const step = quantity === 'h' ? null : { field: quantity, mm };
  const errors = step === null ? slopedPlaneForwardErrors(c, mm) : slopedPlaneInverseErrors(c, step);
  if (errors.length > 0) return { ok: false, errors: fromSolver(errors) };
  const mode: ThreeAxisMode = {
    kind: 'threeAxis',
    slopeDeg: c.slopeDeg,
    passes: c.passes,
    rasterAngleDeg: c.rasterAngleDeg,
  };
  const { model, tool, posture } = posturedModel({ tool: c, mode, surface: PLANE, pattern: 'one-way' });
  const pass = { ...tool, pattern: posture.pattern, surface: PLANE };
  const slope = slopePosture(c.slopeDeg, effectiveRasterAngleDeg(c));
  const noScallop = model.leavesNoScallop(tool, PLANE);
  let L: number;
  let cusp = 0;
  if (step === null) {
    const a = model.forward({ ...pass, scallopHeightMm: mm });
    L = a.intervalMm;
    cusp = a.cuspHeightMm;
  } else {
    L = intervalOfStep(c, slope, step);
    if (!noScallop) cusp = model.inverse({ ...pass, intervalMm: L }).cuspHeightMm;
  }
  return {
    ok: true,
    value: {
      passes: c.passes,
      ...programmedSteps(c, slope, L),
      cuspHeightMm: cusp,
      leadDeg: posture.leadAngleDeg,
      tiltDeg: posture.tiltAngleDeg,
      noScallop,
    },
  };
}

/**
 * The problem validated again and answered (a sloped plane by the plane's model at the mode's
 * posture, a surface of revolution by its waterline solver), or its errors (the page validates its
 * request and shows these, the solvers' refusals, from the reply on their fields).
 */
export function checkThreeAxis(
  p: ThreeAxisProblem,
): { ok: true; value: ThreeAxisAnswer } | { ok: false; errors: readonly ThreeAxisInputError[] } {
  const v = validateThreeAxis(rawOfThreeAxis(p), p.quantity, p.mm);
  if (!v.ok) return v;
  const q = v.value;
  return q.surface === 'plane' ? slopedPlaneByModel(q.case, q.quantity, q.mm) : solveThreeAxis(q);
}

/** The pair of passes in the meridian plane (waterline on a surface of revolution), or null. */
function waterlinePair(p: ThreeAxisProblem): Extract<ThreeAxisReply, { ok: true }>['waterline'] {
  if (p.surface !== 'revolution') return null;
  const r =
    p.quantity === 'h'
      ? waterlineForward(p.case, p.mm)
      : p.quantity === 'stepDown' || p.quantity === 'interval'
        ? waterlineInverse(p.case, { field: p.quantity, mm: p.mm })
        : null;
  if (r === null || !r.ok) return null;
  return { geometry: r.value.geometry, slopeNextDeg: r.value.slopeNextDeg, radialStepMm: r.value.radialStepMm };
}

/**
 * Three-axis machining's sliders' limits (protocol.ts SliderLimits): the largest scallop height at
 * the slope (the posture solver's flank and shank limits at the slope's equivalent posture on a
 * plane, waterlineHeightLimitMm on a surface of revolution); the steps' sliders keep their own
 * ranges (the field says the true limit). Null while the tool, slope and surface are invalid, or
 * where a flat end lies on a flat floor (any h is answered).
 */
export function threeAxisSliderLimits(p: ThreeAxisProblem): SliderLimits | null {
  // Validated with a tiny h: only the tool, slope and surface are looked at.
  const v = validateThreeAxis(rawOfThreeAxis(p), 'h', 1e-6);
  if (!v.ok) return null;
  const q = v.value;
  const only = (hMm: number): SliderLimits => ({ hMm, intervalMm: null, raMm: null, concaveMinMm: 0 });
  if (q.surface === 'revolution') return only(waterlineHeightLimitMm(q.case));
  const c = q.case;
  const posture = slopePosture(c.slopeDeg, effectiveRasterAngleDeg(c));
  const shape = postureShape(c.toolRadiusMm, c.cornerRadiusMm, posture.leadRad, posture.tiltRad);
  if (shape.flatOnPlane && shape.rcr === 0) return null;
  return only(flankLimits(shape).limitMm);
}

/** Solves a three-axis request. Never throws for any numeric input. */
export function solveThreeAxisRequest(request: ThreeAxisRequest): ThreeAxisReply {
  const t0 = performance.now();
  const p = request.input;
  const checked = checkThreeAxis(p);
  const limits = finiteLimits(() => threeAxisSliderLimits(p));
  if (!checked.ok) return { ok: false, request, errors: checked.errors, limits };
  const answer = checked.value;
  const c = p.case;
  const hMm = answer.cuspHeightMm;
  const programmed = answer.passes === 'waterline' ? answer.stepDownMm : answer.horizontalStepMm;
  let sweep = null;
  let crossingDeg: number | null = null;
  if (!answer.noScallop && hMm >= 1e-9) {
    try {
      const swept = slopeSweep({
        toolRadiusMm: c.toolRadiusMm,
        cornerRadiusMm: c.cornerRadiusMm,
        hMm,
        passes: answer.passes,
        rasterAngleDeg: p.surface === 'plane' ? p.case.rasterAngleDeg : 90,
        feedRadiusMm: p.surface === 'revolution' ? p.case.feedRadiusMm : null,
        crossRadiusMm: p.surface === 'revolution' ? p.case.crossRadiusMm : null,
        // Inverse: the step typed, held constant; forward: the flat floor's step (the sweep's default).
        ...(p.quantity === 'h' || programmed === null ? {} : { programmedStepMm: programmed }),
      });
      sweep = swept.ok ? swept.value : null;
      crossingDeg = rasterWaterlineCrossingDeg(
        c.toolRadiusMm,
        c.cornerRadiusMm,
        hMm,
        p.surface === 'plane' && p.case.passes === 'raster' ? p.case.rasterAngleDeg : 0,
      );
    } catch {
      sweep = null;
    }
  }
  const waterline = waterlinePair(p);
  return {
    ok: true,
    request,
    limits,
    answer,
    waterline,
    sweep,
    crossingDeg,
    roughness: p.surface === 'plane' ? roughnessSummary(slopedPlaneRoughness(p.case, hMm), hMm) : null,
    scene: threeAxisSceneGeometry(p, answer, waterline?.geometry ?? null),
    solveMs: performance.now() - t0,
  };
}
