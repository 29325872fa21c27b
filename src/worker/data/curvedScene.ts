/**
 * The 3D scene's data for the questions beyond a plane or a cylinder (issues 19 and 20): a doubly
 * curved point (the torus patch, the tool in its posture, the cusps on the offset surface in the
 * cross-feed plane through the CC point; the neighbouring passes turned about m by the scene) and
 * three-axis machining (the tool upright: the local frame turned into the machine frame, the pass
 * drawn beside this one, the programmed step Lxy or dz as a dimension line). Mm.
 */

import { MIN_LENGTH_MM, type ToolInput } from '../../core/input/validate';
import type { Vec3 } from '../../core/math/vec';
import { type Frame, revolutionFrame, type TorusPatch, toLocal } from '../../core/output/curvedSurfaceGeometry';
import {
  frameMatrix,
  horizontalStepDimension,
  type StepDimension,
  slopeFrame,
  stepDownDimension,
} from '../../core/output/machineGeometry';
import { surfacePoint } from '../../core/output/surfaceGeometry';
import { PLANE } from '../../core/surfaces/cylinder';
import type { DoublyCurvedPass } from '../../core/surfaces/doublyCurved/types';
import { effectiveRasterAngleDeg } from '../../core/threeAxis/slopedPlane';
import type { ThreeAxisAnswer, ThreeAxisProblem } from '../../core/threeAxis/validate';
import type { WaterlineGeometry } from '../../core/threeAxis/waterlineRevolution';
import { placeTool } from '../../core/tool/placement';
import { flankWidthMm, shapeOfTool } from '../../core/tool/posture';
import { toolMesh } from '../../core/tool/toolMesh';
import type { CurvedSummary } from '../pageProtocol';
import { type ExactSummary, type MachineView, type SceneGeometry, TOOL_RADIAL_SEGMENTS } from '../protocol';
import { sceneGeometry } from './scene';

/** Where a cusp stands: its arc across the feed from the CC path and its radial height (mm). */
export interface CuspAt {
  readonly crossMm: number;
  readonly heightMm: number;
}

/**
 * The two cusps of this pass at a doubly curved point (arc lengths along the equator, radial heights):
 * one-way at the flanks' reaches (+wR, -wL) at h; zigzag at +-L/2, the narrower flank's at h, the
 * other at zigzag's other cusp height (as on the plane, worker/data/exact.ts).
 */
export function curvedCusps(e: CurvedSummary): { right: CuspAt; left: CuspAt } {
  const h = e.cuspHeightMm;
  if (e.pattern === 'one-way')
    return { right: { crossMm: e.halfWidthRightMm, heightMm: h }, left: { crossMm: -e.halfWidthLeftMm, heightMm: h } };
  const other = e.otherCuspHeightMm ?? h;
  const rightNarrower = e.halfWidthRightMm <= e.halfWidthLeftMm;
  const L = e.intervalMm;
  return {
    right: { crossMm: L / 2, heightMm: rightNarrower ? h : other },
    left: { crossMm: -L / 2, heightMm: rightNarrower && e.halfWidthRightMm !== e.halfWidthLeftMm ? other : h },
  };
}

/** The tool mesh and placement shared by every scene (mm, local frame). */
function toolPart(tool: ToolInput) {
  const p = placeTool(tool);
  return {
    toolRadiusMm: tool.toolRadiusMm,
    cornerRadiusMm: tool.cornerRadiusMm,
    toolCentre: p.centre,
    toolAxis: p.axis,
    toolPositions: toolMesh(tool, 0.6 * tool.toolRadiusMm, TOOL_RADIAL_SEGMENTS).positions,
  };
}

/** The scene of a doubly curved point: the torus patch, the tool at the CC point, the cusps on the offset surface. */
export function curvedSceneGeometry(pass: DoublyCurvedPass, exact: CurvedSummary): SceneGeometry {
  const surface: TorusPatch = { kind: 'torus', feedRadiusMm: pass.feedRadiusMm, crossRadiusMm: pass.crossRadiusMm };
  const cusps = curvedCusps(exact);
  const point = (c: CuspAt) => (c.heightMm < MIN_LENGTH_MM ? null : surfacePoint(surface, 0, c.crossMm, c.heightMm));
  return {
    ...toolPart(pass),
    pattern: exact.pattern,
    intervalMm: exact.intervalMm,
    scallopHeightMm: exact.cuspHeightMm,
    right: null,
    left: null,
    surface,
    cuspPoints: { right: point(cusps.right), left: point(cusps.left) },
    machine: null,
  };
}

/** A translation by `t` (local frame), column-major 4 x 4. */
function translation(t: Vec3): number[] {
  return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, t[0], t[1], t[2], 1];
}

/** The tool tip (the lowest point of its end on the axis): O - Rcr a (local frame). */
function tipOf(g: { toolCentre: Vec3; toolAxis: Vec3; cornerRadiusMm: number }): Vec3 {
  const [o, a, k] = [g.toolCentre, g.toolAxis, g.cornerRadiusMm];
  return [o[0] - k * a[0], o[1] - k * a[1], o[2] - k * a[2]];
}

/** The machine view of a pair of passes whose next tool is this one moved by `next` (local frame). */
function machineView(
  frame: Frame,
  R: number,
  L: number,
  next: Vec3,
  passes: ThreeAxisAnswer['passes'],
  tip0: Vec3,
): MachineView {
  const arrowMm = Math.min(0.07 * R, 0.25 * L);
  let step: StepDimension;
  if (passes === 'raster') step = horizontalStepDimension(frame, L, 1.4 * R, arrowMm);
  else {
    const tip1: Vec3 = [tip0[0] + next[0], tip0[1] + next[1], tip0[2] + next[2]];
    step = stepDownDimension(frame, tip0, tip1, 1.6 * R, arrowMm);
  }
  // Drawn turned half a turn about the vertical (x downhill): the iso camera, from +x, sees the slope's face.
  const yawed = frame.map((v) => [-v[0], -v[1], v[2]] as const) as unknown as Frame;
  return {
    frameMatrix: frameMatrix(yawed),
    passMatrices: [translation(next)],
    pathOffsetsMm: [0, L],
    step: { kind: passes === 'raster' ? 'horizontal' : 'vertical', points: step.points, labelAt: step.labelAt },
  };
}

/**
 * The scene of a three-axis answer: on a sloped plane the posture's scene (the equivalent lead and
 * tilt, cusps as on a plane, one-way) turned into the machine frame; on a surface of revolution the
 * surface, the upright tool, the next pass at its level and the cusp in the meridian plane
 * (`waterline`, core waterlineRevolution.ts). Null where nothing is drawn (no scallop, no pair).
 */
export function threeAxisSceneGeometry(
  problem: ThreeAxisProblem,
  answer: ThreeAxisAnswer,
  waterline: WaterlineGeometry | null,
): SceneGeometry | null {
  const c = problem.case;
  const R = c.toolRadiusMm;
  const L = answer.intervalMm;
  if (answer.noScallop || !(L > 0)) return null;
  if (problem.surface === 'plane') {
    const tool: ToolInput = {
      toolRadiusMm: R,
      cornerRadiusMm: c.cornerRadiusMm,
      leadAngleDeg: answer.leadDeg,
      tiltAngleDeg: answer.tiltDeg,
    };
    const h = answer.cuspHeightMm;
    const shape = shapeOfTool(tool);
    const wR = flankWidthMm(shape, 'right', h);
    const wL = flankWidthMm(shape, 'left', h);
    const exact: ExactSummary = {
      pattern: 'one-way',
      intervalMm: L,
      halfIntervalMm: L / 2,
      widthRightMm: wR,
      widthLeftMm: wL,
      contactOffsetMm: 0,
      cuspHeightMm: h,
      otherCuspHeightMm: null,
      right: { yMm: wR, heightMm: h },
      left: { yMm: -wL, heightMm: h },
      noScallop: false,
      maxIntervalMm: L,
    };
    const g = sceneGeometry(tool, exact, PLANE);
    const frame = slopeFrame(c.slopeDeg, effectiveRasterAngleDeg(problem.case));
    return { ...g, machine: machineView(frame, R, L, [0, L, 0], answer.passes, tipOf(g)) };
  }
  if (waterline === null) return null;
  const a = c.slopeDeg;
  // Y runs down the slope (revolutionFrame): the vertical leans uphill, a tilt of -alpha.
  const tool: ToolInput = { toolRadiusMm: R, cornerRadiusMm: c.cornerRadiusMm, leadAngleDeg: 0, tiltAngleDeg: -a };
  const frame = revolutionFrame(a);
  // Meridian plane (s down-slope, z up) -> machine (x uphill, y 0, z) -> local.
  const local = (q: readonly [number, number]) => toLocal(frame, [-q[0], 0, q[1]]);
  const tip0 = local(waterline.tip0);
  const tip1 = local(waterline.tip1);
  const next: Vec3 = [tip1[0] - tip0[0], tip1[1] - tip0[1], tip1[2] - tip0[2]];
  const cusp = local(waterline.cusp);
  const rev = c as { feedRadiusMm: number | null; crossRadiusMm: number | null };
  return {
    ...toolPart(tool),
    pattern: 'one-way',
    intervalMm: L,
    scallopHeightMm: answer.cuspHeightMm,
    right: null,
    left: null,
    surface: {
      kind: 'revolution',
      slopeDeg: a,
      feedRadiusMm: rev.feedRadiusMm ?? Number.POSITIVE_INFINITY,
      crossRadiusMm: rev.crossRadiusMm ?? Number.POSITIVE_INFINITY,
    },
    cuspPoints: { right: answer.cuspHeightMm < MIN_LENGTH_MM ? null : cusp, left: null },
    machine: machineView(frame, R, L, next, 'waterline', tip0),
  };
}
