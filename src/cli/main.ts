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
  compareDoublyCurved,
  type DoublyCurvedQuantity,
  doublyCurvedHeightForRaMm,
  doublyCurvedInverse,
  doublyCurvedRoughness,
  doublyCurvedRoughnessAtInterval,
  doublyCurvedSolver,
  validateDoublyCurved,
} from '../core/surfaces/doublyCurved/index';
import { solveThreeAxis } from '../core/threeAxis/solve';
import { type ThreeAxisInputError, type ThreeAxisQuantity, validateThreeAxis } from '../core/threeAxis/validate';
import { parseArgs, type Request, type ValueOption } from './args';
import { runBatch } from './batch';
import { isNumberText } from './csv';
import {
  doublyCurvedForwardJson,
  doublyCurvedForwardTable,
  doublyCurvedInverseJson,
  doublyCurvedInverseTable,
} from './doublyCurvedReport';
import { describeSystemError, errorLine, escapeControls, isClosedPipe, Output } from './output';
import { type Extras, forwardJson, forwardTable, inverseJson, inverseTable, type SimulationRun } from './report';
import { sweepSlopes } from './slopeSweep';
import { slopeSweepJson, slopeSweepTable, threeAxisJson, threeAxisTable } from './threeAxisReport';
import { USAGE } from './usage';

/** The help text (usage.ts), re-exported for the callers. */
export { USAGE };

export interface Io {
  readonly stdin: Readable;
  readonly stdout: Writable;
  readonly stderr: Writable;
}

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
  surfaceRadiusAs?: 'feedRadius' | 'crossRadius',
): number {
  const worded = errors.map((e) => {
    const asHalf = half !== null && e.field === 'interval';
    const options: DescribeOptions = {
      ...(asHalf ? { intervalAsHalf: true, typed: half.typed.trim() } : {}),
      ...(surfaceRadiusAs === undefined ? {} : { surfaceRadiusAs }),
    };
    const message = describeInputError(e, 'mm', options);
    const option =
      surfaceRadiusAs !== undefined && e.field === 'surfaceRadius'
        ? cliFlag(surfaceRadiusAs)
        : optionOf(e.field, asHalf);
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
  /** For `radius-gouging`: what the named radius must be with the other held, and the other's limit. */
  readonly radiusLimit?: AnyInputError['radiusLimit'];
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
    ...(e.radiusLimit === undefined ? {} : { radiusLimit: e.radiusLimit }),
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

function forward(values: Values, wanted: Wanted, io: Io, out: Output, as?: RadiusOption): number {
  const v = validateForward({ ...passValues(values), h: values[FIELDS.h.cli] });
  if (!v.ok) return reportErrors(io, out, v.errors, wanted.json, null, as);
  return writeForward(v.value, wanted, out);
}

/** --ra: the scallop height that leaves the target Ra, then the forward answer for it. */
function targetRa(values: Values, wanted: Wanted, io: Io, out: Output, as?: RadiusOption): number {
  const v = validateTargetRa({ ...passValues(values), ra: values[FIELDS.ra.cli] });
  if (!v.ok) return reportErrors(io, out, v.errors, wanted.json, null, as);
  const p = v.value;
  const h = scallopHeightForRaMm(p, p.pattern, p.targetRaMm, p.surface);
  return writeForward(forwardInput(p, p.pattern, h, p.surface), wanted, out, p.targetRaMm);
}

/** The step-over as validation reads it: --interval, or 2 (L/2) from --half-interval. */
function intervalOf(values: Values, half: boolean): unknown {
  const typedHalf = values[FIELDS.halfInterval.cli];
  if (!half || typedHalf === undefined) return values[FIELDS.interval.cli];
  // L = 2 (L/2) exactly; validation messages quote L/2 as typed.
  // An L/2 so large that 2 (L/2) overflows is beyond any tool: the largest double stands for it.
  const text = typedHalf.trim();
  const doubled = 2 * Number(text);
  if (!isNumberText(text)) return typedHalf;
  return Number.isFinite(doubled) ? doubled : Math.sign(doubled) * Number.MAX_VALUE;
}

function inverse(values: Values, wanted: Wanted, half: boolean, io: Io, out: Output, as?: RadiusOption): number {
  const typedHalf = values[FIELDS.halfInterval.cli];
  const v = validateInverse({ ...passValues(values), interval: intervalOf(values, half) });
  if (!v.ok) return reportErrors(io, out, v.errors, wanted.json, half ? { typed: typedHalf ?? '' } : null, as);
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

/** A principal radius's field, when one alone stands for a cylinder. */
type RadiusOption = 'feedRadius' | 'crossRadius';

/**
 * The surface the options give: the principal radii (--feed-radius, --cross-radius) both given are
 * a doubly curved point; one alone is the cylinder it is (--cross-radius Rs is --surface-radius Rs
 * --surface-axis feed, --feed-radius Rs is the axis across), answered by the cylinder's own path
 * (the same digits); neither leaves the options as they are (args.ts refuses the two forms mixed).
 */
function surfaceForm(
  values: Values,
): { readonly kind: 'doubly' } | { readonly kind: 'pass'; readonly values: Values; readonly as?: RadiusOption } {
  const rf = values[FIELDS.feedRadius.cli];
  const rc = values[FIELDS.crossRadius.cli];
  if (rf !== undefined && rc !== undefined) return { kind: 'doubly' };
  if (rf === undefined && rc === undefined) return { kind: 'pass', values };
  const rest: Partial<Record<ValueOption, string>> = { ...values };
  delete rest[FIELDS.feedRadius.cli];
  delete rest[FIELDS.crossRadius.cli];
  rest[FIELDS.surfaceRadius.cli] = rf ?? rc;
  rest[FIELDS.surfaceAxis.cli] = rf === undefined ? 'feed' : 'cross';
  return { kind: 'pass', values: rest, as: rf === undefined ? 'crossRadius' : 'feedRadius' };
}

/** A doubly curved point (both principal radii): forward, target Ra or inverse. */
function doublyCurved(request: Request & { kind: 'forward' | 'ra' | 'inverse' }, io: Io, out: Output): number {
  const values = request.values;
  const half = request.kind === 'inverse' ? request.half : false;
  const quantity: DoublyCurvedQuantity = request.kind === 'forward' ? 'h' : request.kind === 'ra' ? 'ra' : 'interval';
  const raw = Object.fromEntries(
    (['R', 'Rcr', 'rho', 'tilt', 'pattern', 'feedRadius', 'crossRadius'] as const).map((id) => [
      id,
      values[FIELDS[id].cli],
    ]),
  );
  const given = quantity === 'interval' ? intervalOf(values, half) : values[FIELDS[quantity].cli];
  const v = validateDoublyCurved(raw as { R: unknown; Rcr: unknown; rho: unknown }, quantity, given);
  if (!v.ok) {
    const typedHalf = values[FIELDS.halfInterval.cli];
    return reportErrors(io, out, v.errors, request.json, half ? { typed: typedHalf ?? '' } : null);
  }
  const p = v.value;
  const solver = doublyCurvedSolver(p, p);
  if (quantity === 'interval') {
    const e = doublyCurvedInverse({ ...p, intervalMm: p.valueMm });
    const r = doublyCurvedRoughnessAtInterval(solver, p.pattern, e);
    out.write(
      request.json ? `${JSON.stringify(doublyCurvedInverseJson(p, e, r))}\n` : `${doublyCurvedInverseTable(p, e, r)}\n`,
    );
    return 0;
  }
  const h = quantity === 'ra' ? doublyCurvedHeightForRaMm(p, p.pattern, p, p.valueMm) : p.valueMm;
  const c = compareDoublyCurved({ ...p, scallopHeightMm: h });
  const extras: Extras = {
    roughness: doublyCurvedRoughness(solver, p.pattern, c.exact),
    ...(quantity === 'ra' ? { targetRaMm: p.valueMm } : {}),
  };
  out.write(
    request.json
      ? `${JSON.stringify(doublyCurvedForwardJson(p, h, c, extras))}\n`
      : `${doublyCurvedForwardTable(p, h, c, extras)}\n`,
  );
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
    case 'ra':
    case 'inverse': {
      const form = surfaceForm(request.values);
      if (form.kind === 'doubly') return doublyCurved(request, io, out);
      if (request.kind === 'forward') return forward(form.values, request, io, out, form.as);
      if (request.kind === 'ra') return targetRa(form.values, request, io, out, form.as);
      return inverse(form.values, request, request.kind === 'inverse' && request.half, io, out, form.as);
    }
    case 'threeAxis':
      return threeAxis(request.values, request.quantity, request.json, io, out);
    case 'slopeSweep': {
      const r = sweepSlopes(request.values);
      if (!r.ok) return reportThreeAxisErrors(io, out, r.errors, request.json);
      const step = { typed: r.typed };
      out.write(
        request.json
          ? `${JSON.stringify(slopeSweepJson(r.input, r.sweep, step))}\n`
          : `${slopeSweepTable(r.input, r.sweep, step)}\n`,
      );
      return 0;
    }
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
