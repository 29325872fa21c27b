/** The lookup table: its grid and its CSV, checked cell by cell against the core's own solver. */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { PLANE } from '../../src/core/cylinder';
import { exactForward } from '../../src/core/exact';
import { LOOKUP_HEADER, lookupGrid, lookupTable, series125 } from '../../src/core/lookupTable';
import { forwardInput, scallopHeightLimits } from '../../src/core/validate';

describe('lookup table', () => {
  it('the scallop heights follow the 1-2-5 series from about 1e-4 R up to the largest limit', () => {
    expect(series125(3e-4, 2.4)).toEqual([0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2]);
    expect(lookupGrid({ toolRadiusMm: 3, cornerRadiusMm: 1 }).scallopHeightsMm.at(-1)).toBe(2);
    expect(lookupGrid({ toolRadiusMm: 0.01, cornerRadiusMm: 0.002 }).scallopHeightsMm[0]).toBe(1e-6);
  });

  it('every cell is the exact step-over of its case, or empty with the reason (R 3, Rcr 1, zigzag)', () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, pattern: 'zigzag' as const, surface: PLANE };
    const grid = lookupGrid(tool);
    const t = lookupTable(tool, grid);
    const records = parseCsv(t.csv).filter((r) => !r.blank);
    expect(records[0]?.fields.join(',')).toBe(LOOKUP_HEADER);
    const rows = records.slice(1);
    expect(rows.length).toBe(grid.scallopHeightsMm.length * grid.leadAnglesDeg.length * grid.tiltAnglesDeg.length);
    expect(t.rows).toBe(rows.length);
    const col = (name: string) => LOOKUP_HEADER.split(',').indexOf(name);
    let empty = 0;
    for (const r of rows) {
      const [R, Rcr, rho, h, tilt] = r.fields.slice(0, 5).map(Number) as [number, number, number, number, number];
      const tl = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt };
      const error = r.fields[col('error')] ?? '';
      if (h >= scallopHeightLimits(tl).limitMm) {
        empty++;
        expect(r.fields[col('interval')]).toBe('');
        expect(error).toMatch(/Scallop height h must be below/);
        continue;
      }
      const e = exactForward(forwardInput(tl, 'zigzag', h));
      expect(error).toBe('');
      expect(Number(r.fields[col('interval')])).toBe(e.intervalMm);
      expect(Number(r.fields[col('exact')])).toBe(e.halfIntervalMm);
    }
    expect(empty).toBe(t.emptyCells);
    expect(empty).toBeGreaterThan(0);
  });

  it('a flat end lying flat has its row at L = 2R with the batch note', () => {
    const t = lookupTable(
      { toolRadiusMm: 3, cornerRadiusMm: 0, pattern: 'one-way', surface: PLANE },
      { scallopHeightsMm: [0.01], leadAnglesDeg: [0], tiltAnglesDeg: [0] },
    );
    expect(t.csv.split('\n')[1]).toMatch(/^3,0,0,0\.01,0,one-way,3,,,,6,3,3,0,,,,exact: a flat end without lead/);
  });
});
