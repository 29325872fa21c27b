/**
 * The worker trusts no caller: a request's input is validated again, from the fields the field
 * registry reads back from it (each field's core property), as the page, the command line and the
 * batch validate theirs.
 */
import { PASS_FIELDS } from '../../core/input/fields';
import { rawOf } from '../../core/input/raw';
import type { InputError } from '../../core/input/validate';
import { validateRaTarget } from '../../core/roughness/raTarget';
import { validateForward, validateInverse } from '../../core/surfaces/validate';
import { QUESTION_FIELD, type SolveRequest } from '../protocol';

/** The request's input validated again, or its errors (null when it is valid). */
export function revalidate(request: SolveRequest): readonly InputError[] | null {
  const i = request.input;
  const v =
    request.mode === 'forward'
      ? validateForward(rawOf(i, [...PASS_FIELDS, QUESTION_FIELD.forward]))
      : request.mode === 'ra'
        ? validateRaTarget(rawOf(i, [...PASS_FIELDS, QUESTION_FIELD.ra]))
        : validateInverse(rawOf(i, [...PASS_FIELDS, QUESTION_FIELD.inverse]));
  return v.ok ? null : v.errors;
}
