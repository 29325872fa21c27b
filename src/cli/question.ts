/**
 * One question, one path (issue 26 point 8): the command line's single question and a batch record
 * both come here as raw values by option name (the field registry's `cli` names, lengths in mm),
 * and here they are read the same way: the surface's form (plane, cylinder, or doubly curved point,
 * from the principal radii), the validation, and the quantity asked (h, a target Ra solved for the
 * scallop height that leaves it, or a step-over). The callers only write the answer (a table, JSON
 * or a CSV row). Three-axis questions (a slope) likewise. Pure.
 */

import type { PassPattern } from '../core/domain/tool';
import {
  type AnyInputError,
  type DescribeOptions,
  describeInputError,
  type ForwardInput,
  forwardInput,
  type InverseInput,
  scallopHeightForRaMm,
  validateForward,
  validateInverse,
  validateTargetRa,
} from '../core/index';
import { cliFlag, FIELDS, PASS_FIELDS, type PassFieldName } from '../core/input/fields';
import { type RawFields, rawFields } from '../core/input/raw';
import type { LengthUnit } from '../core/input/units';
import { isNumberText } from '../core/output/csvWrite';
import { doublyCurvedHeightForRaMm } from '../core/roughness/doublyCurved';
import { type DoublyCurvedProblem, validateDoublyCurved } from '../core/roughness/doublyCurvedValidate';
import { curvedPointOf } from '../core/surfaces/doublyCurvedPoint';
import type { QuestionParameter } from '../core/surfaces/mode';
import { findMode } from '../core/surfaces/modes';
import {
  answerQuestion,
  type QuestionAnswer,
  type QuestionError,
  type ValidQuestion,
  validateQuestion,
} from '../core/surfaces/question';
import { findSurfaceModel } from '../core/surfaces/registry';
import { threeAxisMessageInUnit } from '../core/threeAxis/errors';
import { solveThreeAxis } from '../core/threeAxis/solve';
import {
  type ThreeAxisAnswer,
  type ThreeAxisInputError,
  type ThreeAxisProblem,
  type ThreeAxisQuantity,
  validateThreeAxis,
} from '../core/threeAxis/validate';
import type { ValueOption } from './args';

/** Raw values by option: text as typed (lengths in mm: lengthInput.ts reads the user's unit). */
export type QuestionValues = Readonly<Partial<Record<ValueOption, string>>>;

/** What a question gives: a scallop height, a target roughness, or a step-over (L or L/2). */
export type Quantity = 'h' | 'ra' | 'interval';

export interface Question {
  readonly values: QuestionValues;
  readonly quantity: Quantity;
  /** The step-over was given as its half (--half-interval). */
  readonly half: boolean;
}

/** A principal radius's field, when one alone stands for a cylinder. */
export type RadiusOption = 'feedRadius' | 'crossRadius';

/** The answer of a question: what to write, every number of it already solved for. */
export type Answer =
  | { readonly ok: true; readonly kind: 'pass-forward'; readonly input: ForwardInput; readonly targetRaMm?: number }
  | { readonly ok: true; readonly kind: 'pass-inverse'; readonly input: InverseInput }
  | {
      readonly ok: true;
      readonly kind: 'doubly-forward';
      readonly problem: DoublyCurvedProblem;
      readonly scallopHeightMm: number;
      readonly targetRaMm?: number;
    }
  | { readonly ok: true; readonly kind: 'doubly-inverse'; readonly problem: DoublyCurvedProblem }
  | {
      readonly ok: false;
      readonly errors: readonly AnyInputError[];
      /** The radius option a cylinder was given as (its errors name it). */
      readonly as?: RadiusOption;
    };

/** A value as given: undefined when absent or blank (an empty radius is straight, as an empty batch cell). */
function given(values: QuestionValues, option: ValueOption): string | undefined {
  const v = values[option];
  return typeof v === 'string' && v.trim() === '' ? undefined : v;
}

/**
 * The values with every blank principal radius left out (`--feed-radius ''` is straight, the
 * batch's meaning of an empty cell, and is echoed as absent).
 */
export function withoutBlankRadii(values: QuestionValues): QuestionValues {
  const out: Partial<Record<ValueOption, string>> = { ...values };
  for (const id of ['feedRadius', 'crossRadius'] as const) {
    if (given(values, FIELDS[id].cli) === undefined) delete out[FIELDS[id].cli];
  }
  return out;
}

/**
 * The surface the values give: both principal radii are a doubly curved point; one alone is the
 * cylinder it is (--cross-radius Rs is --surface-radius Rs --surface-axis feed, --feed-radius Rs is
 * the axis across), answered by the cylinder's own path (the same digits); neither leaves the
 * values as they are.
 */
function surfaceForm(
  values: QuestionValues,
):
  | { readonly kind: 'doubly' }
  | { readonly kind: 'pass'; readonly values: QuestionValues; readonly as?: RadiusOption }
  | { readonly kind: 'both' } {
  const rf = given(values, FIELDS.feedRadius.cli);
  const rc = given(values, FIELDS.crossRadius.cli);
  // Neither radius: the values as they are (a pass reads no radius; no copy for every batch row).
  if (rf === undefined && rc === undefined) return { kind: 'pass', values };
  const rest: Partial<Record<ValueOption, string>> = { ...values };
  delete rest[FIELDS.feedRadius.cli];
  delete rest[FIELDS.crossRadius.cli];
  const cylinder =
    given(values, FIELDS.surfaceRadius.cli) !== undefined || given(values, FIELDS.surfaceAxis.cli) !== undefined;
  if (cylinder) return { kind: 'both' };
  if (rf !== undefined && rc !== undefined) return { kind: 'doubly' };
  rest[FIELDS.surfaceRadius.cli] = rf ?? rc;
  rest[FIELDS.surfaceAxis.cli] = rf === undefined ? 'feed' : 'cross';
  return { kind: 'pass', values: rest, as: rf === undefined ? 'crossRadius' : 'feedRadius' };
}

/** The step-over as validation reads it: --interval, or 2 (L/2) from --half-interval. */
export function intervalOf(values: QuestionValues, half: boolean): unknown {
  const typedHalf = values[FIELDS.halfInterval.cli];
  if (!half || typedHalf === undefined) return values[FIELDS.interval.cli];
  // L = 2 (L/2) exactly; validation messages quote L/2 as typed.
  // An L/2 so large that 2 (L/2) overflows is beyond any tool: the largest double stands for it.
  const text = typedHalf.trim();
  if (!isNumberText(text)) return typedHalf;
  const doubled = 2 * Number(text);
  return Number.isFinite(doubled) ? doubled : Math.sign(doubled) * Number.MAX_VALUE;
}

/** The doubly curved point of the values (both radii given). */
function doublyCurved(values: QuestionValues, quantity: Quantity, half: boolean): Answer {
  const raw = Object.fromEntries(
    (['R', 'Rcr', 'rho', 'tilt', 'pattern', 'feedRadius', 'crossRadius'] as const).map((id) => [
      id,
      values[FIELDS[id].cli],
    ]),
  );
  const value = quantity === 'interval' ? intervalOf(values, half) : values[FIELDS[quantity].cli];
  const v = validateDoublyCurved(raw as { R: unknown; Rcr: unknown; rho: unknown }, quantity, value);
  if (!v.ok) return { ok: false, errors: v.errors };
  const p = v.value;
  if (quantity === 'interval') return { ok: true, kind: 'doubly-inverse', problem: p };
  if (quantity === 'h') return { ok: true, kind: 'doubly-forward', problem: p, scallopHeightMm: p.valueMm };
  const h = doublyCurvedHeightForRaMm(curvedPointOf(p), p.valueMm);
  return { ok: true, kind: 'doubly-forward', problem: p, scallopHeightMm: h, targetRaMm: p.valueMm };
}

/**
 * The raw pass fields of the values (blank ones absent) and the quantity's `value` under `key`, in
 * one object built key by key (a spread copy is slow to make and to read in V8).
 */
export function rawPass<K extends string>(
  values: QuestionValues,
  key: K,
  value: unknown,
): RawFields<PassFieldName> & Readonly<Record<K, unknown>> {
  const raw = rawFields(PASS_FIELDS, (name) => given(values, FIELDS[name].cli)) as Record<string, unknown>;
  raw[key] = value;
  return raw as RawFields<PassFieldName> & Readonly<Record<K, unknown>>;
}

/** A plane or a cylinder. */
function onPass(values: QuestionValues, quantity: Quantity, half: boolean, as?: RadiusOption): Answer {
  const failed = (errors: readonly AnyInputError[]): Answer =>
    as === undefined ? { ok: false, errors } : { ok: false, errors, as };
  if (quantity === 'h') {
    const v = validateForward(rawPass(values, 'h', values[FIELDS.h.cli]));
    return v.ok ? { ok: true, kind: 'pass-forward', input: v.value } : failed(v.errors);
  }
  if (quantity === 'ra') {
    const v = validateTargetRa(rawPass(values, 'ra', values[FIELDS.ra.cli]));
    if (!v.ok) return failed(v.errors);
    const p = v.value;
    const h = scallopHeightForRaMm(p, p.pattern, p.targetRaMm, p.surface);
    return {
      ok: true,
      kind: 'pass-forward',
      input: forwardInput(p, p.pattern, h, p.surface),
      targetRaMm: p.targetRaMm,
    };
  }
  const v = validateInverse(rawPass(values, 'interval', intervalOf(values, half)));
  return v.ok ? { ok: true, kind: 'pass-inverse', input: v.value } : failed(v.errors);
}

/** The message of a batch record giving the surface twice (the command line refuses it as a usage error). */
export const SURFACE_TWICE =
  'give the surface once: surfaceRadius with surfaceAxis (a cylinder), or feedRadius and crossRadius';

/**
 * Answers a question (see the module comment): the solved answer, or the input errors. A record
 * giving both a cylinder and principal radii is refused with {@link SURFACE_TWICE} (as `null`).
 */
export function answer(q: Question): Answer | null {
  const form = surfaceForm(q.values);
  if (form.kind === 'both') return null;
  if (form.kind === 'doubly') return doublyCurved(q.values, q.quantity, q.half);
  return onPass(form.values, q.quantity, q.half, form.as);
}

/** An input error with its option and its words in the user's unit. */
export interface WordedError {
  readonly error: AnyInputError;
  readonly option: string;
  /** The value as typed (before its unit was read). */
  readonly got: string;
  readonly message: string;
}

/** The option that gives a field, as the user types it, for messages. */
export function optionOf(field: AnyInputError['field'], half: boolean): string {
  return cliFlag(half && field === 'interval' ? 'halfInterval' : field);
}

/**
 * The errors of a refused question in words (the one wording, describeInputError's), in `unit`,
 * each value quoted as typed (`typed`: the text of each option given, before its unit was read).
 */
export function wordErrors(
  refused: Extract<Answer, { ok: false }>,
  q: Question,
  unit: LengthUnit,
  typed: QuestionValues = {},
): WordedError[] {
  const diameter = typed[FIELDS.D.cli as ValueOption] !== undefined;
  return refused.errors.map((e) => {
    const asHalf = q.half && e.field === 'interval';
    const as = refused.as;
    const option =
      as !== undefined && e.field === 'surfaceRadius'
        ? cliFlag(as)
        : diameter && e.field === 'R'
          ? cliFlag('D')
          : optionOf(e.field, asHalf);
    const text = typed[option.slice(2) as ValueOption];
    const options: DescribeOptions = {
      ...(asHalf ? { intervalAsHalf: true } : {}),
      ...(text === undefined ? {} : { typed: text.trim() }),
      ...(as === undefined ? {} : { surfaceRadiusAs: as }),
      ...(diameter ? { toolSizeAsDiameter: true } : {}),
    };
    return { error: e, option, got: text?.trim() ?? e.got, message: describeInputError(e, unit, options) };
  });
}

/** The three-axis fields the question reads (with rho and tilt, refused beside a slope). */
const THREE_AXIS_READ = [
  'R',
  'Rcr',
  'slope',
  'passes',
  'rasterAngle',
  'feedRadius',
  'crossRadius',
  'rho',
  'tilt',
] as const;

/** A three-axis question (a slope): the validated problem and its answer, or the errors; and the passes asked. */
export function answerThreeAxis(
  values: QuestionValues,
  quantity: ThreeAxisQuantity,
):
  | { readonly ok: true; readonly problem: ThreeAxisProblem; readonly answer: ThreeAxisAnswer }
  | { readonly ok: false; readonly errors: readonly ThreeAxisInputError[]; readonly passes: string } {
  const raw = Object.fromEntries(THREE_AXIS_READ.map((id) => [id, given(values, FIELDS[id].cli)]));
  const passes = given(values, FIELDS.passes.cli)?.trim() ?? 'raster';
  const v = validateThreeAxis(raw, quantity, given(values, FIELDS[quantity].cli));
  if (!v.ok) return { ok: false, errors: v.errors, passes };
  const r = solveThreeAxis(v.value);
  if (!r.ok) return { ok: false, errors: r.errors, passes };
  return { ok: true, problem: v.value, answer: r.value };
}

/**
 * A three-axis error's words: a value that is no number or is missing in the one wording of every
 * field (describeInputError's); waterline passes have no raster angle, so their messages name the
 * slope alone. In inches, every length the message gives in mm is written in inches and the value
 * is quoted as typed (`typed`: the options as given, before their unit was read).
 */
export function threeAxisMessage(
  e: ThreeAxisInputError,
  passes: string,
  unit: LengthUnit = 'mm',
  typed: QuestionValues = {},
): string {
  const option = FIELDS[e.field].cli as ValueOption;
  const given = typed[option]?.trim();
  const got = given === undefined ? String(e.got) : given;
  if (e.code === 'missing' || e.code === 'not-a-number') {
    const words = describeInputError(
      {
        field: e.field as AnyInputError['field'],
        code: e.code,
        got,
        message: '',
      },
      'mm',
    );
    return threeAxisMessageInUnit({ message: words, got: null }, passes, 'mm', got);
  }
  return threeAxisMessageInUnit(e, passes, unit, got);
}

/**
 * A question over the registries (core surfaces/question.ts: a registered machine mode over a
 * registered surface) from the command line's values: the tool, the mode's and the surface's
 * parameters (each read from its field's option, mode.ts's QuestionParameter), the pattern and h or
 * L, validated once and answered; or the errors, each naming its option, in one line.
 */
export function answerRegistryQuestion(
  values: QuestionValues,
  kinds: { readonly mode: string; readonly surface: string },
  quantity: 'h' | 'interval',
):
  | { readonly ok: true; readonly question: ValidQuestion; readonly answer: QuestionAnswer }
  | { readonly ok: false; readonly errors: readonly QuestionError[] } {
  const mode = findMode(kinds.mode);
  const model = findSurfaceModel(kinds.surface);
  const errors: QuestionError[] = [];
  const number = (p: QuestionParameter): number => {
    const option = FIELDS[p.field].cli as ValueOption;
    const text = given(values, option)?.trim();
    if (text !== undefined && isNumberText(text)) return Number(text);
    errors.push({
      field: p.name,
      message: `--${option} must be a number (got ${text === undefined ? 'nothing' : `"${text.slice(0, 24)}"`}).`,
    });
    return Number.NaN;
  };
  const of = (ps: readonly QuestionParameter[] | undefined) =>
    Object.fromEntries((ps ?? []).map((p) => [p.name, number(p)]));
  const tool = {
    toolRadiusMm: number({ name: 'R', field: 'R' }),
    cornerRadiusMm: number({ name: 'Rcr', field: 'Rcr' }),
  };
  const target = { quantity, mm: number({ name: quantity, field: quantity }) };
  const question = {
    tool,
    mode: { kind: kinds.mode, ...of(mode?.parameters) },
    surface: { kind: kinds.surface, ...of(model?.parameters) },
    pattern: (given(values, FIELDS.pattern.cli as ValueOption)?.trim() ?? 'one-way') as PassPattern,
    target,
  };
  if (errors.length > 0) return { ok: false, errors };
  const v = validateQuestion(question);
  return v.ok ? { ok: true, question: v.value, answer: answerQuestion(v.value) } : v;
}
