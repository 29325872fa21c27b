/**
 * The page's builder of a question over the registries (core surfaces/question.ts): a registered
 * machine mode over a registered surface, neither of them one the page's own switches build
 * (questionRequest.ts). The tool, the mode's and the surface's parameters (each a field of the field
 * registry, mode.ts's QuestionParameter) and the target are read from the state's fields in the
 * user's unit, converted to mm, and validated once; every error is put on a field, in one line.
 * The worker answers the request (jobs/question.ts). Pure.
 */
import { FIELDS, type FieldId, fieldOfPageKey, pageKeyOf } from '../core/input/fields';
import type { QuestionParameter } from '../core/surfaces/mode';
import { findMode } from '../core/surfaces/modes';
import { type Question, validateQuestion } from '../core/surfaces/question';
import { questionMessageInUnit } from '../core/surfaces/questionWords';
import { findSurfaceModel } from '../core/surfaces/registry';
import type { QuestionRequest } from '../worker/pageProtocol';
import type { BuiltRequest, PageFieldError } from './requestTypes';
import { type CalculatorState, type FieldKey, fieldInMm } from './state';

/** Which mode and surface the question is over (their registries' kinds). */
export interface QuestionKinds {
  readonly mode: string;
  readonly surface: string;
}

/** The page field a validation error names (its parameter's field, or the target's), never null. */
function keyOf(field: string, parameters: readonly QuestionParameter[], targetKey: FieldKey): FieldKey {
  const own = parameters.find((p) => p.name === field)?.field;
  const id = own ?? (field === 'interval' ? 'interval' : field in FIELDS ? (field as FieldId) : null);
  return (id === null ? null : pageKeyOf(id)) ?? targetKey;
}

/** The parameters' values in mm or degrees by descriptor property; a field that is no number is an error on it. */
function read(
  state: CalculatorState,
  parameters: readonly QuestionParameter[],
  errors: PageFieldError[],
): Record<string, number> {
  const out: Record<string, number> = {};
  for (const p of parameters) {
    const key = pageKeyOf(p.field);
    const v = key === null ? Number.NaN : fieldInMm(state, key);
    if (typeof v === 'number' && Number.isFinite(v)) out[p.name] = v;
    else if (key !== null)
      errors.push({ key, message: `${FIELDS[p.field].label} must be a number (got "${String(v).slice(0, 24)}").` });
  }
  return out;
}

/** The request of a question over the registries from the page's state, or its errors, each on a field. */
export function buildQuestionRequest(state: CalculatorState, kinds: QuestionKinds): BuiltRequest<QuestionRequest> {
  const mode = findMode(kinds.mode);
  const model = findSurfaceModel(kinds.surface);
  const parameters = [...(mode?.parameters ?? []), ...(model?.parameters ?? [])];
  const forward = state.mode === 'forward';
  const targetKey: FieldKey = forward ? 'h' : 'L';
  const own: PageFieldError[] = [];
  if (forward && state.target !== 'h')
    own.push({
      key: state.target,
      message: `A target ${FIELDS[fieldOfPageKey(state.target)].short} is not offered here: give the scallop height h.`,
    });
  const values = read(state, [...parameters, { name: 'R', field: 'R' }, { name: 'Rcr', field: 'Rcr' }], own);
  const target = fieldInMm(state, targetKey);
  if (typeof target !== 'number')
    own.push({
      key: targetKey,
      message: `${FIELDS[forward ? 'h' : 'interval'].label} must be a number (got "${target.slice(0, 24)}").`,
    });
  if (own.length > 0 || typeof target !== 'number') return { ok: false, errors: own };
  const pick = (ps: readonly QuestionParameter[] | undefined) =>
    Object.fromEntries((ps ?? []).map((p) => [p.name, values[p.name]]));
  const question: Question = {
    tool: { toolRadiusMm: values.R ?? Number.NaN, cornerRadiusMm: values.Rcr ?? Number.NaN },
    mode: { kind: kinds.mode, ...pick(mode?.parameters) },
    surface: { kind: kinds.surface, ...pick(model?.parameters) },
    pattern: state.pattern,
    target: { quantity: forward ? 'h' : 'interval', mm: target },
  };
  const v = validateQuestion(question);
  if (!v.ok)
    return {
      ok: false,
      errors: v.errors.map((e) => {
        const key = keyOf(e.field, parameters, targetKey);
        // In the user's unit, the value quoted as typed.
        return { key, message: questionMessageInUnit(e, state.unit, state.fields[key].trim()) };
      }),
    };
  return { ok: true, request: { mode: 'question', input: question } };
}
