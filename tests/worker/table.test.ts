/** The worker's `table` job in Node: it echoes its request, revalidates the tool, bounds the grid. */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { lookupGrid, lookupTable } from '../../src/core/output/lookupTable';
import { PLANE } from '../../src/core/surfaces/cylinder';
import { MAX_GRID_AXIS, table } from '../../src/worker/jobs/table';
import { sameTableRequest, type TableRequest } from '../../src/worker/protocol';
import { bruteForceCylinder } from '../support/cylinderBruteForce';

const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, pattern: 'one-way' as const, surface: PLANE };

describe('table job', () => {
  it('answers with the core table and echoes the request', () => {
    const request: TableRequest = { tool, grid: lookupGrid(tool) };
    const reply = table(request);
    expect(reply.ok).toBe(true);
    expect(reply.request).toBe(request);
    if (reply.ok) expect(reply.csv).toBe(lookupTable(tool, request.grid).csv);
    expect(sameTableRequest(reply.request, { tool: { ...tool }, grid: lookupGrid(tool) })).toBe(true);
    expect(sameTableRequest(reply.request, { tool: { ...tool, cornerRadiusMm: 1.5 }, grid: request.grid })).toBe(false);
  });

  it('tabulates a concave cylinder that a flat bottom lying flat gouges: the postures that cut it are answered (issue 17)', () => {
    // R 3, Rcr 1 on Rs = -30 across the feed: lead 0 and tilt 0 gouge a concave cylinder of any
    // radius, the page's rho = 5 does not (L = 3.0381 mm). The tool is no reason to refuse the table.
    const cylinder = { kind: 'cylinder', radiusMm: -30, axis: 'cross' } as const;
    const concave = { ...tool, surface: cylinder };
    const grid = lookupGrid(concave);
    const reply = table({ tool: concave, grid });
    if (!reply.ok) throw new Error(`no table: ${reply.reason}`);
    const rows = parseCsv(reply.csv).filter((r) => !r.blank);
    const header = rows[0]?.fields ?? [];
    const col = (name: string) => header.indexOf(name);
    const cell = (rho: number, tilt: number, h: number) =>
      rows.find((r) => r.fields[2] === String(rho) && r.fields[4] === String(tilt) && r.fields[3] === String(h));
    for (const r of rows.slice(1)) {
      expect(r.fields[col('surfaceRadius')]).toBe('-30');
      expect(r.fields[col('surfaceAxis')]).toBe('cross');
    }
    // The posture that gouges is a row with its reason, as the batch gives it.
    expect(cell(0, 0, 0.05)?.fields[col('error')]).toMatch(/^This tool gouges a concave cylinder of any radius/);
    expect(cell(0, 0, 0.05)?.fields[col('interval')]).toBe('');
    // The page's case: L = 3.0381 mm, whose passes leave 0.05 mm cusps on the sampled real tool
    // swept over the cylinder (brute force, sharing nothing with the solver).
    const page = cell(5, 0, 0.05);
    expect(page?.fields[col('error')]).toBe('');
    const L = Number(page?.fields[col('interval')]);
    expect(L.toFixed(4)).toBe('3.0381');
    const posture = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
    const b = bruteForceCylinder(posture, 'one-way', -30, 'cross', L, { spacingMm: 0.003, bins: 3000 });
    expect(b.cuspHeightsMm.length).toBeGreaterThan(0);
    for (const c of b.cuspHeightsMm) expect(Math.abs(c - 0.05)).toBeLessThanOrEqual(b.boundMm);
    expect(b.boundMm).toBeLessThan(0.3 * 0.05);
    // Most of the grid is answered; the rest are rows with reasons.
    expect(reply.rows).toBe(rows.length - 1);
    expect(reply.emptyCells).toBeLessThan(reply.rows / 2);
  });

  it('refuses an invalid tool or grid, saying why', () => {
    const grid = lookupGrid(tool);
    const bad = table({ tool: { ...tool, cornerRadiusMm: 4 }, grid });
    expect(!bad.ok && bad.reason).toMatch(/Corner radius Rcr must not exceed the tool radius R = 3 mm/);
    const huge = table({
      tool,
      grid: { ...grid, leadAnglesDeg: Array.from({ length: MAX_GRID_AXIS + 1 }, (_, i) => i) },
    });
    expect(!huge.ok && huge.reason).toMatch(/1 to 64 lead angles/);
    const nan = table({ tool, grid: { ...grid, tiltAnglesDeg: [Number.NaN] } });
    expect(!nan.ok && nan.reason).toMatch(/tilts are out of range/);
  });
});
