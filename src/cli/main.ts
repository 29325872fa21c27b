/**
 * Command line: quick lookup, JSON for scripts, the inverse, and CSV batch lookup tables.
 * All lengths in mm and angles in degrees, as at the solver core's public edge.
 */
import { createInterface } from 'node:readline';
import type { Readable, Writable } from 'node:stream';
import {
  compareForward,
  compareInverse,
  describeInputError,
  type ForwardComparison,
  type ForwardEstimate,
  type InputError,
  type InverseComparison,
  type InverseEstimate,
  type ToolInput,
  validateForward,
  validateInverse,
} from '../core/index';

export interface Io {
  readonly stdin: Readable;
  readonly stdout: Writable;
  readonly stderr: Writable;
}

const USAGE = `Usage: path-interval --R <mm> --Rcr <mm> --rho <deg> --h <mm> [--json]
       path-interval --inverse --R <mm> --Rcr <mm> --rho <deg> --half-interval <mm> [--json]
       path-interval --batch < cases.csv > table.csv

Path interval (step-over) of a filleted end mill inclined by rho along the feed, for a
scallop height h: the exact 3D solution and the approximations of Sekine et al.,
Redonnet et al. and Bedi et al. (Sekine & Kameya 2022).

  --R              tool radius, mm (> 0)
  --Rcr            corner radius, mm (0 <= Rcr <= R)
  --rho            lead angle along the feed, degrees (0 <= rho < 90)
  --h              scallop height, mm (0 < h < (R - Rcr) sin(rho) + Rcr)
  --inverse        compute the scallop height left at --half-interval (L/2, mm; 0 < L/2 < R)
  --json           print one JSON object instead of a table
  --batch          read CSV (header R,Rcr,rho,h) on stdin, write CSV of L/2 values
  --help           show this text

Exit codes: 0 success, 2 invalid input or usage.`;

const VALUE_OPTIONS = new Set(['R', 'Rcr', 'rho', 'h', 'half-interval']);
const FLAG_OPTIONS = new Set(['json', 'inverse', 'batch', 'help']);

type Parsed = { values: Record<string, string>; flags: Set<string> } | { error: string };

/** `--name value` or `--name=value`; a value is taken as is, so `--rho -5` reaches validation. */
function parseArgs(args: readonly string[]): Parsed {
  const values: Record<string, string> = {};
  const flags = new Set<string>();
  for (let i = 0; i < args.length; i++) {
    const arg = args[i] as string;
    if (!arg.startsWith('--')) return { error: `unexpected argument "${arg}"` };
    const eq = arg.indexOf('=');
    const name = eq === -1 ? arg.slice(2) : arg.slice(2, eq);
    if (FLAG_OPTIONS.has(name)) {
      if (eq !== -1) return { error: `--${name} takes no value` };
      flags.add(name);
    } else if (VALUE_OPTIONS.has(name)) {
      if (eq !== -1) values[name] = arg.slice(eq + 1);
      else {
        const next = args[i + 1];
        if (next === undefined) return { error: `--${name} needs a value` };
        values[name] = next;
        i++;
      }
    } else return { error: `unknown option --${name}` };
  }
  return { values, flags };
}

const NAMES = {
  sekine: 'Sekine et al. (Eqs. 4-8)',
  redonnet: 'Redonnet et al. (Eqs. 9, 8)',
  bedi: 'Bedi et al. (Eqs. 10-11)',
};
const PROCEDURES = ['sekine', 'redonnet', 'bedi'] as const;

function fixed(value: number, digits: number): string {
  return value.toFixed(digits);
}

function signed(value: number, digits: number): string {
  const text = value.toFixed(digits);
  return value >= 0 && !text.startsWith('-') ? `+${text}` : text;
}

function pad(text: string, width: number, left = false): string {
  return left ? text.padEnd(width) : text.padStart(width);
}

function forwardTable(c: ForwardComparison): string {
  const { input } = c;
  const exact = c.exact.halfIntervalMm;
  const lines = [
    `Filleted end mill R = ${input.toolRadiusMm} mm, Rcr = ${input.cornerRadiusMm} mm, rho = ${input.leadAngleDeg} deg, scallop h = ${input.scallopHeightMm} mm`,
    '',
    `${pad('procedure', 30, true)}${pad('L/2 [mm]', 12)}${pad('L [mm]', 12)}${pad('dev [mm]', 12)}${pad('dev [%]', 10)}`,
    `${pad('exact (3D geometry)', 30, true)}${pad(fixed(exact, 6), 12)}${pad(fixed(2 * exact, 6), 12)}${pad('-', 12)}${pad('-', 10)}`,
  ];
  const notes: string[] = [];
  for (const p of PROCEDURES) {
    const r = c.approximations[p];
    if (r.ok) {
      const dev = r.halfIntervalMm - exact;
      lines.push(
        `${pad(NAMES[p], 30, true)}${pad(fixed(r.halfIntervalMm, 6), 12)}${pad(fixed(r.intervalMm, 6), 12)}${pad(signed(dev, 6), 12)}${pad(signed((100 * dev) / exact, 2), 10)}`,
      );
    } else {
      lines.push(`${pad(NAMES[p], 30, true)}${pad('n/a', 12)}${pad('n/a', 12)}${pad('-', 12)}${pad('-', 10)}`);
      notes.push(`  n/a: ${r.notApplicable}`);
    }
  }
  return [...lines, ...(notes.length ? ['', ...notes] : [])].join('\n');
}

function inverseTable(c: InverseComparison): string {
  const { input } = c;
  const exact = c.exact.cuspHeightMm;
  const lines = [
    `Filleted end mill R = ${input.toolRadiusMm} mm, Rcr = ${input.cornerRadiusMm} mm, rho = ${input.leadAngleDeg} deg, L/2 = ${input.intervalMm / 2} mm (L = ${input.intervalMm} mm)`,
    '',
    `${pad('procedure', 30, true)}${pad('h [mm]', 12)}${pad('dev [mm]', 12)}${pad('dev [%]', 10)}`,
    `${pad('exact (3D geometry)', 30, true)}${pad(fixed(exact, 6), 12)}${pad('-', 12)}${pad('-', 10)}`,
  ];
  const eqs = { sekine: 'Sekine et al. (Eq. 12)', redonnet: 'Redonnet et al. (Eq. 12)', bedi: 'Bedi et al. (Eq. 13)' };
  const notes: string[] = [];
  for (const p of PROCEDURES) {
    const r = c.approximations[p];
    if (r.ok) {
      const dev = r.scallopHeightMm - exact;
      const pct = exact > 0 ? pad(signed((100 * dev) / exact, 2), 10) : pad('-', 10);
      lines.push(`${pad(eqs[p], 30, true)}${pad(fixed(r.scallopHeightMm, 6), 12)}${pad(signed(dev, 6), 12)}${pct}`);
    } else {
      lines.push(`${pad(eqs[p], 30, true)}${pad('n/a', 12)}${pad('-', 12)}${pad('-', 10)}`);
      notes.push(`  n/a: ${r.notApplicable}`);
    }
  }
  return [...lines, ...(notes.length ? ['', ...notes] : [])].join('\n');
}

type JsonValue = number | string | boolean | null | JsonValue[] | { [key: string]: JsonValue };

function halfJson(r: ForwardEstimate<unknown>, exact: number): JsonValue {
  if (!r.ok) return { notApplicable: r.notApplicable };
  const dev = r.halfIntervalMm - exact;
  return {
    halfInterval: r.halfIntervalMm,
    interval: r.intervalMm,
    deviation: dev,
    deviationPercent: (100 * dev) / exact,
  };
}

function heightJson(r: InverseEstimate, exact: number): JsonValue {
  if (!r.ok) return { notApplicable: r.notApplicable };
  const dev = r.scallopHeightMm - exact;
  return { scallopHeight: r.scallopHeightMm, deviation: dev, deviationPercent: exact > 0 ? (100 * dev) / exact : null };
}

function toolJson(t: ToolInput): { R: number; Rcr: number; rho: number } {
  return { R: t.toolRadiusMm, Rcr: t.cornerRadiusMm, rho: t.leadAngleDeg };
}

/** The forward comparison as the documented JSON object (lengths mm, angle degrees). */
export function forwardJson(c: ForwardComparison): JsonValue {
  const exact = c.exact.halfIntervalMm;
  return {
    unit: 'mm',
    input: { ...toolJson(c.input), h: c.input.scallopHeightMm },
    exact: { halfInterval: exact, interval: 2 * exact },
    sekine: halfJson(c.approximations.sekine, exact),
    redonnet: halfJson(c.approximations.redonnet, exact),
    bedi: halfJson(c.approximations.bedi, exact),
  };
}

function inverseJson(c: InverseComparison): JsonValue {
  const exact = c.exact.cuspHeightMm;
  return {
    unit: 'mm',
    input: { ...toolJson(c.input), halfInterval: c.input.intervalMm / 2 },
    exact: { scallopHeight: exact },
    sekine: heightJson(c.approximations.sekine, exact),
    redonnet: heightJson(c.approximations.redonnet, exact),
    bedi: heightJson(c.approximations.bedi, exact),
  };
}

function reportErrors(io: Io, errors: readonly InputError[], json: boolean, intervalAsHalf = false): number {
  for (const e of errors) io.stderr.write(`error: ${describeInputError(e, 'mm', { intervalAsHalf })}\n`);
  if (json) io.stdout.write(`${JSON.stringify({ errors })}\n`);
  return 2;
}

/** Splits one CSV line (no embedded newlines); quoted cells may hold commas and "" escapes. */
export function splitCsvLine(line: string): string[] {
  const cells: string[] = [];
  let cell = '';
  let quoted = false;
  for (let i = 0; i < line.length; i++) {
    const ch = line[i];
    if (quoted) {
      if (ch === '"' && line[i + 1] === '"') {
        cell += '"';
        i++;
      } else if (ch === '"') quoted = false;
      else cell += ch;
    } else if (ch === '"') quoted = true;
    else if (ch === ',') {
      cells.push(cell);
      cell = '';
    } else cell += ch;
  }
  cells.push(cell);
  return cells.map((c) => c.trim());
}

function csvCell(text: string): string {
  return /[",\n\r]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

function csvNumber(r: { readonly ok: boolean; readonly halfIntervalMm?: number }): string {
  return r.ok && r.halfIntervalMm !== undefined ? r.halfIntervalMm.toFixed(9) : '';
}

const BATCH_COLUMNS = ['R', 'Rcr', 'rho', 'h'] as const;

/** Streams CSV rows from stdin to stdout; a bad row gets its message in `error` and the run goes on. */
async function batch(io: Io): Promise<number> {
  const lines = createInterface({ input: io.stdin, crlfDelay: Number.POSITIVE_INFINITY });
  let order: number[] | null = null;
  let buffer: string[] = [];
  const flush = async () => {
    if (buffer.length === 0) return;
    const ok = io.stdout.write(buffer.join(''));
    buffer = [];
    if (!ok) await new Promise<void>((resolve) => io.stdout.once('drain', () => resolve()));
  };
  for await (const raw of lines) {
    const line = raw.replace(/^\uFEFF/, '');
    if (line.trim() === '') continue;
    const cells = splitCsvLine(line);
    if (order === null) {
      const header = cells.map((c) => c.trim());
      const idx = BATCH_COLUMNS.map((name) => header.indexOf(name));
      if (idx.some((i) => i < 0) || header.length !== BATCH_COLUMNS.length) {
        io.stderr.write(`error: the CSV header must be R,Rcr,rho,h (got "${line.slice(0, 60)}")\n`);
        return 2;
      }
      order = idx;
      buffer.push('R,Rcr,rho,h,exact,sekine,redonnet,bedi,error\n');
      continue;
    }
    const values = order.map((i) => cells[i] ?? '');
    const echo = values.map(csvCell).join(',');
    if (cells.length !== BATCH_COLUMNS.length) {
      buffer.push(`${echo},,,,,${csvCell(`expected 4 values (R,Rcr,rho,h), got ${cells.length}`)}\n`);
    } else {
      const [R, Rcr, rho, h] = values;
      const v = validateForward({ R, Rcr, rho, h });
      if (v.ok) {
        const c = compareForward(v.value);
        buffer.push(
          `${echo},${c.exact.halfIntervalMm.toFixed(9)},${csvNumber(c.approximations.sekine)},${csvNumber(c.approximations.redonnet)},${csvNumber(c.approximations.bedi)},\n`,
        );
      } else {
        buffer.push(`${echo},,,,,${csvCell(v.errors.map((e) => e.message).join(' '))}\n`);
      }
    }
    if (buffer.length >= 2048) await flush();
  }
  if (order === null) {
    io.stderr.write('error: no CSV on stdin: expected a header line R,Rcr,rho,h\n');
    return 2;
  }
  await flush();
  return 0;
}

/** Runs the command line; resolves to the exit code. */
export async function main(args: readonly string[], io: Io): Promise<number> {
  const parsed = parseArgs(args);
  if ('error' in parsed) {
    io.stderr.write(`error: ${parsed.error}\n\n${USAGE}\n`);
    return 2;
  }
  const { values, flags } = parsed;
  if (flags.has('help')) {
    io.stdout.write(`${USAGE}\n`);
    return 0;
  }
  if (flags.has('batch')) {
    if (Object.keys(values).length > 0 || flags.has('inverse')) {
      io.stderr.write('error: --batch reads every case from stdin and takes no other option\n');
      return 2;
    }
    return batch(io);
  }
  const json = flags.has('json');
  if (flags.has('inverse')) {
    if (values.h !== undefined) {
      io.stderr.write('error: --inverse computes h: give --half-interval instead of --h\n');
      return 2;
    }
    const half = values['half-interval'];
    const interval =
      half !== undefined && /^\s*[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\s*$/.test(half) ? 2 * Number(half) : half;
    const v = validateInverse({ R: values.R, Rcr: values.Rcr, rho: values.rho, interval });
    if (!v.ok) return reportErrors(io, v.errors, json, true);
    const c = compareInverse(v.value);
    io.stdout.write(json ? `${JSON.stringify(inverseJson(c))}\n` : `${inverseTable(c)}\n`);
    return 0;
  }
  if (values['half-interval'] !== undefined) {
    io.stderr.write('error: --half-interval goes with --inverse\n');
    return 2;
  }
  const v = validateForward({ R: values.R, Rcr: values.Rcr, rho: values.rho, h: values.h });
  if (!v.ok) return reportErrors(io, v.errors, json);
  const c = compareForward(v.value);
  io.stdout.write(json ? `${JSON.stringify(forwardJson(c))}\n` : `${forwardTable(c)}\n`);
  return 0;
}
