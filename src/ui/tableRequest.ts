/**
 * The lookup table's request for the question on screen (lookupDownload.ts asks it of the worker):
 * the tool, pattern and surface, and the grid of core/output/lookupTable.ts (three-axis: the tool
 * and strategy, and the grid of core/output/threeAxisLookup.ts). Apart from the button,
 * so that the grid's code loads on the first download, not with the first result. Pure.
 */

import { PLANE } from '../core/domain/surface';
import type { LengthUnit } from '../core/input/units';
import { lookupGrid } from '../core/output/lookupTable';
import { type ThreeAxisLookupCase, threeAxisLookupGrid } from '../core/output/threeAxisLookup';
import { type CurvedRequest, isCurvedRequest, type ThreeAxisRequest } from '../worker/pageProtocol';
import type { SolveRequest, TableRequest } from '../worker/protocol';

/**
 * The table request for the tool, pattern and surface of a solve request (or of a doubly curved
 * point's), its file in `unit` (the scallop heights on that unit's 1-2-5 series).
 */
export function tableRequestOf(
  request: SolveRequest | CurvedRequest | ThreeAxisRequest,
  unit: LengthUnit,
): TableRequest {
  if (request.mode === 'three-axis') return threeAxisTableRequestOf(request, unit);
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

/**
 * The three-axis table for the tool and strategy of a three-axis request (its slope and h are the
 * grid's axes: slopes 0 to 85 degrees x the scallop heights on `unit`'s 1-2-5 series), its file in `unit`.
 */
function threeAxisTableRequestOf(request: ThreeAxisRequest, unit: LengthUnit): TableRequest {
  const p = request.input;
  const c = p.case;
  const spec: ThreeAxisLookupCase =
    p.surface === 'plane'
      ? {
          toolRadiusMm: c.toolRadiusMm,
          cornerRadiusMm: c.cornerRadiusMm,
          passes: p.case.passes,
          rasterAngleDeg: p.case.passes === 'raster' ? p.case.rasterAngleDeg : null,
          revolution: null,
        }
      : {
          toolRadiusMm: c.toolRadiusMm,
          cornerRadiusMm: c.cornerRadiusMm,
          passes: 'waterline',
          rasterAngleDeg: null,
          revolution: { feedRadiusMm: p.case.feedRadiusMm, crossRadiusMm: p.case.crossRadiusMm },
        };
  const grid = threeAxisLookupGrid(spec, unit);
  const tool = {
    toolRadiusMm: c.toolRadiusMm,
    cornerRadiusMm: c.cornerRadiusMm,
    pattern: 'one-way' as const,
    surface: PLANE,
  };
  return {
    tool,
    grid: { scallopHeightsMm: grid.scallopHeightsMm, leadAnglesDeg: [], tiltAnglesDeg: [] },
    unit,
    threeAxis: { case: spec, slopesDeg: grid.slopesDeg },
  };
}
