/**
 * The one validation of a target Sa (issue 29; the inverse itself is targetSa.ts), apart from its
 * solver so that the page's first script can take it without the teeth's surface code. Lengths mm.
 */
import type { PassInput } from '../domain/pass';
import type { AnyInputError, Validation } from '../input/inputErrors';
import type { RawToolInput } from '../input/validate';
import { validateTargetRa } from './roughness';

/** Raw values of a target Sa (mm and degrees): the tool, pattern, surface and the target. */
export interface RawTargetSaInput extends RawToolInput {
  readonly sa: unknown;
}

/** A validated target Sa: the pass and the Sa (mm) its pairs must leave. */
export interface TargetSaInput extends PassInput {
  /** Target Sa in mm: at least 1e-9 mm, below the largest Ra of the pass (Sa -> Ra as fz -> 0). */
  readonly targetSaMm: number;
}

/**
 * Validates a target Sa: the tool rules and the bound of a target Ra (validateTargetRa: the same
 * limit, since Sa tends to the cross-feed Ra as fz -> 0 and the pairs need L0), each error naming
 * the target Sa field. The one validation of a target Sa, for the command line and the page.
 * @param maxRa the largest Ra of a valid pass (the page passes a cached one).
 */
export function validateTargetSa(
  raw: RawTargetSaInput,
  maxRa?: (pass: PassInput) => number,
): Validation<TargetSaInput, AnyInputError> {
  const v = validateTargetRa({ ...raw, ra: raw.sa }, maxRa);
  if (!v.ok) return { ok: false, errors: v.errors.map((e) => (e.field === 'ra' ? { ...e, field: 'targetSa' } : e)) };
  const { targetRaMm, ...pass } = v.value;
  return { ok: true, value: { ...pass, targetSaMm: targetRaMm } };
}
