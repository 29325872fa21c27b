/**
 * A machine mode (issue 27 point 3): not a surface, but what supplies the tool's posture at the
 * cutter-contact point over a surface model (surface.ts). Five-axis takes the lead and tilt as
 * given; a mode that keeps the tool upright derives them from the slope and the raster angle
 * (modes/). One module per mode under modes/, one line in modes.ts's registry, beside
 * the registry of surfaces (registry.ts): a question is a tool, a mode, a surface, a pattern and a
 * target (question.ts), validated once. Types, and how a refused number is quoted. Angles degrees.
 */
import type { SurfaceDescriptorBase } from '../domain/surface';
import type { PassPattern } from '../domain/tool';
import type { FieldId } from '../input/fields';

/**
 * A number a mode's or a surface's descriptor takes from the user: the descriptor's property and the
 * field of the field registry (input/fields.ts) that gives it, so that the page's and the command
 * line's builders read it with no code of their own (lengths in the user's unit, converted to mm).
 */
export interface QuestionParameter {
  /** The descriptor's property (leadAngleDeg, slopeDeg, radiusMm...). */
  readonly name: string;
  /** The field that gives it. */
  readonly field: FieldId;
}

/** A number as a refusal quotes it: `(got ...)` never shows NaN or Infinity (said in words instead). */
export function shownNumber(x: unknown): string {
  if (typeof x !== 'number') return `"${String(x).slice(0, 24)}"`;
  return Number.isFinite(x) ? String(x) : 'no finite number';
}

/** What every machine mode descriptor has: its kind, the key of its mode in modes.ts. */
export interface ModeDescriptorBase {
  readonly kind: string;
}

/** The tool's posture for one question: lead and tilt at the contact (degrees), and the pattern its passes make. */
export interface Posture {
  readonly leadAngleDeg: number;
  readonly tiltAngleDeg: number;
  /** The pattern the passes make: an upright tool's passes are one-way whichever way they feed. */
  readonly pattern: PassPattern;
}

/** One of a mode's own parameters refused: its name and one line naming the constraint. */
export interface ModeError {
  readonly parameter: string;
  readonly message: string;
}

/** The tool's radii, mm. */
export interface QuestionTool {
  readonly toolRadiusMm: number;
  readonly cornerRadiusMm: number;
}

/** What is given: a scallop height h (forward) or a step-over L (inverse), mm. */
export interface QuestionTarget {
  readonly quantity: 'h' | 'interval';
  readonly mm: number;
}

/** A refused part of a question: what it names (R, Rcr, a mode parameter, surface, h, interval) and one line. */
export interface QuestionError {
  readonly field: string;
  readonly message: string;
}

/**
 * The answer of a question (mm), measured as the surface measures (surface.ts's ForwardAnswer).
 * The per-flank parts (each flank's reach and the contact offset) are null where adjacent passes
 * are not congruent (a mode's own answer: waterline passes on a surface of revolution), which only
 * congruent passes define.
 */
export interface QuestionAnswer {
  readonly intervalMm: number;
  readonly cuspHeightMm: number;
  readonly otherCuspHeightMm: number | null;
  readonly halfWidthRightMm: number | null;
  readonly halfWidthLeftMm: number | null;
  readonly contactOffsetMm: number | null;
  /** The posture the mode supplied at this pass's contact (degrees) and the pattern the passes make. */
  readonly posture: Posture;
  /** The widest step-over that still leaves a scallop (null where the mode's own answer does not give it), and the highest scallop. */
  readonly maxIntervalMm: number | null;
  readonly heightLimitMm: number;
}

/**
 * A mode's own answer on a surface where its passes are not congruent (one pass is not the previous
 * one moved rigidly, so no surface model at one posture answers it): its own solver validates and
 * answers at once.
 */
export interface OwnAnswer<M extends ModeDescriptorBase> {
  /** The surface kind it answers on. */
  readonly surfaceKind: string;
  /** True for the descriptors it answers (waterline passes, say); the others take the mode's refusal. */
  applies(mode: M): boolean;
  /** The answer, or the errors of its own validation, each one line. */
  answer(
    tool: QuestionTool,
    mode: M,
    surface: SurfaceDescriptorBase,
    target: QuestionTarget,
  ):
    | { readonly ok: true; readonly value: QuestionAnswer }
    | { readonly ok: false; readonly errors: readonly QuestionError[] };
}

/** A machine mode: the posture it supplies, on the surfaces it supplies one for. */
export interface MachineMode<M extends ModeDescriptorBase> {
  /** The descriptor kind it answers (the registry's key). */
  readonly kind: M['kind'];
  /**
   * The word a user names it by (the command line's `--machine`); its kind when absent. The
   * product's modes are named by the command line itself (cli/registryOptions.ts), so that their
   * words stay out of the page's scripts.
   */
  readonly name?: string;
  /**
   * The numbers its descriptor takes from the user, for the builders of a question over the
   * registries (ui/questionRequest.ts, the command line's --machine): the fields that give them.
   */
  readonly parameters?: readonly QuestionParameter[];
  /** The surface kinds it has a posture on; null: every registered surface. */
  readonly surfaceKinds: readonly string[] | null;
  /** Its own parameters' errors (ranges, on this surface), one line each; empty when they are valid. */
  check(mode: M, surface: SurfaceDescriptorBase): readonly ModeError[];
  /** The posture for a checked descriptor and the pattern asked. */
  posture(mode: M, pattern: PassPattern): Posture;
  /** Its own answers on surfaces where its passes are not congruent (none: every answer is a posture's). */
  readonly ownAnswers?: readonly OwnAnswer<M>[];
  /** One line naming the constraint, for a surface kind it has no posture on. */
  refusal(surfaceKind: string): string;
}
