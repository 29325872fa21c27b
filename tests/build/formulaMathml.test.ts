import { describe, expect, it } from 'vitest';
import {
  FORMULA_MODULE_ID,
  formulaMathmlPlugin,
  renderAllFormulas,
  renderFormulaTemplate,
} from '../../src/build/formulaMathml';
import { PROCEDURE_KEYS } from '../../src/core/procedures/procedures';
import { FORMULA_TEMPLATES, slotClass, slotNames } from '../../src/ui/views/formulaTemplates';

describe('formula MathML, typeset at build time', () => {
  it('every template becomes one MathML block with one slot element per placeholder and no TeX left', () => {
    for (const [key, lines] of Object.entries(FORMULA_TEMPLATES)) {
      for (const { tex: template } of lines) {
        const out = renderFormulaTemplate(template);
        expect(out, `${key}: ${template}`).toMatch(/^<math display="block"[^>]*>.*<\/math>$/s);
        expect(out.match(/<math /g)?.length).toBe(1);
        expect(out).not.toMatch(/\\|\{\{|#b22222/); // no raw TeX, no slot syntax, no Temml error colour
        for (const name of new Set(slotNames(template))) {
          const inTemplate = slotNames(template).filter((n) => n === name).length;
          const inOutput = out.split(`class="${slotClass(name)}"`).length - 1;
          expect(inOutput, `${key}: slot ${name}`).toBe(inTemplate);
        }
      }
    }
  });

  it('no inline style attribute anywhere: the page runs under a CSP without style-src-attr', () => {
    for (const lines of Object.values(renderAllFormulas()))
      for (const out of lines) expect(out).not.toMatch(/\sstyle=/);
  });

  it('a TeX error fails the build instead of shipping a red formula', () => {
    expect(() => renderFormulaTemplate('\\frac{1}{')).toThrow();
  });

  it('the Vite plugin serves the virtual module with every procedure of the registry typeset', () => {
    const plugin = formulaMathmlPlugin();
    const resolveId = plugin.resolveId as (id: string) => string | undefined;
    const load = plugin.load as (id: string) => string | undefined;
    const id = resolveId(FORMULA_MODULE_ID);
    expect(id).toBeDefined();
    expect(resolveId('./other')).toBeUndefined();
    const code = load(id as string);
    expect(code?.startsWith('export default ')).toBe(true);
    const served = JSON.parse((code as string).slice('export default '.length).replace(/;$/, ''));
    expect(served).toEqual(renderAllFormulas());
    expect(Object.keys(served).sort()).toEqual([...PROCEDURE_KEYS].sort());
  });
});
