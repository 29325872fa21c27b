import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { exactHalfIntervalMm } from '../../src/core/exact';
import { compareForward, forwardInput } from '../../src/core/index';
import { PAPER_CONDITIONS } from '../../src/core/paper';

const BIN = fileURLToPath(new URL('../../src/cli/bin.mjs', import.meta.url));

/** Runs the command line as a separate process, as a user would. */
function run(args: string[], stdin = ''): Promise<{ code: number | null; stdout: string; stderr: string }> {
  return new Promise((resolve, reject) => {
    const child = spawn(process.execPath, [BIN, ...args], { stdio: ['pipe', 'pipe', 'pipe'] });
    let stdout = '';
    let stderr = '';
    child.stdout.setEncoding('utf8').on('data', (d: string) => {
      stdout += d;
    });
    child.stderr.setEncoding('utf8').on('data', (d: string) => {
      stderr += d;
    });
    child.on('error', reject);
    child.on('close', (code) => resolve({ code, stdout, stderr }));
    child.stdin.end(stdin);
  });
}

describe('command line (as a process)', () => {
  it('prints a readable table of the four procedures with deviations', async () => {
    const r = await run(['--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.05']);
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/exact \(3D geometry\)\s+1\.443592\s+2\.887185/);
    expect(r.stdout).toMatch(/Sekine et al\. \(Eqs\. 4-8\)\s+1\.085737\s+2\.171474\s+-0\.357855\s+-24\.79/);
    expect(r.stdout).toMatch(/Redonnet et al\.[^\n]+1\.546688/);
    expect(r.stdout).toMatch(/Bedi et al\.[^\n]+1\.437229/);
  });

  it('--json prints one object with exact, sekine, redonnet and bedi; values match the solver core', async () => {
    const c = PAPER_CONDITIONS[5];
    if (!c) throw new Error('missing condition');
    const r = await run(['--R', `${c.R}`, '--Rcr', `${c.Rcr}`, '--rho', `${c.rho}`, '--h', `${c.h}`, '--json']);
    expect(r.code).toBe(0);
    const out = JSON.parse(r.stdout);
    const exact = exactHalfIntervalMm(
      forwardInput({ toolRadiusMm: c.R, cornerRadiusMm: c.Rcr, leadAngleDeg: c.rho, tiltAngleDeg: 0 }, 'one-way', c.h),
    );
    expect(out.exact.halfInterval).toBe(exact);
    expect(out.exact.interval).toBe(2 * exact);
    for (const name of ['sekine', 'redonnet', 'bedi'] as const) {
      expect(Math.abs(out[name].halfInterval - c.printedHalf[name])).toBeLessThanOrEqual(0.0005);
      expect(out[name].interval).toBeCloseTo(2 * out[name].halfInterval, 14);
    }
  });

  it('--json reports "not applicable" with a reason at rho = 0', async () => {
    const r = await run(['--R=3', '--Rcr=1', '--rho=0', '--h=0.05', '--json']);
    const out = JSON.parse(r.stdout);
    expect(out.exact.halfInterval).toBeCloseTo(2 + Math.sqrt(0.1 - 0.0025), 12);
    for (const name of ['sekine', 'redonnet', 'bedi']) expect(out[name].notApplicable).toMatch(/rho = 0/);
    expect(r.stdout).not.toMatch(/NaN|null/);
  });

  it('--inverse --half-interval prints the scallop height of each procedure', async () => {
    const r = await run([
      '--inverse',
      '--R',
      '3',
      '--Rcr',
      '1',
      '--rho',
      '5',
      '--half-interval',
      '1.443592412967',
      '--json',
    ]);
    expect(r.code).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(Math.abs(out.exact.scallopHeight - 0.05)).toBeLessThan(1e-9);
    expect(out.sekine.scallopHeight).toBeGreaterThan(0.05);
    const table = await run(['--inverse', '--R', '3', '--Rcr', '1', '--rho', '5', '--half-interval', '1.5']);
    expect(table.stdout).toMatch(/Bedi et al\. \(Eq\. 13\)\s+0\.0554/);
  });

  it.each([
    [['--R', '3', '--Rcr', '4', '--rho', '5', '--h', '0.05'], /Corner radius Rcr must not exceed the tool radius R/],
    [['--R', '3', '--Rcr', '1', '--rho', '5', '--h', '2'], /full height .*wall, not a scallop/],
    [['--R', '3', '--Rcr', '1', '--rho', '-5', '--h', '0.05'], /rho must be at least 0/],
    [['--R', 'abc', '--Rcr', '1', '--rho', '5', '--h', '0.05'], /Tool radius R must be a number \(got "abc"\)/],
    [['--R', '3', '--Rcr', '1', '--rho', '5'], /Scallop height h is missing/],
    [['--R', '3', '--bogus', '1'], /unknown option --bogus/],
  ])('invalid case %j prints the constraint and exits with code 2', async (args, message) => {
    const r = await run(args);
    expect(r.code).toBe(2);
    expect(r.stderr).toMatch(message);
    expect(r.stdout).toBe('');
  });

  it('--batch streams CSV: good rows get L/2 values, a bad row gets its message and the run goes on', async () => {
    const input = ['R,Rcr,rho,h', '3,1,5,0.05', '3,4,5,0.05', '3,1,0,0.05', 'x,y', '6,2,10,0.1', ''].join('\n');
    const r = await run(['--batch'], input);
    expect(r.code).toBe(0);
    const lines = r.stdout.trim().split('\n');
    expect(lines[0]).toBe('R,Rcr,rho,h,exact,sekine,redonnet,bedi,error');
    const c = compareForward(
      forwardInput({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way', 0.05),
    );
    const a = c.approximations;
    const nine = (r: { ok: true; halfIntervalMm: number } | { ok: false }) =>
      (r.ok ? r.halfIntervalMm : Number.NaN).toFixed(9);
    expect(lines[1]).toBe(
      `3,1,5,0.05,${c.exact.halfIntervalMm.toFixed(9)},${nine(a.sekine)},${nine(a.redonnet)},${nine(a.bedi)},`,
    );
    expect(lines[2]).toMatch(/^3,4,5,0\.05,,,,,"?Corner radius Rcr must not exceed/);
    expect(lines[3]).toBe(`3,1,0,0.05,${(2 + Math.sqrt(0.1 - 0.0025)).toFixed(9)},,,,`);
    expect(lines[4]).toMatch(/expected 4 values/);
    expect(lines[5]).toMatch(/^6,2,10,0\.1,2\.168976694,/);
    expect(lines).toHaveLength(6);
  });

  it('--batch handles 100k rows (streaming) and a header in another column order', async () => {
    const rows = ['h,rho,Rcr,R'];
    for (let i = 0; i < 100_000; i++) rows.push(`${(0.01 + (i % 50) * 0.001).toFixed(3)},${i % 60},1,3`);
    const r = await run(['--batch'], rows.join('\n'));
    expect(r.code).toBe(0);
    const lines = r.stdout.trim().split('\n');
    expect(lines).toHaveLength(100_001);
    // rho = 0 closed form: Rb + sqrt(2 Rcr h - h^2).
    expect(lines[1]).toBe(`3,1,0,0.010,${(2 + Math.sqrt(0.02 - 0.0001)).toFixed(9)},,,,`);
  });

  it('--batch with a wrong header is a usage error (exit 2)', async () => {
    const r = await run(['--batch'], 'a,b,c\n1,2,3\n');
    expect(r.code).toBe(2);
    expect(r.stderr).toMatch(/header must be R,Rcr,rho,h/);
  });
});
