/**
 * The header of a `--batch` CSV (batch.ts): the input and result columns (the field registry's), the
 * rule a header must follow, and the layout a header gives (where each column is, what is echoed).
 */
import {
  CSV_FINISH_COLUMNS,
  CSV_OPTIONAL_COLUMNS,
  CSV_REQUIRED_COLUMNS,
  CSV_TARGET_COLUMNS,
  CSV_THREE_AXIS_COLUMNS,
  type CsvColumn,
  csvColumnOf,
  fieldOfCsvColumn,
  isLengthField,
} from '../core/input/fields';
import type { LengthUnit } from '../core/input/units';
import { RESULT_COLUMNS } from '../core/output/csvWrite';
import { unitNamedColumn } from '../core/output/lookupUnits';
import { cut } from './args';
import type { CsvRecord } from './csv';

/**
 * Input columns (the field registry's): required first, then the target (one of the two), then the
 * optional ones, in the order they are echoed.
 */
export const REQUIRED_COLUMNS = CSV_REQUIRED_COLUMNS;
export const TARGET_COLUMNS = CSV_TARGET_COLUMNS;
export const OPTIONAL_COLUMNS = CSV_OPTIONAL_COLUMNS;
/** A column of the input (the field registry's CSV names). */
export type InputColumn = CsvColumn;
/**
 * The principal radii of a doubly curved point (optional; empty: straight): both in a row make it a
 * doubly curved point, one alone the cylinder it is (feedRadius Rs: axis across; crossRadius Rs:
 * axis along the feed), as on the command line.
 */
export const RADIUS_COLUMNS: readonly InputColumn[] = [csvColumnOf('feedRadius'), csvColumnOf('crossRadius')];
const INPUT_COLUMNS: readonly InputColumn[] = [
  ...REQUIRED_COLUMNS,
  ...TARGET_COLUMNS,
  ...OPTIONAL_COLUMNS,
  ...RADIUS_COLUMNS,
  ...CSV_FINISH_COLUMNS,
];

/**
 * The areal parameters that are heights (Ssk and Sku are ratios), by the finish report's names: the
 * batch's columns and the JSON's length members alike.
 */
export const AREAL_HEIGHTS = ['Sa', 'Sq', 'Sz', 'Sp', 'Sv'] as const;

/**
 * The finish's result columns (issue 29), written when the header has a finish column (flutes, fz,
 * runout, runoutPhase, passPhase): the feed-mark height along the CC path, its period, the balanced
 * feed fz*, and the areal parameters over one period cell; before `error`. Empty where a row gives
 * no teeth (flutes and fz empty) or where there is none (no balanced feed).
 */
export const FINISH_RESULT_COLUMNS = ['feedMarkHeight', 'feedPeriod', 'balancedFz', ...AREAL_HEIGHTS, 'Ssk', 'Sku'];

/** The scallop height's, the target roughness's and the step-over's columns (h, Ra, L). */
export const H_COLUMN = csvColumnOf('h');
export const RA_COLUMN = csvColumnOf('ra');
export const L_COLUMN = csvColumnOf('interval');

/**
 * Result columns of a row given the step-over L (the inverse): the exact scallop height and the
 * cusps between right and between left flanks, the other cusp (zigzag), the flank reaches at
 * their cusps and the contact offset; a note and the error.
 */
export const INVERSE_RESULT_COLUMNS = [
  'h',
  'rightCuspHeight',
  'leftCuspHeight',
  'otherCuspHeight',
  'halfWidthRight',
  'halfWidthLeft',
  'contactOffset',
  'note',
  'error',
];

/** Column names as a message lists them: `a, b, c and d`. */
function listed(names: readonly string[]): string {
  return names.length < 2 ? names.join('') : `${names.slice(0, -1).join(', ')} and ${names.at(-1)}`;
}

/** Where each input column is in the records, and which are echoed. */
export interface Layout {
  /** Number of fields of a record. */
  readonly width: number;
  /** Header names as given (for messages). */
  readonly names: readonly string[];
  /** Echoed columns (canonical order) and their index in a record. */
  readonly echoed: readonly { readonly name: InputColumn; readonly index: number }[];
  readonly index: Readonly<Partial<Record<InputColumn, number>>>;
  /** The target column: a scallop height h, or a roughness Ra (then `h` is a result column). */
  readonly target: InputColumn;
  /** True for a header with a `slope` column: three-axis rows ({@link THREE_AXIS_RESULT_COLUMNS}). */
  readonly threeAxis: boolean;
  /** True for a header with a finish column: the {@link FINISH_RESULT_COLUMNS} are written. */
  readonly finish: boolean;
  /** The run's length unit (`--unit`): of the columns that name none, and of the results. */
  readonly unit: LengthUnit;
  /** The unit each length column names in the header (`R_in`, `h_mm`); absent: the run's. */
  readonly columnUnits: Readonly<Partial<Record<InputColumn, LengthUnit>>>;
}

/** The column that selects three-axis machining (a header with it needs no rho). */
const SLOPE_COLUMN = csvColumnOf('slope');

/**
 * Result columns of three-axis rows: L along the surface, the horizontal step Lxy, the step-down dz
 * (waterline; empty for raster), the equivalent lead and tilt at the CC point (degrees), a note and
 * the error. In a three-axis header that also has `lead`, `tilt` is this result column (an output
 * read back), not an input.
 */
export const THREE_AXIS_RESULT_COLUMNS = ['interval', 'horizontalStep', 'stepDown', 'lead', 'tilt', 'note', 'error'];

/**
 * Input columns of a three-axis header, in the order they are echoed (R, Rcr, h, then slope,
 * passes, rasterAngle, feedRadius, crossRadius); rho and tilt are read (a row with either and a
 * slope is that row's error) but not echoed.
 */
const THREE_AXIS_ECHOED: readonly InputColumn[] = [
  ...REQUIRED_COLUMNS.filter((c) => c !== csvColumnOf('rho')),
  H_COLUMN,
  ...CSV_THREE_AXIS_COLUMNS,
  ...CSV_FINISH_COLUMNS,
];
const THREE_AXIS_INPUT_COLUMNS: readonly InputColumn[] = [
  ...THREE_AXIS_ECHOED,
  csvColumnOf('rho'),
  csvColumnOf('tilt'),
];

/** What the header must be, as the messages say it. */
export const HEADER_RULE = `the CSV header must be ${[...REQUIRED_COLUMNS, H_COLUMN].join(',')} (or ${RA_COLUMN}, or the step-over ${L_COLUMN}, in place of ${H_COLUMN}) in any order, optionally with ${listed([...OPTIONAL_COLUMNS, ...RADIUS_COLUMNS])} (and the output columns, which are ignored); or, for three-axis machining, R,Rcr,h,${SLOPE_COLUMN} optionally with ${listed(CSV_THREE_AXIS_COLUMNS.filter((c) => c !== SLOPE_COLUMN))}; either optionally with the teeth's ${listed(CSV_FINISH_COLUMNS)}`;

/** Result columns a header may hold (an output read back): ignored, computed again. */
const IGNORED_COLUMNS: readonly string[] = [...RESULT_COLUMNS, ...FINISH_RESULT_COLUMNS];

/** True when a header's columns include a finish column. */
function hasFinish(index: Readonly<Partial<Record<InputColumn, number>>>): boolean {
  return CSV_FINISH_COLUMNS.some((c) => index[c] !== undefined);
}

/**
 * The header's names with their units read (the page's lookup table names them: `R_mm`, `R_in`,
 * `rho_deg`): the batch column each stands for, and the length unit it names (or none).
 */
function plainNames(fields: readonly string[]): { names: string[]; units: (LengthUnit | null)[] } {
  const units: (LengthUnit | null)[] = [];
  const names = fields.map((f) => {
    const named = unitNamedColumn(f.trim());
    if (named.unit !== null) {
      units.push(named.unit);
      return named.column;
    }
    // A length input column the lookup table does not write (Ra) may name its unit too.
    const m = /^(.+)_(mm|in)$/.exec(f.trim());
    const field = m === null ? null : fieldOfCsvColumn(m[1] ?? '');
    if (m !== null && field !== null && isLengthField(field)) {
      units.push(m[2] as LengthUnit);
      return m[1] as string;
    }
    units.push(null);
    return named.column;
  });
  return { names, units };
}

/** The unit each input column of `index` names in the header (`units` by position). */
function columnUnitsOf(
  index: Readonly<Partial<Record<InputColumn, number>>>,
  units: readonly (LengthUnit | null)[],
): Partial<Record<InputColumn, LengthUnit>> {
  const out: Partial<Record<InputColumn, LengthUnit>> = {};
  for (const [column, i] of Object.entries(index) as [InputColumn, number][]) {
    const unit = units[i];
    if (unit !== null && unit !== undefined) out[column] = unit;
  }
  return out;
}

/**
 * The layout of a header read without a problem: the columns of `order` it has, echoed in that
 * order, and the unit each names (`units` by position).
 */
function layoutOf(
  names: readonly string[],
  units: readonly (LengthUnit | null)[],
  unit: LengthUnit,
  index: Partial<Record<InputColumn, number>>,
  order: readonly InputColumn[],
  target: InputColumn,
  threeAxis: boolean,
): Layout {
  const echoed = order.flatMap((name) => {
    const i = index[name];
    return i === undefined ? [] : [{ name, index: i }];
  });
  return {
    width: names.length,
    names,
    echoed,
    index,
    target,
    threeAxis,
    finish: hasFinish(index),
    unit,
    columnUnits: columnUnitsOf(index, units),
  };
}

/** Puts column `name` (one of `known`) at `i` in `index`, or says why not: unknown, or given twice. */
function placeColumn(
  index: Partial<Record<InputColumn, number>>,
  name: string,
  i: number,
  known: readonly string[],
  problems: string[],
): void {
  if (!known.includes(name)) {
    problems.push(`unknown column "${cut(name)}"`);
    return;
  }
  const column = name as InputColumn;
  if (index[column] !== undefined) problems.push(`column ${name} appears twice`);
  else index[column] = i;
}

/** Reads the header record: the layout, or the reason it is not one. */
export function parseHeader(
  record: CsvRecord,
  unit: LengthUnit = 'mm',
): { ok: true; layout: Layout } | { ok: false; error: string } {
  const rule = HEADER_RULE;
  if (record.error !== null) return { ok: false, error: `${rule}; line ${record.line}: ${record.error}` };
  const plain = plainNames(record.fields);
  const names = plain.names;
  if (names.includes(SLOPE_COLUMN)) return parseThreeAxisHeader(names, plain.units, unit);
  const index: Partial<Record<InputColumn, number>> = {};
  const ignored = new Set<string>();
  const problems: string[] = [];
  names.forEach((name, i) => {
    if (IGNORED_COLUMNS.includes(name)) {
      if (ignored.has(name)) problems.push(`column ${name} appears twice`);
      ignored.add(name);
      return;
    }
    if ((CSV_THREE_AXIS_COLUMNS as readonly string[]).includes(name) && !RADIUS_COLUMNS.includes(name as InputColumn)) {
      problems.push(`column ${name} is for three-axis rows: add a ${SLOPE_COLUMN} column`);
      return;
    }
    placeColumn(index, name, i, INPUT_COLUMNS, problems);
  });
  const missing: string[] = REQUIRED_COLUMNS.filter((c) => index[c] === undefined);
  const given = TARGET_COLUMNS.filter((c) => index[c] !== undefined);
  if (given.length === 0) missing.push(`${H_COLUMN} (or ${RA_COLUMN} or ${L_COLUMN})`);
  if (given.length > 1)
    problems.push(`give one of ${H_COLUMN}, ${RA_COLUMN} and ${L_COLUMN}, not ${given.join(' and ')}`);
  if (missing.length > 0) problems.unshift(`missing ${missing.join(', ')}`);
  if (problems.length > 0) return { ok: false, error: `${rule} (${problems.join('; ')})` };
  return { ok: true, layout: layoutOf(names, plain.units, unit, index, INPUT_COLUMNS, given[0] as InputColumn, false) };
}

/** A three-axis header (it has a slope column): R, Rcr, h and slope required; no rho needed. */
function parseThreeAxisHeader(
  names: readonly string[],
  units: readonly (LengthUnit | null)[],
  unit: LengthUnit,
): { ok: true; layout: Layout } | { ok: false; error: string } {
  const index: Partial<Record<InputColumn, number>> = {};
  const ignored = new Set<string>();
  const problems: string[] = [];
  const tiltIsResult = names.includes('lead');
  names.forEach((name, i) => {
    if (
      (THREE_AXIS_RESULT_COLUMNS.includes(name) && (name !== 'tilt' || tiltIsResult)) ||
      FINISH_RESULT_COLUMNS.includes(name)
    ) {
      if (ignored.has(name)) problems.push(`column ${name} appears twice`);
      ignored.add(name);
      return;
    }
    if (name === RA_COLUMN || name === L_COLUMN) {
      problems.push(`three-axis rows take a scallop height ${H_COLUMN}, not ${name}`);
      return;
    }
    placeColumn(index, name, i, THREE_AXIS_INPUT_COLUMNS, problems);
  });
  const missing = [...THREE_AXIS_ECHOED.slice(0, 4)].filter((c) => index[c] === undefined);
  if (missing.length > 0) problems.unshift(`missing ${missing.join(', ')}`);
  if (problems.length > 0) return { ok: false, error: `${HEADER_RULE} (${problems.join('; ')})` };
  return { ok: true, layout: layoutOf(names, units, unit, index, THREE_AXIS_ECHOED, H_COLUMN, true) };
}

/** The result columns of a layout: with a target Ra, the scallop height `h` that leaves it comes first. */
export function resultColumns(layout: Layout): readonly string[] {
  const base = layout.threeAxis
    ? THREE_AXIS_RESULT_COLUMNS
    : layout.target === L_COLUMN
      ? INVERSE_RESULT_COLUMNS
      : layout.target === RA_COLUMN
        ? [H_COLUMN, ...RESULT_COLUMNS]
        : RESULT_COLUMNS;
  // The finish's columns go before `error`, which stays last.
  return layout.finish ? [...base.slice(0, -1), ...FINISH_RESULT_COLUMNS, 'error'] : base;
}

/** Result columns that are no length: the angles of three-axis rows and the text columns. */
const NOT_LENGTH_RESULTS: ReadonlySet<string> = new Set(['lead', 'tilt', 'note', 'error', 'Ssk', 'Sku']);

/** True for a result column that holds a length (in the run's unit). */
export function isLengthResult(column: string): boolean {
  return !NOT_LENGTH_RESULTS.has(column);
}

/** True for an input column that holds a length (the field registry's kind). */
export function isLengthColumn(column: InputColumn): boolean {
  const field = fieldOfCsvColumn(column);
  return field !== null && isLengthField(field);
}

/**
 * The output header line for a layout. In mm, the batch's names as they were; in inches every
 * length column names its unit (`R_in`, `exact_in`, `R_mm` for a column read in mm); in mm, only a
 * column read in inches names it.
 */
export function outputHeader(layout: Layout): string {
  const named = (column: InputColumn): string => {
    const unit = layout.columnUnits[column] ?? layout.unit;
    if (!isLengthColumn(column)) return column;
    return layout.unit === 'in' || unit === 'in' ? `${column}_${unit}` : column;
  };
  const results = resultColumns(layout).map((c) => (layout.unit === 'in' && isLengthResult(c) ? `${c}_in` : c));
  return `${[...layout.echoed.map((c) => named(c.name)), ...results].join(',')}\n`;
}

/** Empty fields for the result columns before `error` (numbers and `note`), each after a comma. */
export function emptyResults(layout: Layout): string {
  return ','.repeat(resultColumns(layout).length - 1);
}
