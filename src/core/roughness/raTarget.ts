/**
 * A target roughness instead of a scallop height: validation of `Ra` (below the largest Ra the
 * tool can leave, maxRaMm) and the forward input it comes to (h from scallopHeightForRaMm; the
 * step-over and everything else then follow from that h). Lengths mm.
 */

import type { ForwardInput, PassInput } from '../domain/pass';
import { PASS_FIELDS } from '../input/fields';
import { rawOf } from '../input/raw';
import { forwardInput, type Validation } from '../input/validate';
import {
  maxRaMm,
  type RawTargetRaInput,
  type Roughness,
  raRuleOfThumbMm,
  scallopHeightForRaMm,
  type TargetRaInput,
  validateTargetRa,
} from './roughness';

/** Tool, posture, pattern, surface and the target Ra (mm, 0 < Ra < maxRaMm). */
export type RaTargetInput = TargetRaInput;

/** Raw values of a target Ra (as typed). */
export type RawRaTargetInput = RawTargetRaInput;

/**
 * The last maxRaMm asked (a solve costs about 1 ms): the worker validates a target Ra and ranges the
 * Ra slider with it, one solve for both, and the same pass comes again while the Ra alone changes.
 */
let cached: { key: string; value: number } | null = null;

/** maxRaMm, remembered for the last tool, posture, pattern and surface. */
export function maxRaCachedMm(input: PassInput): number {
  // Every field of the pass, by the field registry's names (a plane has no surface fields).
  const key = JSON.stringify(rawOf(input, PASS_FIELDS));
  if (cached?.key !== key) cached = { key, value: maxRaMm(input, input.pattern, input.surface) };
  return cached.value;
}

/**
 * Validates a target Ra for the page's worker: {@link validateTargetRa} (the one validation, shared
 * with the command line) with maxRaMm remembered for the last pass (asked on every keystroke).
 */
export function validateRaTarget(raw: RawRaTargetInput): Validation<RaTargetInput> {
  // Its errors name the tool, pass and Ra fields only (never a doubly curved point's radii).
  return validateTargetRa(raw, maxRaCachedMm) as Validation<RaTargetInput>;
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
