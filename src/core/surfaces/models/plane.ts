/**
 * The plane as a surface model (surface.ts): the paper's surface, solved by exact.ts's plane
 * solutions; scallops measured along the normal; nothing gouges it. Lengths mm.
 */
import type { PlaneSurface } from '../../domain/surface';
import type { PassPattern, ToolInput } from '../../domain/tool';
import { flankAtHeight, flankLimits, flankWidthMm, shapeOfTool } from '../../tool/posture';
import { stepOverFromReaches } from '../../tool/stepOverRule';
import { planeForward, planeIntervalMm, planeInverse } from '../exact';
import { FITS, type SurfaceModel } from '../surface';

/**
 * A flat end (Rcr = 0) with neither lead nor tilt: its bottom face lies on the plane and has no
 * corner to curve up, so it leaves no scallop at any step-over up to its diameter. Any h is then
 * a valid question, answered by L = 2R (exact.ts).
 */
export function leavesNoScallop(tool: ToolInput): boolean {
  return tool.cornerRadiusMm === 0 && tool.leadAngleDeg === 0 && tool.tiltAngleDeg === 0;
}

/** The widest step-over on a plane (mm): the flanks' widths at the height limit; 2R without tilt. */
function planeMaxIntervalMm(tool: ToolInput, pattern: PassPattern): number {
  const s = shapeOfTool(tool);
  const h = flankLimits(s).limitMm;
  const right = flankAtHeight(s, 'right', h).widthMm;
  const left = flankAtHeight(s, 'left', h).widthMm;
  return stepOverFromReaches(pattern, right, left);
}

/** The plane's model. */
export const planeModel: SurfaceModel<PlaneSurface> = {
  kind: 'plane',
  intervalMm: planeIntervalMm,
  forward: planeForward,
  inverse: planeInverse,
  limits: (tool) => flankLimits(shapeOfTool(tool)),
  maxIntervalMm: planeMaxIntervalMm,
  flankWidths: (tool) => {
    const s = shapeOfTool(tool);
    return (flank, h) => flankWidthMm(s, flank, h);
  },
  fit: () => FITS,
  leavesNoScallop,
};
