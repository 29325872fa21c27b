/**
 * Issue 26, point 6, on the command line: the two questions that answered `null` at exit 0
 * (a doubly curved roughness at a step-over of 4.2e-5 mm; a flat end's simulation at a target Ra of
 * 1.6e-8 mm) give a number in every field of their JSON.
 */
import { describe, expect, it } from 'vitest';
import { runMain } from './helpers';

/** Paths (a.b.c) of the members of a parsed JSON value that are null. */
function nullPaths(value: unknown, path = ''): string[] {
  if (value === null) return [path];
  if (typeof value !== 'object') return [];
  return Object.entries(value as Record<string, unknown>).flatMap(([k, v]) => nullPaths(v, path ? `${path}.${k}` : k));
}

describe('roughness and simulation JSON at tiny scallops (issue 26, point 6)', () => {
  it('a doubly curved point at --interval 4.2e-5: Ra, Rq and the rule of thumb deviation are numbers', async () => {
    const r = await runMain([
      ...['--R', '1.116', '--Rcr', '0.6216', '--rho', '41.627362190769055'],
      ...['--feed-radius', '3413.9965998497723', '--cross-radius', '0.1143'],
      ...['--interval', '0.000042261027907111694', '--json'],
    ]);
    expect(r.code).toBe(0);
    const json = JSON.parse(r.stdout);
    expect(nullPaths(json)).toEqual([]);
    expect(json.roughness.Ra).toBeGreaterThan(0);
    expect(json.roughness.Rq).toBeGreaterThan(json.roughness.Ra);
  });

  it('a flat end leaning 37.7 deg, --ra 1.64e-8 --simulate: every simulated height is a number', async () => {
    const r = await runMain([
      ...['--R', '4.231758111389403', '--Rcr', '0', '--rho', '2.5549168162280695'],
      ...['--tilt', '37.69496732666157', '--ra=1.6396786026998403e-8', '--simulate', '--json'],
    ]);
    expect(r.code).toBe(0);
    const json = JSON.parse(r.stdout);
    expect(nullPaths(json)).toEqual([]);
    expect(json.simulation.cuspHeight).toBeGreaterThan(0);
  });
});
