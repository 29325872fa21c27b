/**
 * The page's language in force and its words (issue 30): null is English, the page as written.
 * Read by the modules that write words (fields.ts, results.ts); set by language.ts once a
 * catalogue has loaded, with the pass that puts the results into its words. Small: it loads with
 * the first result; what only another language needs loads with language.ts.
 */
import type { Catalogue, FieldWords } from './catalogue';

let current: Catalogue | null = null;
/** Puts the results drawn in English into the language in force (language.ts's), or none. */
let localizer: ((root: ParentNode) => void) | null = null;

/** Makes `catalogue` (null: English) the page's words, `results` the pass over the drawn results. */
export function setCatalogue(catalogue: Catalogue | null, results: ((root: ParentNode) => void) | null): void {
  current = catalogue;
  localizer = catalogue === null ? null : results;
}

/** The catalogue in force, or null for English. */
export function catalogue(): Catalogue | null {
  return current;
}

/** A field's words in the language in force, from its English ones. */
export function fieldWords(key: keyof Catalogue['fields'], english: FieldWords): FieldWords {
  return current?.fields[key] ?? english;
}

/** Puts the results just drawn (in English) under `root` into the language in force; nothing in English. */
export function localize(root: ParentNode): void {
  localizer?.(root);
}
