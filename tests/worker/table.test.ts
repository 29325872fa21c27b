/** The worker's `table` job in Node: it echoes its request, revalidates the tool, bounds the grid. */
import { describe, expect, it } from 'vitest';
import { PLANE } from '../../src/core/cylinder';
import { lookupGrid, lookupTable } from '../../src/core/lookupTable';
import { sameTableRequest, type TableRequest } from '../../src/worker/protocol';
import { MAX_GRID_AXIS, table } from '../../src/worker/table';

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
