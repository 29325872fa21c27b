/**
 * A chart gap's reason in a language (issue 30): the core's sentence (core/procedures/sweepGaps.ts
 * noAnswerReason: a model's own reason, or h above the widest point of its circle or ellipse) read
 * back against the English words (chartWords.ts) and worded from `words`; null for a sentence not
 * known (the chart then keeps it English, marked so). tests/ui/i18n/gapReasons.test.ts makes every
 * reason the core gives and reads it back. Loaded with the teaching views.
 */
import type { ChartWords, GapReason } from '../i18n/catalogue';
import { EN_CHART } from './chartWords';

/** The English of h above the widest point: its shape and its symbol (EN_CHART.widest's). */
const WIDEST = /^h is above the widest point of its (circle|ellipse) \(its (?:radius|height) (.+) is below h\)$/;

/** `reason` (the core's English) in `words`' language, or null when it is not one the page knows. */
export function gapReasonIn(reason: string, words: ChartWords): string | null {
  const widest = WIDEST.exec(reason);
  if (widest !== null) {
    const shape = widest[1] === 'circle' ? 'circle' : 'ellipse';
    const symbol = widest[2] ?? '';
    return EN_CHART.widest(shape, symbol) === reason ? words.widest(shape, symbol) : null;
  }
  const key = (Object.keys(EN_CHART.reasons) as GapReason[]).find((k) => EN_CHART.reasons[k] === reason);
  return key === undefined ? null : words.reasons[key];
}
