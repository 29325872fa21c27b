/**
 * Each procedure's equations with the current numbers substituted (lengths in the user's unit),
 * and what each assumes. The MathML is typeset at build time (virtual:formula-mathml); the page
 * fills the slots.
 */
import mathml from 'virtual:formula-mathml';
import { unitSymbol } from '../../core/input/units';
import { PROCEDURE_KEYS, PROCEDURES, type ProcedureKey } from '../../core/procedures/procedures';
import { formatSignedLenUnit } from '../format';
import { ScrollCues } from '../scrollCue';
import { html, type PageViewContext, type TeachingView, untilted, type ViewContext } from './common';
import { formulaSlotValues } from './formulaSlots';
import { FORMULA_TEMPLATES, slotClass } from './formulaTemplates';
import { postureFormulaLines } from './threeAxisViewText';

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
    const tilted = !untilted(ctx);
    const surface = forward.surface;
    if (surface.kind === 'cylinder') {
      // The exact formulas below are the plane's: on a cylinder the exact answer is solved there.
      this.element.append(
        html(
          'p',
          { class: 'view-note', 'data-testid': 'formulas-cylinder-note' },
          `On a cylinder (Rs = ${formatSignedLenUnit(surface.radiusMm, ctx.unit)}, axis ${surface.axis === 'feed' ? 'along' : 'across'} the feed) the exact step-over is solved on the cylinder itself (the flanks' reach at the radial height h, ${surface.axis === 'feed' ? 'as angles about its axis' : 'of the tool revolved about its axis'}), not by the plane's formulas, so they are left out. The approximations below are as on a plane; the table's corrected rows put 1/rho = 1/Reff + 1/Rs into L = 2 sqrt(2 rho h - h^2).`,
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
        'aria-label': `${info.label}: equations (a wide one scrolls sideways)`,
      });
      maths.innerHTML = mathml[key]
        .filter((_, i) => {
          const only = FORMULA_TEMPLATES[key][i]?.pattern;
          return only === undefined || only === forward.pattern;
        })
        .join('');
      for (const [name, text] of Object.entries(slots)) {
        for (const el of maths.querySelectorAll(`.${slotClass(name)}`)) el.textContent = text;
      }
      const about =
        tilted && info.leadOnly
          ? `${info.assumes} Lead-only model: applied with the lead angle alone, the tilt ignored.`
          : info.assumes;
      const frame = html('div', { class: 'maths-frame' });
      frame.append(maths);
      box.append(html('h3', {}, info.label), html('p', {}, about), frame);
      this.cues.watch(maths, frame);
      this.element.append(box);
    }
    const missing = PROCEDURE_KEYS.filter((k) => !values[k]);
    if (missing.length > 0) {
      this.element.append(
        html(
          'p',
          { class: 'view-note' },
          `${missing.map((k) => PROCEDURES[k].shortLabel).join(', ')}: not applicable here (see the notes under the results table).`,
        ),
      );
    }
    this.element.append(
      html(
        'p',
        { class: 'view-note' },
        `Lengths in ${unitSymbol(ctx.unit)} (small ones in ${ctx.unit === 'mm' ? '\u00b5m' : 'thou'}), angles in degrees; each L/2 is at the h of the current state.`,
      ),
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
    for (const line of postureFormulaLines(page.data))
      list.append(html('li', {}, `${line.label}: ${line.formula}, so ${line.value}`));
    box.append(
      html('h3', {}, 'Posture from the slope (three-axis)'),
      html(
        'p',
        {},
        "The upright tool on the sloped plane is the tool at this lead and tilt on a plane; the formulas below are the plane's at that posture.",
      ),
      list,
    );
    this.element.prepend(box);
  }

  highlight(key: ProcedureKey | null): void {
    for (const s of this.element.querySelectorAll<HTMLElement>('section.formula'))
      s.classList.toggle('dimmed', key !== null && s.dataset.procedure !== key);
  }
}
