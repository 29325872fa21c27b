/**
 * `--batch`: CSV cases on stdin to a CSV table on stdout, streamed record by record.
 *
 * Input: a header naming R, Rcr, rho and either h (scallop height) or Ra (target roughness),
 * optionally tilt, pattern, surfaceRadius and surfaceAxis, in any order; the result columns
 * ({@link RESULT_COLUMNS}) may be there too and are ignored, so a batch's own output, or the
 * page's lookup table, reads back as it is (no other column); one case per record. Blank lines
 * are not records: they are skipped. An empty field of an optional column takes its default
 * (tilt 0, one-way, a plane, axis along the feed). Output: one row per record, in order: the
 * input columns echoed (R,Rcr,rho,h or Ra, then the optional ones given, in the order above),
 * with Ra the scallop height `h` that leaves it, the results ({@link RESULT_COLUMNS}) and `error`
 * last. Numbers are written in full precision (the shortest text that reads back to the same
 * double); a value that does not exist is an empty field. A bad record gets its message in
 * `error` (on one line, control characters escaped) and the run goes on.
 */

import type { Readable } from 'node:stream';
import { StringDecoder } from 'node:string_decoder';
import {
  type AnyInputError,
  APPROXIMATIONS,
  type ApproximationKey,
  describeInputError,
  forwardInput,
  type RawToolInput,
  scallopHeightForRaMm,
  validateForward,
  validateTargetRa,
} from '../core/index';
import {
  CSV_OPTIONAL_COLUMNS,
  CSV_REQUIRED_COLUMNS,
  CSV_TARGET_COLUMNS,
  CSV_THREE_AXIS_COLUMNS,
  type CsvColumn,
  csvColumnOf,
  FIELDS,
  PASS_FIELDS,
} from '../core/input/fields';
import { rawFields } from '../core/input/raw';
import { csvNumber, RESULT_COLUMNS, resultFields } from '../core/output/csvWrite';
import {
  doublyCurvedForward,
  doublyCurvedHeightForRaMm,
  validateDoublyCurved,
} from '../core/surfaces/doublyCurved/index';
import { solveThreeAxis, validateThreeAxis } from '../core/threeAxis/validate';
import { CsvReader, type CsvRecord, csvText } from './csv';
import { describeSystemError, errorLine, escapeControls, FLUSH_CHARS, type Output } from './output';

/** The result columns and their writers live in the shared CSV writer (core/csvWrite.ts). */
export { csvNumber, RESULT_COLUMNS, resultFields };

/**
 * Input columns (the field registry's): required first, then the target (one of the two), then the
 * optional ones, in the order they are echoed.
 */
export const REQUIRED_COLUMNS = CSV_REQUIRED_COLUMNS;
export const TARGET_COLUMNS = CSV_TARGET_COLUMNS;
export const OPTIONAL_COLUMNS = CSV_OPTIONAL_COLUMNS;
type InputColumn = CsvColumn;
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
const H_COLUMN = csvColumnOf('h');
const RA_COLUMN = csvColumnOf('ra');

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

/** Reads the header record: the layout, or the reason it is not one. */
export function parseHeader(record: CsvRecord): { ok: true; layout: Layout } | { ok: false; error: string } {
  const rule = HEADER_RULE;
  if (record.error !== null) return { ok: false, error: `${rule}; line ${record.line}: ${record.error}` };
  const names = record.fields.map((f) => f.trim());
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
function emptyResults(layout: Layout): string {
  return ','.repeat(resultColumns(layout).length - 1);
}

/** Spaces and tabs around a field are dropped in the echo; a line break is kept (and quoted). */
function trimSpaces(text: string): string {
  return text.replace(/^[ \t]+|[ \t]+$/g, '');
}

/** A row with no results: its message in `error`, on one line (control characters escaped, as on stderr). */
function errorRow(echo: string, layout: Layout, message: string): string {
  return `${echo}${emptyResults(layout)},${csvText(escapeControls(message))}\n`;
}

/** A field of an optional column: undefined (the default) when the column is absent or the field empty. */
function optionalField(fields: readonly string[], index: number | undefined): string | undefined {
  if (index === undefined) return undefined;
  const text = fields[index] as string;
  return text.trim() === '' ? undefined : text;
}

/** The output row of one record (with its line break). */
export function batchRow(record: CsvRecord, layout: Layout): string {
  const fields = record.fields;
  let echo = '';
  for (let j = 0; j < layout.echoed.length; j++) {
    const c = layout.echoed[j] as { readonly index: number };
    echo += `${j === 0 ? '' : ','}${csvText(trimSpaces(fields[c.index] ?? ''))}`;
  }
  if (record.error !== null) return errorRow(echo, layout, `line ${record.line}: ${record.error}`);
  if (fields.length !== layout.width) {
    return errorRow(
      echo,
      layout,
      `line ${record.line}: expected ${layout.width} values (${layout.names.join(',')}), got ${fields.length}`,
    );
  }
  for (const c of layout.echoed) {
    const text = fields[c.index] as string;
    if (text.includes('\n') || text.includes('\r')) {
      return errorRow(echo, layout, `line ${record.line}: the ${c.name} field holds a line break`);
    }
  }
  const { index } = layout;
  if (layout.threeAxis) return threeAxisRow(fields, layout, echo);
  // Each field from its column; an empty optional field takes its default (tilt 0, one-way, plane,
  // feed), as a missing column does.
  const pass = rawFields(PASS_FIELDS, (name) => {
    const csv = FIELDS[name].csv;
    const i = index[csv.column];
    return csv.role === 'optional' ? optionalField(fields, i) : fields[i as number];
  });
  if (layout.target === RA_COLUMN) {
    const v = validateTargetRa({ ...pass, ra: fields[index[RA_COLUMN] as number] });
    if (!v.ok) return errorRow(echo, layout, v.errors.map((e) => e.message).join(' '));
    const p = v.value;
    const h = scallopHeightForRaMm(p, p.pattern, p.targetRaMm, p.surface);
    return `${echo},${csvNumber(h)},${resultFields(forwardInput(p, p.pattern, h, p.surface))},\n`;
  }
  const rf = optionalField(fields, index[csvColumnOf('feedRadius')]);
  const rc = optionalField(fields, index[csvColumnOf('crossRadius')]);
  if (rf !== undefined || rc !== undefined) {
    const cylinder = pass.surfaceRadius !== undefined || pass.surfaceAxis !== undefined;
    if (cylinder) {
      return errorRow(
        echo,
        layout,
        'give the surface once: surfaceRadius with surfaceAxis (a cylinder), or feedRadius and crossRadius',
      );
    }
    if (rf !== undefined && rc !== undefined) return doublyCurvedRow(pass, rf, rc, fields, layout, echo);
    // One radius alone: the cylinder it is (the cylinder's own path, the same digits).
    const cylinderPass = { ...pass, surfaceRadius: rf ?? rc, surfaceAxis: rf === undefined ? 'feed' : 'cross' };
    const as = rf === undefined ? 'crossRadius' : 'feedRadius';
    return passRow(cylinderPass, fields, layout, echo, as);
  }
  return passRow(pass, fields, layout, echo);
}

/** The row of a plane or a cylinder (h or a target Ra). */
function passRow(
  pass: RawToolInput,
  fields: readonly string[],
  layout: Layout,
  echo: string,
  as?: 'feedRadius' | 'crossRadius',
): string {
  const { index } = layout;
  const words = (errors: readonly AnyInputError[]) =>
    errors.map((e) => (as === undefined ? e.message : describeInputError(e, 'mm', { surfaceRadiusAs: as }))).join(' ');
  if (layout.target === RA_COLUMN) {
    const v = validateTargetRa({ ...pass, ra: fields[index[RA_COLUMN] as number] });
    if (!v.ok) return errorRow(echo, layout, words(v.errors));
    const p = v.value;
    const h = scallopHeightForRaMm(p, p.pattern, p.targetRaMm, p.surface);
    return `${echo},${csvNumber(h)},${resultFields(forwardInput(p, p.pattern, h, p.surface))},\n`;
  }
  const v = validateForward({ ...pass, h: fields[index[H_COLUMN] as number] });
  if (!v.ok) return errorRow(echo, layout, words(v.errors));
  return `${echo},${resultFields(v.value)},\n`;
}

/**
 * The row of a doubly curved point: the exact answer in the result columns (exact L/2, interval,
 * flank reaches, contact offset, otherCuspHeight), the paper's procedures and the others as on a
 * plane (as the cylinder rows give them: they ignore the curvature); a gouging point's message in
 * `error`.
 */
function doublyCurvedRow(
  pass: RawToolInput,
  rf: string,
  rc: string,
  fields: readonly string[],
  layout: Layout,
  echo: string,
): string {
  const { index } = layout;
  const ra = layout.target === RA_COLUMN;
  const quantity = ra ? 'ra' : 'h';
  const raw = {
    R: pass.R,
    Rcr: pass.Rcr,
    rho: pass.rho,
    tilt: pass.tilt,
    pattern: pass.pattern,
    feedRadius: rf,
    crossRadius: rc,
  };
  const v = validateDoublyCurved(raw, quantity, fields[index[ra ? RA_COLUMN : H_COLUMN] as number]);
  if (!v.ok) return errorRow(echo, layout, v.errors.map((e) => e.message).join(' '));
  const p = v.value;
  const h = ra ? doublyCurvedHeightForRaMm(p, p.pattern, p, p.valueMm) : p.valueMm;
  const e = doublyCurvedForward({ ...p, scallopHeightMm: h });
  const plane = forwardInput(p, p.pattern, h);
  const half = (key: ApproximationKey) => {
    const r = APPROXIMATIONS[key].halfInterval(plane);
    return r.ok ? csvNumber(r.halfIntervalMm) : '';
  };
  const other = e.otherCuspHeightMm === null ? '' : csvNumber(e.otherCuspHeightMm);
  return (
    `${echo},${ra ? `${csvNumber(h)},` : ''}${csvNumber(e.intervalMm / 2)},${half('sekine')},${half('redonnet')},${half('bedi')},` +
    `${csvNumber(e.intervalMm)},${csvNumber(e.halfWidthRightMm)},${csvNumber(e.halfWidthLeftMm)},` +
    `${csvNumber(e.contactOffsetMm)},${other},${half('osculating')},${half('cornerBall')},,\n`
  );
}

/** The output row of a valid-shaped three-axis record: interval, Lxy, dz, lead, tilt, note, error. */
function threeAxisRow(fields: readonly string[], layout: Layout, echo: string): string {
  const { index } = layout;
  const at = (column: InputColumn) => optionalField(fields, index[column]);
  const raw = Object.fromEntries(
    (['R', 'Rcr', 'slope', 'passes', 'rasterAngle', 'feedRadius', 'crossRadius', 'rho', 'tilt'] as const).map((id) => [
      id,
      at(csvColumnOf(id)),
    ]),
  );
  const v = validateThreeAxis(raw, 'h', at(H_COLUMN));
  if (!v.ok) return errorRow(echo, layout, v.errors.map((e) => e.message).join(' '));
  const r = solveThreeAxis(v.value);
  if (!r.ok) return errorRow(echo, layout, r.errors.map((e) => e.message).join(' '));
  const a = r.value;
  const note = a.noScallop ? 'no scallop: a flat end on a flat floor, L = 2R for any h' : '';
  const stepDown = a.stepDownMm === null ? '' : csvNumber(a.stepDownMm);
  return `${echo},${csvNumber(a.intervalMm)},${csvNumber(a.horizontalStepMm)},${stepDown},${csvNumber(a.leadDeg)},${csvNumber(a.tiltDeg)},${csvText(note)},\n`;
}

/** Stderr and stdout of a batch run. */
export interface BatchIo {
  readonly stdin: Readable;
  readonly stderr: { write(text: string): unknown };
}

/**
 * Streams the batch from stdin to `out`; resolves to the exit code: 0 (rows written, bad rows
 * included), 1 (stdin unreadable), 2 (no header or a wrong one). Stops reading when `out` fails.
 */
export async function runBatch(io: BatchIo, out: Output): Promise<number> {
  const reader = new CsvReader();
  const decoder = new StringDecoder('utf8');
  let layout: Layout | null = null;
  let headerError: string | null = null;
  const take = (records: readonly CsvRecord[]): void => {
    for (const record of records) {
      if (record.blank || headerError !== null) continue;
      if (layout === null) {
        const header = parseHeader(record);
        if (header.ok) {
          layout = header.layout;
          out.write(outputHeader(layout));
        } else headerError = header.error;
        continue;
      }
      out.write(batchRow(record, layout));
    }
  };
  try {
    for await (const chunk of io.stdin) {
      take(reader.push(typeof chunk === 'string' ? chunk : decoder.write(chunk as Buffer)));
      if (headerError !== null) break;
      if (out.pending >= FLUSH_CHARS) await out.flush();
      if (out.error !== null) break;
    }
    if (headerError === null && out.error === null) take([...reader.push(decoder.end()), ...reader.end()]);
  } catch (e) {
    await out.flush();
    io.stderr.write(errorLine(`cannot read standard input: ${describeSystemError(e)}`));
    return 1;
  }
  if (headerError !== null) {
    io.stderr.write(errorLine(headerError));
    return 2;
  }
  if (layout === null) {
    io.stderr.write(
      errorLine(
        `no CSV on stdin: expected a header line ${[...REQUIRED_COLUMNS, H_COLUMN].join(',')} (or ${RA_COLUMN}; optionally ${OPTIONAL_COLUMNS.join(', ')})`,
      ),
    );
    return 2;
  }
  await out.flush();
  return 0;
}
