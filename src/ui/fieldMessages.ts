/**
 * Each field's message as the page shows it: a core error worded in the user's unit (quoting the
 * text as typed) on the field it names, or a message the page words itself on its field. A leaf of
 * the page's builders (fiveAxisRequest.ts, request.ts). Pure.
 */
import { type FieldName, pageKeyOf } from '../core/input/fields';
import type { InputError } from '../core/input/validate';
import { describeError } from './i18n/words';
import type { PageFieldError } from './requestTypes';
import { type CalculatorState, type FieldKey, sizeIsDiameter } from './state';

/**
 * The page field that shows an error of the core's field (the field registry's). Pattern and axis
 * errors cannot happen here (switches offer only valid values); the surface radius's errors
 * (gouging included) show on the radius field.
 */
export const fieldOfError: (field: FieldName) => FieldKey | null = pageKeyOf;

/** Each field's message, in the user's unit, quoting the text as typed. */
export function fieldMessages(
  state: CalculatorState,
  errors: readonly (InputError | PageFieldError)[],
): Map<FieldKey, string> {
  const out = new Map<FieldKey, string>();
  for (const e of errors) {
    if ('key' in e) {
      if (!out.has(e.key)) out.set(e.key, e.message);
      continue;
    }
    const key = pageKeyOf(e.field);
    if (key === null || out.has(key)) continue;
    out.set(
      key,
      describeError(e, state.unit, {
        typed: state.fields[key].trim(),
        toolSizeAsDiameter: sizeIsDiameter(state),
        radiusAsMagnitude: true,
      }),
    );
  }
  return out;
}
