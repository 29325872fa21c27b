/**
 * The page's lookup table read back by the command line (issue 17): the worker's table, fed to
 * `--batch` as a process, is answered on the same surface, row for row: the batch writes the very
 * same file (the same echoed inputs, the same results in full precision, the same reasons).
 */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { lookupGrid } from '../../src/core/output/lookupTable';
import { PLANE, type Surface } from '../../src/core/surfaces/cylinder';
import { table } from '../../src/worker/jobs/table';
import { run } from './helpers';

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
  }, 30_000);

  it('a convex cylinder along the feed (zigzag) and a plane: the same file back', async () => {
    for (const surface of [{ kind: 'cylinder', radiusMm: 12.5, axis: 'feed' } as const, PLANE]) {
      const csv = tableOf(surface, 'zigzag');
      const r = await run(['--batch'], csv);
      expect(r.code, JSON.stringify(surface)).toBe(0);
      expect(r.stdout, JSON.stringify(surface)).toBe(csv);
    }
  }, 30_000);
});
