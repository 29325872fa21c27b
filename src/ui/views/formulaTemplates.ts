/**
 * The equations of the formulas view as TeX templates. `{{name}}` marks a number that the
 * page fills in at run time. The templates are typeset to MathML once, at build time
 * (src/build/formulaMathml.ts), so the page ships MathML, not a TeX engine.
 * Pure data with no runtime imports: the Vite config (the build step) loads it natively.
 */

import type { PassPattern } from '../../core/input/validate';
import type { ProcedureKey } from '../../core/procedures/procedures';

/** Slot syntax inside a template: `{{name}}`, name in [A-Za-z0-9]. */
export const SLOT_PATTERN = /\{\{([A-Za-z0-9]+)\}\}/g;

/** One display equation; shown only for one pass pattern when `pattern` is set. */
export interface FormulaLine {
  readonly tex: string;
  readonly pattern?: PassPattern;
}

/**
 * Per procedure, its display equations: the paper's Eqs. 4-11, the exact profile for any posture
 * (shared/notes/posture-and-surfaces.md: the ring ellipse turned by phi and offset by Rcr, each
 * flank's width the farthest reach of a torus section at the height h), the osculating circle
 * at the contact and the corner ball.
 */
export const FORMULA_TEMPLATES: Readonly<Record<ProcedureKey, readonly FormulaLine[]>> = {
  exact: [
    { tex: 'a = R_b = R - R_{cr} = {{Rb}},\\quad b = R_b\\cos\\beta\\sin\\rho = {{b}}' },
    {
      tex: '\\varphi = \\operatorname{atan2}(\\sin\\beta,\\ \\cos\\beta\\cos\\rho) = {{phi}}^\\circ,\\quad D_0 = \\sqrt{a^2\\sin^2\\varphi + b^2\\cos^2\\varphi} = {{d0}}',
    },
    {
      tex: '(\\sin t_0,\\ \\cos t_0) = \\frac{(a\\sin\\varphi,\\ b\\cos\\varphi)}{D_0},\\quad y_0 = \\frac{(a^2 - b^2)\\sin\\varphi\\cos\\varphi}{D_0} = {{y0}}',
    },
    {
      tex: 'w(h) = \\max_{\\delta}\\Bigl[2\\sin\\tfrac{\\delta}{2}\\bigl(a\\cos\\varphi\\cos(t_0 + \\tfrac{\\delta}{2}) + b\\sin\\varphi\\sin(t_0 + \\tfrac{\\delta}{2})\\bigr) + \\sqrt{q\\,(2R_{cr} - q)}\\Bigr],\\quad q = h - 2D_0\\sin^2\\tfrac{\\delta}{2}',
    },
    {
      tex: 'h = {{h}}:\\quad w_R = w(h)\\big|_{\\varphi} = {{wR}}\\ (\\delta^* = {{deltaR}}^\\circ),\\quad w_L = w(h)\\big|_{-\\varphi} = {{wL}}\\ (\\delta^* = {{deltaL}}^\\circ)',
    },
    { tex: 'L = w_R + w_L = {{L}},\\quad L/2 = {{half}}', pattern: 'one-way' },
    { tex: 'L = 2\\min(w_R,\\ w_L) = {{L}},\\quad L/2 = {{half}}', pattern: 'zigzag' },
  ],
  sekine: [
    { tex: 'Z_{tc} = |R_b\\sin\\rho| + R_{cr} = {{ztc}}' },
    {
      tex: 'R_{short} = Z_{tc} - R_{cr}\\cos\\rho = {{rshort}},\\quad R_{long} = \\frac{R_{short}}{|\\sin\\rho|} = {{rlong}}',
    },
    { tex: 'R_{eff} = \\frac{R_{long}^2 + R_{short}^2}{2R_{short}} = {{reff}}' },
    { tex: 'L/2 = \\sqrt{2R_{eff}h - h^2} = {{half}}' },
  ],
  redonnet: [
    { tex: 'R_{eff} = \\frac{R_b}{\\sin\\rho} + R_{cr} = {{reff}}' },
    { tex: 'L/2 = \\sqrt{2R_{eff}h - h^2} = {{half}}' },
  ],
  bedi: [
    { tex: 'R_{long} = R_b + R_{cr}\\sin\\rho = {{rlong}}' },
    {
      tex: 'L/2 = R_{long}\\sqrt{1 - \\Bigl(\\frac{R_{long}\\sin\\rho - h}{R_{long}\\sin\\rho}\\Bigr)^2} = {{half}}',
    },
  ],
  osculating: [
    { tex: 'R_{eff} = R_{cr} + \\frac{a^2 b^2}{D_0^3} = {{reff}}' },
    { tex: 'L/2 = \\sqrt{2R_{eff}h - h^2} = {{half}}' },
  ],
  cornerBall: [{ tex: 'L/2 = \\sqrt{2R_{cr}h - h^2},\\quad R_{cr} = {{Rcr}}:\\quad L/2 = {{half}}' }],
};

/** The slot names of one template, in order of appearance. */
export function slotNames(template: string): string[] {
  return [...template.matchAll(SLOT_PATTERN)].map((m) => m[1] ?? '');
}

/** The class a slot's MathML element carries: `slot-<name>`. */
export function slotClass(name: string): string {
  return `slot-${name}`;
}
