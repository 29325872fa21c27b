/** The lookup table's file name and status line: they name the tool, the pattern and the surface. */
import { describe, expect, it } from 'vitest';
import { lookupGrid } from '../../src/core/output/lookupTable';
import { PLANE } from '../../src/core/surfaces/cylinder';
import { tableFileName } from '../../src/ui/lookupDownload';

const base = { toolRadiusMm: 3, cornerRadiusMm: 1, pattern: 'one-way' as const };
const grid = lookupGrid(base);

describe('lookup table file name', () => {
  it('names the surface: a plane, or the cylinder by its signed radius and axis (as the CSV columns)', () => {
    expect(tableFileName({ tool: { ...base, surface: PLANE }, grid })).toBe(
      'step-over-table_R3_Rcr1_one-way_plane.csv',
    );
    expect(
      tableFileName({
        tool: { ...base, pattern: 'zigzag', surface: { kind: 'cylinder', radiusMm: -30, axis: 'cross' } },
        grid,
      }),
    ).toBe('step-over-table_R3_Rcr1_zigzag_Rs-30_cross.csv');
    expect(
      tableFileName({ tool: { ...base, surface: { kind: 'cylinder', radiusMm: 12.5, axis: 'feed' } }, grid }),
    ).toBe('step-over-table_R3_Rcr1_one-way_Rs12.5_feed.csv');
  });
});
