/** The lookup table's file name and status line: they name the tool, the pattern and the surface. */
import { describe, expect, it } from 'vitest';
import { lookupGrid } from '../../src/core/output/lookupTable';
import { PLANE } from '../../src/core/surfaces/cylinder';
import { tableFileName } from '../../src/ui/lookupDownload';

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
});
