/**
 * Build step: typesets the formula templates to MathML with Temml, in Node, so that the
 * page ships plain MathML strings (a few kB) instead of a TeX engine (about 60 kB gzip).
 * Each `{{name}}` slot becomes `<mn class="slot-name">`, which the page fills in. Temml's inline
 * `style` attributes are removed (the stylesheet gives `math` its display), so the page runs
 * under a Content-Security-Policy without `style-src-attr`.
 */
import temml from 'temml';
import type { Plugin } from 'vite';
import { FORMULA_TEMPLATES, SLOT_PATTERN, slotClass } from '../ui/views/formulaTemplates.ts';

export const FORMULA_MODULE_ID = 'virtual:formula-mathml';
const RESOLVED_ID = `\0${FORMULA_MODULE_ID}`;

/** Removes inline style attributes (Temml writes `style="display:block math;"` on `<math>`). */
export function withoutStyleAttributes(markup: string): string {
  return markup.replace(/\sstyle="[^"]*"/g, '');
}

/** Typesets one template (display mode); a TeX error throws, so a broken formula fails the build. */
export function renderFormulaTemplate(template: string): string {
  const tex = template.replace(SLOT_PATTERN, (_all, name: string) => `\\class{${slotClass(name)}}{0}`);
  return withoutStyleAttributes(temml.renderToString(tex, { displayMode: true, throwOnError: true, trust: true }));
}

/** Every template typeset, keyed like FORMULA_TEMPLATES (one string per line, in order). */
export function renderAllFormulas(): Record<string, string[]> {
  return Object.fromEntries(
    Object.entries(FORMULA_TEMPLATES).map(([key, lines]) => [
      key,
      lines.map((line) => renderFormulaTemplate(line.tex)),
    ]),
  );
}

/** Vite plugin serving `virtual:formula-mathml` (default export: procedure key -> MathML strings). */
export function formulaMathmlPlugin(): Plugin {
  return {
    name: 'formula-mathml',
    resolveId(id) {
      return id === FORMULA_MODULE_ID ? RESOLVED_ID : undefined;
    },
    load(id) {
      return id === RESOLVED_ID ? `export default ${JSON.stringify(renderAllFormulas())};` : undefined;
    },
  };
}
