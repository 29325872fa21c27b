/**
 * The numbers that fill the formulas' slots (formulaTemplates.ts): each length with its unit, in
 * the unit it reads best in as everywhere on the page (readableLengthUnit: mm or in, µm below
 * 0.1 mm, thou below 0.01 in); angles in degrees (the templates put the degree sign). Pure: no DOM.
 */

import { formatSignificant, fromMm, type LengthUnit, radToDeg, readableLengthUnit } from '../../core/input/units';
import type { ProcedureKey } from '../../core/procedures/procedures';
import type { FormulaModels } from '../../worker/protocol';

/** What the slots are filled from: the forward state (mm, degrees), its exact answer and the models. */
export interface FormulaInputs {
  readonly R: number;
  readonly Rcr: number;
  readonly rho: number;
  readonly tilt: number;
  /** The state's scallop height h, mm. */
  readonly h: number;
  /** The exact flank widths at h and the step-over, mm. */
  readonly widthRightMm: number;
  readonly widthLeftMm: number;
  readonly intervalMm: number;
  readonly models: FormulaModels;
  readonly unit: LengthUnit;
}

/** A number for a formula: 5 significant digits, trailing zeros dropped, a true minus sign. */
export function formulaNumber(v: number | null): string {
  if (v === null || !Number.isFinite(v)) return 'n/a';
  return formatSignificant(v, { digits: 5, trimZeros: true }).replace('-', '\u2212');
}

type Slots = Readonly<Record<string, string>>;

/** Slot values per procedure; the exact procedure always applies. */
export type FormulaSlots = Readonly<{ exact: Slots } & Record<Exclude<ProcedureKey, 'exact'>, Slots | null>>;

/**
 * The slot values of each procedure's equations (text; lengths with their unit, angles in degrees), or
 * null for a procedure whose model does not apply. Keys match slotNames() of its templates.
 */
export function formulaSlotValues(x: FormulaInputs): FormulaSlots {
  const len = (mm: number | null) => {
    if (mm === null || !Number.isFinite(mm)) return formulaNumber(null);
    const shown = readableLengthUnit(mm, x.unit);
    return `${formulaNumber(fromMm(mm, x.unit) * shown.perUserUnit)} ${shown.symbol}`;
  };
  const deg = (rad: number) => formulaNumber(radToDeg(rad));
  const m = x.models;
  const s = m.shape;
  return {
    exact: {
      Rb: len(s.a),
      b: len(s.b),
      phi: deg(s.phiRad),
      d0: len(s.d0),
      y0: len(s.contactOffsetMm),
      h: len(x.h),
      wR: len(x.widthRightMm),
      wL: len(x.widthLeftMm),
      deltaR: deg(m.rightOffsetRad),
      deltaL: deg(m.leftOffsetRad),
      L: len(x.intervalMm),
      half: len(x.intervalMm / 2),
    },
    sekine: m.sekine && {
      ztc: len(m.sekine.toolCentreHeightMm),
      rshort: len(m.sekine.shortRadiusMm),
      rlong: len(m.sekine.longRadiusMm),
      reff: len(m.sekine.effectiveRadiusMm),
      half: len(m.sekine.halfIntervalMm),
    },
    redonnet: m.redonnet && { reff: len(m.redonnet.effectiveRadiusMm), half: len(m.redonnet.halfIntervalMm) },
    bedi: m.bedi && { rlong: len(m.bedi.longRadiusMm), half: len(m.bedi.halfIntervalMm) },
    osculating: m.osculating && { reff: len(m.osculating.effectiveRadiusMm), half: len(m.osculating.halfIntervalMm) },
    cornerBall: m.cornerBall && { Rcr: len(x.Rcr), half: len(m.cornerBall.halfIntervalMm) },
  };
}
