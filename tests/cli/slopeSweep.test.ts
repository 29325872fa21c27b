/**
 * --slope-sweep (issue 20): the programmed step for h at each slope and the cusp one
 * constant step leaves, against the ball end's closed form (the ball's profile is a circle of radius
 * R in any posture: L = 2 sqrt(2 R h - h^2) along the surface, and a step L' leaves
 * R - sqrt(R^2 - L'^2 / 4)); with the passes along the contour (raster psi = 90) the horizontal step
 * is L cos(alpha), and waterline's step-down L sin(alpha) (the CC paths L apart up the fall line).
 */
import { describe, expect, it } from 'vitest';
import { run, runMain } from './helpers';

interface Sweep {
  input: Record<string, number | string | boolean>;
  largestSlope: number;
  programmedStep: number;
  programmedStepTyped: boolean;
  points: Array<{
    slope: number;
    horizontalStep?: number;
    stepDown?: number;
    interval?: number;
    cuspAtProgrammedStep?: number;
    programmedStepRefusal?: string;
  }>;
}

async function sweep(args: readonly string[]): Promise<Sweep> {
  const r = await runMain([...args, '--slope-sweep', '--json']);
  if (r.code !== 0) throw new Error(r.stderr);
  return JSON.parse(r.stdout) as Sweep;
}

const deg = Math.PI / 180;
const ballL = (R: number, h: number) => 2 * Math.sqrt(2 * R * h - h * h);
const ballCusp = (R: number, L: number) => R - Math.sqrt(R * R - (L * L) / 4);

describe('--slope-sweep', () => {
  it('raster along the contour, a ball end: Lxy = L cos(alpha) and the flat floor step leaves the circle cusp at every slope', async () => {
    const s = await sweep(['--R', '2', '--Rcr', '2', '--h', '0.01', '--raster-angle', '90']);
    expect(s.points).toHaveLength(31);
    expect(s.programmedStepTyped).toBe(false);
    expect(Math.abs(s.programmedStep - ballL(2, 0.01))).toBeLessThan(1e-12);
    let checked = 0;
    for (const p of s.points) {
      if (p.horizontalStep === undefined) continue;
      const a = p.slope * deg;
      expect(Math.abs(p.horizontalStep - ballL(2, 0.01) * Math.cos(a)), String(p.slope)).toBeLessThan(1e-9);
      if (p.cuspAtProgrammedStep !== undefined) {
        expect(
          Math.abs(p.cuspAtProgrammedStep - ballCusp(2, s.programmedStep / Math.cos(a))),
          String(p.slope),
        ).toBeLessThan(1e-9);
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(5);
  });

  it('waterline with a typed --step-down, a ball end on a plane: dz = L sin(alpha), the constant dz leaves the circle cusp', async () => {
    const s = await sweep(['--R', '2', '--Rcr', '2', '--h', '0.01', '--passes', 'waterline', '--step-down', '0.2']);
    expect(s.programmedStepTyped).toBe(true);
    expect(s.input.stepDown).toBe(0.2);
    let checked = 0;
    for (const p of s.points) {
      if (p.slope === 0 || p.stepDown === undefined) continue;
      const a = p.slope * deg;
      expect(Math.abs(p.stepDown - ballL(2, 0.01) * Math.sin(a)), String(p.slope)).toBeLessThan(1e-9);
      if (p.cuspAtProgrammedStep !== undefined) {
        expect(Math.abs(p.cuspAtProgrammedStep - ballCusp(2, 0.2 / Math.sin(a))), String(p.slope)).toBeLessThan(1e-9);
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(5);
  });

  it('a surface that gouges at every slope is the gouging input error, as --slope gives it (issue 26 point 2)', async () => {
    const tool = ['--R', '3', '--Rcr', '1', '--h', '0.01', '--passes', 'waterline'];
    for (const [radii, field] of [
      [['--feed-radius', '-0.5', '--cross-radius', '-0.5'], 'crossRadius'],
      [['--feed-radius', '-0.5', '--cross-radius', '-2'], 'crossRadius'],
      [['--cross-radius', '-2'], 'crossRadius'],
    ] as const) {
      const r = await runMain([...tool, ...radii, '--slope-sweep', '--json']);
      expect(r.code, radii.join(' ')).toBe(2);
      const e = JSON.parse(r.stdout).errors;
      expect(e).toHaveLength(1);
      expect(e[0]).toMatchObject({ field, code: 'gouging' });
      expect(e[0].message).toContain('at every slope');
      const single = await runMain([...tool, ...radii, '--slope', '45', '--json']);
      expect(single.code).toBe(2);
      expect(JSON.parse(single.stdout).errors[0].code).toBe('gouging');
      const table = await runMain([...tool, ...radii, '--slope-sweep']);
      expect(table.code).toBe(2);
      expect(table.stdout).toBe('');
      expect(table.stderr.trimEnd().split('\n')).toHaveLength(1);
      expect(table.stderr).toMatch(/^error: --cross-radius: Cross radius Rc .*too tight for this tool at every slope/);
    }
  });

  it('a table of 31 slopes; the combinations that do not exist are one-line usage errors', async () => {
    const r = await run(['--R', '3', '--Rcr', '1', '--h', '0.05', '--slope-sweep']);
    expect(r.code).toBe(0);
    const lines = r.stdout.split('\n');
    const head = lines.findIndex((l) => l.startsWith('slope [deg]'));
    expect(head).toBeGreaterThan(0);
    expect(lines.slice(head + 1, head + 32).every((l) => /^\s+\d/.test(l))).toBe(true);
    expect(r.stdout).toMatch(/Constant programmed step: the flat floor's step-over for h, Lxy = 4.624500 mm/);
    for (const args of [
      ['--slope', '30'],
      ['--interval', '1'],
      ['--rho', '3'],
      ['--horizontal-step', '1', '--step-down', '1'],
      ['--step-down', '1'],
      ['--passes', 'waterline', '--horizontal-step', '1'],
    ]) {
      const u = await runMain(['--R', '3', '--Rcr', '1', '--h', '0.05', '--slope-sweep', ...args]);
      expect(u.code, args.join(' ')).toBe(2);
      expect(u.stderr.trimEnd().split('\n'), args.join(' ')).toHaveLength(1);
    }
    const noH = await runMain(['--R', '3', '--Rcr', '1', '--slope-sweep']);
    expect(noH.stderr).toMatch(/--slope-sweep needs the scallop height --h/);
    const wall = await runMain(['--R', '3', '--Rcr', '1', '--h', '5', '--slope-sweep', '--json']);
    expect(wall.code).toBe(2);
    expect(JSON.parse(wall.stdout).errors[0].field).toBe('h');
  });
});
