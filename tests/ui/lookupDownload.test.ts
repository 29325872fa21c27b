/** The lookup table's file name and status line: they name the tool, the pattern and the surface. */
import { describe, expect, it } from 'vitest';
import { lookupGrid } from '../../src/core/output/lookupTable';
import { PLANE } from '../../src/core/surfaces/cylinder';
import { tableFileName } from '../../src/ui/lookupFile';
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
});
