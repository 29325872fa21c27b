import { describe, expect, it } from 'vitest';
import { FORMULA_TEMPLATES, formulaNumber, formulaSlotValues, slotNames } from '../../../src/ui/views/formulaTemplates';
import { solve } from '../../../src/worker/api';
import type { ProcedureKey } from '../../../src/worker/protocol';

const KEYS: readonly ProcedureKey[] = ['exact', 'sekine', 'redonnet', 'bedi'];

function valuesFor(R: number, Rcr: number, rho: number, h: number) {
  const reply = solve({ id: 1, mode: 'forward', R, Rcr, rho, value: h, withViews: true });
  if (!reply.ok || !reply.teaching) throw new Error('expected teaching data');
  return formulaSlotValues({
    R,
    Rcr,
    rho,
    h: reply.scallopHeightMm,
    exactHalfMm: reply.halfIntervalMm,
    models: reply.teaching.models,
  });
}

describe('formula slot values', () => {
  it('fill exactly the slots of each procedure’s templates', () => {
    const values = valuesFor(3, 1, 5, 0.05);
    for (const key of KEYS) {
      const wanted = new Set(FORMULA_TEMPLATES[key].flatMap(slotNames));
      expect(new Set(Object.keys(values[key] ?? {})), key).toEqual(wanted);
    }
    expect(values.exact.R).toBe('3');
    expect(values.exact.Rb).toBe('2');
  });

  it('at rho = 0 only the exact procedure has equations (the approximations do not apply)', () => {
    const values = valuesFor(3, 1, 0, 0.05);
    expect(values.exact).not.toBeNull();
    expect(values.sekine).toBeNull();
    expect(values.redonnet).toBeNull();
    expect(values.bedi).toBeNull();
  });

  it('numbers: 5 significant digits, a true minus sign, n/a for no value', () => {
    expect(formulaNumber(1.4435924)).toBe('1.4436');
    expect(formulaNumber(-0.0123456)).toBe('\u22120.012346');
    expect(formulaNumber(null)).toBe('n/a');
    expect(formulaNumber(Number.NaN)).toBe('n/a');
  });
});
