/** The lookup table in the user's unit (issue 21): unit-named columns, inch lengths, the batch layout kept. */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../../src/cli/csv';
import { forwardInput } from '../../../src/core/input/validate';
import { LOOKUP_HEADER, lookupGrid, lookupTable } from '../../../src/core/output/lookupTable';
import { lookupCsvInUnit, unitNamedColumn } from '../../../src/core/output/lookupUnits';
import { PLANE } from '../../../src/core/surfaces/cylinder';
import { exactForward } from '../../../src/core/surfaces/solve';
import { table } from '../../../src/worker/jobs/table';

/** A quarter-inch tool, corner 1/16 in. */
const tool = { toolRadiusMm: 6.35, cornerRadiusMm: 1.5875, pattern: 'zigzag' as const, surface: PLANE };

function records(csv: string): string[][] {
  return parseCsv(csv)
    .filter((r) => !r.blank)
    .map((r) => [...r.fields]);
}

describe('lookup table in the user unit', () => {
  it('mm: the same numbers, every dimensioned column named _mm or _deg', () => {
    const grid = { scallopHeightsMm: [0.01, 0.05], leadAnglesDeg: [0, 5], tiltAnglesDeg: [0] };
    const mm = lookupTable(tool, grid).csv;
    const named = lookupCsvInUnit(mm, 'mm');
    const [head, ...rows] = records(named);
    expect(head?.slice(0, 9)).toEqual([
      'R_mm',
      'Rcr_mm',
      'rho_deg',
      'h_mm',
      'tilt_deg',
      'pattern',
      'surfaceRadius_mm',
      'surfaceAxis',
      'exact_mm',
    ]);
    expect(head?.slice(-3)).toEqual(['cornerBall_mm', 'note', 'error']);
    expect(rows).toEqual(records(mm).slice(1));
  });

  it('inch: the lengths in inches (inputs as typed, results in full precision), _in in the header, the reasons in inches', () => {
    const reply = table({ tool, grid: lookupGrid(tool, 'in'), unit: 'in' });
    if (!reply.ok) throw new Error(reply.reason);
    const [head = [], ...rows] = records(reply.csv);
    expect(head.join(',')).toBe(
      LOOKUP_HEADER.split(',')
        .map((c) =>
          ['rho', 'tilt'].includes(c)
            ? `${c}_deg`
            : ['pattern', 'surfaceAxis', 'note', 'error'].includes(c)
              ? c
              : `${c}_in`,
        )
        .join(','),
    );
    const col = (name: string) => head.indexOf(name);
    // The inch grid: 1-2-5 in inches, from about 1e-4 R (0.000025 in -> 0.00002 in).
    const hs = [...new Set(rows.map((r) => r[col('h_in')]))];
    expect(hs.slice(0, 4)).toEqual(['0.00002', '0.00005', '0.0001', '0.0002']);
    let answered = 0;
    let refused = 0;
    for (const r of rows) {
      expect(r[col('R_in')]).toBe('0.25');
      expect(r[col('Rcr_in')]).toBe('0.0625');
      const h = Number(r[col('h_in')]) * 25.4;
      const t = { toolRadiusMm: 6.35, cornerRadiusMm: 1.5875, leadAngleDeg: Number(r[col('rho_deg')]) };
      const error = r[col('error')] ?? '';
      if (error !== '') {
        refused++;
        expect(error).toMatch(/^Scallop height h must be below .* in \(got [\d.e-]+\)/);
        expect(error).not.toMatch(/mm/);
        continue;
      }
      answered++;
      const e = exactForward(forwardInput({ ...t, tiltAngleDeg: Number(r[col('tilt_deg')]) }, 'zigzag', h));
      expect(Number(r[col('interval_in')])).toBeCloseTo(e.intervalMm / 25.4, 12);
    }
    expect(answered).toBeGreaterThan(100);
    expect(refused).toBeGreaterThan(0);
  });

  it('a unit-named column reads as its batch column and its unit', () => {
    expect(unitNamedColumn('R_in')).toEqual({ column: 'R', unit: 'in' });
    expect(unitNamedColumn('interval_mm')).toEqual({ column: 'interval', unit: 'mm' });
    expect(unitNamedColumn('rho_deg')).toEqual({ column: 'rho', unit: null });
    expect(unitNamedColumn('R')).toEqual({ column: 'R', unit: null });
    expect(unitNamedColumn('pattern_mm')).toEqual({ column: 'pattern_mm', unit: null });
  });
});
