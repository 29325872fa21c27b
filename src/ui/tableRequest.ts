/**
 * The lookup table's request for the question on screen (lookupDownload.ts asks it of the worker):
 * the tool, pattern and surface, and the grid of core/output/lookupTable.ts. Apart from the button,
 * so that the grid's code loads on the first download, not with the first result. Pure.
 */
import type { LengthUnit } from '../core/input/units';
import { lookupGrid } from '../core/output/lookupTable';
import { PLANE } from '../core/surfaces/cylinder';
import { type CurvedRequest, isCurvedRequest } from '../worker/pageProtocol';
import type { SolveRequest, TableRequest } from '../worker/protocol';

/**
 * The table request for the tool, pattern and surface of a solve request (or of a doubly curved
 * point's), its file in `unit` (the scallop heights on that unit's 1-2-5 series).
 */
export function tableRequestOf(request: SolveRequest | CurvedRequest, unit: LengthUnit): TableRequest {
  const i = request.input;
  const tool = {
    toolRadiusMm: i.toolRadiusMm,
    cornerRadiusMm: i.cornerRadiusMm,
    pattern: i.pattern,
    surface: isCurvedRequest(request) ? PLANE : request.input.surface,
  };
  const grid = lookupGrid(tool, unit);
  return isCurvedRequest(request)
    ? {
        tool,
        grid,
        unit,
        radii: { feedRadiusMm: request.input.feedRadiusMm, crossRadiusMm: request.input.crossRadiusMm },
      }
    : { tool, grid, unit };
}
