/**
 * The command line's answer to a question over the registries (`--machine` / `--surface` naming a
 * registered mode or surface the product's own paths do not answer; registryOptions.ts): the
 * question read and answered once (question.ts answerRegistryQuestion), written as a short table
 * or as JSON (its lengths named as unitJson.ts converts them). Pure: the caller writes the text.
 */
import { FIELDS, type FieldId } from '../core/input/fields';
import { formatInputNumber, fromMm, type LengthUnit, unitSymbol } from '../core/input/units';
import type { QuestionError } from '../core/surfaces/question';
import { questionMessageInUnit } from '../core/surfaces/questionWords';
import { answerRegistryQuestion, type QuestionValues } from './question';
import type { RegistryKinds } from './registryOptions';
import type { JsonValue } from './reportJson';

/** The answer as a table and as JSON (lengths mm, converted by the caller's JSON writer), or the refusal's lines. */
export type RegistryReport =
  | { readonly ok: true; readonly table: string; readonly json: { [key: string]: JsonValue } }
  | { readonly ok: false; readonly errors: readonly string[] };

/** A refusal in the user's unit, the value quoted as typed (`typed`: the options as given). */
function inUserWords(e: QuestionError, unit: LengthUnit, typed: QuestionValues): string {
  const option = e.field in FIELDS ? FIELDS[e.field as FieldId].cli : null;
  return questionMessageInUnit(e, unit, option === null ? undefined : typed[option as keyof QuestionValues]?.trim());
}

/**
 * Answers a question over the registries from the command line's values (lengths in mm; `typed`:
 * as given, for the refusals' quotes) and writes it in `unit`.
 */
export function registryReport(
  values: QuestionValues,
  kinds: RegistryKinds,
  quantity: 'h' | 'interval',
  unit: LengthUnit,
  typed: QuestionValues = values,
): RegistryReport {
  const r = answerRegistryQuestion(values, kinds, quantity);
  if (!r.ok) return { ok: false, errors: r.errors.map((e) => inUserWords(e, unit, typed)) };
  const a = r.answer;
  const length = (mm: number | null) =>
    mm === null || !Number.isFinite(mm) ? '-' : `${formatInputNumber(fromMm(mm, unit))} ${unitSymbol(unit)}`;
  const rows: Array<[string, string]> = [
    ['Step-over L', length(a.intervalMm)],
    ['Scallop height h', length(a.cuspHeightMm)],
    ['Lead, tilt', `${a.posture.leadAngleDeg}, ${a.posture.tiltAngleDeg} degrees (${a.posture.pattern})`],
    ['Widest step-over', length(a.maxIntervalMm)],
    ['Highest scallop', length(a.heightLimitMm)],
  ];
  const width = Math.max(...rows.map(([k]) => k.length));
  const table = [
    `${kinds.modeName} machining over a surface of kind ${kinds.surface} (a question over the registries)`,
    ...rows.map(([k, v]) => `  ${k.padEnd(width)}  ${v}`),
  ].join('\n');
  const json: { [key: string]: JsonValue } = {
    machine: kinds.modeName,
    surface: kinds.surface,
    interval: a.intervalMm,
    scallopHeight: a.cuspHeightMm,
    lead: a.posture.leadAngleDeg,
    tilt: a.posture.tiltAngleDeg,
    pattern: a.posture.pattern,
    ...(a.maxIntervalMm === null ? {} : { maxInterval: a.maxIntervalMm }),
    heightLimit: a.heightLimitMm,
  };
  return { ok: true, table, json };
}
