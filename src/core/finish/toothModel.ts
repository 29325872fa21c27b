/**
 * The kinematic model of the teeth on a plane (shared/notes/surface-finish.md), prepared once per
 * question: the tool placed in its posture with its contact at the origin (tool/placement.ts), the
 * basis in which the tooth angles are measured, the angular rate per millimetre of feed, the feed
 * period and the passes. Lengths mm, angles radians.
 *
 * Conventions (the notes leave these to the model; the brute force in the tests shares them):
 * - Pass-local frame: X the pass's feed, Y = Z x X, Z the plane's normal; the pass's CC path is
 *   y = 0 and the contact of the continuous model is z = 0. The tool centre point O (the centre of
 *   the ring of corner centres, placement.ts) moves along the pass; its x is the spindle position u.
 * - Tooth angles are measured about the axis `a` from `u1` (X projected on the plane normal to a)
 *   towards `u2 = a x u1`; M3 turns them clockwise seen from the shank, so tooth k is at
 *   `theta_k(u) = -omega u + 2 pi k / z` with `omega = 2 pi / (z fz)` (tooth 0 at 0 when O crosses x = 0).
 * - Pass j (global frame = pass 0's local frame): one-way, local (x, y) = (X - j q P, Y - j L); zigzag
 *   odd j, the pass turned by 180 degrees about Z: local (x, y) = (-(X - j q P), -(Y - j L)), with P the
 *   feed period and q the pass phase (the shift is along +X of the global frame for every pass).
 */
import type { PassPattern, ToolInput } from '../domain/tool';
import { cross, type Vec3 } from '../math/vec';
import { placeTool } from '../tool/placement';
import { flankAtHeight, flankLimits, type PostureShape, shapeOfTool } from '../tool/posture';
import type { FinishInput } from './finishInput';

/** A question about the surface the teeth leave: tool, posture, passes and the finish inputs. */
export interface ToothPassInput {
  readonly tool: ToolInput;
  readonly pattern: PassPattern;
  /** Step-over L between CC paths, mm (> 0). */
  readonly intervalMm: number;
  readonly finish: FinishInput;
}

/** The prepared model (see the module comment). */
export interface ToothModel {
  readonly input: ToothPassInput;
  readonly shape: PostureShape;
  /** Tool radius R, ring radius Rb = R - Rcr, corner radius Rcr, mm. */
  readonly toolRadiusMm: number;
  readonly ringRadiusMm: number;
  readonly cornerRadiusMm: number;
  /** Tool centre point O at spindle position u = 0 (its x is 0), pass-local, mm. */
  readonly centreYMm: number;
  readonly centreZMm: number;
  /** Unit axis a and the angle basis u1, u2 (pass-local). */
  readonly axis: Vec3;
  readonly u1: Vec3;
  readonly u2: Vec3;
  /** x of the contact point relative to O along the CC path (the contact lies at x = u + this). */
  readonly contactOffsetXMm: number;
  /** Tooth angle per mm of feed, rad/mm: `2 pi / (z fz)`. */
  readonly omegaRadPerMm: number;
  /** Angle between adjacent teeth, `2 pi / z`. */
  readonly toothPitchRad: number;
  /** Feed period along the pass: fz, or z fz with runout, mm. */
  readonly feedPeriodMm: number;
  /** Period of the passes across the feed: L one-way, 2 L zigzag, mm. */
  readonly crossPeriodMm: number;
  /** Widest reach of the right (+Y) and left flank from the CC path (the end's silhouette), mm. */
  readonly reachRightMm: number;
  readonly reachLeftMm: number;
}

/** Prepares the model of a validated question (tool validated, L > 0, finish validated). */
export function toothModel(input: ToothPassInput): ToothModel {
  const { tool, finish } = input;
  const placement = placeTool(tool);
  const shape = shapeOfTool(tool);
  const axis = placement.axis;
  // u1: X projected on the plane normal to a, normalised (a_x < 1 since the lead is below 90).
  const ax = axis[0];
  const n1 = Math.sqrt(Math.max(0, 1 - ax * ax));
  const u1: Vec3 = [(1 - ax * ax) / n1, (-ax * axis[1]) / n1, (-ax * axis[2]) / n1];
  const u2 = cross(axis, u1);
  const z = finish.flutes;
  const fz = finish.feedPerToothMm;
  const limits = flankLimits(shape);
  const reach = (flank: 'right' | 'left', top: number) =>
    shape.a === 0 || shape.flatOnPlane ? tool.toolRadiusMm : flankAtHeight(shape, flank, top).widthMm;
  return {
    input,
    shape,
    toolRadiusMm: tool.toolRadiusMm,
    ringRadiusMm: tool.toolRadiusMm - tool.cornerRadiusMm,
    cornerRadiusMm: tool.cornerRadiusMm,
    centreYMm: placement.centre[1],
    centreZMm: placement.centre[2],
    axis,
    u1,
    u2,
    contactOffsetXMm: -placement.centre[0],
    omegaRadPerMm: (2 * Math.PI) / (z * fz),
    toothPitchRad: (2 * Math.PI) / z,
    feedPeriodMm: finish.runoutMm > 0 ? z * fz : fz,
    crossPeriodMm: input.pattern === 'zigzag' ? 2 * input.intervalMm : input.intervalMm,
    reachRightMm: reach('right', limits.topRightMm),
    reachLeftMm: reach('left', limits.topLeftMm),
  };
}
