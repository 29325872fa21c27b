/**
 * Each procedure's equations with the current numbers substituted, and what each assumes.
 * The MathML is typeset at build time (virtual:formula-mathml); the page fills the slots.
 */
import mathml from 'virtual:formula-mathml';
import type { ProcedureKey } from '../../worker/protocol';
import { COLOURS, html, LABELS, PROCEDURE_KEYS, type TeachingView, type ViewContext } from './common';
import { formulaSlotValues, slotClass } from './formulaTemplates';

const TEXTS: Readonly<Record<ProcedureKey, string>> = {
  exact:
    'True 3D: the tool moves along X, so the surface it leaves is its projection along X: the ring ellipse (semi-axes Rb and Rb sin rho) offset by Rcr. L/2 is where that exact profile stands h above its lowest point; one 1-D root in the normal angle theta. Valid for every rho, including 0, and for ball and flat ends.',
  sekine:
    "True-circular approximation (Eqs. 4-8): an ellipse from the tool centre height, replaced by one circle of radius Reff. It ignores where the real profile's curvature changes, so it is far off for small rho.",
  redonnet:
    'Osculating circle at the lowest point (Eqs. 9, 8): exact as h tends to 0, then it overestimates L/2 because the real profile curves up faster than its lowest-point circle.',
  bedi: 'Elliptic projection (Eqs. 10-11): one ellipse with semi-axes Rlong and Rlong sin rho stands for the offset ellipse. Close for these tools, but an offset ellipse is not an ellipse, so a small error remains; it breaks down at rho = 0.',
};

export class FormulasView implements TeachingView {
  readonly id = 'formulas';
  readonly title = 'Formulas';
  readonly element = html('div', { class: 'view-formulas', 'data-testid': 'formulas' });

  update(ctx: ViewContext): void {
    const t = ctx.reply.teaching;
    if (!t) return;
    const values = formulaSlotValues({
      R: ctx.R,
      Rcr: ctx.Rcr,
      rho: ctx.rho,
      h: ctx.reply.scallopHeightMm,
      exactHalfMm: ctx.reply.halfIntervalMm,
      models: t.models,
    });
    this.element.replaceChildren();
    for (const key of PROCEDURE_KEYS) {
      const slots = values[key];
      if (!slots) continue;
      const box = html('section', { class: 'formula', 'data-procedure': key });
      const title = html('h3', { style: `color:${COLOURS[key]}` }, LABELS[key]);
      const maths = html('div', { class: 'maths' });
      maths.innerHTML = mathml[key].join('');
      for (const [name, text] of Object.entries(slots)) {
        for (const el of maths.querySelectorAll(`.${slotClass(name)}`)) el.textContent = text;
      }
      box.append(title, html('p', {}, TEXTS[key]), maths);
      this.element.append(box);
    }
    const missing = PROCEDURE_KEYS.filter((k) => !values[k]);
    if (missing.length > 0) {
      this.element.append(
        html(
          'p',
          { class: 'view-note' },
          `${missing.map((k) => LABELS[k]).join(', ')}: not applicable here (rho = 0).`,
        ),
      );
    }
    this.element.append(
      html('p', { class: 'view-note' }, 'Lengths in mm, angles in degrees; each L/2 is at the h of the current state.'),
    );
  }

  highlight(key: ProcedureKey | null): void {
    for (const s of this.element.querySelectorAll<HTMLElement>('section.formula'))
      s.classList.toggle('dimmed', key !== null && s.dataset.procedure !== key);
  }
}
