/** The lookup table's file name and status line: they name the tool, the pattern and the surface. */
import { describe, expect, it } from 'vitest';
import { lookupGrid } from '../../src/core/output/lookupTable';
import { PLANE } from '../../src/core/surfaces/cylinder';
import { catalogue as de } from '../../src/ui/i18n/de';
import { catalogue as ja } from '../../src/ui/i18n/ja';
import { tableFileName, tableSummary } from '../../src/ui/lookupFile';
import { buildRequest } from '../../src/ui/request';
import { parseUrl } from '../../src/ui/state';
import { tableRequestOf } from '../../src/ui/tableRequest';

const base = { toolRadiusMm: 3, cornerRadiusMm: 1, pattern: 'one-way' as const };
const grid = lookupGrid(base);

describe('lookup table file name', () => {
  it('names the surface: a plane, or the cylinder by its signed radius and axis (as the CSV columns)', () => {
    expect(tableFileName({ tool: { ...base, surface: PLANE }, grid, unit: 'mm' })).toBe(
      'step-over-table_5-axis_R3_Rcr1_one-way_plane_mm.csv',
    );
    expect(
      tableFileName({
        tool: { ...base, pattern: 'zigzag', surface: { kind: 'cylinder', radiusMm: -30, axis: 'cross' } },
        grid,
        unit: 'mm',
      }),
    ).toBe('step-over-table_5-axis_R3_Rcr1_zigzag_Rs-30_cross_mm.csv');
    expect(
      tableFileName({
        tool: { ...base, surface: { kind: 'cylinder', radiusMm: 12.5, axis: 'feed' } },
        grid,
        unit: 'mm',
      }),
    ).toBe('step-over-table_5-axis_R3_Rcr1_one-way_Rs12.5_feed_mm.csv');
  });

  it('in inch mode names inches: the lengths of the name in inches, the file ends _in', () => {
    const tool = { toolRadiusMm: 6.35, cornerRadiusMm: 1.5875, pattern: 'one-way' as const, surface: PLANE };
    const request = { tool, grid: lookupGrid(tool, 'in'), unit: 'in' as const };
    expect(tableFileName(request)).toBe('step-over-table_5-axis_R0.25_Rcr0.0625_one-way_plane_in.csv');
  });

  it('three-axis: the machine first, the strategy and the surface (tableRequest.ts builds the question on screen)', () => {
    const name = (query: string) => {
      const state = parseUrl(query).state;
      const built = buildRequest(state);
      if (!built.ok) throw new Error('valid');
      return tableFileName(tableRequestOf(built.request, state.unit));
    };
    expect(name('?machine=3axis&R=3&Rcr=1&slope=30&rasterAngle=30&h=0.01&unit=mm')).toBe(
      'step-over-table_3-axis_R3_Rcr1_raster30_plane_mm.csv',
    );
    expect(
      name('?machine=3axis&R=3&Rcr=1&slope=40&passes=waterline&feedRadius=50&crossRadius=-20&h=0.02&unit=mm'),
    ).toBe('step-over-table_3-axis_R3_Rcr1_waterline_Rf50_Rc-20_mm.csv');
    expect(name('?machine=3axis&R=0.25&Rcr=0.03&slope=30&rasterAngle=30&h=0.0004&unit=in')).toBe(
      'step-over-table_3-axis_R0.25_Rcr0.03_raster30_plane_in.csv',
    );
  });

  it("the status line's summary in Japanese and German: the file, the grid's ranges with the locale's decimal sign, no English word", () => {
    const summary = (query: string, c: typeof de | null) => {
      const state = parseUrl(query).state;
      const built = buildRequest(state);
      if (!built.ok) throw new Error('valid');
      const request = tableRequestOf(built.request, state.unit);
      return tableSummary({ ok: true, request, csv: '', rows: 120, emptyCells: 7 }, c);
    };
    for (const query of [
      '?R=3&Rcr=1&rho=5&h=0.05&unit=mm',
      '?machine=3axis&R=3&Rcr=1&slope=30&rasterAngle=30&h=0.01&unit=mm',
    ]) {
      const english = summary(query, null);
      expect(english).toMatch(/^Saved step-over-table_.*: 120 rows, h 0\.\d+ to .* 7 cells outside the valid domain/);
      for (const c of [ja, de]) {
        const text = summary(query, c);
        const file = /^Saved (\S+):/.exec(english)?.[1] ?? '';
        expect(text, c.lang).toContain(file);
        expect(text.replace(file, ''), c.lang).not.toMatch(
          /\b(Saved|rows|to|lead|tilt|slope|deg|cells|outside|valid|domain|reason|column|programmed|step)\b/,
        );
        expect(text, c.lang).toMatch(/120.*7/);
        if (c.lang === 'de') expect(text.replace(file, '')).toMatch(/h 0,\d+ bis /);
      }
    }
    expect(ja.said.tableComputing).not.toBe('Computing the table in the worker...');
  });
});
