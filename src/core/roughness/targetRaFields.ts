/**
 * A target roughness's own checks (issue 27 point 4: the page validates, the worker solves): Ra a
 * length of at least MIN_LENGTH_MM, after the tool, pattern and surface (a PassValidation: the
 * page's passFieldsAnd, or validatePassAnd with gouging). What needs a solver, a posture that cuts a
 * step only and an Ra beyond the largest the passes leave, roughness.ts's validateTargetRa checks
 * after these. Lengths mm.
 */
import type { PassInput } from '../domain/pass';
import type { PassValidation } from '../input/passFields';
import { type AnyInputError, inputError, MIN_LENGTH_MM, type RawToolInput, type Validation } from '../input/validate';

/** Raw values of the target-roughness problem (mm and degrees): the tool, pattern, surface and a target Ra. */
export interface RawTargetRaInput extends RawToolInput {
  readonly ra: unknown;
}

/** A validated target roughness: the pass and the Ra (mm) its passes must leave. */
export interface TargetRaInput extends PassInput {
  /** Target Ra in mm: at least {@link MIN_LENGTH_MM}, below maxRaMm of the pass. */
  readonly targetRaMm: number;
}

/** A target Ra's fields checked: their errors, the valid pass, Ra as given (mm) and as shown. */
export interface TargetRaFields {
  readonly errors: readonly AnyInputError[];
  readonly pass: PassInput | null;
  readonly ra: number | undefined;
  readonly shown: string;
  /** True when the pass is valid and Ra a length of at least MIN_LENGTH_MM: the solver's checks come next. */
  readonly toSolve: boolean;
}

/** The checks of a target Ra that need no solver, after its pass's (`v`, of the field `ra`): validateTargetRa's first part. */
export function targetRaFields(v: PassValidation): TargetRaFields {
  const errors = [...v.errors];
  const ra = v.value;
  let toSolve = false;
  if (ra !== undefined && !v.gouges) {
    if (ra <= 0) errors.push(inputError('ra', 'not-positive', v.shown));
    else if (ra < MIN_LENGTH_MM) errors.push(inputError('ra', 'too-small', v.shown, MIN_LENGTH_MM));
    else toSolve = v.pass !== null;
  }
  return { errors, pass: v.pass, ra, shown: v.shown, toSolve };
}

/**
 * The target Ra's input once its checks found no error (the fields' and, where the caller made
 * them, the solver's); else the errors.
 */
export function targetRaValidation(
  f: TargetRaFields,
  errors: readonly AnyInputError[] = f.errors,
): Validation<TargetRaInput, AnyInputError> {
  if (errors.length > 0 || f.pass === null || f.ra === undefined) return { ok: false, errors: [...errors] };
  const p = f.pass;
  return {
    ok: true,
    value: {
      toolRadiusMm: p.toolRadiusMm,
      cornerRadiusMm: p.cornerRadiusMm,
      leadAngleDeg: p.leadAngleDeg,
      tiltAngleDeg: p.tiltAngleDeg,
      pattern: p.pattern,
      surface: p.surface,
      targetRaMm: f.ra,
    },
  };
}
