import { describe, expect, it } from 'vitest';
import { forwardInput, type ToolInput } from '../../../src/core/index';
import { PROCEDURE_KEYS } from '../../../src/core/procedures/procedures';
import { formulaNumber, formulaSlotValues } from '../../../src/ui/views/formulaSlots';
import { FORMULA_TEMPLATES, slotNames } from '../../../src/ui/views/formulaTemplates';
import { teach } from '../../../src/worker/api';

function valuesFor(R: number, Rcr: number, rho: number, h: number, tilt = 0, unit: 'mm' | 'in' = 'mm') {
  const tool: ToolInput = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt };
  const reply = teach({ mode: 'forward', input: forwardInput(tool, 'one-way', h) });
  if (!reply.ok) throw new Error('expected teaching data');
  return formulaSlotValues({
    R,
    Rcr,
    rho,
    tilt,
    h,
    widthRightMm: reply.exact.widthRightMm,
    widthLeftMm: reply.exact.widthLeftMm,
    intervalMm: reply.exact.intervalMm,
    models: reply.models,
    unit,
  });
}

describe('formula slot values', () => {
  it('fill exactly the slots of each procedure’s templates', () => {
    const values = valuesFor(3, 1, 5, 0.05);
    for (const key of PROCEDURE_KEYS) {
      const wanted = new Set(FORMULA_TEMPLATES[key].flatMap((line) => slotNames(line.tex)));
      expect(new Set(Object.keys(values[key] ?? {})), key).toEqual(wanted);
    }
    // Each length with its unit (small ones in µm, as everywhere on the page); angles bare (the template's °).
    expect(values.exact.Rb).toBe('2 mm');
    expect(values.exact.phi).toBe('0');
    expect(values.exact.half).toBe('1.4436 mm');
    expect(values.exact.h).toBe('50 \u00b5m');
    expect(values.exact.deltaR).not.toMatch(/[a-z\u00b5]/);
  });

  it('at rho = 0 without tilt only the exact procedure and the corner ball have equations', () => {
    const values = valuesFor(3, 1, 0, 0.05);
    expect(values.exact).not.toBeNull();
    expect(values.sekine).toBeNull();
    expect(values.redonnet).toBeNull();
    expect(values.bedi).toBeNull();
    expect(values.osculating).toBeNull();
    expect(values.cornerBall).not.toBeNull();
  });

  it('with tilt: the projected ellipse b = Rb cos(beta) sin(rho), phi, y0 and the osculating radius', () => {
    const v = valuesFor(3, 1, 5, 0.05, 10);
    const mm = (x: number) => `${formulaNumber(x)} mm`;
    const beta = (10 * Math.PI) / 180;
    const rho = (5 * Math.PI) / 180;
    expect(v.exact.b).toBe(mm(2 * Math.cos(beta) * Math.sin(rho)));
    expect(v.exact.phi).toBe(
      formulaNumber((Math.atan2(Math.sin(beta), Math.cos(beta) * Math.cos(rho)) * 180) / Math.PI),
    );
    const a = 2;
    const b = 2 * Math.cos(beta) * Math.sin(rho);
    const phi = Math.atan2(Math.sin(beta), Math.cos(beta) * Math.cos(rho));
    const d0 = Math.sqrt((a * Math.sin(phi)) ** 2 + (b * Math.cos(phi)) ** 2);
    expect(v.exact.d0).toBe(mm(d0));
    expect(v.exact.y0).toBe(mm(((a * a - b * b) * Math.sin(phi) * Math.cos(phi)) / d0));
    expect(v.osculating?.reff).toBe(mm(1 + (a * a * b * b) / d0 ** 3));
  });

  it('lengths in the user unit: inches, no float noise', () => {
    const v = valuesFor(3, 0.762, 5, 0.05, 0, 'in');
    expect(v.cornerBall?.Rcr).toBe('0.03 in');
    expect(v.exact.Rb).toBe(`${formulaNumber((3 - 0.762) / 25.4)} in`);
    expect(v.exact.h).toBe(`${formulaNumber(50 / 25.4)} thou`);
    // At most 5 significant digits (0.7619999999999999 was the float noise of a converted Rcr).
    for (const text of Object.values(v.exact))
      expect((text.split(' ')[0] ?? '').replace(/^\u2212?[0.]*/, '').replace('.', '').length, text).toBeLessThanOrEqual(
        5,
      );
  });

  it('numbers: 5 significant digits, a true minus sign, n/a for no value', () => {
    expect(formulaNumber(1.4435924)).toBe('1.4436');
    expect(formulaNumber(-0.0123456)).toBe('\u22120.012346');
    expect(formulaNumber(null)).toBe('n/a');
    expect(formulaNumber(Number.NaN)).toBe('n/a');
    expect(formulaNumber(-0)).toBe('0');
  });
});
