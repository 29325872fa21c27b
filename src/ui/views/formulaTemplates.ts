/**
 * The equations of the formulas view as TeX templates. `{{name}}` marks a number that the
 * page fills in at run time. The templates are typeset to MathML once, at build time
 * (src/build/formulaMathml.ts), so the page ships MathML, not a TeX engine.
 * Pure data: no DOM, so Node (the build, the tests) reads it too.
 */
import type { ProcedureKey, TeachingData } from '../../worker/protocol';

/** Slot syntax inside a template: `{{name}}`, name in [A-Za-z0-9]. */
export const SLOT_PATTERN = /\{\{([A-Za-z0-9]+)\}\}/g;

/** Per procedure, its display equations (paper Eqs. 4-11; the exact one from notes/geometry.md). */
export const FORMULA_TEMPLATES: Readonly<Record<ProcedureKey, readonly string[]>> = {
  exact: [
    'a = R_b = {{R}} - {{Rcr}} = {{Rb}},\\quad b = R_b\\sin\\rho = {{b}}',
    'H(\\theta) = 2R_{cr}\\sin^2\\tfrac{\\theta}{2} + \\frac{b\\,a^2\\sin^2\\theta}{D\\,(D + b\\cos\\theta)} = h = {{h}},\\quad D = \\sqrt{a^2\\sin^2\\theta + b^2\\cos^2\\theta}',
    '\\theta^* = {{theta}}^\\circ,\\quad \\gamma^* = \\operatorname{atan2}(a\\sin\\theta^*, b\\cos\\theta^*) = {{gamma}}^\\circ',
    'L/2 = \\Bigl(\\frac{a^2}{D} + R_{cr}\\Bigr)\\sin\\theta^* = {{half}}',
  ],
  sekine: [
    'Z_{tc} = |R_b\\sin\\rho| + R_{cr} = {{ztc}}',
    'R_{short} = Z_{tc} - R_{cr}\\cos\\rho = {{rshort}},\\quad R_{long} = \\frac{R_{short}}{|\\sin\\rho|} = {{rlong}}',
    'R_{eff} = \\frac{R_{long}^2 + R_{short}^2}{2R_{short}} = {{reff}}',
    'L/2 = \\sqrt{2R_{eff}h - h^2} = {{half}}',
  ],
  redonnet: ['R_{eff} = \\frac{R_b}{\\sin\\rho} + R_{cr} = {{reff}}', 'L/2 = \\sqrt{2R_{eff}h - h^2} = {{half}}'],
  bedi: [
    'R_{long} = R_b + R_{cr}\\sin\\rho = {{rlong}}',
    'L/2 = R_{long}\\sqrt{1 - \\Bigl(\\frac{R_{long}\\sin\\rho - h}{R_{long}\\sin\\rho}\\Bigr)^2} = {{half}}',
  ],
};

/** The slot names of one template, in order of appearance. */
export function slotNames(template: string): string[] {
  return [...template.matchAll(SLOT_PATTERN)].map((m) => m[1] ?? '');
}

/** The class a slot's MathML element carries: `slot-<name>`. */
export function slotClass(name: string): string {
  return `slot-${name}`;
}

/** What the slots are filled from: inputs (mm, degrees), the solved state and the model quantities. */
export interface FormulaInputs {
  readonly R: number;
  readonly Rcr: number;
  readonly rho: number;
  /** The state's scallop height h and exact L/2, mm. */
  readonly h: number;
  readonly exactHalfMm: number;
  readonly models: TeachingData['models'];
}

/** A number for a formula: 5 significant digits, a true minus sign. */
export function formulaNumber(v: number | null): string {
  if (v === null || !Number.isFinite(v)) return 'n/a';
  return String(Number(v.toPrecision(5))).replace('-', '\u2212');
}

type Slots = Readonly<Record<string, string>>;

/** Slot values per procedure; the exact procedure always applies. */
export type FormulaSlots = Readonly<{ exact: Slots } & Record<Exclude<ProcedureKey, 'exact'>, Slots | null>>;

/**
 * The slot values of each procedure's equations (text), or null for a procedure whose model
 * does not apply (the approximations at rho = 0). Keys match slotNames() of its templates.
 */
export function formulaSlotValues(x: FormulaInputs): FormulaSlots {
  const f = formulaNumber;
  const m = x.models;
  const Rb = x.R - x.Rcr;
  return {
    exact: {
      R: f(x.R),
      Rcr: f(x.Rcr),
      Rb: f(Rb),
      b: f(Rb * Math.sin((x.rho * Math.PI) / 180)),
      h: f(x.h),
      theta: f((m.exactNormalAngleRad * 180) / Math.PI),
      gamma: f((m.exactRingAngleRad * 180) / Math.PI),
      half: f(x.exactHalfMm),
    },
    sekine: m.sekine && {
      ztc: f(m.sekine.toolCentreHeightMm),
      rshort: f(m.sekine.shortRadiusMm),
      rlong: f(m.sekine.longRadiusMm),
      reff: f(m.sekine.effectiveRadiusMm),
      half: f(m.sekine.halfIntervalMm),
    },
    redonnet: m.redonnet && { reff: f(m.redonnet.effectiveRadiusMm), half: f(m.redonnet.halfIntervalMm) },
    bedi: m.bedi && { rlong: f(m.bedi.longRadiusMm), half: f(m.bedi.halfIntervalMm) },
  };
}
