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
import { csvColumnOf, FIELDS, PASS_FIELDS } from '../core/input/fields';
import { rawFields } from '../core/input/raw';
import { csvNumber, RESULT_COLUMNS, resultFields } from '../core/output/csvWrite';
import {
  doublyCurvedForward,
  doublyCurvedHeightForRaMm,
  validateDoublyCurved,
} from '../core/surfaces/doublyCurved/index';
import { solveThreeAxis } from '../core/threeAxis/solve';
import { validateThreeAxis } from '../core/threeAxis/validate';
import {
  emptyResults,
  H_COLUMN,
  type InputColumn,
  type Layout,
  OPTIONAL_COLUMNS,
  outputHeader,
  parseHeader,
  RA_COLUMN,
  REQUIRED_COLUMNS,
} from './batchHeader';
import { CsvReader, type CsvRecord, csvText } from './csv';
import { describeSystemError, errorLine, escapeControls, FLUSH_CHARS, type Output } from './output';

/** The header's columns, rule and layout (batchHeader.ts), re-exported for the callers. */
export {
  HEADER_RULE,
  type Layout,
  OPTIONAL_COLUMNS,
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
