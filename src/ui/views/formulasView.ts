/**
 * Each procedure's equations typeset (Temml, MathML output) with the current numbers
 * substituted, and what each assumes.
 */
import temml from 'temml';
import type { ProcedureKey } from '../../worker/protocol';
import { COLOURS, html, LABELS, type TeachingView, type ViewContext } from './common';

/** A number for a formula: 5 significant digits. */
function n(v: number): string {
  return String(Number(v.toPrecision(5)));
}

function block(tex: string): string {
  return temml.renderToString(tex, { displayMode: true, throwOnError: false });
}

export class FormulasView implements TeachingView {
  readonly id = 'formulas';
  readonly title = 'Formulas';
  readonly element = html('div', { class: 'view-formulas', 'data-testid': 'formulas' });

  update(ctx: ViewContext): void {
    const t = ctx.reply.teaching;
    if (!t) return;
    const { R, Rcr, rho } = ctx;
    const h = ctx.reply.scallopHeightMm;
    const Rb = R - Rcr;
    const rows = ctx.reply.rows;
    const half = (key: ProcedureKey) => rows.find((r) => r.key === key);
    const m = t.models;
    const sections: Array<[ProcedureKey, string, string[]]> = [];
    const theta = (t.models.exactNormalAngleRad * 180) / Math.PI;
    const gamma = (t.models.exactRingAngleRad * 180) / Math.PI;
    sections.push([
      'exact',
      'True 3D: the tool moves along X, so the surface it leaves is its projection along X: the ring ellipse (semi-axes Rb and Rb sin rho) offset by Rcr. L/2 is where that exact profile stands h above its lowest point; one 1-D root in the normal angle theta. Valid for every rho, including 0, and for ball and flat ends.',
      [
        `a = R_b = ${n(R)} - ${n(Rcr)} = ${n(Rb)},\\quad b = R_b\\sin\\rho = ${n(Rb * Math.sin((rho * Math.PI) / 180))}`,
        `H(\\theta) = 2R_{cr}\\sin^2\\tfrac{\\theta}{2} + \\frac{b\\,a^2\\sin^2\\theta}{D\\,(D + b\\cos\\theta)} = h = ${n(h)},\\quad D = \\sqrt{a^2\\sin^2\\theta + b^2\\cos^2\\theta}`,
        `\\theta^* = ${n(theta)}^\\circ,\\quad \\gamma^* = \\operatorname{atan2}(a\\sin\\theta^*, b\\cos\\theta^*) = ${n(gamma)}^\\circ`,
        `L/2 = \\Bigl(\\frac{a^2}{D} + R_{cr}\\Bigr)\\sin\\theta^* = ${n(ctx.reply.halfIntervalMm)}`,
      ],
    ]);
    if (m.sekine) {
      sections.push([
        'sekine',
        "True-circular approximation (Eqs. 4-8): an ellipse from the tool centre height, replaced by one circle of radius Reff. It ignores where the real profile's curvature changes, so it is far off for small rho.",
        [
          `Z_{tc} = |R_b\\sin\\rho| + R_{cr} = ${n(m.sekine.toolCentreHeightMm)}`,
          `R_{short} = Z_{tc} - R_{cr}\\cos\\rho = ${n(m.sekine.shortRadiusMm)},\\quad R_{long} = \\frac{R_{short}}{|\\sin\\rho|} = ${n(m.sekine.longRadiusMm)}`,
          `R_{eff} = \\frac{R_{long}^2 + R_{short}^2}{2R_{short}} = ${n(m.sekine.effectiveRadiusMm)}`,
          `L/2 = \\sqrt{2R_{eff}h - h^2} = ${half('sekine')?.valueMm === null ? '\\text{n/a}' : n(half('sekine')?.valueMm ?? 0)}`,
        ],
      ]);
    }
    if (m.redonnet) {
      sections.push([
        'redonnet',
        'Osculating circle at the lowest point (Eqs. 9, 8): exact as h tends to 0, then it overestimates L/2 because the real profile curves up faster than its lowest-point circle.',
        [
          `R_{eff} = \\frac{R_b}{\\sin\\rho} + R_{cr} = ${n(m.redonnet.effectiveRadiusMm)}`,
          `L/2 = \\sqrt{2R_{eff}h - h^2} = ${half('redonnet')?.valueMm === null ? '\\text{n/a}' : n(half('redonnet')?.valueMm ?? 0)}`,
        ],
      ]);
    }
    if (m.bedi) {
      sections.push([
        'bedi',
        'Elliptic projection (Eqs. 10-11): one ellipse with semi-axes Rlong and Rlong sin rho stands for the offset ellipse. Close for these tools, but an offset ellipse is not an ellipse, so a small error remains; it breaks down at rho = 0.',
        [
          `R_{long} = R_b + R_{cr}\\sin\\rho = ${n(m.bedi.longRadiusMm)}`,
          `L/2 = R_{long}\\sqrt{1 - \\Bigl(\\frac{R_{long}\\sin\\rho - h}{R_{long}\\sin\\rho}\\Bigr)^2} = ${half('bedi')?.valueMm === null ? '\\text{n/a}' : n(half('bedi')?.valueMm ?? 0)}`,
        ],
      ]);
    }
    this.element.replaceChildren();
    for (const [key, text, lines] of sections) {
      const box = html('section', { class: 'formula', 'data-procedure': key });
      const title = html('h3', { style: `color:${COLOURS[key]}` }, LABELS[key]);
      const p = html('p', {}, text);
      const maths = html('div', { class: 'maths' });
      maths.innerHTML = lines.map(block).join('');
      box.append(title, p, maths);
      this.element.append(box);
    }
    const missing = (['sekine', 'redonnet', 'bedi'] as const).filter((k) => !m[k]);
    if (missing.length > 0) {
      this.element.append(
        html(
          'p',
          { class: 'view-note' },
          `${missing.map((k) => LABELS[k]).join(', ')}: not applicable here (rho = 0).`,
        ),
      );
    }
    this.element.append(html('p', { class: 'view-note' }, 'Lengths in mm, angles in degrees.'));
  }

  highlight(key: ProcedureKey | null): void {
    for (const s of this.element.querySelectorAll<HTMLElement>('section.formula'))
      s.classList.toggle('dimmed', key !== null && s.dataset.procedure !== key);
  }
}
