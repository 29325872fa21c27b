/**
 * The finish question the inputs on screen ask (issue 29), built from the answer on screen: its
 * tool, posture, pattern, step-over L and scallop h, and the finish fields (in mm: converted here,
 * at the page's edge). Feed marks are computed on a plane (five-axis, or the three-axis sloped
 * plane at its equivalent posture, one-way); on a cylinder, a doubly curved point or waterline on a
 * surface of revolution the answer is the core's one-line refusal, never the continuous one. Pure.
 */

import type { FinishField } from '../core/finish/finishInput';
import { type FinishSurfaceKind, finishScopeError } from '../core/finish/finishScope';
import { formatInputNumber, fromMm, type LengthUnit, unitSymbol } from '../core/input/units';
import type { ToolInput } from '../core/input/validate';
import { equivalentPlaneRequest } from '../worker/equivalentPlane';
import type { FinishRequest, FinishValue } from '../worker/finishProtocol';
import { isCurvedRequest, isSolveReply, type PageReply, type ThreeAxisReply } from '../worker/pageProtocol';

/** The finish fields as the page holds them (finishLazy.ts finishInputs): in mm and degrees, and as typed. */
export interface FinishInputs {
  /** True when any finish field holds text. */
  readonly given: boolean;
  readonly values: Readonly<Record<FinishField, FinishValue>>;
  readonly typed: Readonly<Record<FinishField, string>>;
  readonly unit: LengthUnit;
}

/** What the finish box answers: nothing asked, a refusal in one line, or a question for the worker. */
export type FinishAsk =
  | { readonly kind: 'none' }
  | { readonly kind: 'refused'; readonly message: string; readonly surface: FinishSurfaceKind }
  | { readonly kind: 'ask'; readonly request: FinishRequest; readonly raMm: number | null };

/** The tool and posture of a validated input (its other fields left out of the finish question). */
function toolOf(i: ToolInput): ToolInput {
  return {
    toolRadiusMm: i.toolRadiusMm,
    cornerRadiusMm: i.cornerRadiusMm,
    leadAngleDeg: i.leadAngleDeg,
    tiltAngleDeg: i.tiltAngleDeg,
  };
}

/** The plane an answer stands on, or the kind of surface where feed marks are not computed. */
function planeOf(reply: PageReply):
  | {
      tool: ToolInput;
      pattern: 'one-way' | 'zigzag';
      intervalMm: number;
      scallopMm: number;
      threeAxisName?: string;
    }
  | string
  | null {
  if (isSolveReply(reply)) {
    if (!reply.ok) return null;
    const i = reply.request.input;
    if (i.surface.kind !== 'plane') return 'cylinder';
    return {
      tool: toolOf(i),
      pattern: i.pattern,
      intervalMm: reply.exact.intervalMm,
      scallopMm: reply.exact.cuspHeightMm,
    };
  }
  if (isCurvedRequest(reply.request)) return 'doublyCurved';
  const three = reply as ThreeAxisReply;
  if (!three.ok) return null;
  if (three.request.input.surface !== 'plane') return 'waterlineRevolution';
  const plane = equivalentPlaneRequest(three);
  if (plane === null || plane.mode !== 'forward') return null;
  const i = plane.input;
  const c = three.request.input.case;
  const passes = c.passes === 'raster' ? `raster${formatInputNumber(c.rasterAngleDeg)}` : 'waterline';
  return {
    tool: toolOf(i),
    pattern: 'one-way',
    intervalMm: three.answer.intervalMm,
    scallopMm: three.answer.cuspHeightMm,
    threeAxisName: `3-axis_slope${formatInputNumber(c.slopeDeg)}_${passes}`,
  };
}

/**
 * The finish the inputs ask of `reply` (the answer to the inputs on screen, or null while none is):
 * none without teeth and feed, the refusal off a plane, else the worker's question.
 */
export function finishAsk(inputs: FinishInputs, reply: PageReply | null): FinishAsk {
  if (!inputs.given || reply === null) return { kind: 'none' };
  const plane = planeOf(reply);
  if (plane === null) return { kind: 'none' };
  if (typeof plane === 'string') return { kind: 'refused', message: finishScopeError(plane) ?? '', surface: plane };
  if (!(plane.intervalMm > 0 && Number.isFinite(plane.intervalMm))) return { kind: 'none' };
  const raMm = 'roughness' in reply && reply.ok && reply.roughness !== null ? reply.roughness.raMm : null;
  const { values, typed, unit } = inputs;
  return { kind: 'ask', request: { ...plane, values, typed, unit, part: 'marks' }, raMm };
}

/**
 * The x3p file's name: the question it answers, lengths in `unit`:
 * `finish_R3_Rcr1_rho5_tilt0_one-way_L0.9_z4_fz0.08_mm.x3p`; three-axis
 * `finish_R3_Rcr1_3-axis_slope30_raster30_L1.40219_z4_fz0.1_mm.x3p` (L along the surface).
 */
export function x3pFileName(r: FinishRequest): string {
  const n = (mm: number) => formatInputNumber(fromMm(mm, r.unit));
  const t = r.tool;
  const v = r.values;
  const runout = typeof v.runout === 'number' && v.runout > 0 ? `_e${n(v.runout)}` : '';
  // Three-axis: the question asked (slope and passes), not the posture it stands on.
  const posture =
    r.threeAxisName ?? `rho${formatInputNumber(t.leadAngleDeg)}_tilt${formatInputNumber(t.tiltAngleDeg)}_${r.pattern}`;
  return (
    `finish_R${n(t.toolRadiusMm)}_Rcr${n(t.cornerRadiusMm)}_${posture}_L${n(r.intervalMm)}_z${String(v.flutes)}` +
    `_fz${typeof v.fz === 'number' ? n(v.fz) : ''}${runout}_${unitSymbol(r.unit)}.x3p`
  );
}
