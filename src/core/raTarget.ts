/**
 * A target roughness instead of a scallop height: validation of `Ra` (below the largest Ra the
 * tool can leave, maxRaMm) and the forward input it comes to (h from scallopHeightForRaMm; the
 * step-over and everything else then follow from that h). Lengths mm.
 */
import { maxRaMm, type Roughness, raRuleOfThumbMm, scallopHeightForRaMm } from './roughness';
import {
  describeInputError,
  type ForwardInput,
  forwardInput,
  type InputError,
  type InputErrorCode,
  MIN_LENGTH_MM,
  type PassInput,
  type RawToolInput,
  type Validation,
  validateForward,
} from './validate';

/** Tool, posture, pattern, surface and the target Ra (mm, 0 < Ra < maxRaMm). */
export interface RaTargetInput extends PassInput {
  readonly targetRaMm: number;
}

export interface RawRaTargetInput extends RawToolInput {
  readonly ra: unknown;
}

/** The last maxRaMm asked (the page validates on every keystroke; a solve costs about 1 ms). */
let cached: { key: string; value: number } | null = null;

/** maxRaMm, remembered for the last tool, posture, pattern and surface. */
export function maxRaCachedMm(input: PassInput): number {
  const s = input.surface;
  const key = [
    input.toolRadiusMm,
    input.cornerRadiusMm,
    input.leadAngleDeg,
    input.tiltAngleDeg,
    input.pattern,
    s.kind === 'plane' ? 'plane' : `${s.radiusMm},${s.axis}`,
  ].join('|');
  if (cached?.key !== key) cached = { key, value: maxRaMm(input, input.pattern, input.surface) };
  return cached.value;
}

function raError(code: InputErrorCode, got: string, limit: number | null): InputError {
  const data = { field: 'ra' as const, code, got, limit, side: null, message: '' };
  return { ...data, message: describeInputError(data, 'mm') };
}

/**
 * Validates a target Ra: the tool rules of validateForward, and `Ra` a number of at least
 * MIN_LENGTH_MM below maxRaMm (the Ra of the highest scallop the tool leaves before a wall).
 * The number itself is checked by validateForward as if it were h (so the same words), and
 * errors of h are reported on Ra.
 */
export function validateRaTarget(raw: RawRaTargetInput): Validation<RaTargetInput> {
  const v = validateForward({ ...raw, h: raw.ra });
  const errors: InputError[] = [];
  const got = typeof raw.ra === 'string' ? raw.ra.trim() : String(raw.ra);
  let tooHigh = false;
  for (const e of v.ok ? [] : v.errors) {
    if (e.field !== 'h') errors.push(e);
    else if (e.code === 'flank-wall' || e.code === 'shank-cuts')
      tooHigh = true; // Ra < h always
    else errors.push(raError(e.code, e.got, e.limit));
  }
  // A tool with an error elsewhere has no maxRa to compare with.
  if (errors.length > 0 || !v.ok) {
    if (errors.length > 0 || !tooHigh) return { ok: false, errors };
    // Only an h limit broken (Ra is below h, so Ra is too): the tool is valid; maxRa names the limit.
    const again = validateForward({ ...raw, h: MIN_LENGTH_MM });
    const max = again.ok ? maxRaCachedMm(again.value) : 0;
    return { ok: false, errors: [raError(max > 0 ? 'beyond-max-ra' : 'wall-only', got, max > 0 ? max : null)] };
  }
  const tool = v.value;
  const max = maxRaCachedMm(tool);
  const ra = tool.scallopHeightMm;
  if (!(ra < max)) return { ok: false, errors: [raError('beyond-max-ra', got, max)] };
  return {
    ok: true,
    value: {
      toolRadiusMm: tool.toolRadiusMm,
      cornerRadiusMm: tool.cornerRadiusMm,
      leadAngleDeg: tool.leadAngleDeg,
      tiltAngleDeg: tool.tiltAngleDeg,
      pattern: tool.pattern,
      surface: tool.surface,
      targetRaMm: ra,
    },
  };
}

/** The forward input a valid target Ra comes to: the scallop height whose passes leave that Ra. */
export function forwardOfRaTarget(input: RaTargetInput): ForwardInput {
  const h = scallopHeightForRaMm(input, input.pattern, input.targetRaMm, input.surface);
  return forwardInput(input, input.pattern, h, input.surface);
}

/** Roughness beside the rule of thumb `Ra ~ h/4` (mm; the rule's error in % of the exact Ra). */
export interface RoughnessSummary {
  readonly rzMm: number;
  readonly raMm: number;
  readonly rqMm: number;
  /** The scallop height the rule is applied to (the highest cusp). */
  readonly scallopHeightMm: number;
  readonly ruleOfThumbRaMm: number;
  /** (rule - exact) / exact in %, null when the exact Ra is 0 (no scallop). */
  readonly ruleErrorPercent: number | null;
}

/** A roughness and the rule of thumb at the highest cusp. */
export function roughnessSummary(r: Roughness, scallopHeightMm: number): RoughnessSummary {
  const rule = raRuleOfThumbMm(scallopHeightMm);
  return {
    rzMm: r.rzMm,
    raMm: r.raMm,
    rqMm: r.rqMm,
    scallopHeightMm,
    ruleOfThumbRaMm: rule,
    ruleErrorPercent: r.raMm > 0 ? (100 * (rule - r.raMm)) / r.raMm : null,
  };
}
