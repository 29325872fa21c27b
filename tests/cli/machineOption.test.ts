/**
 * The command line's `--machine <mode>` and `--surface <kind>` (issue 27 point 3), named from the
 * registries of modes and surfaces (cli/registryOptions.ts): the product's modes and surfaces only
 * name what the other options give (the same answer, to the byte, as without them), a mismatch or
 * an unknown name is a usage error in one line that lists the registries' names, and a registered
 * mode or surface beyond the product's (the throwaway fixed-lead head and drum) is answered as the
 * one question over the registries. In-process, and once as a process.
 */
import { afterEach, describe, expect, it } from 'vitest';
import { registerMode } from '../../src/core/surfaces/modes';
import { registerSurfaceModel } from '../../src/core/surfaces/registry';
import { exactForward } from '../../src/core/surfaces/solve';
import { DRUM_AS_CYLINDER, drumModel } from '../support/throwaway/drumSurface';
import { fixedLeadMode } from '../support/throwaway/fixedLeadMode';
import { run, runProcess } from './helpers';

const FIVE = ['--R', '5', '--Rcr', '1.5', '--rho', '12', '--h', '0.01'];
const THREE = ['--R', '5', '--Rcr', '1.5', '--slope', '30', '--h', '0.01'];

let removers: Array<() => void> = [];
afterEach(() => {
  for (const remove of removers) remove();
  removers = [];
});

describe('--machine and --surface: the product modes and surfaces', () => {
  it('name what the other options give: the same output as without them', async () => {
    const cases: Array<[string[], string[]]> = [
      [FIVE, ['--machine', '5-axis', '--surface', 'plane']],
      [
        [...FIVE, '--surface-radius', '-40'],
        ['--surface', 'cylinder'],
      ],
      [
        [...FIVE, '--feed-radius', '50', '--cross-radius', '-80'],
        ['--machine', 'fiveAxis', '--surface', 'doublyCurved'],
      ],
      [
        [...FIVE, '--cross-radius', '60'],
        ['--surface', 'cylinder'],
      ],
      [THREE, ['--machine', '3-axis', '--surface', 'plane']],
      [
        [...THREE, '--passes', 'waterline', '--feed-radius', '50', '--cross-radius', '50'],
        ['--machine', '3-axis', '--surface', 'doublyCurved'],
      ],
      [
        ['--R', '3', '--Rcr', '1', '--h', '0.01', '--slope-sweep'],
        ['--machine', '3-axis'],
      ],
      [
        [...FIVE, '--json'],
        ['--machine', '5-axis'],
      ],
    ];
    for (const [base, named] of cases) {
      const plain = await run(base);
      expect(plain.code, base.join(' ')).toBe(0);
      const withNames = await run([...base, ...named]);
      expect(withNames, [...base, ...named].join(' ')).toEqual(plain);
    }
  });

  it('a mismatch or an unknown name: a usage error in one line, the names listed from the registries', async () => {
    const cases: Array<[string[], RegExp]> = [
      [[...FIVE, '--machine', '4-axis'], /^error: --machine must be one of 5-axis, 3-axis \(got "4-axis"\)/],
      [
        [...FIVE, '--surface', 'torus'],
        /^error: --surface must be one of plane, cylinder, doublyCurved \(got "torus"\)/,
      ],
      [[...THREE, '--machine', '5-axis'], /^error: --machine 5-axis does not go with --slope/],
      [[...FIVE, '--machine', '3-axis'], /^error: --machine 3-axis needs the surface's slope: give --slope <deg>/],
      [
        [...FIVE, '--surface', 'cylinder'],
        /^error: --surface cylinder does not match the other options, which give a plane: give its radius with --surface-radius <mm>/,
      ],
      [
        [...FIVE, '--surface-radius', '40', '--surface', 'plane'],
        /^error: --surface plane does not match the other options, which give a cylinder/,
      ],
      [
        [...THREE, '--surface', 'cylinder'],
        /^error: --surface cylinder does not match the other options, which give a plane/,
      ],
      [['--batch', '--machine', '5-axis'], /^error: --machine does not go with --batch/],
    ];
    for (const [args, message] of cases) {
      const r = await run(args);
      expect(r.code, args.join(' ')).toBe(2);
      expect(r.stderr, args.join(' ')).toMatch(message);
      expect(r.stderr.trim().split('\n'), args.join(' ')).toHaveLength(1);
    }
  });
});

describe('--machine and --surface: a registered mode and surface beyond the product', () => {
  it('the throwaway head over the drum: the one question answered, listed once registered', async () => {
    const args = ['--R', '5', '--Rcr', '1.5', '--rho', '12', '--pattern', 'zigzag', '--h', '0.01'];
    const named = ['--machine', 'throwawayFixedLead', '--surface', 'throwawayDrum'];
    const before = await run([...args, ...named]);
    expect(before.stderr).toMatch(/^error: --machine must be one of 5-axis, 3-axis \(got "throwawayFixedLead"\)/);
    removers.push(registerSurfaceModel(drumModel), registerMode(fixedLeadMode));
    const own = exactForward({
      toolRadiusMm: 5,
      cornerRadiusMm: 1.5,
      leadAngleDeg: 12,
      tiltAngleDeg: 0,
      pattern: 'zigzag',
      surface: DRUM_AS_CYLINDER,
      scallopHeightMm: 0.01,
    });
    const json = await run([...args, ...named, '--json']);
    expect(json.code, json.stderr).toBe(0);
    const answer = JSON.parse(json.stdout) as Record<string, unknown>;
    expect(answer.interval).toBe(own.intervalMm);
    expect([answer.lead, answer.tilt, answer.pattern]).toEqual([12, 0, 'zigzag']);
    // In inches: the same question typed in inches, the answer in inches.
    const inch = await run([
      ...['--R', String(5 / 25.4), '--Rcr', String(1.5 / 25.4), '--rho', '12', '--pattern', 'zigzag'],
      ...['--h', String(0.01 / 25.4), '--unit', 'inch', '--json', ...named],
    ]);
    expect(Math.abs((JSON.parse(inch.stdout) as { interval: number }).interval * 25.4 - own.intervalMm)).toBeLessThan(
      1e-12,
    );
    const table = await run([...args, ...named]);
    expect(table.stdout).toMatch(/^throwawayFixedLead machining over a surface of kind throwawayDrum/);
    expect(table.stdout).toContain(`Step-over L       ${Number(own.intervalMm.toPrecision(6))} mm`);
    // The mode's own refusal, one line; a product mode over the drum (five-axis has a posture everywhere).
    const steep = await run([...args.map((a) => (a === '12' ? '45' : a)), ...named]);
    expect([steep.code, steep.stderr]).toEqual([
      2,
      'error: Lead angle must be from 0 to 30 degrees on this head (got 45).\n',
    ]);
    const five = await run([...args, '--tilt', '0', '--surface', 'throwawayDrum', '--json']);
    expect((JSON.parse(five.stdout) as { interval: number }).interval).toBe(own.intervalMm);
    expect((await run([...args.slice(0, -2), ...named])).stderr).toMatch(/takes --h <mm> or --interval <mm>/);
  });
});

describe('--machine as a process', () => {
  it('node bin.mjs --machine 3-axis answers as --slope alone; an unknown mode exits 2', async () => {
    const [plain, named, unknown] = await Promise.all([
      runProcess(THREE),
      runProcess([...THREE, '--machine', '3-axis']),
      runProcess([...THREE, '--machine', 'lathe']),
    ]);
    expect(plain.code).toBe(0);
    expect(named).toEqual(plain);
    expect(unknown.code).toBe(2);
    expect(unknown.stderr).toMatch(/^error: --machine must be one of 5-axis, 3-axis \(got "lathe"\)/);
  });
});

describe('--machine over a registered surface: refusals in the user unit', () => {
  it('inches: the limit in inches, the value quoted as typed', async () => {
    removers.push(registerSurfaceModel(drumModel), registerMode(fixedLeadMode));
    const args = ['--R', '0.2', '--Rcr', '0.06', '--rho', '12', '--machine', 'throwawayFixedLead'];
    const named = [...args, '--surface', 'throwawayDrum', '--unit', 'inch', '--interval', '0.7874'];
    const r = await run(named);
    expect(r.code).toBe(2);
    expect(r.stderr).toMatch(/^error: Step-over L must be below 0\.\d+ in here \(got 0\.7874\): passes this far apart/);
    expect(r.stderr).not.toMatch(/\bmm\b/);
  });
});
