/**
 * Build step: typesets the formula templates to MathML with Temml, in Node, so that the
 * page ships plain MathML strings (a few kB) instead of a TeX engine (about 60 kB gzip).
 * Each `{{name}}` slot becomes `<mn class="slot-name">`, which the page fills in.
 */
import temml from 'temml';
import type { Plugin } from 'vite';
import { FORMULA_TEMPLATES, SLOT_PATTERN, slotClass } from '../ui/views/formulaTemplates.ts';

export const FORMULA_MODULE_ID = 'virtual:formula-mathml';
const RESOLVED_ID = `\0${FORMULA_MODULE_ID}`;

/** Typesets one template (display mode); a TeX error throws, so a broken formula fails the build. */
export function renderFormulaTemplate(template: string): string {
  const tex = template.replace(SLOT_PATTERN, (_all, name: string) => `\\class{${slotClass(name)}}{0}`);
  return temml.renderToString(tex, { displayMode: true, throwOnError: true, trust: true });
}

/** Every template typeset, keyed like FORMULA_TEMPLATES. */
export function renderAllFormulas(): Record<string, string[]> {
  return Object.fromEntries(
    Object.entries(FORMULA_TEMPLATES).map(([key, lines]) => [key, lines.map(renderFormulaTemplate)]),
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
