/**
 * Command line: quick lookup, JSON for scripts, the inverse, and CSV batch lookup tables.
 * All lengths in mm and angles in degrees, as at the solver core's public edge.
 */
import type { Readable, Writable } from 'node:stream';
import {
  type AnyFieldName,
  type AnyInputError,
  compareForward,
  compareInverse,
  type DescribeOptions,
  describeInputError,
  exactRoughness,
  exactRoughnessAtInterval,
  type ForwardInput,
  forwardInput,
  type PassInput,
  SimulationTooLargeError,
  scallopHeightForRaMm,
  simulatePasses,
  validateForward,
  validateInverse,
  validateTargetRa,
} from '../core/index';
import { cliFlag, FIELDS, PASS_FIELDS } from '../core/input/fields';
import { rawFields } from '../core/input/raw';
import {
  solveThreeAxis,
  type ThreeAxisInputError,
  type ThreeAxisQuantity,
  validateThreeAxis,
} from '../core/threeAxis/validate';
import { parseArgs, type Request, type ValueOption } from './args';
import { runBatch } from './batch';
import { isNumberText } from './csv';
import { describeSystemError, errorLine, escapeControls, isClosedPipe, Output } from './output';
import { type Extras, forwardJson, forwardTable, inverseJson, inverseTable, type SimulationRun } from './report';
import { threeAxisJson, threeAxisTable } from './threeAxisReport';

export interface Io {
  readonly stdin: Readable;
  readonly stdout: Writable;
  readonly stderr: Writable;
}

export const USAGE = `Usage: path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --h <mm> [--json] [--simulate]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --ra <mm> [--json] [--simulate]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --interval <mm> [--json] [--simulate]
       path-interval --R <mm> --Rcr <mm> --rho <deg> [options] --half-interval <mm> [--json] [--simulate]
       path-interval --R <mm> --Rcr <mm> --slope <deg> [three-axis options] --h <mm> [--json]
       path-interval --R <mm> --Rcr <mm> --slope <deg> [three-axis options] --horizontal-step <mm> [--json]
       path-interval --R <mm> --Rcr <mm> --slope <deg> --passes waterline [...] --step-down <mm> [--json]
       path-interval --batch < cases.csv > table.csv

Step-over (path interval L, between adjacent cutter-contact paths) of a filleted (bull-nose)
end mill for a scallop height h or a roughness Ra, exact for any tool posture on a plane or a
cylinder, beside the approximations of Sekine et al., Redonnet et al. and Bedi et al. (Sekine &
Kameya 2022; lead-only models), the osculating circle at the contact and the ball of the corner
radius; with the exact roughness (Rz, Ra, Rq) of the surface the passes leave.

  --R <mm>              tool radius (0.001 to 1000)
  --Rcr <mm>            corner radius (0 <= Rcr <= R; Rcr = R is a ball end)
  --rho <deg>           lead angle, along the feed (0 <= rho < 90)
  --tilt <deg>          tilt angle, across the feed; + leans the shank to +Y (-90 < tilt < 90; default 0)
  --pattern <p>         one-way (default) or zigzag (posture mirrored on every other pass)
  --surface-radius <mm> a cylinder: signed radius, > 0 convex, < 0 concave (0.001 <= |Rs| <= 1e6);
                        omitted: a plane. Scallop heights are measured radially, L along the surface
  --surface-axis <a>    feed (default: passes run along the cylinder) or cross (passes go around it)
  --h <mm>              scallop height (from 1e-9 up to the flank and shank limits)
  --ra <mm>             instead of --h: the step-over that leaves this roughness Ra (up to the
                        largest Ra the tool leaves, named in the error)
  --interval <mm>       inverse: the scallop height left at step-over L
  --half-interval <mm>  inverse, the step-over given as L/2
  --inverse             optional with --interval or --half-interval (kept for old scripts)
  --simulate            also simulate the passes (the tool solid over a 512 x 512 height field;
                        a plane only) and show its cusp height and roughness beside the exact ones
  --json                print one JSON object instead of a table

Three-axis machining (the tool upright, the surface sloped; then --rho and --tilt are not given):
  --slope <deg>         slope alpha of the surface at the contact (0 to 90; 90 is a vertical wall,
                        cut flat by the side: no scallop)
  --passes <p>          raster (default: parallel passes) or waterline (Z-level, along the contour)
  --raster-angle <deg>  raster only: plan angle psi of the passes to the fall line (0 to 90; default 0)
  --feed-radius <mm>    waterline only: a surface of revolution about a vertical axis, signed normal
                        radius along the feed (> 0 convex: dome, boss; < 0 concave: bowl, fillet)
  --cross-radius <mm>   waterline only: signed radius of the meridian (signs as --feed-radius);
                        without either radius: a sloped plane
  --h <mm>              the scallop height: gives the programmed step (Lxy or dz), L along the
                        surface and the equivalent lead and tilt
  --interval <mm>       inverse: the cusp height a step-over L along the surface leaves
  --horizontal-step <mm> inverse, raster: the cusp height a horizontal step Lxy leaves
  --step-down <mm>      inverse, waterline: the cusp height a step-down dz (tool tip to tool tip) leaves
  --batch               read CSV on stdin (header R,Rcr,rho and h or Ra; optional tilt, pattern,
                        surfaceRadius, surfaceAxis; any order; an empty field takes the default;
                        output columns are ignored, so an output or a lookup table reads back),
                        three-axis: a header with slope needs no rho; optional passes,
                        rasterAngle, feedRadius, crossRadius; output interval,horizontalStep,
                        stepDown,lead,tilt,scallopHeight,note,error),
                        write CSV: the input columns, h (with Ra), then
                        exact,sekine,redonnet,bedi (L/2 of each), interval,halfWidthRight,
                        halfWidthLeft,contactOffset,otherCuspHeight (exact), osculating,
                        cornerBall (L/2), note, error; full precision; blank lines skipped
  -h, --help            show this text

Table: 7 significant digits. JSON and CSV: every digit of the double.
Exit codes: 0 success (a batch with bad rows included), 1 a read or write error,
2 invalid input or usage.`;

/** The option that gives a field, as the user types it, for messages. */
export function optionOf(field: AnyFieldName, half: boolean): string {
  return cliFlag(half && field === 'interval' ? 'halfInterval' : field);
}

function reportErrors(
  io: Io,
  out: Output,
  errors: readonly AnyInputError[],
  json: boolean,
  half: { readonly typed: string } | null,
): number {
  const worded = errors.map((e) => {
    const asHalf = half !== null && e.field === 'interval';
    const options: DescribeOptions = asHalf ? { intervalAsHalf: true, typed: half.typed.trim() } : {};
    const message = describeInputError(e, 'mm', options);
    const option = optionOf(e.field, asHalf);
    io.stderr.write(errorLine(`${option}: ${message}`));
    return errorJson(e, option, escapeControls(message));
  });
  if (json) out.write(`${JSON.stringify({ errors: worded })}\n`);
  return 2;
}

/** An input error as JSON prints it: what does not exist (no limit, no side) is left out, never `null`. */
export interface ErrorJson {
  readonly field: AnyFieldName;
  readonly option: string;
  readonly code: AnyInputError['code'];
  /** The value as given (JSON escapes its control characters). */
  readonly got: string;
  /** The bound it broke: mm for lengths, degrees for angles. */
  readonly limit?: number;
  /** For a flank or the shank: the side that sets the limit. */
  readonly side?: 'right' | 'left';
  /** For `shank-gouging`: the shank's lean from the surface normal seen along the cylinder's axis. */
  readonly shankLean?: AnyInputError['shankLean'];
  /** The words of the stderr line, control characters escaped. */
  readonly message: string;
}

/** The JSON of an input error (see {@link ErrorJson}). */
export function errorJson(e: AnyInputError, option: string, message: string): ErrorJson {
  return {
    field: e.field,
    option,
    code: e.code,
    got: e.got,
    ...(e.limit === null ? {} : { limit: e.limit }),
    ...(e.side === null ? {} : { side: e.side }),
    ...(e.shankLean === undefined ? {} : { shankLean: e.shankLean }),
    message,
  };
}

type Values = Readonly<Partial<Record<ValueOption, string>>>;

/** What the options ask besides the answer: the output form and a simulation. */
interface Wanted {
  readonly json: boolean;
  readonly simulate: boolean;
}

/** The raw tool, posture, pattern and surface of the options (each field's option, the field registry's). */
function passValues(values: Values) {
  return rawFields(PASS_FIELDS, (name) => values[FIELDS[name].cli]);
}

/**
 * Simulates the passes at a step-over (plane only: args.ts refuses --simulate on a cylinder). A
 * case too large to simulate is answered without it, saying why.
 */
function simulate(pass: PassInput, intervalMm: number): SimulationRun {
  const t0 = performance.now();
  try {
    const result = simulatePasses({ tool: pass, pattern: pass.pattern, intervalMm });
    return { ok: true, result, ms: performance.now() - t0 };
  } catch (e) {
    if (e instanceof SimulationTooLargeError) return { ok: false, notApplicable: e.message };
    throw e;
  }
}

/** The forward answer for a valid input, with its roughness (and the simulation when asked). */
function writeForward(input: ForwardInput, wanted: Wanted, out: Output, targetRaMm?: number): number {
  const c = compareForward(input);
  const extras: Extras = {
    roughness: exactRoughness(input, c.exact),
    ...(targetRaMm === undefined ? {} : { targetRaMm }),
    ...(wanted.simulate ? { simulation: simulate(input, c.exact.intervalMm) } : {}),
  };
  out.write(wanted.json ? `${JSON.stringify(forwardJson(c, extras))}\n` : `${forwardTable(c, extras)}\n`);
  return 0;
}

function forward(values: Values, wanted: Wanted, io: Io, out: Output): number {
  const v = validateForward({ ...passValues(values), h: values[FIELDS.h.cli] });
  if (!v.ok) return reportErrors(io, out, v.errors, wanted.json, null);
  return writeForward(v.value, wanted, out);
}

/** --ra: the scallop height that leaves the target Ra, then the forward answer for it. */
function targetRa(values: Values, wanted: Wanted, io: Io, out: Output): number {
  const v = validateTargetRa({ ...passValues(values), ra: values[FIELDS.ra.cli] });
  if (!v.ok) return reportErrors(io, out, v.errors, wanted.json, null);
  const p = v.value;
  const h = scallopHeightForRaMm(p, p.pattern, p.targetRaMm, p.surface);
  return writeForward(forwardInput(p, p.pattern, h, p.surface), wanted, out, p.targetRaMm);
}

function inverse(values: Values, wanted: Wanted, half: boolean, io: Io, out: Output): number {
  let interval: unknown = values[FIELDS.interval.cli];
  const typedHalf = values[FIELDS.halfInterval.cli];
  if (half && typedHalf !== undefined) {
    // L = 2 (L/2) exactly; validation messages quote L/2 as typed.
    // An L/2 so large that 2 (L/2) overflows is beyond any tool: the largest double stands for it.
    const text = typedHalf.trim();
    const doubled = 2 * Number(text);
    if (!isNumberText(text)) interval = typedHalf;
    else interval = Number.isFinite(doubled) ? doubled : Math.sign(doubled) * Number.MAX_VALUE;
  }
  const v = validateInverse({ ...passValues(values), interval });
  if (!v.ok) return reportErrors(io, out, v.errors, wanted.json, half ? { typed: typedHalf ?? '' } : null);
  const input = v.value;
  const c = compareInverse(input);
  const extras: Extras = {
    roughness: exactRoughnessAtInterval(input, input.pattern, c.exact, input.surface),
    ...(wanted.simulate ? { simulation: simulate(input, input.intervalMm) } : {}),
  };
  out.write(wanted.json ? `${JSON.stringify(inverseJson(c, extras))}\n` : `${inverseTable(c, extras)}\n`);
  return 0;
}

/** A three-axis input error as a stderr line (and JSON): named by its option, the registry's. */
function reportThreeAxisErrors(io: Io, out: Output, errors: readonly ThreeAxisInputError[], json: boolean): number {
  const worded = errors.map((e) => {
    const option = cliFlag(e.field);
    const message = escapeControls(e.message);
    io.stderr.write(errorLine(`${option}: ${e.message}`));
    return {
      field: e.field,
      option,
      code: e.code,
      got: escapeControls(String(e.got)),
      ...(e.limit === null ? {} : { limit: e.limit }),
      message,
    };
  });
  if (json) out.write(`${JSON.stringify({ errors: worded })}\n`);
  return 2;
}

/** --slope: three-axis machining, forward (--h) or the cusp a step leaves. */
function threeAxis(values: Values, quantity: ThreeAxisQuantity, json: boolean, io: Io, out: Output): number {
  const raw = Object.fromEntries(
    (['R', 'Rcr', 'slope', 'passes', 'rasterAngle', 'feedRadius', 'crossRadius'] as const).map((id) => [
      id,
      values[FIELDS[id].cli],
    ]),
  );
  const v = validateThreeAxis(raw, quantity, values[FIELDS[quantity].cli]);
  if (!v.ok) return reportThreeAxisErrors(io, out, v.errors, json);
  const r = solveThreeAxis(v.value);
  if (!r.ok) return reportThreeAxisErrors(io, out, r.errors, json);
  out.write(json ? `${JSON.stringify(threeAxisJson(v.value, r.value))}\n` : `${threeAxisTable(v.value, r.value)}\n`);
  return 0;
}

async function run(request: Request, io: Io, out: Output): Promise<number> {
  switch (request.kind) {
    case 'help':
      out.write(`${USAGE}\n`);
      return 0;
    case 'usage':
      io.stderr.write(errorLine(`${request.error} (see path-interval --help)`));
      return 2;
    case 'batch':
      return runBatch(io, out);
    case 'forward':
      return forward(request.values, request, io, out);
    case 'ra':
      return targetRa(request.values, request, io, out);
    case 'inverse':
      return inverse(request.values, request, request.half, io, out);
    case 'threeAxis':
      return threeAxis(request.values, request.quantity, request.json, io, out);
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
  io.stderr.write(errorLine(`cannot write to standard output: ${describeSystemError(e)}`));
  return 1;
}
