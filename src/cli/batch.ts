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

import { fstatSync } from 'node:fs';
import type { Readable } from 'node:stream';
import { StringDecoder } from 'node:string_decoder';
import { APPROXIMATIONS, type ApproximationKey, type ExactInverse, forwardInput } from '../core/index';
import { FIELDS, fieldOfCsvColumn } from '../core/input/fields';
import { fromMm, type LengthUnit } from '../core/input/units';
import { csvNumber, emptyCellNotes, type LengthText, RESULT_COLUMNS, resultFields } from '../core/output/csvWrite';
import type { DoublyCurvedProblem } from '../core/roughness/doublyCurvedValidate';
import { curvedForward, curvedInverse, curvedPointOf } from '../core/surfaces/doublyCurvedPoint';
import { exactForward, exactInverse } from '../core/surfaces/solve';
import type { ValueOption } from './args';
import {
  emptyResults,
  HEADER_RULE,
  type InputColumn,
  isLengthColumn,
  L_COLUMN,
  type Layout,
  outputHeader,
  parseHeader,
  RA_COLUMN,
  REQUIRED_COLUMNS,
} from './batchHeader';
import { CsvReader, type CsvRecord, csvText, isNumberText } from './csv';
import { finishCells } from './finish';
import { lengthText } from './lengthInput';
import { describeSystemError, errorLine, escapeControls, FLUSH_CHARS, type Output } from './output';
import {
  type Answer,
  answer,
  answerThreeAxis,
  type Question,
  type QuestionValues,
  SURFACE_TWICE,
  threeAxisMessage,
  wordErrors,
} from './question';

/** The header's columns, rule and layout (batchHeader.ts), re-exported for the callers. */
export {
  HEADER_RULE,
  type Layout,
  outputHeader,
  parseHeader,
  RADIUS_COLUMNS,
  REQUIRED_COLUMNS,
  resultColumns,
  TARGET_COLUMNS,
  THREE_AXIS_RESULT_COLUMNS,
} from './batchHeader';

/** The result columns and their writers live in the shared CSV writer (core/csvWrite.ts). */
export { csvNumber, RESULT_COLUMNS, resultFields };

/** Spaces and tabs around a field are dropped in the echo; a line break is kept (and quoted). */
function trimSpaces(text: string): string {
  return text.replace(/^[ \t]+|[ \t]+$/g, '');
}

/**
 * True for a field the echo writes as it is: printable ASCII without a comma or a quote, not
 * starting with a space, a tab or a character a spreadsheet may read as a formula (`=+-@`), not
 * ending with a space or a tab. trimSpaces, escapeControls and csvText leave such a field alone,
 * so it needs none of them (the plain numbers of most records).
 */
function echoedAsIs(text: string): boolean {
  const n = text.length;
  if (n === 0) return true;
  const first = text.charCodeAt(0);
  if (first === 61 /* = */ || first === 43 /* + */ || first === 45 /* - */ || first === 64 /* @ */) return false;
  if (first === 32 || text.charCodeAt(n - 1) === 32) return false;
  for (let i = 0; i < n; i++) {
    const c = text.charCodeAt(i);
    if (c < 33 || c > 126 || c === 34 /* " */ || c === 44 /* , */) return false;
  }
  return true;
}

/** A field as the echo writes it: spaces around dropped, control characters escaped, quoted for CSV. */
function echoText(text: string): string {
  return echoedAsIs(text) ? text : csvText(escapeControls(trimSpaces(text)));
}

/** A row with no results: its message in `error`, on one line (control characters escaped, as on stderr). */
function errorRow(echo: string, layout: Layout, message: string): string {
  return `${echo}${emptyResults(layout)},${csvText(escapeControls(message))}\n`;
}

/** How a layout's input columns become a question: each column's option, whether it is required, its unit. */
interface ColumnPlan {
  readonly index: number;
  readonly option: ValueOption;
  /** An empty field of a column not required takes its default, as a missing column does. */
  readonly required: boolean;
  /** The unit of a length column (its own or the run's); null for a column that is no length. */
  readonly unit: LengthUnit | null;
}

/** The plan of each input column of `layout`, in the layout's index order (the fields' order of a question). */
function columnPlans(layout: Layout): readonly ColumnPlan[] {
  const plans: ColumnPlan[] = [];
  for (const [column, i] of Object.entries(layout.index) as [InputColumn, number][]) {
    const field = fieldOfCsvColumn(column);
    const option = field === null ? null : FIELDS[field].cli;
    if (option === null || field === null) continue;
    const required = column === layout.target || (REQUIRED_COLUMNS as readonly string[]).includes(column);
    const unit = isLengthColumn(column) ? (layout.columnUnits[column] ?? layout.unit) : null;
    plans.push({ index: i, option: option as ValueOption, required, unit });
  }
  return plans;
}

/** The plans of the last layout asked (a run has one layout: they are made once). */
let planned: { readonly layout: Layout; readonly plans: readonly ColumnPlan[] } | null = null;

function plansOf(layout: Layout): readonly ColumnPlan[] {
  if (planned === null || planned.layout !== layout) planned = { layout, plans: columnPlans(layout) };
  return planned.plans;
}

/** A length field's text in mm: a plain decimal in mm is handed on as typed (lengthText's rule, without parsing). */
function lengthField(text: string, unit: LengthUnit): string {
  return unit === 'mm' && isNumberText(text) ? text : lengthText(text, unit);
}

/**
 * The question of a record: each input column's field by its option (question.ts), lengths in mm;
 * with `asTyped`, each field as typed (before its unit was read: for the messages of a refused row).
 */
function recordValues(fields: readonly string[], layout: Layout, asTyped = false): QuestionValues {
  const values: Partial<Record<ValueOption, string>> = {};
  const plans = plansOf(layout);
  for (let j = 0; j < plans.length; j++) {
    const plan = plans[j] as ColumnPlan;
    const text = fields[plan.index] as string;
    if (!plan.required && text.trim() === '') continue;
    values[plan.option] = asTyped || plan.unit === null ? text : lengthField(text, plan.unit);
  }
  return values;
}

/** Length results (mm text, or empty) in the run's unit, each converted once from its double. */
function inUnit(texts: readonly string[], unit: LengthUnit): string {
  return texts.map((t) => (t === '' || unit === 'mm' ? t : csvNumber(fromMm(Number(t), unit)))).join(',');
}

/** The output row of one record (with its line break). */
export function batchRow(record: CsvRecord, layout: Layout): string {
  const fields = record.fields;
  let echo = '';
  for (let j = 0; j < layout.echoed.length; j++) {
    const c = layout.echoed[j] as { readonly index: number };
    echo += `${j === 0 ? '' : ','}${echoText(fields[c.index] ?? '')}`;
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
  const values = recordValues(fields, layout);
  if (layout.threeAxis) return threeAxisRow(values, fields, layout, echo);
  const quantity = layout.target === RA_COLUMN ? 'ra' : layout.target === L_COLUMN ? 'interval' : 'h';
  const q: Question = { values, quantity, half: false };
  const a = answer(q);
  if (a === null) return errorRow(echo, layout, SURFACE_TWICE);
  if (!a.ok) {
    const words = wordErrors(a, q, layout.unit, recordValues(fields, layout, true)).map((w) => w.message);
    return errorRow(echo, layout, words.join(' '));
  }
  // The finish's cells (none without finish columns; empty without teeth), or the row's error.
  let teeth = '';
  /** The error column of a row whose finish is answered but for its areal parameters (finish.ts finishCells). */
  let teethNote = '';
  if (layout.finish) {
    const cells =
      a.kind === 'pass-forward' || a.kind === 'pass-inverse'
        ? finishCells(
            values,
            a.input,
            a.input.pattern,
            passInterval(a),
            a.input.surface.kind,
            layout.unit,
            recordValues(fields, layout, true),
          )
        : finishCells(values, null, 'one-way', 0, 'doublyCurved', layout.unit);
    if (!cells.ok) return errorRow(echo, layout, cells.message);
    teeth = cells.text;
    teethNote = csvText(escapeControls(cells.note));
  }
  if (a.kind === 'pass-inverse')
    return `${echo},${inverseResults(exactInverse(a.input), layout.unit)},${teeth},${teethNote}\n`;
  if (a.kind === 'doubly-inverse') {
    const e = curvedInverse(curvedPointOf(a.problem), a.problem.valueMm);
    return `${echo},${inverseResults(e, layout.unit)},${teeth},${teethNote}\n`;
  }
  const hMm = a.kind === 'pass-forward' ? a.input.scallopHeightMm : a.scallopHeightMm;
  const length = lengthWriter(layout.unit);
  const h = a.targetRaMm === undefined ? '' : `${length(hMm)},`;
  if (a.kind === 'doubly-forward') {
    const notes = emptyCellNotes(forwardInput(a.problem, a.problem.pattern, a.scallopHeightMm)).join(' ');
    return `${echo},${h}${doublyCurvedResults(a.problem, a.scallopHeightMm, layout.unit)},${csvText(notes)}${teeth},${teethNote}\n`;
  }
  return `${echo},${h}${resultFields(a.input, length)}${teeth},${teethNote}\n`;
}

/** The step-over of a plane or cylinder row: the exact one for h (or Ra), the given one for L. */
function passInterval(a: Extract<Answer, { kind: 'pass-forward' | 'pass-inverse' }>): number {
  return a.kind === 'pass-inverse' ? a.input.intervalMm : exactForward(a.input).intervalMm;
}

/** A length result's text in the run's unit (from its double, as csvNumber writes it). */
function inchText(lengthMm: number): string {
  return csvNumber(fromMm(lengthMm, 'in'));
}

/** The writer of length results in `unit`. */
function lengthWriter(unit: LengthUnit): LengthText {
  return unit === 'mm' ? csvNumber : inchText;
}

/** The inverse answer's lengths in the order of INVERSE_RESULT_COLUMNS before `note`. */
const INVERSE_LENGTHS = [
  'cuspHeightMm',
  'rightCuspHeightMm',
  'leftCuspHeightMm',
  'otherCuspHeightMm',
  'halfWidthRightMm',
  'halfWidthLeftMm',
  'contactOffsetMm',
] as const satisfies readonly (keyof ExactInverse)[];

/** The results of a row given the step-over (INVERSE_RESULT_COLUMNS before `note`), in the run's unit. */
function inverseResults(e: ExactInverse, unit: LengthUnit): string {
  return inUnit(
    INVERSE_LENGTHS.map((k) => {
      const x = e[k];
      return x === null ? '' : csvNumber(x);
    }),
    unit,
  );
}

/**
 * The results of a doubly curved point: the exact answer in the result columns (exact L/2, interval,
 * flank reaches, contact offset, otherCuspHeight), the paper's procedures and the others as on a
 * plane (as the cylinder rows give them: they ignore the curvature).
 */
function doublyCurvedResults(p: DoublyCurvedProblem, h: number, unit: LengthUnit): string {
  const e = curvedForward(curvedPointOf(p), h);
  const plane = forwardInput(p, p.pattern, h);
  const half = (key: ApproximationKey) => {
    const r = APPROXIMATIONS[key].halfInterval(plane);
    return r.ok ? csvNumber(r.halfIntervalMm) : '';
  };
  const other = e.otherCuspHeightMm === null ? '' : csvNumber(e.otherCuspHeightMm);
  const numbers = [
    csvNumber(e.intervalMm / 2),
    half('sekine'),
    half('redonnet'),
    half('bedi'),
    csvNumber(e.intervalMm),
    csvNumber(e.halfWidthRightMm),
    csvNumber(e.halfWidthLeftMm),
    csvNumber(e.contactOffsetMm),
    other,
    half('osculating'),
    half('cornerBall'),
  ];
  return inUnit(numbers, unit);
}

/** The output row of a valid-shaped three-axis record: interval, Lxy, dz, lead, tilt, note, error. */
function threeAxisRow(values: QuestionValues, fields: readonly string[], layout: Layout, echo: string): string {
  const r = answerThreeAxis(values, 'h');
  if (!r.ok) {
    const typed = recordValues(fields, layout, true);
    const words = r.errors.map((e) => threeAxisMessage(e, r.passes, layout.unit, typed));
    return errorRow(echo, layout, words.join(' '));
  }
  const a = r.answer;
  let teeth = '';
  /** The error column of a row whose finish is answered but for its areal parameters (finish.ts finishCells). */
  let teethNote = '';
  if (layout.finish) {
    // The sloped plane is a plane in the posture the slope gives; every pass fed the same way.
    const c = r.problem.case;
    const tool = {
      toolRadiusMm: c.toolRadiusMm,
      cornerRadiusMm: c.cornerRadiusMm,
      leadAngleDeg: a.leadDeg,
      tiltAngleDeg: a.tiltDeg,
    };
    const kind = r.problem.surface === 'plane' ? 'slopedPlane' : 'waterlineRevolution';
    const cells = finishCells(
      values,
      tool,
      'one-way',
      a.intervalMm,
      kind,
      layout.unit,
      recordValues(fields, layout, true),
    );
    if (!cells.ok) return errorRow(echo, layout, cells.message);
    teeth = cells.text;
    teethNote = csvText(escapeControls(cells.note));
  }
  const note = a.noScallop ? 'no scallop: a flat end on a flat floor, L = 2R for any h' : '';
  const stepDown = a.stepDownMm === null ? '' : csvNumber(a.stepDownMm);
  const lengths = inUnit([csvNumber(a.intervalMm), csvNumber(a.horizontalStepMm), stepDown], layout.unit);
  return `${echo},${lengths},${csvNumber(a.leadDeg)},${csvNumber(a.tiltDeg)},${csvText(note)}${teeth},${teethNote}\n`;
}

/**
 * Standard input that is a directory (`--batch < /tmp`) reads as empty on some systems: a read
 * error (EISDIR), not an empty CSV.
 */
function refuseDirectory(stdin: Readable): void {
  const fd = (stdin as Readable & { fd?: unknown }).fd;
  if (typeof fd === 'number' && fstatSync(fd).isDirectory()) {
    throw Object.assign(new Error('standard input is a directory'), { code: 'EISDIR' });
  }
}

/** Characters of stdin handed to the CSV reader at a time (see runBatch). */
const READ_PIECE_CHARS = 4096;

/** Stderr and stdout of a batch run. */
export interface BatchIo {
  readonly stdin: Readable;
  readonly stderr: { write(text: string): unknown };
}

/**
 * Streams the batch from stdin to `out`; resolves to the exit code: 0 (rows written, bad rows
 * included), 1 (stdin unreadable), 2 (no header or a wrong one). Stops reading when `out` fails.
 */
export async function runBatch(io: BatchIo, out: Output, unit: LengthUnit = 'mm'): Promise<number> {
  const reader = new CsvReader();
  const decoder = new StringDecoder('utf8');
  let layout: Layout | null = null;
  let headerError: string | null = null;
  const take = (records: readonly CsvRecord[]): void => {
    for (const record of records) {
      if (record.blank || headerError !== null) continue;
      if (layout === null) {
        const header = parseHeader(record, unit);
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
    refuseDirectory(io.stdin);
    for await (const chunk of io.stdin) {
      const text = typeof chunk === 'string' ? chunk : decoder.write(chunk as Buffer);
      // Read and written in small pieces: few records and rows are alive at a time (a pipe's
      // 64 kB hold about 3,000 records), so they die young, where garbage is cheap.
      for (let at = 0; at < text.length && headerError === null && out.error === null; at += READ_PIECE_CHARS) {
        take(reader.push(text.slice(at, at + READ_PIECE_CHARS)));
        if (out.pending >= FLUSH_CHARS) await out.flush();
      }
      if (headerError !== null || out.error !== null) break;
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
    io.stderr.write(errorLine(`no CSV on stdin: ${HEADER_RULE}`));
    return 2;
  }
  await out.flush();
  return 0;
}
