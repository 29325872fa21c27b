/**
 * The worker's `table` job: the lookup table for the page's download (core/lookupTable.ts). The
 * worker trusts no caller: the tool, pattern and surface are validated again (on their own: which
 * postures a concave cylinder admits is a question for each cell) and the grid must be finite
 * numbers in the domain's ranges, at most MAX_GRID_AXIS per axis; each cell is then validated and
 * solved as the command line's batch does, a posture that gouges the cylinder being a row with
 * its reason. The reply echoes the request it answers.
 */

import { PASS_FIELDS } from '../../core/input/fields';
import { rawOf } from '../../core/input/raw';
import { type LookupTable, lookupTable } from '../../core/output/lookupTable';
import { lookupCsvInUnit } from '../../core/output/lookupUnits';
import { threeAxisLookupTable } from '../../core/output/threeAxisLookup';
import { validateForward } from '../../core/surfaces/validate';
import { badRadii, curvedLookupTable } from '../data/curvedTable';
import type { TableReply, TableRequest } from '../protocol';

/** Values per axis of the grid, at most (the page asks about 12 x 12 x 5). */
export const MAX_GRID_AXIS = 64;

/** Why a grid cannot be tabulated, or null. */
function badGrid(request: TableRequest): string | null {
  const g = request.grid;
  const axes: ReadonlyArray<[string, readonly number[], (v: number) => boolean]> = [
    ['scallop heights', g.scallopHeightsMm, (v) => v > 0],
    ['lead angles', g.leadAnglesDeg, (v) => v >= 0 && v < 90],
    ['tilts', g.tiltAnglesDeg, (v) => v > -90 && v < 90],
  ];
  for (const [name, values, inRange] of axes) {
    if (values.length === 0 || values.length > MAX_GRID_AXIS)
      return `the grid needs 1 to ${MAX_GRID_AXIS} ${name} (got ${values.length}).`;
    if (!values.every((v) => Number.isFinite(v) && inRange(v))) return `the grid's ${name} are out of range.`;
  }
  return null;
}

/** The lookup table of a request, or why there is none. */
export function table(request: TableRequest): TableReply {
  const t = request.tool;
  const tool = validateForward({
    ...rawOf({ ...t, leadAngleDeg: 0, tiltAngleDeg: 0 }, PASS_FIELDS),
    // Any h the flat-lying tool accepts: only the tool, pattern and surface are checked here.
    h: 1e-6 * t.toolRadiusMm,
  });
  // Gouging depends on the posture, and this one (lead 0, tilt 0) is only a placeholder: a flat
  // bottom lying flat gouges every concave cylinder, while most of the grid's postures cut it.
  const toolErrors = tool.ok ? [] : tool.errors.filter((e) => e.field !== 'h' && e.code !== 'gouging');
  if (toolErrors.length > 0) return { ok: false, request, reason: toolErrors.map((e) => e.message).join(' ') };
  if (request.threeAxis !== undefined) return threeAxisTable(request, request.threeAxis);
  const grid = badGrid(request);
  if (grid !== null) return { ok: false, request, reason: grid };
  if (request.radii !== undefined) {
    const bad = badRadii(request.radii);
    if (bad !== null) return { ok: false, request, reason: bad };
    return inUnit(request, curvedLookupTable(t, t.pattern, request.radii, request.grid, request.unit));
  }
  return inUnit(request, lookupTable(t, request.grid, request.unit));
}

/** A three-axis table (slopes x scallop heights), or why the grid cannot be tabulated. */
function threeAxisTable(request: TableRequest, spec: NonNullable<TableRequest['threeAxis']>): TableReply {
  const g = { scallopHeightsMm: request.grid.scallopHeightsMm, slopesDeg: spec.slopesDeg };
  for (const [name, values, inRange] of [
    ['scallop heights', g.scallopHeightsMm, (v: number) => v > 0],
    ['slopes', g.slopesDeg, (v: number) => v >= 0 && v < 90],
  ] as const) {
    if (values.length === 0 || values.length > MAX_GRID_AXIS)
      return { ok: false, request, reason: `the grid needs 1 to ${MAX_GRID_AXIS} ${name} (got ${values.length}).` };
    if (!values.every((v) => Number.isFinite(v) && inRange(v)))
      return { ok: false, request, reason: `the grid's ${name} are out of range.` };
  }
  // Each cell is validated and solved as the batch does (its tool and strategy with it).
  return inUnit(request, threeAxisLookupTable(spec.case, g, request.unit));
}

/** The reply with the table in the request's unit (its columns named with units), if it asks one. */
function inUnit(request: TableRequest, t: LookupTable): TableReply {
  const csv = request.unit === undefined ? t.csv : lookupCsvInUnit(t.csv, request.unit);
  return { ok: true, request, ...t, csv };
}
