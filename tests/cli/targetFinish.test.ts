/**
 * --target-sa and --target-rz on the command line (issue 29; src/cli/targetFinish.ts): the best
 * pair in the table and the JSON (its Sa checked with the full areal parameters of a fresh model),
 * the unit, and the one-line refusals (the options that do not go with a target, flutes missing,
 * runout with a target Sa, a target beyond the largest Ra). In process.
 */
import { describe, expect, it } from 'vitest';
import { PLANE } from '../../src/core/domain/surface';
import { arealParameters } from '../../src/core/finish/areal';
import { toothModel } from '../../src/core/finish/toothModel';
import { inverseInput } from '../../src/core/input/validate';
import { targetRzPair } from '../../src/core/roughness/targetSa';
import { planeInverse } from '../../src/core/surfaces/exact';
import { runMain } from './helpers';

const BASE = ['--R', '3', '--Rcr', '1', '--rho', '5'];
const PASS = {
  toolRadiusMm: 3,
  cornerRadiusMm: 1,
  leadAngleDeg: 5,
  tiltAngleDeg: 0,
  pattern: 'one-way' as const,
  surface: PLANE,
};
const TEETH = { flutes: 2, runoutMm: 0, runoutPhaseDeg: 0, passPhase: 0 };

describe('--target-sa', () => {
  it('answers the pair whose Sa is the target, with the curve of pairs, in the table and the JSON', async () => {
    const r = await runMain([...BASE, '--target-sa', '0.0008', '--flutes', '2', '--json']);
    expect(r.code, r.stderr).toBe(0);
    const t = (JSON.parse(r.stdout) as { targetSa: Record<string, unknown> }).targetSa;
    const best = t.best as {
      interval: number;
      feedPerTooth: number;
      Sa: number;
      feedLimited: boolean;
      scallopHeight: number;
    };
    expect(best.feedLimited).toBe(false);
    // The scallop across the feed at the best pair's step-over: the plane's exact inverse there.
    expect(best.scallopHeight).toBe(planeInverse(inverseInput(PASS, 'one-way', best.interval)).cuspHeightMm);
    const full = arealParameters(
      toothModel({
        tool: PASS,
        pattern: 'one-way',
        intervalMm: best.interval,
        finish: { ...TEETH, feedPerToothMm: best.feedPerTooth },
      }),
    );
    expect(Math.abs(full.saMm / 0.0008 - 1)).toBeLessThan(1e-6);
    expect(t.zeroFeedInterval as number).toBeGreaterThan(best.interval);
    const curve = t.curve as { interval: number; feedPerTooth: number }[];
    expect(curve.length).toBeGreaterThanOrEqual(10);
    for (const c of curve) expect(c.interval * c.feedPerTooth).toBeLessThan(best.interval * best.feedPerTooth * 1.005);
  }, 300_000);

  it.each([
    [['--target-sa', '0.0008'], '--target-sa needs --flutes <N>'],
    [['--target-sa', '0.0008', '--flutes', '2', '--fz', '0.1'], '--fz does not go with --target-sa'],
    [['--target-sa', '0.0008', '--flutes', '2', '--h', '0.01'], '--h does not go with --target-sa'],
    [
      ['--target-sa', '0.0008', '--flutes', '2', '--surface-radius', '50'],
      '--surface-radius does not go with --target-sa',
    ],
    [['--target-sa', '0.0008', '--target-rz', '0.003', '--flutes', '2'], 'do not go together'],
    [['--target-rz', '0.003', '--flutes', '2', '--slope', '30'], '--slope does not go with --target-rz'],
  ])('%j is a usage error in one line', async (args, words) => {
    const r = await runMain([...BASE, ...args]);
    expect(r.code).toBe(2);
    expect(r.stdout).toBe('');
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    expect(r.stderr).toContain(words);
  });

  it('refuses runout, a target beyond the largest Ra and a bad target in one line each, named by the option', async () => {
    const runout = await runMain([...BASE, '--target-sa', '0.0008', '--flutes', '2', '--runout', '0.01']);
    expect(runout.code).toBe(2);
    expect(runout.stderr).toMatch(/^error: --runout: Target Sa is computed without runout/);
    const big = await runMain([...BASE, '--target-sa', '1', '--flutes', '2', '--json']);
    expect(big.code).toBe(2);
    expect(big.stderr).toMatch(/^error: --target-sa: Target Sa must be below 0\.15\d+ mm \(got 1\)/);
    expect(JSON.parse(big.stdout).errors[0]).toMatchObject({
      field: 'targetSa',
      option: '--target-sa',
      code: 'beyond-max-ra',
    });
    const flutes = await runMain([...BASE, '--target-sa', '0.0008', '--flutes', '2.5']);
    expect(flutes.code).toBe(2);
    expect(flutes.stderr).toMatch(/^error: --flutes: Flutes z must be a whole number/);
  });
});

describe('--target-rz', () => {
  it("answers the core's pair to the last digit, in mm and in inches", async () => {
    const want = targetRzPair(PASS, TEETH, 0.003);
    const r = await runMain([...BASE, '--target-rz', '0.003', '--flutes', '2', '--json']);
    expect(r.code, r.stderr).toBe(0);
    const j = JSON.parse(r.stdout).targetRz;
    expect(j).toMatchObject({ interval: want.intervalMm, feedPerTooth: want.feedPerToothMm, feedLimited: false });
    expect(Math.abs(j.feedMarkHeight - 0.003)).toBeLessThan(1e-9);
    const table = await runMain([...BASE, '--target-rz', '0.003', '--flutes', '2']);
    expect(table.stdout).toMatch(/step-over L\s+0\.755\d+ mm/);
    expect(table.stdout).toMatch(/balanced feed: hf = h/);
    const inch = await runMain([
      '--R',
      '0.125',
      '--Rcr',
      '0.04',
      '--rho',
      '5',
      '--unit',
      'inch',
      '--target-rz',
      '0.0001',
      '--flutes',
      '2',
      '--json',
    ]);
    const ji = JSON.parse(inch.stdout).targetRz;
    const mm = targetRzPair({ ...PASS, toolRadiusMm: 3.175, cornerRadiusMm: 1.016 }, TEETH, 0.00254);
    expect(ji.interval).toBeCloseTo(mm.intervalMm / 25.4, 12);
    expect(ji.feedPerTooth).toBeCloseTo(mm.feedPerToothMm / 25.4, 12);
  });
});
