/**
 * The formulas view's data: the exact profile's quantities (the projected ring ellipse, its turn
 * phi, D0, the contact) and each approximation's model with its L/2 at h, or null where its model
 * does not apply. Mm and radians.
 */

import type { ForwardInput } from '../../core/input/validate';
import {
  APPROXIMATION_KEYS,
  APPROXIMATIONS,
  type ApproximationFunctions,
  type ApproximationKey,
  type ForwardModels,
} from '../../core/procedures/procedures';
import { contactOffsetMm, flankAtHeight, shapeOfTool } from '../../core/tool/posture';
import type { FormulaModel, FormulaModels, FormulaShape } from '../protocol';

/** One approximation's model and its L/2 at h (null where its model has none here). */
function formulaModel<K extends ApproximationKey>(key: K, input: ForwardInput): FormulaModel<K> | null {
  const procedure: ApproximationFunctions<ForwardModels[K]> = APPROXIMATIONS[key];
  const m = procedure.model(input);
  if (!m.ok) return null;
  // The model's own quantities (without the `ok` of the result); TypeScript cannot follow Omit through K.
  const { ok: _ok, ...model } = m;
  const r = procedure.halfInterval(input);
  return { ...model, halfIntervalMm: r.ok ? r.halfIntervalMm : null } as unknown as FormulaModel<K>;
}

/** The formulas' quantities for the forward state. */
export function formulaModels(input: ForwardInput): FormulaModels {
  const s = shapeOfTool(input);
  const h = input.scallopHeightMm;
  const shape: FormulaShape = {
    shape: {
      a: s.a,
      b: s.b,
      phiRad: s.phi,
      d0: s.d0,
      t0Rad: Math.atan2(s.sinT0, s.cosT0),
      contactOffsetMm: contactOffsetMm(s),
    },
    rightOffsetRad: flankAtHeight(s, 'right', h).ringOffsetRad,
    leftOffsetRad: flankAtHeight(s, 'left', h).ringOffsetRad,
  };
  const models = Object.fromEntries(APPROXIMATION_KEYS.map((key) => [key, formulaModel(key, input)]));
  return { ...shape, ...(models as { [K in ApproximationKey]: FormulaModel<K> | null }) };
}
