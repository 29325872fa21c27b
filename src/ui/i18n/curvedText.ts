/**
 * A doubly curved point's refusals in the language in force (issue 30): the worker's data (the
 * field, the bound, the limiting flank or shank, the radius limit with the other radius held)
 * worded from the catalogue's CurvedWords, the fields named as the page names them, lengths in the
 * user's unit with the locale's decimal sign, what was typed quoted; the target Ra's bound as the
 * input errors word it. English is curvedRequest.ts's describeCurvedError. Loaded with a catalogue.
 */
import { quotedEntry } from '../../core/input/entryMessages';
import { formatInputNumber, fromMm, unitSymbol } from '../../core/input/units';
import type { InputError } from '../../core/input/validate';
import type { CurvedError } from '../../worker/pageProtocol';
import type { PageFieldError } from '../requestTypes';
import type { CalculatorState } from '../state';
import type { Catalogue, CurvedWords } from './catalogue';
import { describeInputErrorIn } from './errorText';
import { localDecimal } from './langChoice';

/** What was typed, shortened as the English messages quote it. */
const typed = (text: string) => {
  const t = text.trim();
  return quotedEntry(t);
};

/** One doubly curved refusal in `c`'s language (`w` its CurvedWords), on its field. */
export function curvedMessageIn(c: Catalogue, w: CurvedWords, e: CurvedError, state: CalculatorState): PageFieldError {
  const unit = state.unit;
  const len = (mm: number) => localDecimal(`${formatInputNumber(fromMm(mm, unit))} ${unitSymbol(unit)}`, c);
  if (e.field === 'ra') {
    const got = state.fields.ra.trim();
    const error = { field: 'ra', code: 'beyond-max-ra', got, limit: e.maxMm, message: '' } as InputError;
    return { key: 'ra', message: describeInputErrorIn(c, error, unit, { typed: got }).replace(...w.atPoint) };
  }
  if (e.field === 'interval')
    return { key: 'L', message: w.beyondMax(c.fields.L.label, len(e.maxMm), typed(state.fields.L)) };
  if (e.field === 'h') {
    const shank = e.limitBy === 'shank-right' || e.limitBy === 'shank-left';
    const right = e.limitBy === 'right-flank' || e.limitBy === 'shank-right';
    return { key: 'h', message: w.aboveLimit(c.fields.h.label, len(e.limitMm), typed(state.fields.h), shank, right) };
  }
  const key = e.field === 'feedRadius' ? 'Rf' : 'Rc';
  const label = c.fields[key].label;
  const side = key === 'Rf' ? state.feedSide : state.crossSide;
  const got = typed(`${state.fields[key].trim()}${side === 'straight' ? '' : `, ${c.question[side]}`}`);
  if (e.code === 'out-of-range') return { key, message: w.outOfRange(label, len(0.001), len(1e6), got) };
  const other = key === 'Rf' ? 'Rc' : 'Rf';
  const held = w.held(
    other,
    Number.isFinite(e.otherMm) ? `${e.otherMm < 0 ? '-' : ''}${len(Math.abs(e.otherMm))}` : null,
  );
  const kind = e.limit.kind;
  const known = kind === 'concave-at-least' || kind === 'convex-at-most' || kind === 'not-concave' ? kind : 'other';
  return { key, message: w.gouging(known, label, len(e.limit.radiusMm ?? 0), held, got) };
}

/**
 * A radius field's own error in `c`'s language (`w` its CurvedWords): empty, not a number (`value`
 * null), a sign or 0 typed.
 */
export function radiusFieldIn(
  c: Catalogue,
  w: CurvedWords,
  key: 'Rf' | 'Rc',
  text: string,
  value: number | null,
): PageFieldError {
  const label = c.fields[key].label;
  const message =
    text === ''
      ? w.missing(label)
      : value === null
        ? w.notNumber(label, quotedEntry(text))
        : w.positive(label, typed(text));
  return { key, message };
}
