/** A flat end without lead or tilt: no scallop, L = 2R, in the table, JSON and batch alike. */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { run } from './helpers';

describe('flat end without lead (Rcr = 0, rho = 0, tilt = 0)', () => {
  it('answers L = 2R with no scallop in JSON and says so in the table; with tilt it is a wall', async () => {
    const json = await run(['--R', '3', '--Rcr', '0', '--rho', '0', '--h', '0.05', '--json']);
    expect(json.code).toBe(0);
    const out = JSON.parse(json.stdout);
    expect(out.exact).toMatchObject({ interval: 6, halfInterval: 3, noScallop: true, scallopHeight: 0 });
    const table = await run(['--R', '3', '--Rcr', '0', '--rho', '0', '--h', '0.05']);
    expect(table.code).toBe(0);
    expect(table.stdout).toMatch(/no scallop/i);
    const tilted = await run(['--R', '3', '--Rcr', '0', '--rho', '0', '--tilt', '5', '--h', '0.05']);
    expect(tilted.code).toBe(2);
    expect(tilted.stderr).toMatch(/cuts a step at any step-over/);
  });

  it('the batch row gives exact = R, interval = 2R and the note', async () => {
    const batch = await run(['--batch'], 'R,Rcr,rho,h\n3,0,0,0.05\n');
    expect(batch.code).toBe(0);
    const [head, row] = parseCsv(batch.stdout).filter((r) => !r.blank);
    const at = (name: string) => row?.fields[head?.fields.indexOf(name) ?? -1];
    expect(at('exact')).toBe('3');
    expect(at('interval')).toBe('6');
    expect(at('note')).toMatch(/leaves no scallop at any step-over up to its diameter \(L = 2R\)/);
    expect(at('error')).toBe('');
  });
});
