/**
 * The language a visit starts in (issue 30), from text only (no DOM, so it is checked in Node): a
 * link's `lang=` (the field registry's), else the language remembered (read as untrusted), else
 * the browser's first language the page has, else English.
 */
import { FIELDS } from '../../core/input/fields';
import type { ToolStorage } from '../savedTools';
import type { Catalogue, Lang } from './catalogue';
import { LANGS, langOf } from './langOf';

export { LANGS, langOf } from './langOf';

/** The storage key of the chosen language (versioned). */
export const LANGUAGE_KEY = 'path-interval.language.v1';

/** The language chosen on an earlier visit, as stored (read as untrusted: langOf checks it), or null. */
export function storedLanguage(storage: ToolStorage | null): string | null {
  try {
    return storage?.getItem(LANGUAGE_KEY) ?? null;
  } catch {
    return null;
  }
}

/** The browser's first language the page has (`de-AT` is German), or null. */
export function browserLang(languages: readonly string[]): Lang | null {
  for (const tag of languages) {
    const lang = langOf(tag);
    if (lang !== null) return lang;
  }
  return null;
}

/** The language a visit starts in, and a notice when the link's `lang=` is not one. */
export function chooseLang(
  search: string,
  stored: string | null,
  languages: readonly string[],
): { readonly lang: Lang; readonly fromLink: boolean; readonly notice: string | null } {
  const text = new URLSearchParams(search).get(FIELDS.lang.url);
  const linked = langOf(text);
  if (linked !== null) return { lang: linked, fromLink: true, notice: null };
  const fallback = langOf(stored) ?? browserLang(languages) ?? 'en';
  const notice =
    text === null || text.trim() === ''
      ? null
      : `${FIELDS.lang.url}="${text.slice(0, 20)}" is not ${LANGS.slice(0, -1).join(', ')} or ${LANGS.at(-1)}; showing ${fallback}.`;
  return { lang: fallback, fromLink: false, notice };
}

/**
 * A number as the page shows it in `catalogue`'s language: its decimal point becomes the locale's
 * decimal sign (Intl's: German `2,8872 mm`). Only the sign changes: every digit the length rule
 * keeps stays (no rounding, no grouping separator: the number may be pasted into CAM). Copy and
 * the link keep the point (copy.ts's data-copy, state.ts).
 */
export function localDecimal(text: string, catalogue: Pick<Catalogue, 'lang'> | null): string {
  const sign =
    catalogue === null
      ? '.'
      : (new Intl.NumberFormat(catalogue.lang).formatToParts(0.5).find((p) => p.type === 'decimal')?.value ?? '.');
  return sign === '.' ? text : text.replace(/(\d)\.(\d)/g, `$1${sign}$2`);
}
