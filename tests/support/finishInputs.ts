/**
 * The finish fields as the page holds them (src/ui/finishLazy.ts finishInputs: mm, mm/min, rpm,
 * degrees, and as typed), for tests: the fields not given are empty.
 */
import type { FinishInputs } from '../../src/ui/finishRequest';

export function finishInputsOf(values: Partial<FinishInputs['values']>, unit: 'mm' | 'in' = 'mm'): FinishInputs {
  const all = {
    flutes: undefined,
    fz: undefined,
    feedRate: undefined,
    spindleSpeed: undefined,
    runout: undefined,
    runoutPhase: undefined,
    passPhase: undefined,
    ...values,
  };
  const typed = Object.fromEntries(Object.entries(all).map(([k, v]) => [k, v === undefined ? '' : String(v)]));
  return {
    given: Object.values(all).some((v) => v !== undefined),
    values: all,
    typed: typed as FinishInputs['typed'],
    unit,
  };
}
