/**
 * A language's word (issue 30), from text: small, so the page's first script can read a link's
 * `lang=` before the language's code loads (app.ts), with langChoice.ts's rules.
 */
import { FIELDS } from '../../core/input/fields';
import type { Lang } from './catalogue';

/** The languages, as the registry names them. */
export const LANGS: readonly Lang[] = FIELDS.lang.values;

/** The word of a language in `text` (exactly one of the registry's), or null. */
export function langOf(text: unknown): Lang | null {
  // A language tag as HTML's lang attribute and browsers write it: `de-DE`, `DE`, `ja_JP`.
  const primary = typeof text === 'string' ? text.trim().toLowerCase().split(/[-_]/)[0] : null;
  return LANGS.find((l) => l === primary) ?? null;
}
