/**
 * The header of a `--batch` CSV (batch.ts): the input and result columns (the field registry's), the
 * rule a header must follow, and the layout a header gives (where each column is, what is echoed).
 */
import {
  CSV_OPTIONAL_COLUMNS,
  CSV_REQUIRED_COLUMNS,
  CSV_TARGET_COLUMNS,
  CSV_THREE_AXIS_COLUMNS,
  type CsvColumn,
  csvColumnOf,
} from '../core/input/fields';
import { RESULT_COLUMNS } from '../core/output/csvWrite';
import { unitNamedColumn } from '../core/output/lookupUnits';
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
];

/** The scallop height's and the target roughness's columns (h, Ra). */
export const H_COLUMN = csvColumnOf('h');
export const RA_COLUMN = csvColumnOf('ra');

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
];
const THREE_AXIS_INPUT_COLUMNS: readonly InputColumn[] = [
  ...THREE_AXIS_ECHOED,
  csvColumnOf('rho'),
  csvColumnOf('tilt'),
];

/** What the header must be, as the messages say it. */
export const HEADER_RULE = `the CSV header must be ${[...REQUIRED_COLUMNS, H_COLUMN].join(',')} (or ${RA_COLUMN} in place of ${H_COLUMN}) in any order, optionally with ${listed([...OPTIONAL_COLUMNS, ...RADIUS_COLUMNS])} (and the output columns, which are ignored); or, for three-axis machining, R,Rcr,h,${SLOPE_COLUMN} optionally with ${listed(CSV_THREE_AXIS_COLUMNS.filter((c) => c !== SLOPE_COLUMN))}`;

/** Result columns a header may hold (an output read back): ignored, computed again. */
const IGNORED_COLUMNS: readonly string[] = RESULT_COLUMNS;

/**
 * The header's names with their units read (the page's lookup table names them: `R_mm`,
 * `rho_deg`): the batch column each stands for, or why the batch cannot read it (a column in
 * inches: the batch reads mm).
 */
function plainNames(fields: readonly string[]): { names: string[]; problems: string[] } {
  const problems: string[] = [];
  const names = fields.map((f) => {
    const named = unitNamedColumn(f.trim());
    if (named.unit === 'in')
      problems.push(`column ${f.trim()} is in inches: the command line reads mm (download the table in mm)`);
    return named.column;
  });
  return { names, problems };
}

/** Reads the header record: the layout, or the reason it is not one. */
export function parseHeader(record: CsvRecord): { ok: true; layout: Layout } | { ok: false; error: string } {
  const rule = HEADER_RULE;
  if (record.error !== null) return { ok: false, error: `${rule}; line ${record.line}: ${record.error}` };
  const plain = plainNames(record.fields);
  if (plain.problems.length > 0) return { ok: false, error: `${rule} (${plain.problems.join('; ')})` };
  const names = plain.names;
  if (names.includes(SLOPE_COLUMN)) return parseThreeAxisHeader(names);
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
    if (!(INPUT_COLUMNS as readonly string[]).includes(name)) {
      problems.push(`unknown column "${name}"`);
      return;
    }
    const column = name as InputColumn;
    if (index[column] !== undefined) problems.push(`column ${name} appears twice`);
    else index[column] = i;
  });
  const missing: string[] = REQUIRED_COLUMNS.filter((c) => index[c] === undefined);
  const given = TARGET_COLUMNS.filter((c) => index[c] !== undefined);
  if (given.length === 0) missing.push(`${H_COLUMN} (or ${RA_COLUMN})`);
  if (given.length > 1) problems.push(`give ${H_COLUMN} or ${RA_COLUMN}, not both`);
  if (missing.length > 0) problems.unshift(`missing ${missing.join(', ')}`);
  if (problems.length > 0) return { ok: false, error: `${rule} (${problems.join('; ')})` };
  const echoed = INPUT_COLUMNS.flatMap((name) => {
    const i = index[name];
    return i === undefined ? [] : [{ name, index: i }];
  });
  const target = given[0] as InputColumn;
  return { ok: true, layout: { width: names.length, names, echoed, index, target, threeAxis: false } };
}

/** A three-axis header (it has a slope column): R, Rcr, h and slope required; no rho needed. */
function parseThreeAxisHeader(names: readonly string[]): { ok: true; layout: Layout } | { ok: false; error: string } {
  const index: Partial<Record<InputColumn, number>> = {};
  const ignored = new Set<string>();
  const problems: string[] = [];
  const tiltIsResult = names.includes('lead');
  names.forEach((name, i) => {
    if (THREE_AXIS_RESULT_COLUMNS.includes(name) && (name !== 'tilt' || tiltIsResult)) {
      if (ignored.has(name)) problems.push(`column ${name} appears twice`);
      ignored.add(name);
      return;
    }
    if (name === RA_COLUMN) {
      problems.push(`three-axis rows take a scallop height ${H_COLUMN}, not ${RA_COLUMN}`);
      return;
    }
    if (!(THREE_AXIS_INPUT_COLUMNS as readonly string[]).includes(name)) {
      problems.push(`unknown column "${name}"`);
      return;
    }
    const column = name as InputColumn;
    if (index[column] !== undefined) problems.push(`column ${name} appears twice`);
    else index[column] = i;
  });
  const missing = [...THREE_AXIS_ECHOED.slice(0, 4)].filter((c) => index[c] === undefined);
  if (missing.length > 0) problems.unshift(`missing ${missing.join(', ')}`);
  if (problems.length > 0) return { ok: false, error: `${HEADER_RULE} (${problems.join('; ')})` };
  const echoed = THREE_AXIS_ECHOED.flatMap((name) => {
    const i = index[name];
    return i === undefined ? [] : [{ name, index: i }];
  });
  return { ok: true, layout: { width: names.length, names, echoed, index, target: H_COLUMN, threeAxis: true } };
}

/** The result columns of a layout: with a target Ra, the scallop height `h` that leaves it comes first. */
export function resultColumns(layout: Layout): readonly string[] {
  if (layout.threeAxis) return THREE_AXIS_RESULT_COLUMNS;
  return layout.target === RA_COLUMN ? [H_COLUMN, ...RESULT_COLUMNS] : RESULT_COLUMNS;
}

/** The output header line for a layout. */
export function outputHeader(layout: Layout): string {
  return `${[...layout.echoed.map((c) => c.name), ...resultColumns(layout)].join(',')}\n`;
}

/** Empty fields for the result columns before `error` (numbers and `note`), each after a comma. */
export function emptyResults(layout: Layout): string {
  return ','.repeat(resultColumns(layout).length - 1);
}
