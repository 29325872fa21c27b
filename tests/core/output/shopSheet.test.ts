/**
 * The shop sheet's matrix (issue 21): every cell is the core solver's answer called directly, and
 * an independent check: the cell's step fed to the inverse gives back its row's h (1e-9 relative).
 * Refused cells carry a mark and a reason in the user's unit; no cell is NaN.
 */
import { describe, expect, it } from 'vitest';
import { forwardInput, inverseInput } from '../../../src/core/input/validate';
import { SHEET_HEIGHTS, type SheetCase, type ShopSheet, shopSheet } from '../../../src/core/output/shopSheet';
import { PLANE, type Surface } from '../../../src/core/surfaces/cylinder';
import { doublyCurvedForward, doublyCurvedInverse } from '../../../src/core/surfaces/doublyCurved';
import { exactForward, exactInverse } from '../../../src/core/surfaces/solve';
import { scallopHeightLimits } from '../../../src/core/surfaces/validate';
import { solveThreeAxis } from '../../../src/core/threeAxis/solve';
import { type ThreeAxisProblem, validateThreeAxis } from '../../../src/core/threeAxis/validate';

const MM = [...SHEET_HEIGHTS.mm];

function fiveAxis(surface: Surface, pattern: 'one-way' | 'zigzag' = 'one-way', tilt = 0, Rcr = 1): SheetCase {
  return { kind: 'five-axis', toolRadiusMm: 3, cornerRadiusMm: Rcr, tiltAngleDeg: tilt, pattern, surface };
}

function threeAxis(raw: Record<string, unknown>): SheetCase {
  const v = validateThreeAxis({ R: 3, Rcr: 1, ...raw }, 'h', 0.01);
  if (!v.ok) throw new Error(v.errors.map((e) => e.message).join(' '));
  return { kind: 'three-axis', problem: v.value };
}

/** Each answered cell: [row, column, step mm]. */
function answered(sheet: ShopSheet): Array<[number, number, number]> {
  const out: Array<[number, number, number]> = [];
  sheet.cells.forEach((row, i) => {
    row.forEach((cell, j) => {
      if (cell.ok) out.push([i, j, cell.stepMm]);
    });
  });
  return out;
}

const near = (got: number, want: number, rel: number) => expect(Math.abs(got - want)).toBeLessThanOrEqual(rel * want);

describe('shop sheet', () => {
  it('a plane, one-way and zigzag with tilt: each cell is exactForward, and the inverse gives back h', () => {
    for (const [pattern, tilt] of [
      ['one-way', 0],
      ['zigzag', 4],
    ] as const) {
      const c = fiveAxis(PLANE, pattern, tilt);
      const sheet = shopSheet(c, MM);
      expect(sheet.columnKind).toBe('lead');
      expect(sheet.columnsDeg).toEqual([0, 2, 5, 10, 15, 20, 30]);
      expect(sheet.step).toBe('interval');
      const cells = answered(sheet);
      expect(cells.length).toBeGreaterThan(40);
      for (const [i, j, L] of cells) {
        const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: sheet.columnsDeg[j] ?? 0, tiltAngleDeg: tilt };
        const h = MM[i] ?? 0;
        expect(L).toBe(exactForward(forwardInput(tool, pattern, h)).intervalMm);
        near(exactInverse(inverseInput(tool, pattern, L)).cuspHeightMm, h, 1e-9);
      }
    }
  });

  it('a scallop height at or above the limit is a wall mark with its reason, never a number', () => {
    const sheet = shopSheet(fiveAxis(PLANE), [0.01, 1.5, 2.5]);
    // Lead 0: the limit is Rcr = 1 mm, so 1.5 and 2.5 are walls.
    expect(scallopHeightLimits({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 0, tiltAngleDeg: 0 }).limitMm).toBe(
      1,
    );
    const c = sheet.cells[1]?.[0];
    expect(c?.ok).toBe(false);
    if (c?.ok === false) {
      expect(c.mark).toBe('wall');
      expect(c.reason).toMatch(/^Scallop height h must be below .* = 1 mm \(got 1\.5\)/);
    }
    for (const row of sheet.cells) for (const cell of row) if (cell.ok) expect(Number.isFinite(cell.stepMm)).toBe(true);
  });

  it('inch: the reasons in inches, the height as the row gives it', () => {
    const sheet = shopSheet(fiveAxis(PLANE), [2.54], 'in');
    const c = sheet.cells[0]?.[0];
    if (c?.ok !== false) throw new Error('refused');
    expect(c.reason).toMatch(/= 0\.0393701 in \(got 0\.1\)/);
    expect(c.reason).not.toMatch(/mm/);
  });

  it('a flat end lying flat: L = 2R, marked as leaving no scallop; with lead it leaves one', () => {
    const sheet = shopSheet(fiveAxis(PLANE, 'one-way', 0, 0), [0.01]);
    expect(sheet.cells[0]?.[0]).toEqual({ ok: true, stepMm: 6, noScallop: true });
    expect(sheet.cells[0]?.[1]).toMatchObject({ ok: true, noScallop: false });
  });

  it('a concave cylinder across the feed: gouging marks where the flat bottom lies flat, the others on the cylinder', () => {
    const surface: Surface = { kind: 'cylinder', radiusMm: -30, axis: 'cross' };
    const sheet = shopSheet(fiveAxis(surface), MM);
    expect(sheet.cells[0]?.[0]).toMatchObject({ ok: false, mark: 'gouge' });
    const cells = answered(sheet);
    expect(cells.length).toBeGreaterThan(20);
    for (const [i, j, L] of cells) {
      const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: sheet.columnsDeg[j] ?? 0, tiltAngleDeg: 0 };
      const h = MM[i] ?? 0;
      expect(L).toBe(exactForward(forwardInput(tool, 'one-way', h, surface)).intervalMm);
      near(exactInverse(inverseInput(tool, 'one-way', L, surface)).cuspHeightMm, h, 1e-9);
    }
  });

  it('a doubly curved point: each cell is the doubly curved solver, the inverse gives back h', () => {
    const radii = { feedRadiusMm: 80, crossRadiusMm: -40 };
    const c: SheetCase = {
      kind: 'doubly-curved',
      toolRadiusMm: 3,
      cornerRadiusMm: 1,
      tiltAngleDeg: 0,
      pattern: 'one-way',
      radii,
    };
    const sheet = shopSheet(c, MM);
    const cells = answered(sheet);
    expect(cells.length).toBeGreaterThan(20);
    for (const [i, j, L] of cells) {
      const pass = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: sheet.columnsDeg[j] ?? 0, tiltAngleDeg: 0 };
      const h = MM[i] ?? 0;
      expect(L).toBe(doublyCurvedForward({ ...pass, ...radii, pattern: 'one-way', scallopHeightMm: h }).intervalMm);
      const back = doublyCurvedInverse({ ...pass, ...radii, pattern: 'one-way', intervalMm: L }).cuspHeightMm;
      near(back, h, 1e-9);
    }
  });

  it('three-axis raster: columns are slopes, each cell Lxy of solveThreeAxis, the inverse from Lxy gives back h', () => {
    const c = threeAxis({ slope: 0, passes: 'raster', rasterAngle: 30 });
    const sheet = shopSheet(c, MM);
    expect(sheet.columnKind).toBe('slope');
    expect(sheet.step).toBe('horizontalStep');
    const cells = answered(sheet);
    expect(cells.length).toBe(MM.length * sheet.columnsDeg.length);
    const problem = c.kind === 'three-axis' ? c.problem : (null as never);
    for (const [i, j, Lxy] of cells) {
      const at = { ...problem, case: { ...problem.case, slopeDeg: sheet.columnsDeg[j] ?? 0 } } as ThreeAxisProblem;
      const h = MM[i] ?? 0;
      const f = solveThreeAxis({ ...at, quantity: 'h', mm: h });
      expect(f.ok && f.value.horizontalStepMm).toBe(Lxy);
      const back = solveThreeAxis({ ...at, quantity: 'horizontalStep', mm: Lxy });
      if (!back.ok) throw new Error('inverse');
      near(back.value.cuspHeightMm, h, 1e-9);
    }
  });

  it('three-axis waterline on a bowl: each cell dz; refused slopes get a mark and a reason, no NaN', () => {
    const c = threeAxis({ slope: 30, passes: 'waterline', feedRadius: -50, crossRadius: -50 });
    const sheet = shopSheet(c, [...MM, 0.5, 0.9], 'mm');
    expect(sheet.step).toBe('stepDown');
    expect(sheet.columnsDeg[0]).toBeGreaterThan(0);
    const problem = c.kind === 'three-axis' ? c.problem : (null as never);
    const heights = sheet.scallopHeightsMm;
    let refused = 0;
    sheet.cells.forEach((row, i) => {
      row.forEach((cell, j) => {
        const at = { ...problem, case: { ...problem.case, slopeDeg: sheet.columnsDeg[j] ?? 0 } } as ThreeAxisProblem;
        const h = heights[i] ?? 0;
        if (!cell.ok) {
          refused++;
          expect(['wall', 'gouge', 'range']).toContain(cell.mark);
          expect(cell.reason.length).toBeGreaterThan(10);
          return;
        }
        expect(Number.isFinite(cell.stepMm)).toBe(true);
        const back = solveThreeAxis({ ...at, quantity: 'stepDown', mm: cell.stepMm });
        if (!back.ok) throw new Error(back.errors[0]?.message);
        near(back.value.cuspHeightMm, h, 1e-9);
      });
    });
    expect(refused).toBeGreaterThan(0);
  });
});
