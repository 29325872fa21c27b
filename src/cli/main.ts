/**
 * Command line: quick lookup, JSON for scripts, the inverse, and CSV batch lookup tables.
 * All lengths in mm and angles in degrees, as at the solver core's public edge.
 */
import { writeFileSync } from 'node:fs';
import type { Readable, Writable } from 'node:stream';
import {
  type AnyFieldName,
  type AnyInputError,
  compareForward,
  compareInverse,
  exactRoughness,
  exactRoughnessAtInterval,
  type PassInput,
  type PassPattern,
  SimulationTooLargeError,
  simulatePasses,
  type ToolInput,
} from '../core/index';
import { cliFlag } from '../core/input/fields';
import type { LengthUnit } from '../core/input/units';
import { compareDoublyCurved } from '../core/procedures/compareDoublyCurved';
import { doublyCurvedRoughness, doublyCurvedRoughnessAtInterval } from '../core/roughness/doublyCurved';
import { curvedInverse, curvedPointOf } from '../core/surfaces/doublyCurvedPoint';
import type { ThreeAxisInputError, ThreeAxisQuantity } from '../core/threeAxis/validate';
import { cut, parseArgs, type Request, type ValueOption } from './args';
import { runBatch } from './batch';
import {
  doublyCurvedForwardJson,
  doublyCurvedForwardTable,
  doublyCurvedInverseJson,
  doublyCurvedInverseTable,
} from './doublyCurvedReport';
import {
  type FinishError,
  type FinishRun,
  finishErrorOption,
  finishErrorWords,
  finishJson,
  finishLines,
  finishOf,
  finishRequested,
  finishScopeRefusal,
  THREE_AXIS_FINISH_NOTE,
} from './finish';
import { unitOfText, valuesInMm } from './lengthInput';
import { describeSystemError, errorLine, escapeControls, isClosedPipe, Output } from './output';
import {
  type Answer,
  answer,
  answerThreeAxis,
  optionOf,
  type Quantity,
  SURFACE_TWICE,
  threeAxisMessage,
  type WordedError,
  wordErrors,
} from './question';
import { registryReport } from './registryReport';
import {
  type Extras,
  forwardJson,
  forwardTable,
  inverseJson,
  inverseTable,
  type JsonValue,
  type SimulationRun,
} from './report';
import { sweepSlopes } from './slopeSweep';
import { lengthsIn } from './table';
import { targetFinish } from './targetFinish';
import { slopeSweepJson, slopeSweepTable, threeAxisJson, threeAxisTable } from './threeAxisReport';
import { jsonInUnit } from './unitJson';
import { USAGE } from './usage';
import { loadX3pWriter, X3P_DEFAULT_SIZE, x3pOfFinish } from './x3pOption';

/** The help text (usage.ts), re-exported for the callers. */
export { USAGE };

export interface Io {
  readonly stdin: Readable;
  readonly stdout: Writable;
  readonly stderr: Writable;
}

/** The option that gives a field (question.ts), re-exported for the callers. */
export { optionOf };

/** Input errors on stderr, one line each (and as JSON on stdout with --json); exit code 2. */
function reportErrors(io: Io, out: Output, worded: readonly WordedError[], json: boolean, unit: LengthUnit): number {
  const errors = worded.map((w) => {
    io.stderr.write(errorLine(`${w.option}: ${w.message}`));
    return errorJson({ ...w.error, got: w.got }, w.option, escapeControls(w.message));
  });
  const list = errors as unknown as JsonValue[];
  // In inches the errors name their unit (their limits are inches).
  if (json) writeJson(out, unit === 'mm' ? { errors: list } : { unit: 'mm', errors: list }, unit);
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
    got: cut(e.got),
    ...(e.limit === undefined ? {} : { limit: e.limit }),
    ...(e.side === undefined ? {} : { side: e.side }),
    ...(e.shankLean === undefined ? {} : { shankLean: e.shankLean }),
    ...(e.radiusLimit === undefined ? {} : { radiusLimit: e.radiusLimit }),
    message,
  };
}

type Values = Readonly<Partial<Record<ValueOption, string>>>;

/** What the options ask besides the answer: the output form and a simulation; the options as typed. */
interface Wanted {
  readonly json: boolean;
  readonly simulate: boolean;
  readonly typed: Values;
}

/**
 * With --x3p: the areal surface of a computed finish written to the file (args.ts checked the grid
 * options); the finish with its file named, or 1 when the file cannot be written, 2 where the areal
 * surface is not defined (each said on stderr).
 */
function withX3p(
  run: Extract<FinishRun, { ok: true }>,
  tool: ToolInput,
  pattern: PassPattern,
  intervalMm: number,
  values: Values,
  io: Io,
): NonNullable<Extras['finish']> | number {
  const file = values.x3p;
  if (file === undefined) return run;
  if (run.report.areal === null) {
    // No file of a surface that is not defined (a flat end lying flat): said on --x3p, exit 2.
    io.stderr.write(errorLine(`--x3p: no file: ${run.report.arealRefusal ?? ''}`));
    return 2;
  }
  const pair = (text: string | undefined, fallback: readonly [number, number]) =>
    (text?.split(/[,x]/i).map(Number) as unknown as readonly [number, number] | undefined) ?? fallback;
  const f = run.input;
  const comment =
    `Surface left by ${f.flutes} straight teeth (M3), fz ${f.feedPerToothMm} mm, runout ${f.runoutMm} mm at ${f.runoutPhaseDeg} deg, ` +
    `pass phase ${f.passPhase}: R ${tool.toolRadiusMm} mm, Rcr ${tool.cornerRadiusMm} mm, lead ${tool.leadAngleDeg} deg, ` +
    `tilt ${tool.tiltAngleDeg} deg, ${pattern}, step-over ${intervalMm} mm, on a plane (path-interval)`;
  const { bytes, facts } = x3pOfFinish(
    tool,
    pattern,
    intervalMm,
    f,
    pair(values['x3p-size'], X3P_DEFAULT_SIZE),
    pair(values['x3p-cells'], [1, 1]),
    comment,
  );
  try {
    writeFileSync(file, bytes);
  } catch (e) {
    io.stderr.write(errorLine(`cannot write the x3p file ${escapeControls(cut(file))}: ${describeSystemError(e)}`));
    return 1;
  }
  return { ...run, x3p: { file, facts } };
}

/** The refusal of the finish options on a doubly curved point. */
function doublyScope(): FinishError {
  return finishScopeRefusal('doublyCurved');
}

/** Finish input errors on stderr, one line each named by its option (and as JSON with --json); exit code 2. */
function reportFinishErrors(
  io: Io,
  out: Output,
  errors: readonly FinishError[],
  json: boolean,
  unit: LengthUnit,
  typed: Values,
): number {
  const worded = errors.map((e) => {
    const option = finishErrorOption(e);
    const words = finishErrorWords(e, unit, typed);
    io.stderr.write(errorLine(`${option}: ${words}`));
    const given = typed[option.slice(2) as ValueOption]?.trim();
    return {
      field: e.field,
      option,
      code: e.code,
      got: escapeControls(cut(given ?? e.got)),
      ...(e.limit === undefined ? {} : { limit: e.limit }),
      message: escapeControls(words),
    };
  });
  if (json) writeJson(out, unit === 'mm' ? { errors: worded } : { unit: 'mm', errors: worded }, unit);
  return 2;
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

/** One JSON object on its line, every length in `unit` (converted once from mm). */
function writeJson(out: Output, value: { [key: string]: JsonValue }, unit: LengthUnit): void {
  out.write(`${JSON.stringify(jsonInUnit(value, unit))}\n`);
}

/** Writes a solved question (question.ts): a table or JSON; with the finish options, their errors (exit 2). */
function writeAnswer(
  a: Extract<Answer, { ok: true }>,
  wanted: Wanted,
  io: Io,
  out: Output,
  unit: LengthUnit,
  values: Values,
): number {
  const json = wanted.json;
  /** The finish's extras (none without its options), or its errors reported (a number: the exit code). */
  const finish = (input: PassInput, intervalMm: number, surfaceKind: string): Extras | number => {
    if (!finishRequested(values)) return {};
    const run = finishOf(values, input, input.pattern, intervalMm, surfaceKind);
    if (!run.ok) return reportFinishErrors(io, out, run.errors, json, unit, wanted.typed);
    const written = withX3p(run, input, input.pattern, intervalMm, values, io);
    return typeof written === 'number' ? written : { finish: written };
  };
  switch (a.kind) {
    case 'pass-forward': {
      const input = a.input;
      const c = compareForward(input);
      const teeth = finish(input, c.exact.intervalMm, input.surface.kind);
      if (typeof teeth === 'number') return teeth;
      const extras: Extras = {
        roughness: exactRoughness(input, c.exact),
        ...(a.targetRaMm === undefined ? {} : { targetRaMm: a.targetRaMm }),
        ...(wanted.simulate ? { simulation: simulate(input, c.exact.intervalMm) } : {}),
        ...teeth,
      };
      if (json) writeJson(out, forwardJson(c, extras), unit);
      else out.write(`${forwardTable(c, extras, unit)}\n`);
      return 0;
    }
    case 'pass-inverse': {
      const input = a.input;
      const c = compareInverse(input);
      const teeth = finish(input, input.intervalMm, input.surface.kind);
      if (typeof teeth === 'number') return teeth;
      const extras: Extras = {
        roughness: exactRoughnessAtInterval(input, input.pattern, c.exact, input.surface),
        ...(wanted.simulate ? { simulation: simulate(input, input.intervalMm) } : {}),
        ...teeth,
      };
      if (json) writeJson(out, inverseJson(c, extras), unit);
      else out.write(`${inverseTable(c, extras, unit)}\n`);
      return 0;
    }
    case 'doubly-inverse': {
      if (finishRequested(values)) return reportFinishErrors(io, out, [doublyScope()], json, unit, wanted.typed);
      const p = a.problem;
      const point = curvedPointOf(p);
      const e = curvedInverse(point, p.valueMm);
      const report = { pass: p, exact: e, roughness: doublyCurvedRoughnessAtInterval(point, e) };
      if (json) writeJson(out, doublyCurvedInverseJson(report), unit);
      else out.write(`${doublyCurvedInverseTable(report, unit)}\n`);
      return 0;
    }
    case 'doubly-forward': {
      if (finishRequested(values)) return reportFinishErrors(io, out, [doublyScope()], json, unit, wanted.typed);
      const p = a.problem;
      const h = a.scallopHeightMm;
      const c = compareDoublyCurved({ ...p, scallopHeightMm: h });
      const extras: Extras = {
        roughness: doublyCurvedRoughness(curvedPointOf(p), c.exact),
        ...(a.targetRaMm === undefined ? {} : { targetRaMm: a.targetRaMm }),
      };
      const report = { pass: p, h, comparison: c, extras };
      if (json) writeJson(out, doublyCurvedForwardJson(report), unit);
      else out.write(`${doublyCurvedForwardTable(report, unit)}\n`);
      return 0;
    }
  }
}

/** A question of a tool on a plane, a cylinder or a doubly curved point: --h, --ra or the step-over. */
function question(request: Request & { kind: 'forward' | 'ra' | 'inverse' }, io: Io, out: Output): number {
  const unit = unitOfText(request.values.unit) ?? 'mm';
  const quantity: Quantity = request.kind === 'forward' ? 'h' : request.kind === 'ra' ? 'ra' : 'interval';
  const q = { values: valuesInMm(request.values, unit), quantity, half: request.kind === 'inverse' && request.half };
  const a = answer(q);
  // args.ts refuses a cylinder beside the principal radii before a question is asked.
  if (a === null) throw new Error(SURFACE_TWICE);
  if (!a.ok) return reportErrors(io, out, wordErrors(a, q, unit, request.values), request.json, unit);
  return writeAnswer(a, { ...request, typed: request.values }, io, out, unit, q.values);
}

/** A three-axis input error as a stderr line (and JSON): named by its option, the registry's. */
function reportThreeAxisErrors(
  io: Io,
  out: Output,
  errors: readonly ThreeAxisInputError[],
  passes: string,
  json: boolean,
  unit: LengthUnit,
  typed: Values,
): number {
  const worded = errors.map((e) => {
    const option = cliFlag(e.field);
    const words = threeAxisMessage(e, passes, unit, typed);
    const message = escapeControls(words);
    io.stderr.write(errorLine(`${option}: ${words}`));
    return {
      field: e.field,
      option,
      code: e.code,
      // The value as typed (before its unit was read), else as the solver took it.
      got: escapeControls(cut(typed[cliFlag(e.field).slice(2) as ValueOption]?.trim() ?? String(e.got))),
      ...(e.limit === null ? {} : { limit: e.limit }),
      message,
    };
  });
  if (json) writeJson(out, unit === 'mm' ? { errors: worded } : { unit: 'mm', errors: worded }, unit);
  return 2;
}

/** --slope: three-axis machining, forward (--h) or the cusp a step leaves. */
function threeAxis(values: Values, quantity: ThreeAxisQuantity, json: boolean, io: Io, out: Output): number {
  const unit = unitOfText(values.unit) ?? 'mm';
  const r = answerThreeAxis(valuesInMm(values, unit), quantity);
  if (!r.ok) return reportThreeAxisErrors(io, out, r.errors, r.passes, json, unit, values);
  const { problem, answer: a } = r;
  let teeth: Extras['finish'];
  if (finishRequested(values)) {
    // The sloped plane is a plane in the posture the slope gives; every pass fed the same way.
    const tool: ToolInput = {
      toolRadiusMm: problem.case.toolRadiusMm,
      cornerRadiusMm: problem.case.cornerRadiusMm,
      leadAngleDeg: a.leadDeg,
      tiltAngleDeg: a.tiltDeg,
    };
    const kind = problem.surface === 'plane' ? 'slopedPlane' : 'waterlineRevolution';
    const mm = valuesInMm(values, unit);
    const run = finishOf(mm, tool, 'one-way', a.intervalMm, kind);
    if (!run.ok) return reportFinishErrors(io, out, run.errors, json, unit, values);
    const written = withX3p(run, tool, 'one-way', a.intervalMm, mm, io);
    if (typeof written === 'number') return written;
    teeth = written;
  }
  if (json)
    writeJson(out, { ...threeAxisJson(problem, a), ...(teeth ? finishJson(teeth.report, teeth.x3p) : {}) }, unit);
  else {
    const finish =
      teeth === undefined
        ? ''
        : `\n\n${[...finishLines(teeth, a.cuspHeightMm, lengthsIn(unit)), '', THREE_AXIS_FINISH_NOTE].join('\n')}`;
    out.write(`${threeAxisTable(problem, a, unit)}${finish}\n`);
  }
  return 0;
}

/** --target-sa / --target-rz (targetFinish.ts): the best pair, or the input errors named by their options. */
function target(request: Extract<Request, { kind: 'target' }>, io: Io, out: Output): number {
  const unit = unitOfText(request.values.unit) ?? 'mm';
  const mm = valuesInMm(request.values, unit);
  const r = targetFinish(mm, request.target, unit);
  if (!r.ok) {
    if (r.inputErrors.length > 0) {
      const q = { values: mm, quantity: 'h' as const, half: false };
      return reportErrors(
        io,
        out,
        wordErrors({ ok: false, errors: r.inputErrors }, q, unit, request.values),
        request.json,
        unit,
      );
    }
    return reportFinishErrors(io, out, r.finishErrors, request.json, unit, request.values);
  }
  if (request.json) writeJson(out, r.json, unit);
  else out.write(`${r.table}\n`);
  return 0;
}

async function run(request: Request, io: Io, out: Output): Promise<number> {
  if (request.kind !== 'help' && request.kind !== 'usage' && request.values.x3p !== undefined) await loadX3pWriter();
  switch (request.kind) {
    case 'help':
      out.write(`${USAGE}\n`);
      return 0;
    case 'usage':
      io.stderr.write(errorLine(`${request.error} (see path-interval --help)`));
      return 2;
    case 'batch':
      return runBatch(io, out, unitOfText(request.values.unit) ?? 'mm');
    case 'forward':
    case 'ra':
    case 'inverse':
      return question(request, io, out);
    case 'threeAxis':
      return threeAxis(request.values, request.quantity, request.json, io, out);
    case 'question': {
      // --machine / --surface naming a registered mode or surface beyond the product's (registryReport.ts).
      const unit = unitOfText(request.values.unit) ?? 'mm';
      const r = registryReport(valuesInMm(request.values, unit), request.kinds, request.quantity, unit, request.values);
      if (!r.ok) for (const e of r.errors) io.stderr.write(errorLine(e));
      else if (request.json) writeJson(out, r.json, unit);
      else out.write(`${r.table}\n`);
      return r.ok ? 0 : 2;
    }
    case 'target':
      return target(request, io, out);
    case 'slopeSweep': {
      const unit = unitOfText(request.values.unit) ?? 'mm';
      const r = sweepSlopes(valuesInMm(request.values, unit));
      const passes = request.values.passes?.trim() || 'raster';
      if (!r.ok) return reportThreeAxisErrors(io, out, r.errors, passes, request.json, unit, request.values);
      const step = { typed: r.typed };
      if (request.json) writeJson(out, slopeSweepJson(r.input, r.sweep, step), unit);
      else out.write(`${slopeSweepTable(r.input, r.sweep, step, unit)}\n`);
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
