/**
 * Issue 19's command line: doubly curved points (--feed-radius and --cross-radius),
 * the cylinder shorthand (one radius alone is --surface-radius with its axis: the same digits), the
 * gouging and range errors (one line, named on the radius, in JSON too), the JSON fields and the
 * batch columns. Independent reference: a ball end on a sphere, where a pass's section in the
 * cross-feed plane is the ball's own disk (the swept ball is a torus about l, whose meridian plane is
 * that plane), so the cusp is where two circles of radius R whose centres lie D = Rs + R (convex) or
 * |Rs| - R (concave) from the sphere's centre, phi = L / |Rs| apart, cross:
 * `d^2 + D^2 - 2 d D cos(phi / 2) = R^2` with `d = Rs + h` (convex) or `|Rs| - h` (concave).
 */
import { describe, expect, it } from 'vitest';
import { doublyCurvedForward } from '../../src/core/surfaces/doublyCurved/solve';
import { run, runMain } from './helpers';

/** The ball end's step-over on a sphere of signed radius rs for a scallop h (closed form, module comment). */
function ballOnSphereL(R: number, rs: number, h: number): number {
  const a = Math.abs(rs);
  const D = rs > 0 ? a + R : a - R;
  const d = rs > 0 ? a + h : a - h;
  const c = (d * d + D * D - R * R) / (2 * d * D);
  return 2 * a * Math.acos(c);
}

/** The cusp height a ball end leaves on a sphere at step-over L (the same circles, solved for d). */
function ballOnSphereH(R: number, rs: number, L: number): number {
  const a = Math.abs(rs);
  const D = rs > 0 ? a + R : a - R;
  const half = L / (2 * a);
  // d^2 - 2 d D cos + D^2 - R^2 = 0: the root nearest the sphere (the lower intersection).
  const d = D * Math.cos(half) + (rs > 0 ? -1 : 1) * Math.sqrt(R * R - D * D * Math.sin(half) ** 2);
  return rs > 0 ? d - a : a - d;
}

async function json(args: readonly string[]): Promise<Record<string, unknown>> {
  const r = await runMain([...args, '--json']);
  if (r.code !== 0) throw new Error(`${args.join(' ')}: ${r.stderr}`);
  return JSON.parse(r.stdout) as Record<string, unknown>;
}

const TOOL = ['--R', '3', '--Rcr', '1', '--rho', '10', '--tilt', '5'];

describe('doubly curved points on the command line', () => {
  it('a ball end on a sphere (convex and concave, both patterns): L and the inverse h within 1e-9 mm of the circles', async () => {
    for (const rs of [40, -40, 7.5, -12]) {
      for (const pattern of ['one-way', 'zigzag']) {
        const base = ['--R', '2', '--Rcr', '2', '--rho', '15', '--pattern', pattern];
        const radii = ['--feed-radius', String(rs), '--cross-radius', String(rs)];
        const f = (await json([...base, ...radii, '--h', '0.02'])) as { exact: { interval: number } };
        expect(Math.abs(f.exact.interval - ballOnSphereL(2, rs, 0.02)), `${rs} ${pattern}`).toBeLessThan(1e-9);
        const i = (await json([...base, ...radii, '--interval', '0.9'])) as { exact: { scallopHeight: number } };
        expect(Math.abs(i.exact.scallopHeight - ballOnSphereH(2, rs, 0.9)), `${rs} ${pattern}`).toBeLessThan(1e-9);
      }
    }
  });

  it('the table shows the exact answer, the comparison rows and the roughness; JSON echoes the radii', async () => {
    const r = await run([...TOOL, '--h', '0.05', '--feed-radius', '40', '--cross-radius', '-80']);
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/saddle/);
    for (const row of [
      'Plane, exact (curvature ignored)',
      'Cylinder along the feed, exact (Rf ignored)',
      'Cylinder across the feed, exact (Rc ignored)',
      'Redonnet et al., 1/rho = 1/Reff + 1/Rc',
      'Ra ',
    ]) {
      expect(r.stdout).toContain(row);
    }
    const j = await run([...TOOL, '--h', '0.05', '--feed-radius', '40', '--cross-radius', '-80', '--json']);
    const out = JSON.parse(j.stdout);
    expect(out.input).toMatchObject({ feedRadius: 40, crossRadius: -80, h: 0.05, tilt: 5 });
    const core = doublyCurvedForward({
      toolRadiusMm: 3,
      cornerRadiusMm: 1,
      leadAngleDeg: 10,
      tiltAngleDeg: 5,
      pattern: 'one-way',
      feedRadiusMm: 40,
      crossRadiusMm: -80,
      scallopHeightMm: 0.05,
    });
    expect(out.exact.interval).toBe(core.intervalMm);
    for (const key of ['plane', 'cylinderAlong', 'cylinderAcross', 'sekine', 'redonnet', 'osculating', 'cornerBall']) {
      expect(out.comparison[key], key).toBeDefined();
    }
    // Each row's deviation is its L minus the exact one; its real scallop is the exact inverse at its L.
    const plane = out.comparison.plane;
    expect(plane.intervalDeviation).toBeCloseTo(plane.interval - out.exact.interval, 15);
    const back = await json([
      ...TOOL,
      '--interval',
      String(plane.interval),
      '--feed-radius',
      '40',
      '--cross-radius',
      '-80',
    ]);
    expect((back as { exact: { scallopHeight: number } }).exact.scallopHeight).toBe(plane.realScallopHeight);
    const z = await json([
      ...TOOL,
      '--h',
      '0.05',
      '--feed-radius',
      '40',
      '--cross-radius',
      '80',
      '--pattern',
      'zigzag',
    ]);
    expect((z as { exact: { otherCuspHeight: number } }).exact.otherCuspHeight).toBeLessThan(0.05);
    expect(out.roughness.Ra).toBeGreaterThan(0);
  });

  it('one radius alone is the cylinder shorthand: the very same digits as --surface-radius with its axis', async () => {
    for (const extra of [
      ['--h', '0.05'],
      ['--ra', '0.01'],
      ['--interval', '1.2'],
      ['--half-interval', '0.6'],
    ]) {
      for (const [mine, axis] of [
        ['--cross-radius', 'feed'],
        ['--feed-radius', 'cross'],
      ] as const) {
        for (const rs of ['50', '-60']) {
          const a = await runMain([...TOOL, ...extra, mine, rs, '--json']);
          const b = await runMain([...TOOL, ...extra, '--surface-radius', rs, '--surface-axis', axis, '--json']);
          expect(a.code).toBe(0);
          const ja = JSON.parse(a.stdout);
          const jb = JSON.parse(b.stdout);
          expect(ja.exact, `${mine} ${rs} ${extra}`).toEqual(jb.exact);
          expect(ja.roughness).toEqual(jb.roughness);
          expect(ja.input[mine === '--cross-radius' ? 'crossRadius' : 'feedRadius']).toBe(Number(rs));
          const ta = await runMain([...TOOL, ...extra, mine, rs]);
          const tb = await runMain([...TOOL, ...extra, '--surface-radius', rs, '--surface-axis', axis]);
          expect(ta.stdout).toBe(tb.stdout);
        }
      }
    }
    // Omitted: the plane, as before.
    const p = await runMain([...TOOL, '--h', '0.05', '--json']);
    expect(JSON.parse(p.stdout).input.feedRadius).toBeUndefined();
  });

  it('gouging: one line naming the radius and its limit with the other held; JSON carries it; "at any radius" where none helps', async () => {
    const r = await run([...TOOL, '--h', '0.05', '--feed-radius', '40', '--cross-radius', '-8']);
    expect(r.code).toBe(2);
    expect(r.stdout).toBe('');
    const lines = r.stderr.trimEnd().split('\n');
    expect(lines).toHaveLength(1);
    expect(lines[0]).toMatch(
      /^error: --cross-radius: Cross radius Rc: a concave Rc must be at least [\d.]+ mm .*Rf = 40 mm held/,
    );
    const j = await run([...TOOL, '--h', '0.05', '--feed-radius', '40', '--cross-radius', '-8', '--json']);
    const e = JSON.parse(j.stdout).errors[0];
    expect(e).toMatchObject({ field: 'crossRadius', option: '--cross-radius', code: 'radius-gouging' });
    // The limit is the boundary: a little wider passes, a little tighter gouges.
    const limit = e.limit as number;
    expect(limit).toBeLessThan(-8);
    const wider = await runMain([
      ...TOOL,
      '--h',
      '0.05',
      '--feed-radius',
      '40',
      '--cross-radius',
      String(limit * 1.001),
    ]);
    expect(wider.code).toBe(0);
    const tighter = await runMain([
      ...TOOL,
      '--h',
      '0.05',
      '--feed-radius',
      '40',
      '--cross-radius',
      String(limit * 0.999),
    ]);
    expect(tighter.code).toBe(2);
    // A flat end without lead on a bowl: no concave Rc helps with Rf held.
    const flat = await run([
      '--R',
      '3',
      '--Rcr',
      '0',
      '--rho',
      '0',
      '--h',
      '0.01',
      '--feed-radius',
      '50',
      '--cross-radius',
      '-80',
    ]);
    expect(flat.code).toBe(2);
    expect(flat.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(flat.stderr).toMatch(/Cross radius Rc must be straight or convex .* any concave Rc is gouged/);
    const none = await run([
      ...TOOL.slice(0, 6),
      '--h',
      '0.05',
      '--feed-radius',
      '-5',
      '--cross-radius',
      '300',
      '--json',
    ]);
    const en = JSON.parse(none.stdout).errors[0];
    expect(en.field).toBe('feedRadius');
    expect(en.message).toMatch(/no Rc helps with Rf held/);
  });

  it('range errors and usage errors: one line each, exit 2', async () => {
    const r = await run([...TOOL, '--h', '0.05', '--feed-radius', '40', '--cross-radius', '0']);
    expect(r.code).toBe(2);
    expect(r.stderr).toBe(
      'error: --cross-radius: Cross radius Rc must be a radius from 0.001 mm to 1000000 mm, negative for concave; leave it out for straight (got 0).\n',
    );
    const big = await run([...TOOL, '--h', '0.05', '--feed-radius', '2e6']);
    expect(big.stderr).toMatch(/^error: --feed-radius: Feed radius Rf must be a radius from 0.001 mm to 1000000 mm/);
    for (const args of [
      ['--feed-radius', '40', '--surface-radius', '50'],
      ['--cross-radius', '40', '--surface-axis', 'cross', '--surface-radius', '5'],
      ['--cross-radius', '40', '--simulate'],
    ]) {
      const u = await run([...TOOL, '--h', '0.05', ...args]);
      expect(u.code, args.join(' ')).toBe(2);
      expect(u.stderr.trimEnd().split('\n'), args.join(' ')).toHaveLength(1);
      expect(u.stderr).toMatch(/see path-interval --help/);
    }
  });

  it('--ra at a doubly curved point: the h found leaves that Ra (the inverse at its L gives it back)', async () => {
    const args = [...TOOL, '--feed-radius', '-60', '--cross-radius', '25'];
    const f = (await json([...args, '--ra', '0.004'])) as {
      input: { Ra: number };
      exact: { interval: number };
      roughness: { Ra: number };
    };
    expect(f.input.Ra).toBe(0.004);
    expect(Math.abs(f.roughness.Ra - 0.004)).toBeLessThan(1e-12);
    const i = (await json([...args, '--interval', String(f.exact.interval)])) as { roughness: { Ra: number } };
    expect(Math.abs(i.roughness.Ra - 0.004)).toBeLessThan(1e-9);
  });

  it('--batch: feedRadius and crossRadius columns, interval and otherCuspHeight out, gouging in error; reads back to itself', async () => {
    const csv = [
      'R,Rcr,rho,tilt,pattern,h,feedRadius,crossRadius',
      '3,1,10,5,zigzag,0.05,40,-80',
      '3,1,10,5,one-way,0.05,,50',
      '3,1,10,5,one-way,0.05,40,-8',
      '3,1,10,5,one-way,0.05,,',
      '',
    ].join('\n');
    const r = await run(['--batch'], csv);
    expect(r.code).toBe(0);
    const [head, ...rows] = r.stdout.trimEnd().split('\n');
    const cols = (head as string).split(',');
    const at = (row: string, name: string) => row.split(',')[cols.indexOf(name)];
    const z = (await json([
      ...TOOL,
      '--pattern',
      'zigzag',
      '--h',
      '0.05',
      '--feed-radius',
      '40',
      '--cross-radius',
      '-80',
    ])) as {
      exact: { interval: number; otherCuspHeight: number };
    };
    expect(Number(at(rows[0] as string, 'interval'))).toBe(z.exact.interval);
    expect(Number(at(rows[0] as string, 'otherCuspHeight'))).toBe(z.exact.otherCuspHeight);
    const cyl = (await json([...TOOL, '--h', '0.05', '--surface-radius', '50'])) as { exact: { interval: number } };
    expect(Number(at(rows[1] as string, 'interval'))).toBe(cyl.exact.interval);
    expect(rows[2]).toMatch(/Cross radius Rc: a concave Rc must be at least/);
    const plane = (await json([...TOOL, '--h', '0.05'])) as { exact: { interval: number } };
    expect(Number(at(rows[3] as string, 'interval'))).toBe(plane.exact.interval);
    const back = await run(['--batch'], r.stdout);
    expect(back.stdout).toBe(r.stdout);
    const mixed = await run(['--batch'], 'R,Rcr,rho,h,surfaceRadius,feedRadius\n3,1,10,0.05,50,40\n');
    expect(mixed.stdout).toMatch(/give the surface once/);
  });
});
