/**
 * The page's lookup table read back by the command line (issue 17): the worker's table, fed to
 * `--batch`, is answered on the same surface, row for row: the batch writes the very
 * same file (the same echoed inputs, the same results in full precision, the same reasons).
 */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { lookupGrid } from '../../src/core/output/lookupTable';
import { PLANE, type Surface } from '../../src/core/surfaces/cylinder';
import { doublyCurvedForward } from '../../src/core/surfaces/doublyCurved';
import { table } from '../../src/worker/jobs/table';
import { run, runMain } from './helpers';

function tableOf(surface: Surface, pattern: 'one-way' | 'zigzag' = 'one-way'): string {
  const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, pattern, surface };
  const reply = table({ tool, grid: lookupGrid(tool) });
  if (!reply.ok) throw new Error(`no table: ${reply.reason}`);
  return reply.csv;
}

/** The `interval` of the row at lead 5, tilt 0, h 0.05 (the case). */
function pageCase(csv: string): string | undefined {
  const [head, ...rows] = parseCsv(csv).filter((r) => !r.blank);
  const col = (name: string) => head?.fields.indexOf(name) ?? -1;
  const row = rows.find(
    (r) => r.fields[col('rho')] === '5' && r.fields[col('tilt')] === '0' && r.fields[col('h')] === '0.05',
  );
  return row?.fields[col('interval')];
}

describe('lookup table read back by --batch', () => {
  it('a concave cylinder across the feed: the same file back, answered on the cylinder, gouging rows included', async () => {
    const csv = tableOf({ kind: 'cylinder', radiusMm: -30, axis: 'cross' });
    const r = await run(['--batch'], csv);
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    expect(r.stdout).toBe(csv);
    // On the cylinder (L = 3.0381 mm), not on a plane.
    const L = Number(pageCase(r.stdout));
    expect(L.toFixed(4)).toBe('3.0381');
    expect(L).not.toBe(Number(pageCase(tableOf(PLANE))));
    expect(r.stdout).toMatch(/This tool gouges a concave cylinder of any radius/);
  });

  it('a convex cylinder along the feed (zigzag) and a plane: the same file back', async () => {
    for (const surface of [{ kind: 'cylinder', radiusMm: 12.5, axis: 'feed' } as const, PLANE]) {
      const csv = tableOf(surface, 'zigzag');
      const r = await run(['--batch'], csv);
      expect(r.code, JSON.stringify(surface)).toBe(0);
      expect(r.stdout, JSON.stringify(surface)).toBe(csv);
    }
  });

  it('a doubly curved point (a saddle): its feedRadius and crossRadius columns read back, the same answers', async () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, pattern: 'one-way' as const, surface: PLANE };
    const reply = table({ tool, grid: lookupGrid(tool), radii: { feedRadiusMm: 80, crossRadiusMm: -40 } });
    if (!reply.ok) throw new Error(`no table: ${reply.reason}`);
    const r = await run(['--batch'], reply.csv);
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    // Row for row the same inputs and the same exact answer (full precision), refused on the same
    // rows. (The batch also fills the plane procedures' columns and words gouging its own way.)
    const page = parseCsv(reply.csv).filter((x) => !x.blank);
    const back = parseCsv(r.stdout).filter((x) => !x.blank);
    expect(back[0]?.fields).toEqual(page[0]?.fields);
    expect(back.length).toBe(page.length);
    const head = page[0]?.fields ?? [];
    const same = ['R', 'Rcr', 'rho', 'h', 'tilt', 'pattern', 'feedRadius', 'crossRadius', 'exact', 'interval']
      .concat(['halfWidthRight', 'halfWidthLeft', 'contactOffset', 'otherCuspHeight'])
      .map((name) => head.indexOf(name));
    expect(same).not.toContain(-1);
    const error = head.indexOf('error');
    let answered = 0;
    for (let i = 1; i < page.length; i++) {
      const a = page[i]?.fields ?? [];
      const b = back[i]?.fields ?? [];
      expect(
        same.map((c) => b[c]),
        `row ${i}`,
      ).toEqual(same.map((c) => a[c]));
      expect(b[error] === '', `row ${i}`).toBe(a[error] === '');
      if (a[error] === '') answered++;
    }
    expect(answered).toBeGreaterThan(100);
    // Answered at the point (core compareDoublyCurved), not on the plane.
    const exact = doublyCurvedForward({
      toolRadiusMm: 3,
      cornerRadiusMm: 1,
      leadAngleDeg: 5,
      tiltAngleDeg: 0,
      pattern: 'one-way',
      feedRadiusMm: 80,
      crossRadiusMm: -40,
      scallopHeightMm: 0.05,
    });
    expect(Number(pageCase(r.stdout))).toBe(exact.intervalMm);
    expect(Number(pageCase(r.stdout))).not.toBe(Number(pageCase(tableOf(PLANE))));
  });
});

describe("the page's download read back by --batch (issue 21)", () => {
  it('the mm file (columns named R_mm, rho_deg, ...) is answered row for row, the same numbers', async () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, pattern: 'one-way' as const, surface: PLANE };
    const plain = table({ tool, grid: lookupGrid(tool) });
    const named = table({ tool, grid: lookupGrid(tool, 'mm'), unit: 'mm' });
    if (!plain.ok || !named.ok) throw new Error('tables');
    expect(named.csv.split('\n')[0]).toMatch(/^R_mm,Rcr_mm,rho_deg,h_mm,tilt_deg,pattern,/);
    const r = await run(['--batch'], named.csv);
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    // The batch writes its own plain header, then the very same rows.
    expect(r.stdout).toBe(plain.csv);
    expect(r.stdout.split('\n').slice(1)).toEqual(named.csv.split('\n').slice(1));
  });

  it("the inch file reads back (columns R_in...): its results are the inch table's (issue 26 point 9)", async () => {
    const tool = { toolRadiusMm: 6.35, cornerRadiusMm: 1.5875, pattern: 'one-way' as const, surface: PLANE };
    const named = table({
      tool,
      grid: { scallopHeightsMm: [0.0254], leadAnglesDeg: [5], tiltAnglesDeg: [0] },
      unit: 'in',
    });
    if (!named.ok) throw new Error('table');
    const r = await runMain(['--batch', '--unit', 'inch'], named.csv);
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    const [head, ...rows] = parseCsv(r.stdout).map((x) => x.fields);
    const [wantHead, ...want] = parseCsv(named.csv).map((x) => x.fields);
    // The batch names the unit of every length column; angles are degrees without saying so.
    expect(head).toEqual(wantHead?.map((name) => name.replace(/_deg$/, '')));
    expect(rows.length).toBe(want.length);
    rows.forEach((row, i) => {
      row.forEach((text, j) => {
        const expected = want[i]?.[j] ?? '';
        // Inch inputs become mm once (0.001 in is 0.0254 mm to an ulp): the results agree to 1e-12.
        if (text === '' || Number.isNaN(Number(text))) expect(text).toBe(expected);
        else expect(Math.abs(Number(text) - Number(expected))).toBeLessThanOrEqual(1e-12 * Math.abs(Number(expected)));
      });
    });
  });
});
