/**
 * Each procedure's equations with the current numbers substituted (lengths in the user's unit),
 * and what each assumes. The MathML is typeset at build time (virtual:formula-mathml); the page
 * fills the slots.
 */
import mathml from 'virtual:formula-mathml';
import { unitSymbol } from '../../core/input/units';
import { PROCEDURE_KEYS, PROCEDURES, type ProcedureKey } from '../../core/procedures/procedures';
import { formatSignedLenUnit } from '../format';
import { localDecimal } from '../i18n/langChoice';
import type { FormulaWords, PostureLabel } from '../i18n/teachWords';
import { catalogue } from '../i18n/words';
import { ScrollCues } from '../scrollCue';
import { html, type PageViewContext, type TeachingView, untilted, type ViewContext } from './common';
import { formulaNumber, formulaSlotValues } from './formulaSlots';
import { FORMULA_TEMPLATES, slotClass } from './formulaTemplates';
import { EN_FORMULAS } from './formulaWords';
import { postureFormulaLines } from './threeAxisViewText';

/** The view's words in the language in force (English: formulaWords.ts). */
function words(): FormulaWords {
  return catalogue()?.formulas ?? EN_FORMULAS;
}

/** A text with the language in force's decimal sign. */
function local(text: string): string {
  return localDecimal(text, catalogue());
}

/** A procedure's name in the language in force (English: the registry's). */
function procedureName(key: ProcedureKey, short: boolean): string {
  const names = catalogue()?.procedures.names[key] ?? PROCEDURES[key];
  return short ? names.shortLabel : names.label;
}

export class FormulasView implements TeachingView {
  readonly id = 'formulas';
  readonly title = 'Formulas';
  readonly element = html('div', { class: 'view-formulas', 'data-testid': 'formulas' });
  /** The equations' boxes, shaded at an edge with more of a formula beyond it (scrollCue.ts). */
  private readonly cues = new ScrollCues();

  update(ctx: ViewContext): void {
    const { forward, exact, models } = ctx.data;
    const values = formulaSlotValues({
      R: forward.toolRadiusMm,
      Rcr: forward.cornerRadiusMm,
      rho: forward.leadAngleDeg,
      tilt: forward.tiltAngleDeg,
      h: forward.scallopHeightMm,
      widthRightMm: exact.widthRightMm,
      widthLeftMm: exact.widthLeftMm,
      intervalMm: exact.intervalMm,
      models,
      unit: ctx.unit,
    });
    this.cues.clear();
    this.element.replaceChildren();
    const w = words();
    const lang = catalogue()?.lang;
    if (lang === undefined) this.element.removeAttribute('lang');
    else this.element.lang = lang;
    const tilted = !untilted(ctx);
    const surface = forward.surface;
    if (surface.kind === 'cylinder') {
      // The exact formulas below are the plane's: on a cylinder the exact answer is solved there.
      this.element.append(
        html(
          'p',
          { class: 'view-note', 'data-testid': 'formulas-cylinder-note' },
          local(w.cylinder(formatSignedLenUnit(surface.radiusMm, ctx.unit), surface.axis)),
        ),
      );
    }
    for (const key of PROCEDURE_KEYS) {
      if (key === 'exact' && surface.kind === 'cylinder') continue;
      const slots = values[key];
      if (!slots) continue;
      const info = PROCEDURES[key];
      const box = html('section', { class: 'formula', 'data-procedure': key });
      // Focusable: a wide equation scrolls sideways on a phone or in a narrow embed, and keys must
      // reach it; the edge with more beyond it is shaded.
      const maths = html('div', {
        class: 'maths',
        tabindex: '0',
        role: 'group',
        'aria-label': w.maths(procedureName(key, false)),
      });
      maths.innerHTML = mathml[key]
        .filter((_, i) => {
          const only = FORMULA_TEMPLATES[key][i]?.pattern;
          return only === undefined || only === forward.pattern;
        })
        .join('');
      for (const [name, text] of Object.entries(slots)) {
        // A value it cannot give ("n/a") in the language's words.
        const shown = text === formulaNumber(null) ? (catalogue()?.said.notAvailable ?? text) : local(text);
        for (const el of maths.querySelectorAll(`.${slotClass(name)}`)) el.textContent = shown;
      }
      const about = tilted && info.leadOnly ? `${w.assumes[key]} ${w.leadOnly}` : w.assumes[key];
      const frame = html('div', { class: 'maths-frame' });
      frame.append(maths);
      box.append(html('h3', {}, procedureName(key, false)), html('p', {}, local(about)), frame);
      this.cues.watch(maths, frame);
      this.element.append(box);
    }
    const missing = PROCEDURE_KEYS.filter((k) => !values[k]);
    if (missing.length > 0) {
      this.element.append(
        html(
          'p',
          { class: 'view-note' },
          w.notApplicable(missing.map((k) => procedureName(k, true)).join(catalogue()?.question[', '] ?? ', ')),
        ),
      );
    }
    this.element.append(
      html('p', { class: 'view-note' }, w.units(unitSymbol(ctx.unit), ctx.unit === 'mm' ? '\u00b5m' : 'thou')),
    );
  }

  /**
   * A sloped plane machined three-axis: first the formulas that take the slope and raster angle to
   * the equivalent lead and tilt and L to the programmed step, then the plane's at that posture.
   */
  updateEquivalent(equivalent: ViewContext, page: PageViewContext): void {
    this.update(equivalent);
    if (page.kind !== 'three-axis') return;
    const box = html('section', { class: 'formula', 'data-testid': 'formulas-posture' });
    const list = html('ul', { class: 'posture-formulas' });
    const w = words();
    for (const line of postureFormulaLines(page.data)) {
      const label = w.postureLabels[line.label as PostureLabel] ?? line.label;
      const formula = line.formula === EN_FORMULAS.anglesFormula ? w.anglesFormula : line.formula;
      // An angle's unit: the English "deg" as °, in another language.
      const value = catalogue() === null ? line.value : line.value.replace(/ deg$/, '°');
      list.append(html('li', {}, local(w.postureLine(label, formula, value))));
    }
    box.append(html('h3', {}, w.postureTitle), html('p', {}, w.postureIntro), list);
    this.element.prepend(box);
  }

  highlight(key: ProcedureKey | null): void {
    for (const s of this.element.querySelectorAll<HTMLElement>('section.formula'))
      s.classList.toggle('dimmed', key !== null && s.dataset.procedure !== key);
  }
}
