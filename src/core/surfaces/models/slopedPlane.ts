/**
 * A plane machined on three axes (shared/notes/doubly-curved-and-3-axis.md, section 2a) as a surface
 * model (surface.ts): a surface that supplies the posture. The tool stays upright; the slope and the
 * pass direction give its lead and tilt at the CC point in closed form (threeAxis/slopePosture.ts),
 * and the plane's model answers at that posture, ignoring the tool's own lead and tilt. Feeding down
 * the slope is the same upright tool on the same line, so zigzag passes leave what one-way passes
 * leave: the pattern is taken as one-way. The programmed steps (Lxy, dz), the validation and its
 * three-axis wording stay in threeAxis/slopedPlane.ts. Lengths mm, angles degrees.
 */
import type { ForwardInput, InverseInput } from '../../domain/pass';
import type { ToolInput } from '../../domain/tool';
import type { ThreeAxisPasses } from '../../threeAxis/slopedPlane';
import { slopePosture } from '../../threeAxis/slopePosture';
import type { SurfaceModel } from '../surface';
import { planeModel } from './plane';

/** A plane of slope `slopeDeg` (0 <= alpha < 90) under an upright tool, with raster or waterline passes. */
export interface SlopedPlaneSurface {
  readonly kind: 'slopedPlane';
  readonly slopeDeg: number;
  readonly passes: ThreeAxisPasses;
  /** Raster angle psi in plan from the fall line, degrees, 0 to 90; ignored for waterline (90). */
  readonly rasterAngleDeg: number;
}

const PLANE = { kind: 'plane' } as const;

/** The upright tool's posture on the slope, as a tool input of the plane (its own lead and tilt replaced). */
export function uprightTool(tool: ToolInput, surface: SlopedPlaneSurface): ToolInput {
  const p = slopePosture(surface.slopeDeg, surface.passes === 'waterline' ? 90 : surface.rasterAngleDeg);
  return {
    toolRadiusMm: tool.toolRadiusMm,
    cornerRadiusMm: tool.cornerRadiusMm,
    leadAngleDeg: p.leadDeg,
    tiltAngleDeg: p.tiltDeg,
  };
}

function onPlane(input: ForwardInput<SlopedPlaneSurface>): ForwardInput<typeof PLANE> {
  return {
    ...uprightTool(input, input.surface),
    pattern: 'one-way',
    surface: PLANE,
    scallopHeightMm: input.scallopHeightMm,
  };
}

function onPlaneInverse(input: InverseInput<SlopedPlaneSurface>): InverseInput<typeof PLANE> {
  return { ...uprightTool(input, input.surface), pattern: 'one-way', surface: PLANE, intervalMm: input.intervalMm };
}

/** The sloped plane's model. */
export const slopedPlaneModel: SurfaceModel<SlopedPlaneSurface> = {
  kind: 'slopedPlane',
  intervalMm: (input) => planeModel.intervalMm(onPlane(input)),
  forward: (input) => planeModel.forward(onPlane(input)),
  inverse: (input) => planeModel.inverse(onPlaneInverse(input)),
  limits: (tool, surface) => planeModel.limits(uprightTool(tool, surface), PLANE),
  maxIntervalMm: (tool, _pattern, surface) => planeModel.maxIntervalMm(uprightTool(tool, surface), 'one-way', PLANE),
  flankWidths: (tool, surface) => planeModel.flankWidths(uprightTool(tool, surface), PLANE),
  fit: () => ({ gouges: false }),
  leavesNoScallop: (tool, surface) => planeModel.leavesNoScallop(uprightTool(tool, surface), PLANE),
};
