/**
 * One question over the two registries (issue 27 point 3): a tool, a machine mode (modes.ts: the
 * posture supplier), a surface (registry.ts: the model), a pass pattern and a target (a scallop
 * height, or a step-over), validated once (validateQuestion) and answered by the surface's model
 * at the mode's posture (answerQuestion). Any registered mode over any registered surface it has a
 * posture on is answered here with no other change; where a mode's passes on a surface are not
 * congruent, its own answer (mode.ts OwnAnswer), with the per-flank parts null; a mode on a surface
 * it has neither for is refused with the mode's own one-line message. Never throws for any numeric
 * input. Lengths mm, angles degrees.
 */
import type { SurfaceDescriptorBase } from '../domain/surface';
import type { PassPattern, ToolInput } from '../domain/tool';
import { MAX_TOOL_RADIUS_MM, MIN_LENGTH_MM, MIN_TOOL_RADIUS_MM } from '../input/limits';
import {
  type ModeDescriptorBase,
  type Posture,
  type QuestionAnswer,
  type QuestionError,
  type QuestionTarget,
  type QuestionTool,
  shownNumber,
} from './mode';
import { findMode, ownAnswerOn, postureOn } from './modes';
import { findSurfaceModel } from './registry';
import type { SurfaceModel } from './surface';

/** A question: tool + mode + surface + pattern + target. */
export interface Question<
  M extends ModeDescriptorBase = ModeDescriptorBase,
  S extends SurfaceDescriptorBase = SurfaceDescriptorBase,
> {
  readonly tool: QuestionTool;
  readonly mode: M;
  readonly surface: S;
  readonly pattern: PassPattern;
  readonly target: QuestionTarget;
}

/**
 * A validated question and the posture its mode supplies; where the mode answers itself (its own
 * solver validates by solving), the answer found then, so that it is not solved twice.
 */
export interface ValidQuestion extends Question {
  readonly posture: Posture;
  readonly answered?: QuestionAnswer;
}

/** A number for a message: 6 significant digits, no exponent noise. */
function num(x: number): string {
  return String(Number(x.toPrecision(6)));
}

/** The tool at the posture, as the surface models take it. */
export function posturedTool(tool: QuestionTool, posture: Posture): ToolInput {
  return {
    toolRadiusMm: tool.toolRadiusMm,
    cornerRadiusMm: tool.cornerRadiusMm,
    leadAngleDeg: posture.leadAngleDeg,
    tiltAngleDeg: posture.tiltAngleDeg,
  };
}

function toolErrors(tool: QuestionTool): QuestionError[] {
  const R = tool.toolRadiusMm;
  const Rcr = tool.cornerRadiusMm;
  const out: QuestionError[] = [];
  if (!(R >= MIN_TOOL_RADIUS_MM && R <= MAX_TOOL_RADIUS_MM))
    out.push({
      field: 'R',
      message: `Tool radius R must be from ${MIN_TOOL_RADIUS_MM} mm to ${MAX_TOOL_RADIUS_MM} mm (got ${shownNumber(R)}).`,
    });
  if (!(Rcr >= 0 && (out.length > 0 || Rcr <= R)))
    out.push({
      field: 'Rcr',
      message: `Corner radius Rcr must be from 0 to the tool radius R (got ${shownNumber(Rcr)}).`,
    });
  return out;
}

/** The target against the surface's limits at the posture (the model's heights and widest step-over). */
function targetErrors(q: Question, tool: ToolInput, pattern: PassPattern): QuestionError[] {
  const model = findSurfaceModel(q.surface.kind);
  if (model === null) return [];
  const { quantity, mm } = q.target;
  const min = quantity === 'h' ? MIN_LENGTH_MM : 2 * MIN_LENGTH_MM;
  const name = quantity === 'h' ? 'Scallop height h' : 'Step-over L';
  if (!(mm >= min))
    return [{ field: quantity, message: `${name} must be at least ${min} mm (got ${shownNumber(mm)}).` }];
  const noScallop = model.leavesNoScallop(tool, q.surface);
  const limit = model.limits(tool, q.surface).limitMm;
  if (quantity === 'h') {
    if (noScallop) return [];
    if (!(limit >= MIN_LENGTH_MM))
      return [
        { field: 'h', message: `${name} cannot be answered here: the tool's side leaves a wall at any step-over.` },
      ];
    return mm < limit
      ? []
      : [
          {
            field: 'h',
            message: `${name} must be below ${num(limit)} mm here (got ${shownNumber(mm)}): above it a flank or the shank leaves a wall.`,
          },
        ];
  }
  const max = noScallop || limit >= MIN_LENGTH_MM ? model.maxIntervalMm(tool, pattern, q.surface) : Number.NaN;
  if (!(max > 0) || !Number.isFinite(max))
    return [
      {
        field: 'interval',
        message: `${name} cannot be answered here: the tool's side leaves a wall at any step-over.`,
      },
    ];
  return mm < max
    ? []
    : [
        {
          field: 'interval',
          message: `${name} must be below ${num(max)} mm here (got ${shownNumber(mm)}): passes this far apart leave a wall.`,
        },
      ];
}

/**
 * Validates a question once: the tool, the mode (registered, its parameters, a posture on this
 * surface), the surface (registered, not gouged at the posture), the pattern and the target against
 * the surface's limits. Every refusal one line naming the constraint (mm, degrees).
 */
export function validateQuestion<M extends ModeDescriptorBase, S extends SurfaceDescriptorBase>(
  q: Question<M, S>,
):
  | { readonly ok: true; readonly value: ValidQuestion }
  | { readonly ok: false; readonly errors: readonly QuestionError[] } {
  const errors = toolErrors(q.tool);
  const mode = findMode(q.mode.kind);
  const model = findSurfaceModel(q.surface.kind);
  if (mode === null) errors.push({ field: 'mode', message: `No machine mode of kind "${q.mode.kind}" is registered.` });
  if (model === null)
    errors.push({ field: 'surface', message: `No surface model of kind "${q.surface.kind}" is registered.` });
  if (q.pattern !== 'one-way' && q.pattern !== 'zigzag')
    errors.push({
      field: 'pattern',
      message: `Pass pattern must be one-way or zigzag (got ${shownNumber(q.pattern)}).`,
    });
  if (mode === null || model === null) return { ok: false, errors };
  errors.push(...mode.check(q.mode, q.surface).map((e) => ({ field: e.parameter, message: e.message })));
  const own = ownAnswerOn(mode, q.mode, q.surface);
  if (own === null && !postureOn(mode, q.surface))
    errors.push({ field: 'surface', message: mode.refusal(q.surface.kind) });
  if (errors.length > 0) return { ok: false, errors };
  const posture = mode.posture(q.mode, q.pattern);
  if (own !== null) {
    const answered = own.answer(q.tool, q.mode, q.surface, q.target);
    return answered.ok ? { ok: true, value: { ...q, posture, answered: answered.value } } : answered;
  }
  const tool = posturedTool(q.tool, posture);
  const fit = model.fit(tool, q.surface);
  if (fit.gouges)
    return {
      ok: false,
      errors: [
        {
          field: 'surface',
          message:
            fit.limitRadiusMm === null
              ? `The surface is gouged by the tool's ${fit.by} at any radius at this posture.`
              : `The surface is gouged by the tool's ${fit.by}: its radius must be at least ${num(Math.abs(fit.limitRadiusMm))} mm at this posture.`,
        },
      ],
    };
  const target = targetErrors(q, tool, posture.pattern);
  if (target.length > 0) return { ok: false, errors: target };
  return { ok: true, value: { ...q, posture } };
}

/** A surface's model and the tool at a posture, with the pattern its passes make: what a model's answers take. */
export interface PosturedModel {
  readonly model: SurfaceModel<SurfaceDescriptorBase>;
  readonly tool: ToolInput;
  readonly posture: Posture;
}

/**
 * The surface's model (registry.ts) and the tool at the posture the mode supplies (modes.ts), for
 * a caller that has validated the question its own way (the worker's doubly curved and three-axis
 * jobs, whose refusals are worded for their views). Throws for a mode or surface kind not
 * registered, or a model that loads on first use and is not loaded yet: programming errors.
 */
export function posturedModel(q: Omit<Question, 'target'>): PosturedModel {
  const mode = findMode(q.mode.kind);
  if (mode === null) throw new Error(`no machine mode registered for kind "${q.mode.kind}"`);
  const model = findSurfaceModel(q.surface.kind);
  if (model === null) throw new Error(`no surface model registered for kind "${q.surface.kind}"`);
  const posture = mode.posture(q.mode, q.pattern);
  return { model, tool: posturedTool(q.tool, posture), posture };
}

/** Answers a validated question: the surface's model at the mode's posture (or the mode's own answer, found by the validation). */
export function answerQuestion(q: ValidQuestion): QuestionAnswer {
  if (q.answered !== undefined) return q.answered;
  const model = findSurfaceModel(q.surface.kind);
  if (model === null) throw new Error(`no surface model registered for kind "${q.surface.kind}"`);
  const tool = posturedTool(q.tool, q.posture);
  const pattern = q.posture.pattern;
  const base = { ...tool, pattern, surface: q.surface };
  const a =
    q.target.quantity === 'h'
      ? model.forward({ ...base, scallopHeightMm: q.target.mm })
      : model.inverse({ ...base, intervalMm: q.target.mm });
  return {
    intervalMm: a.intervalMm,
    cuspHeightMm: a.cuspHeightMm,
    otherCuspHeightMm: a.otherCuspHeightMm,
    halfWidthRightMm: a.halfWidthRightMm,
    halfWidthLeftMm: a.halfWidthLeftMm,
    contactOffsetMm: a.contactOffsetMm,
    posture: q.posture,
    maxIntervalMm: model.maxIntervalMm(tool, pattern, q.surface),
    heightLimitMm: model.limits(tool, q.surface).limitMm,
  };
}

export type { QuestionAnswer, QuestionError, QuestionTarget, QuestionTool };
