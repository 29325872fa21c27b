/**
 * The limits of the question on screen beyond a plane's or a cylinder's, for the sliders' maxima:
 * at a doubly curved point (both radii curved, in range, not gouging) the scallop height below the
 * flank and shank limits, the widest step-over that leaves a scallop and the largest Ra
 * (core surfaces/doublyCurved); in three-axis machining the largest scallop height at the slope
 * (the posture solver's flank and shank limits at the slope's equivalent posture on a plane, or
 * waterlineHeightLimitMm on a surface of revolution). The same limits the fields' messages state.
 * Null where the inputs do not make such a question (the plane's or cylinder's ranges apply). Pure.
 */

import type { PassPattern, ToolInput } from '../core/input/validate';
import { doublyCurvedMaxRaMm } from '../core/roughness/doublyCurved';
import { doublyCurvedMaxIntervalMm, doublyCurvedSolver, type PrincipalRadii } from '../core/surfaces/doublyCurved';
import { effectiveRasterAngleDeg, slopePosture, validateThreeAxis, waterlineHeightLimitMm } from '../core/threeAxis';
import { flankLimits } from '../core/tool/posture';
import { postureShape } from '../core/tool/postureShape';
import { curvedRadiusErrors } from '../worker/data/curvedCheck';
import { radiusMm } from './curvedRequest';
import type { PageFieldError } from './request';
import type { CalculatorState } from './state';
import { threeAxisRaw } from './threeAxisRequest';

/** A question's limits, mm: h below `hMm`, L below `intervalMm`, Ra below `raMm` (null: not asked or none). */
export interface QuestionLimits {
  readonly hMm: number;
  readonly intervalMm: number | null;
  readonly raMm: number | null;
}

/** The last largest Ra worked out (a few ms; the sliders are ranged on every change). */
let lastRa: { key: string; value: number } | null = null;

function maxRaAt(tool: ToolInput, pattern: PassPattern, radii: PrincipalRadii): number {
  const key = JSON.stringify([tool, pattern, radii]);
  if (lastRa?.key !== key) lastRa = { key, value: doublyCurvedMaxRaMm(tool, pattern, radii) };
  return lastRa.value;
}

/**
 * A doubly curved point's limits for `tool` (the sliders' tool), or null when a radius is straight,
 * invalid or out of range, or the tool gouges. The largest Ra only while Ra is the target.
 */
export function curvedLimits(state: CalculatorState, tool: ToolInput): QuestionLimits | null {
  if (state.machine === '3axis' || state.surface !== 'curved') return null;
  const rf = radiusMm(state, 'Rf');
  const rc = radiusMm(state, 'Rc');
  if (typeof rf !== 'number' || typeof rc !== 'number' || !Number.isFinite(rf) || !Number.isFinite(rc)) return null;
  const radii = { feedRadiusMm: rf, crossRadiusMm: rc };
  if (curvedRadiusErrors(tool, radii).length > 0) return null;
  const solver = doublyCurvedSolver(tool, radii);
  const hMm = solver.limits().limitMm;
  const ra = state.mode === 'forward' && state.target === 'ra' && hMm > 0;
  return {
    hMm,
    intervalMm: doublyCurvedMaxIntervalMm(solver, state.pattern),
    raMm: ra ? maxRaAt(tool, state.pattern, radii) : null,
  };
}

/**
 * Three-axis machining's largest scallop height (mm) for the tool, slope, passes and surface on
 * screen; null while those are invalid. The steps' sliders keep their own ranges (the field says
 * the true limit).
 */
export function threeAxisLimits(state: CalculatorState): QuestionLimits | null {
  if (state.machine !== '3axis') return null;
  const errors: PageFieldError[] = [];
  const raw = threeAxisRaw(state, errors);
  // Validated with a tiny h: only the tool, slope and surface are looked at.
  const v = validateThreeAxis(raw, 'h', 1e-6);
  if (errors.length > 0 || !v.ok) return null;
  const p = v.value;
  if (p.surface === 'revolution') return { hMm: waterlineHeightLimitMm(p.case), intervalMm: null, raMm: null };
  const c = p.case;
  const posture = slopePosture(c.slopeDeg, effectiveRasterAngleDeg(c));
  const shape = postureShape(c.toolRadiusMm, c.cornerRadiusMm, posture.leadRad, posture.tiltRad);
  // A flat end lying on a flat floor leaves no scallop: any h is answered (L = 2R).
  if (shape.flatOnPlane && shape.rcr === 0) return null;
  return { hMm: flankLimits(shape).limitMm, intervalMm: null, raMm: null };
}

/** A question's limits for the sliders: a doubly curved point's or three-axis machining's (null for any other). */
export type QuestionLimitsOf = (state: CalculatorState, tool: ToolInput) => QuestionLimits | null;

/** The limits of the question on screen beyond a plane's or a cylinder's (sliders.ts's `limitsOf`). */
export const questionLimitsOf: QuestionLimitsOf = (state, tool) => curvedLimits(state, tool) ?? threeAxisLimits(state);
