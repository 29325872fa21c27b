/** The lookup table: its grid and its CSV, checked cell by cell against the core's own solver. */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../../src/cli/csv';
import { forwardInput } from '../../../src/core/input/validate';
import { LOOKUP_HEADER, lookupGrid, lookupTable, series125 } from '../../../src/core/output/lookupTable';
import { PLANE } from '../../../src/core/surfaces/cylinder';
import { exactForward } from '../../../src/core/surfaces/solve';
import { scallopHeightLimits, validateForward } from '../../../src/core/surfaces/validate';

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
    expect(t.csv.split('\n')[1]).toMatch(/^3,0,0,0\.01,0,one-way,,,3,,,,6,3,3,0,,,,"exact: a flat end without lead/);
    // The empty cells of the approximations say why (issue 26 point 10).
    expect(t.csv.split('\n')[1]).toMatch(/Sekine et al\.: at rho = 0 .*Osculating circle: /);
  });

  it('names its surface in every row: empty surface columns on a plane, the signed radius and the axis on a cylinder', () => {
    expect(LOOKUP_HEADER).toMatch(/^R,Rcr,rho,h,tilt,pattern,surfaceRadius,surfaceAxis,exact,/);
    const grid = { scallopHeightsMm: [0.05], leadAnglesDeg: [0, 5], tiltAnglesDeg: [0] };
    const base = { toolRadiusMm: 3, cornerRadiusMm: 1, pattern: 'one-way' as const };
    const plane = lookupTable({ ...base, surface: PLANE }, grid).csv.split('\n');
    const concave = lookupTable({ ...base, surface: { kind: 'cylinder', radiusMm: -30, axis: 'cross' } }, grid);
    const rows = concave.csv.split('\n');
    expect(plane[2]).toMatch(/^3,1,5,0\.05,0,one-way,,,/);
    expect(rows[2]).toMatch(/^3,1,5,0\.05,0,one-way,-30,cross,/);
    // Lead 0 and tilt 0 gouge it (a flat bottom lying flat); lead 5 cuts it: a row with its reason, a row with L.
    expect(rows[1]).toMatch(
      /^3,1,0,0\.05,0,one-way,-30,cross,,,,,,,,,,,,,"?This tool gouges a concave cylinder of any radius/,
    );
    expect(concave.emptyCells).toBe(1);
    const col = LOOKUP_HEADER.split(',').indexOf('interval');
    const L = Number(rows[2]?.split(',')[col]);
    const v = validateForward({ R: 3, Rcr: 1, rho: 5, h: 0.05, surfaceRadius: -30, surfaceAxis: 'cross' });
    if (!v.ok) throw new Error('valid case');
    expect(L).toBe(exactForward(v.value).intervalMm);
    // The cylinder's answer, not the plane's (the issue's page shows L = 3.0381 mm).
    expect(L.toFixed(4)).toBe('3.0381');
    expect(L).not.toBe(Number(plane[2]?.split(',')[col]));
  });
});
