/**
 * Command line: quick lookup, JSON for scripts, the inverse, and CSV batch lookup tables.
 * All lengths in mm and angles in degrees, as at the solver core's public edge.
 */
import type { Readable, Writable } from 'node:stream';
import {
  compareForward,
  compareInverse,
  type DescribeOptions,
  describeInputError,
  type FieldName,
  type InputError,
  validateForward,
  validateInverse,
} from '../core/index';
import { parseArgs, type Request, type ValueOption } from './args';
import { runBatch } from './batch';
import { isNumberText } from './csv';
import { describeSystemError, isClosedPipe, Output } from './output';
import { forwardJson, forwardTable, inverseJson, inverseTable } from './report';

export interface Io {
  readonly stdin: Readable;
  readonly stdout: Writable;
  readonly stderr: Writable;
}

export const USAGE = `Usage: path-interval --R <mm> --Rcr <mm> --rho <deg> [--tilt <deg>] [--pattern one-way|zigzag] --h <mm> [--json]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [--tilt <deg>] [--pattern ...] --interval <mm> [--json]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [--tilt <deg>] [--pattern ...] --half-interval <mm> [--json]
       path-interval --batch < cases.csv > table.csv

Step-over (path interval L, between adjacent cutter-contact paths) of a filleted (bull-nose)
end mill for a scallop height h, exact for any tool posture, beside the approximations of
Sekine et al., Redonnet et al. and Bedi et al. (Sekine & Kameya 2022; lead-only models), the
osculating circle at the contact and the ball of the corner radius.

  --R <mm>              tool radius (0.001 to 1000)
  --Rcr <mm>            corner radius (0 <= Rcr <= R; Rcr = R is a ball end)
  --rho <deg>           lead angle, along the feed (0 <= rho < 90)
  --tilt <deg>          tilt angle, across the feed; + leans the shank to +Y (-90 < tilt < 90; default 0)
  --pattern <p>         one-way (default) or zigzag (posture mirrored on every other pass)
  --h <mm>              scallop height (from 1e-9 up to the flank and shank limits)
  --interval <mm>       inverse: the scallop height left at step-over L
  --half-interval <mm>  inverse, the step-over given as L/2
  --inverse             optional with --interval or --half-interval (kept for old scripts)
  --json                print one JSON object instead of a table
  --batch               read CSV on stdin (header R,Rcr,rho,h; optional tilt, pattern; any
                        order), write CSV: the input columns, then
                        exact,sekine,redonnet,bedi (L/2 of each), interval,halfWidthRight,
                        halfWidthLeft,contactOffset,otherCuspHeight (exact), osculating,
                        cornerBall (L/2), note, error; full precision; blank lines skipped
  -h, --help            show this text

Table: 7 significant digits. JSON and CSV: every digit of the double.
Exit codes: 0 success (a batch with bad rows included), 1 a read or write error,
2 invalid input or usage.`;

/** The option that gives a field, for messages. */
function optionOf(field: FieldName, half: boolean): string {
  if (field === 'interval') return half ? '--half-interval' : '--interval';
  return `--${field}`;
}

function reportErrors(
  io: Io,
  out: Output,
  errors: readonly InputError[],
  json: boolean,
  half: { readonly typed: string } | null,
): number {
  const worded = errors.map((e) => {
    const asHalf = half !== null && e.field === 'interval';
    const options: DescribeOptions = asHalf ? { intervalAsHalf: true, typed: half.typed.trim() } : {};
    const message = describeInputError(e, 'mm', options);
    io.stderr.write(`error: ${optionOf(e.field, asHalf)}: ${message}\n`);
    return { ...e, message };
  });
  if (json) out.write(`${JSON.stringify({ errors: worded })}\n`);
  return 2;
}

type Values = Readonly<Partial<Record<ValueOption, string>>>;

function forward(values: Values, json: boolean, io: Io, out: Output): number {
  const v = validateForward({
    R: values.R,
    Rcr: values.Rcr,
    rho: values.rho,
    tilt: values.tilt,
    pattern: values.pattern,
    h: values.h,
  });
  if (!v.ok) return reportErrors(io, out, v.errors, json, null);
  const c = compareForward(v.value);
  out.write(json ? `${JSON.stringify(forwardJson(c))}\n` : `${forwardTable(c)}\n`);
  return 0;
}

function inverse(values: Values, json: boolean, half: boolean, io: Io, out: Output): number {
  let interval: unknown = values.interval;
  const typedHalf = values['half-interval'];
  if (half && typedHalf !== undefined) {
    // L = 2 (L/2) exactly; validation messages quote L/2 as typed.
    // An L/2 so large that 2 (L/2) overflows is beyond any tool: the largest double stands for it.
    const text = typedHalf.trim();
    const doubled = 2 * Number(text);
    if (!isNumberText(text)) interval = typedHalf;
    else interval = Number.isFinite(doubled) ? doubled : Math.sign(doubled) * Number.MAX_VALUE;
  }
  const v = validateInverse({
    R: values.R,
    Rcr: values.Rcr,
    rho: values.rho,
    tilt: values.tilt,
    pattern: values.pattern,
    interval,
  });
  if (!v.ok) return reportErrors(io, out, v.errors, json, half ? { typed: typedHalf ?? '' } : null);
  const c = compareInverse(v.value);
  out.write(json ? `${JSON.stringify(inverseJson(c))}\n` : `${inverseTable(c)}\n`);
  return 0;
}

async function run(request: Request, io: Io, out: Output): Promise<number> {
  switch (request.kind) {
    case 'help':
      out.write(`${USAGE}\n`);
      return 0;
    case 'usage':
      io.stderr.write(`error: ${request.error} (see path-interval --help)\n`);
      return 2;
    case 'batch':
      return runBatch(io, out);
    case 'forward':
      return forward(request.values, request.json, io, out);
    case 'inverse':
      return inverse(request.values, request.json, request.half, io, out);
  }
}

/**
 * Runs the command line; resolves to the exit code. Never throws for a write error: a closed
 * pipe (`| head -1`) ends quietly with the run's code, any other write error is named in one
 * line on stderr and gives 1.
 */
export async function main(args: readonly string[], io: Io): Promise<number> {
  const out = new Output(io.stdout);
  const code = await run(parseArgs(args), io, out);
  await out.flush();
  const e = out.error;
  if (e === null || isClosedPipe(e)) return code;
  io.stderr.write(`error: cannot write to standard output: ${describeSystemError(e)}\n`);
  return 1;
}
