/** The shop sheet's words and files (issue 21): heights list, title lines, cells, CSV and file name, in mm and inch. */
import { describe, expect, it } from 'vitest';
import { forwardInput } from '../../src/core/input/validate';
import { SHEET_HEIGHTS, type SheetCase, shopSheet } from '../../src/core/output/shopSheet';
import { PLANE } from '../../src/core/surfaces/cylinder';
import { exactForward } from '../../src/core/surfaces/solve';
import { validateThreeAxis } from '../../src/core/threeAxis/validate';
import { buildRequest } from '../../src/ui/request';
import {
  cellText,
  parseHeights,
  sheetCaseOf,
  sheetCsv,
  sheetFileName,
  sheetTitleLines,
} from '../../src/ui/shopSheetText';
import { parseUrl } from '../../src/ui/state';

const plane: SheetCase = {
  kind: 'five-axis',
  toolRadiusMm: 3,
  cornerRadiusMm: 1,
  tiltAngleDeg: 0,
  pattern: 'one-way',
  surface: PLANE,
};

function caseOf(query: string): SheetCase {
  const built = buildRequest(parseUrl(query).state);
  if (!built.ok) throw new Error(JSON.stringify(built.errors));
  return sheetCaseOf(built.request);
}

describe('shop sheet text', () => {
  it('the heights list: spaces or semicolons, a decimal comma, sorted and each once; bad text named', () => {
    expect(parseHeights('0.01 0.002;0,005  0.01', 'mm')).toEqual({ ok: true, mm: [0.002, 0.005, 0.01] });
    const inch = parseHeights('0.001 0.0002', 'in');
    expect(inch.ok && inch.mm).toEqual([0.0002 * 25.4, 0.001 * 25.4]);
    expect(parseHeights('0.01 abc', 'in')).toEqual({
      ok: false,
      message: 'Scallop heights: give 1 to 12 scallop heights above 0 in, separated by spaces (got "abc").',
    });
    expect(parseHeights('0', 'mm').ok).toBe(false);
    expect(parseHeights('-1', 'mm').ok).toBe(false);
    expect(parseHeights('', 'mm').ok).toBe(false);
    expect(parseHeights('1e999', 'mm').ok).toBe(false);
    expect(parseHeights(Array.from({ length: 13 }, (_, i) => `${i + 1}`).join(' '), 'mm')).toEqual({
      ok: false,
      message: 'Scallop heights: give 1 to 12 scallop heights above 0 mm, separated by spaces (got 13).',
    });
  });

  it('the case of the question on screen: five-axis plane, cylinder, doubly curved point, three-axis', () => {
    expect(caseOf('?R=3&Rcr=1&rho=5&tilt=4&h=0.05&unit=mm&pattern=zigzag')).toEqual({
      ...plane,
      tiltAngleDeg: 4,
      pattern: 'zigzag',
    });
    expect(caseOf('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&surfaceRadius=-30&surfaceAxis=cross')).toMatchObject({
      kind: 'five-axis',
      surface: { kind: 'cylinder', radiusMm: -30, axis: 'cross' },
    });
    expect(caseOf('?R=3&Rcr=1&rho=5&h=0.05&feedRadius=80&crossRadius=-40&unit=mm')).toMatchObject({
      kind: 'doubly-curved',
      radii: { feedRadiusMm: 80, crossRadiusMm: -40 },
    });
    expect(caseOf('?R=3&Rcr=1&h=0.01&machine=3axis&slope=20&rasterAngle=30&unit=mm')).toMatchObject({
      kind: 'three-axis',
      problem: { surface: 'plane', case: { passes: 'raster', rasterAngleDeg: 30 } },
    });
  });

  it('mm: the title lines name the tool, posture, pattern, surface and unit; the CSV names mm in header and file name', () => {
    const sheet = shopSheet(plane, [0.01, 1.5]);
    expect(sheetTitleLines(plane, sheet, 'mm', '2026-11-29')).toEqual([
      'Tool: D 6 mm (R 3 mm), corner radius Rcr 1 mm',
      'Five-axis, tilt 0 deg; one-way passes; on a plane',
      'Rows: scallop height h (mm). Columns: lead angle rho (deg). Cells: step-over L between adjacent passes, along the surface (mm).',
      'Exact solution, path-interval calculator, 2026-11-29.',
    ]);
    const csv = sheetCsv(sheet, 'mm').split('\n');
    expect(csv[0]).toBe(
      'h_mm,L_mm_lead_0_deg,L_mm_lead_2_deg,L_mm_lead_5_deg,L_mm_lead_10_deg,L_mm_lead_15_deg,L_mm_lead_20_deg,L_mm_lead_30_deg',
    );
    const L5 = exactForward(
      forwardInput({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way', 0.01),
    ).intervalMm;
    expect(csv[1]?.split(',')[3]).toBe(String(L5));
    // h 1.5 mm is above the lead-0 limit (Rcr = 1 mm): the words, not a number.
    expect(csv[2]?.split(',').slice(0, 2)).toEqual(['1.5', 'wall: h at or above the limit']);
    expect(csv.join('\n')).not.toMatch(/NaN|Infinity/);
    expect(sheetFileName(plane, 'mm')).toBe('shop-sheet_R3_Rcr1_one-way_plane_tilt0_mm.csv');
    expect(
      cellText(sheet.cells[0]?.[2] ?? { ok: false, mark: 'range', reason: '', refusal: { kind: 'lead-range' } }, 'mm'),
    ).toMatch(/^\d+\.\d{4}$/);
    expect(cellText(sheet.cells[1]?.[0] ?? { ok: true, stepMm: 0, noScallop: false }, 'mm')).toBe('W');
  });

  it('inch: heights, cells, header and file name in inches', () => {
    const c: SheetCase = { ...plane, toolRadiusMm: 6.35, cornerRadiusMm: 1.5875 };
    const heights = SHEET_HEIGHTS.in.map((h) => h * 25.4);
    const sheet = shopSheet(c, heights, 'in');
    const lines = sheetTitleLines(c, sheet, 'in', '2026-11-29');
    expect(lines[0]).toBe('Tool: D 0.5 in (R 0.25 in), corner radius Rcr 0.0625 in');
    expect(lines[2]).toMatch(/scallop height h \(in\).*\(in\)\.$/);
    const csv = sheetCsv(sheet, 'in').split('\n');
    expect(csv[0]?.startsWith('h_in,L_in_lead_0_deg,L_in_lead_2_deg,')).toBe(true);
    expect(csv.slice(1, -1).map((r) => r.split(',')[0])).toEqual([
      '0.0001',
      '0.0002',
      '0.0005',
      '0.001',
      '0.002',
      '0.005',
    ]);
    const first = sheet.cells[0]?.[2];
    if (!first?.ok) throw new Error('answered');
    expect(Number(csv[1]?.split(',')[3])).toBe(first.stepMm / 25.4);
    expect(cellText(first, 'in')).toMatch(/^0\.\d{5}$/);
    expect(sheetFileName(c, 'in')).toBe('shop-sheet_R0.25_Rcr0.0625_one-way_plane_tilt0_in.csv');
  });

  it('three-axis: the slope columns and the step as programmed (Lxy raster, dz waterline) in header and title', () => {
    const v = validateThreeAxis({ R: 3, Rcr: 1, slope: 20, passes: 'raster', rasterAngle: 30 }, 'h', 0.01);
    if (!v.ok) throw new Error('valid');
    const c: SheetCase = { kind: 'three-axis', problem: v.value };
    const sheet = shopSheet(c, [0.01]);
    expect(sheetCsv(sheet, 'mm').split('\n')[0]).toBe(
      'h_mm,Lxy_mm_slope_0_deg,Lxy_mm_slope_10_deg,Lxy_mm_slope_20_deg,Lxy_mm_slope_30_deg,Lxy_mm_slope_45_deg,Lxy_mm_slope_60_deg,Lxy_mm_slope_75_deg',
    );
    expect(sheetTitleLines(c, sheet, 'mm', 'd')[1]).toBe(
      'Three-axis, the tool upright; raster passes at 30 deg from the fall line; on a sloped plane',
    );
    expect(sheetFileName(c, 'mm')).toBe('shop-sheet_R3_Rcr1_raster_psi30_plane_mm.csv');
    const w = validateThreeAxis({ R: 3, Rcr: 1, slope: 30, passes: 'waterline', feedRadius: -50 }, 'h', 0.01);
    if (!w.ok) throw new Error('valid');
    const cw: SheetCase = { kind: 'three-axis', problem: w.value };
    const ws = shopSheet(cw, [0.01]);
    expect(sheetCsv(ws, 'mm').split('\n')[0]).toMatch(/^h_mm,dz_mm_slope_5_deg,/);
    expect(sheetTitleLines(cw, ws, 'mm', 'd')[1]).toBe(
      'Three-axis, the tool upright; waterline passes; on a surface of revolution, Rf -50 mm, Rc straight (negative: concave)',
    );
    expect(sheetFileName(cw, 'mm')).toBe('shop-sheet_R3_Rcr1_waterline_Rf-50_Rcstraight_mm.csv');
  });
});
