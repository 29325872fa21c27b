/**
 * A lookup table for the shop floor: the exact step-over of one tool, pass pattern and surface over
 * a grid of scallop heights x lead angles x tilts, as CSV in the command line's batch format
 * (csvWrite.ts): the input columns R, Rcr, rho, h, tilt, pattern, surfaceRadius, surfaceAxis (both
 * empty on a plane), then the batch's result columns (`exact` is L/2, `interval` is L) and `error`.
 * Fed back to the command line's `--batch`, the file is answered on the same surface, row for row.
 * A cell outside the valid domain (a scallop height at or above the posture's limit, a posture
 * that cuts a wall or gouges a concave cylinder) keeps its input columns, leaves the results empty
 * and gives the reason in `error`, as the batch does. Pure; mm and degrees.
 */

import type { Surface } from '../domain/surface';
import type { PassPattern } from '../domain/tool';
import {
  CSV_OPTIONAL_COLUMNS,
  CSV_REQUIRED_COLUMNS,
  csvColumnOf,
  type FieldName,
  fieldOfCsvColumn,
  PASS_FIELDS,
} from '../input/fields';
import { describeInputError, type InputError } from '../input/inputErrors';
import { rawOf } from '../input/raw';
import { fromMm, type LengthUnit, toMm } from '../input/units';
import type { RawForwardInput } from '../input/validate';
import { scallopHeightLimits, validateForward } from '../surfaces/validate';
import { csvNumber, csvText, RESULT_COLUMNS, resultFields } from './csvWrite';

/** The grid of a table: scallop heights (mm), lead angles and tilts (degrees), each ascending. */
export interface LookupGrid {
  readonly scallopHeightsMm: readonly number[];
  readonly leadAnglesDeg: readonly number[];
  readonly tiltAnglesDeg: readonly number[];
}

/** The tool, pattern and surface a table is for (validated: mm). */
export interface LookupTool {
  readonly toolRadiusMm: number;
  readonly cornerRadiusMm: number;
  readonly pattern: PassPattern;
  readonly surface: Surface;
}

/** Lead angles of the grid (degrees): finer at small leads, where the step-over changes fastest. */
export const LOOKUP_LEADS_DEG: readonly number[] = [0, 0.5, 1, 2, 3, 5, 7.5, 10, 15, 20, 30, 45];

/** Tilts of the grid (degrees): -10 to 10 in steps of 5. */
export const LOOKUP_TILTS_DEG: readonly number[] = [-10, -5, 0, 5, 10];

/** The smallest scallop height of the grid, as a fraction of the tool radius (then rounded down to 1-2-5). */
const SMALLEST_H_PER_R = 1e-4;

/**
 * The 1-2-5 series (1, 2, 5, 10, 20, ... times a power of ten) from the largest such value at or
 * below `from` (> 0) to the last one below `below`; values rounded to 12 significant digits, so
 * they read 0.002 and not 0.0020000000000000005.
 */
export function series125(from: number, below: number): number[] {
  const all: number[] = [];
  for (let decade = 10 ** Math.floor(Math.log10(from)); all.length < 400; decade *= 10)
    for (const m of [1, 2, 5]) {
      const v = Number((m * decade).toPrecision(12));
      if (v >= below) return all.slice(Math.max(0, all.filter((x) => x <= from).length - 1));
      all.push(v);
    }
  return all;
}

/**
 * The grid for a tool: scallop heights on the 1-2-5 series in `unit` (mm: 0.001, 0.002, 0.005 mm;
 * inch: 0.0001, 0.0002, 0.0005 in; given in mm) from about 1e-4 R up to the largest limit over
 * the grid's postures (below which some posture leaves a scallop; capped at R), lead angles
 * LOOKUP_LEADS_DEG, tilts LOOKUP_TILTS_DEG.
 */
export function lookupGrid(
  tool: Pick<LookupTool, 'toolRadiusMm' | 'cornerRadiusMm'>,
  unit: LengthUnit = 'mm',
): LookupGrid {
  let limit = 0;
  for (const lead of LOOKUP_LEADS_DEG)
    for (const tilt of LOOKUP_TILTS_DEG) {
      const l = scallopHeightLimits({ ...tool, leadAngleDeg: lead, tiltAngleDeg: tilt }).limitMm;
      if (Number.isFinite(l)) limit = Math.max(limit, l);
    }
  const top = Math.min(tool.toolRadiusMm, limit > 0 ? limit : tool.toolRadiusMm);
  return {
    scallopHeightsMm: series125(fromMm(SMALLEST_H_PER_R * tool.toolRadiusMm, unit), fromMm(top, unit)).map((h) =>
      toMm(h, unit),
    ),
    leadAnglesDeg: LOOKUP_LEADS_DEG,
    tiltAnglesDeg: LOOKUP_TILTS_DEG,
  };
}

/**
 * The CSV header of a table: the batch's output header for these input columns (the batch echoes
 * its input columns in this order), so the batch reads the file back as it is.
 */
const INPUT_COLUMNS = [...CSV_REQUIRED_COLUMNS, csvColumnOf('h'), ...CSV_OPTIONAL_COLUMNS];
export const LOOKUP_HEADER = [...INPUT_COLUMNS, ...RESULT_COLUMNS].join(',');

/** The field each input column holds. */
const INPUT_FIELDS = INPUT_COLUMNS.map((column) => fieldOfCsvColumn(column) as FieldName);

/** A value as the batch reads it back: a number in full precision, a word, or empty (none, the default). */
function inputCell(value: unknown): string {
  if (value === undefined) return '';
  return typeof value === 'number' ? csvNumber(value) : csvText(String(value));
}

/** A refused cell's reason in `unit` (the cell's h, mm, as the file shows it). */
function reasonIn(e: InputError, unit: LengthUnit, hMm: number): string {
  if (unit === 'mm') return e.message;
  const typed = e.field === 'h' ? csvNumber(Number(fromMm(hMm, unit).toPrecision(12))) : undefined;
  return describeInputError(e, unit, typed === undefined ? {} : { typed });
}

/** A table: its CSV text (header, then one row per cell, tilt slowest, h fastest) and counts. */
export interface LookupTable {
  readonly csv: string;
  /** Rows after the header (one per cell of the grid). */
  readonly rows: number;
  /** Cells outside the valid domain (results empty, the reason in `error`). */
  readonly emptyCells: number;
}

/**
 * The exact step-over (and the batch's other results) of every cell of the grid, validated and
 * solved as the command line's batch validates and solves each record; a refused cell's reason
 * worded in `unit` (the numbers stay mm: lookupUnits.ts converts the file).
 */
export function lookupTable(tool: LookupTool, grid: LookupGrid, unit: LengthUnit = 'mm'): LookupTable {
  const lines = [LOOKUP_HEADER];
  let empty = 0;
  for (const tilt of grid.tiltAnglesDeg)
    for (const rho of grid.leadAnglesDeg)
      for (const h of grid.scallopHeightsMm) {
        // The cell's inputs as the batch reads them (a plane: both surface fields empty).
        const raw: Partial<Record<FieldName, unknown>> = {
          ...rawOf({ ...tool, leadAngleDeg: rho, tiltAngleDeg: tilt }, PASS_FIELDS),
          h,
        };
        const echo = INPUT_FIELDS.map((field) => inputCell(raw[field])).join(',');
        const v = validateForward(raw as RawForwardInput);
        if (v.ok) lines.push(`${echo},${resultFields(v.value)},`);
        else {
          empty++;
          const reason = v.errors.map((e) => reasonIn(e, unit, h)).join(' ');
          lines.push(`${echo}${','.repeat(RESULT_COLUMNS.length - 1)},${csvText(reason)}`);
        }
      }
  return { csv: `${lines.join('\n')}\n`, rows: lines.length - 1, emptyCells: empty };
}
