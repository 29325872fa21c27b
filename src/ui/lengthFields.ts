/**
 * The page's length fields read as people write them (`1/2`, `1 1/4`, `0.5"`, `12.7 mm`, `5 µm`,
 * `0.2 thou`, `200 uin`: core/input/lengthText.ts), as the plain number in the page's unit that the
 * rest of the page reads. The field keeps the text as typed while it has focus; the question, the
 * link and the committed field hold the plain number. Pure (no DOM).
 */
import { parseLengthText } from '../core/input/lengthText';
import { type CalculatorState, FIELD_KEYS, type FieldKey, formatField, isLengthField } from './state';

/**
 * The plain number (in the page's unit, 6 significant digits as the fields show numbers) a length
 * field's text means when it is written with a fraction or a unit; null for a plain number, text
 * that is not a length (it keeps its usual message), and any field that is not a length.
 */
export function plainLengthText(state: CalculatorState, key: FieldKey): string | null {
  if (!isLengthField(key)) return null;
  const read = parseLengthText(state.fields[key], state.unit);
  return read.ok && read.written ? formatField(read.value) : null;
}

/** The state with every length field written with a fraction or a unit replaced by its plain number. */
export function plainLengths(state: CalculatorState): CalculatorState {
  let fields: Record<FieldKey, string> | null = null;
  for (const key of FIELD_KEYS) {
    const plain = plainLengthText(state, key);
    if (plain === null) continue;
    fields ??= { ...state.fields };
    fields[key] = plain;
  }
  return fields === null ? state : { ...state, fields };
}
