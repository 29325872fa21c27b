/**
 * A throwaway surface (issue 18's demonstration that adding a surface is one module and its
 * registration): the plane offset by a constant along its normal. Translating the design surface
 * moves every pass with it, so the step-over, the cusp heights above the surface, the limits and the
 * fit are the plane's. Lengths mm.
 */
import type { ToolInput } from '../../domain/tool';
import type { SurfaceModel } from '../surface';
import { planeModel } from './plane';

/** The plane `z = offsetMm` (any finite offset, mm). */
export interface OffsetPlaneSurface {
  readonly kind: 'offsetPlane';
  readonly offsetMm: number;
}

const PLANE = { kind: 'plane' } as const;

/** The offset plane's model: the plane's answers, the offset dropping out. */
export const offsetPlaneModel: SurfaceModel<OffsetPlaneSurface> = {
  kind: 'offsetPlane',
  intervalMm: (input) => planeModel.intervalMm({ ...input, surface: PLANE }),
  forward: (input) => planeModel.forward({ ...input, surface: PLANE }),
  inverse: (input) => planeModel.inverse({ ...input, surface: PLANE }),
  limits: (tool: ToolInput) => planeModel.limits(tool, PLANE),
  maxIntervalMm: (tool, pattern) => planeModel.maxIntervalMm(tool, pattern, PLANE),
  flankWidths: (tool) => planeModel.flankWidths(tool, PLANE),
  fit: (tool) => planeModel.fit(tool, PLANE),
  leavesNoScallop: (tool) => planeModel.leavesNoScallop(tool, PLANE),
};
