/**
 * The lookup table of a doubly curved point (issue 19: the page's lookup table with the columns
 * `feedRadius` and `crossRadius`): the batch's layout with the two radii in place of the cylinder's,
 * every answered cell the core's exact step-over, a posture that gouges or an h at its limit a row
 * with its reason, and the request echoed (its radii part of what it asks).
 */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { lookupGrid } from '../../src/core/output/lookupTable';
import { PLANE } from '../../src/core/surfaces/cylinder';
import { doublyCurvedForward, doublyCurvedGouges, doublyCurvedLimits } from '../../src/core/surfaces/doublyCurved';
import { tableFileName } from '../../src/ui/lookupFile';
import { buildRequest } from '../../src/ui/request';
import { parseUrl } from '../../src/ui/state';
import { tableRequestOf } from '../../src/ui/tableRequest';
import { table } from '../../src/worker/jobs/table';
import { sameTableRequest, type TableRequest } from '../../src/worker/protocol';

const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, pattern: 'one-way' as const, surface: PLANE };

describe('a doubly curved point lookup table', () => {
  it('the page asks it with the radii; the file name says them; another radius is another table', () => {
    const built = buildRequest(parseUrl('?R=3&Rcr=1&rho=5&h=0.05&feedRadius=80&crossRadius=-40&unit=mm').state);
    if (!built.ok || built.request.mode !== 'curved-forward') throw new Error('valid');
    const request = tableRequestOf(built.request, 'mm');
    expect(request.radii).toEqual({ feedRadiusMm: 80, crossRadiusMm: -40 });
    expect(tableFileName(request)).toBe('step-over-table_5-axis_R3_Rcr1_one-way_Rf80_Rc-40_mm.csv');
    expect(sameTableRequest(request, { ...request, unit: 'in' })).toBe(false);
    expect(sameTableRequest(request, { ...request, radii: { feedRadiusMm: 80, crossRadiusMm: -41 } })).toBe(false);
    expect(sameTableRequest(request, { ...request, radii: undefined })).toBe(false);
    expect(sameTableRequest(request, { ...request, radii: { feedRadiusMm: 80, crossRadiusMm: -40 } })).toBe(true);
  });

  it('columns feedRadius and crossRadius; each cell the core value or its reason', () => {
    const radii = { feedRadiusMm: -60, crossRadiusMm: -25 };
    const request: TableRequest = { tool, grid: lookupGrid(tool), radii };
    const reply = table(request);
    if (!reply.ok) throw new Error(reply.reason);
    expect(reply.request).toBe(request);
    const rows = parseCsv(reply.csv).filter((r) => !r.blank);
    const header = rows[0]?.fields ?? [];
    expect(header.slice(0, 8)).toEqual(['R', 'Rcr', 'rho', 'h', 'tilt', 'pattern', 'feedRadius', 'crossRadius']);
    expect(header).not.toContain('surfaceRadius');
    const col = (name: string) => header.indexOf(name);
    let answered = 0;
    let gouging = 0;
    for (const r of rows.slice(1)) {
      const f = r.fields;
      expect(f[col('feedRadius')]).toBe('-60');
      expect(f[col('crossRadius')]).toBe('-25');
      const posture = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: Number(f[2]), tiltAngleDeg: Number(f[4]) };
      const h = Number(f[3]);
      const error = f[col('error')] ?? '';
      if (doublyCurvedGouges(posture, radii)) {
        gouging++;
        expect(error).toMatch(/gouges/);
        continue;
      }
      if (!(h < doublyCurvedLimits({ ...posture, ...radii }).limitMm)) {
        expect(error).toMatch(/^Scallop height h must be below/);
        continue;
      }
      answered++;
      expect(error).toBe('');
      const L = doublyCurvedForward({ ...posture, ...radii, pattern: 'one-way', scallopHeightMm: h }).intervalMm;
      expect(Number(f[col('interval')])).toBe(L);
      expect(Number(f[col('exact')])).toBe(L / 2);
    }
    expect(answered).toBeGreaterThan(100);
    // Lead 0 and tilt 0: the flat bottom lying flat gouges a bowl.
    expect(gouging).toBeGreaterThan(0);
    expect(reply.csv).not.toMatch(/NaN|Infinity|,-0[,\n]/);
  });

  it('refuses radii out of range, with the range', () => {
    const reply = table({ tool, grid: lookupGrid(tool), radii: { feedRadiusMm: 1e7, crossRadiusMm: 40 } });
    expect(reply.ok).toBe(false);
    if (!reply.ok) expect(reply.reason).toMatch(/from 0.001 mm to 1000000 mm/);
  });
});
