/**
 * The surface the teeth leave on the command line (issue 29): --flutes, --fz, --runout,
 * --runout-phase, --pass-phase add the feed marks and the areal parameters to a plane's answer
 * (five-axis and the three-axis sloped plane), the JSON's feedMarks and areal, the batch's finish
 * columns, --x3p with its grid options, and the one-line refusals (a bad value, the options
 * incomplete, a surface where feed marks are not computed yet). In process, but for one run as a
 * process that writes an x3p file which an outside reader (x3pio, surfalize) reads back.
 */
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, describe, expect, it } from 'vitest';
import { arealMap } from '../../src/core/finish/arealMap';
import { finishReport } from '../../src/core/finish/index';
import { toothModel } from '../../src/core/finish/toothModel';
import { arealSampled } from '../../src/core/output/arealSampled';
import { exactForward } from '../../src/core/surfaces/solve';
import { runMain, runProcess } from './helpers';

const TOOL = { toolRadiusMm: 5, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const BASE = ['--R', '5', '--Rcr', '1', '--rho', '5'];
const FINISH = { flutes: 2, feedPerToothMm: 0.1, runoutMm: 0, runoutPhaseDeg: 0, passPhase: 0 };
const dir = mkdtempSync(join(tmpdir(), 'cli-finish-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

function json(stdout: string): Record<string, unknown> {
  return JSON.parse(stdout) as Record<string, unknown>;
}

describe('--flutes and --fz on a plane', () => {
  it("adds the core's feed marks and areal parameters, to the last digit, in the table and the JSON", async () => {
    const interval = exactForward({
      ...TOOL,
      pattern: 'one-way',
      surface: { kind: 'plane' },
      scallopHeightMm: 0.01,
    } as Parameters<typeof exactForward>[0]).intervalMm;
    const want = finishReport(TOOL, 'one-way', interval, FINISH);
    const r = await runMain([...BASE, '--h', '0.01', '--flutes', '2', '--fz', '0.1', '--json']);
    expect(r.code, r.stderr).toBe(0);
    const j = json(r.stdout);
    expect(j.feedMarks).toEqual({
      height: want.feedMarks.height,
      period: 0.1,
      balancedFz: want.feedMarks.balancedFz,
    });
    expect(j.areal).toEqual(want.areal);
    // The corner's closed form (the lead keeps the contact on the corner arc): Rcr - sqrt(Rcr^2 - fz^2/4).
    expect(want.feedMarks.height).toBeCloseTo(1 - Math.sqrt(1 - 0.0025), 12);
    const table = await runMain([...BASE, '--h', '0.01', '--flutes', '2', '--fz', '0.1']);
    expect(table.stdout).toMatch(/Feed marks \(2 teeth, fz 0\.1 mm; straight teeth, M3\):/);
    expect(table.stdout).toMatch(/hf\s+0\.001250782\s+mm/);
    expect(table.stdout).toMatch(/Sa\s+0\.00256\d+\s+mm/);
    expect(table.stdout).toMatch(/Ssk\s+0\.63\d\d/);
    // Without the options, no finish at all.
    const plain = json((await runMain([...BASE, '--h', '0.01', '--json'])).stdout);
    expect(plain.feedMarks).toBeUndefined();
    expect(plain.areal).toBeUndefined();
  });

  it('reads the feed in the unit and writes every length in it (inch = mm / 25.4)', async () => {
    const mm = json((await runMain([...BASE, '--h', '0.01', '--flutes', '3', '--fz', '0.1', '--json'])).stdout);
    const inch = json(
      (
        await runMain([
          '--R',
          '5mm',
          '--Rcr',
          '1mm',
          '--rho',
          '5',
          '--h',
          '0.01mm',
          '--flutes',
          '3',
          '--fz',
          '0.1mm',
          '--unit',
          'inch',
          '--json',
        ])
      ).stdout,
    );
    const m = mm.areal as Record<string, number>;
    const i = inch.areal as Record<string, number>;
    expect(i.Sa).toBe((m.Sa as number) / 25.4);
    expect(i.Sz).toBe((m.Sz as number) / 25.4);
    expect(i.Ssk).toBe(m.Ssk);
    expect((inch.feedMarks as Record<string, number>).height).toBe(
      ((mm.feedMarks as Record<string, number>).height as number) / 25.4,
    );
  });

  it('the inverse (a given step-over) and the three-axis sloped plane answer it too', async () => {
    const inv = json((await runMain([...BASE, '--interval', '1.5', '--flutes', '2', '--fz', '0.1', '--json'])).stdout);
    expect(inv.areal).toEqual(finishReport(TOOL, 'one-way', 1.5, FINISH).areal);
    const slope = await runMain([
      '--R',
      '5',
      '--Rcr',
      '1',
      '--slope',
      '30',
      '--raster-angle',
      '30',
      '--h',
      '0.01',
      '--flutes',
      '3',
      '--fz',
      '0.05',
      '--json',
    ]);
    expect(slope.code, slope.stderr).toBe(0);
    const s = json(slope.stdout);
    const posture = s.posture as { lead: number; tilt: number };
    const interval = (s.exact as { interval: number }).interval;
    const want = finishReport(
      { toolRadiusMm: 5, cornerRadiusMm: 1, leadAngleDeg: posture.lead, tiltAngleDeg: posture.tilt },
      'one-way',
      interval,
      { ...FINISH, flutes: 3, feedPerToothMm: 0.05 },
    );
    expect(s.areal).toEqual(want.areal);
  });
});

describe('refusals, one line each', () => {
  const cases: ReadonlyArray<readonly [string[], RegExp, number]> = [
    [['--flutes', '2'], /--flutes needs --fz <mm>/, 2],
    [['--runout', '0.01'], /--runout needs --flutes <N> and --fz <mm>/, 2],
    [
      ['--flutes', '2.5', '--fz', '0.1'],
      /--flutes: Flutes z must be a whole number of teeth from 1 to 64 \(got 2\.5\)/,
      2,
    ],
    [['--flutes', '2', '--fz', '0'], /--fz: Feed per tooth fz must be greater than 0 mm \(got 0\)/, 2],
    [['--flutes', '2', '--fz', '0.1', '--runout', '-1'], /--runout: Runout e must be 0 mm or more \(got -1\)/, 2],
    [
      ['--flutes', '2', '--fz', '0.1', '--pass-phase', '1'],
      /--pass-phase: Pass phase q must be at least 0 and below 1/,
      2,
    ],
    [
      ['--flutes', '2', '--fz', '0.1', '--surface-radius', '50'],
      /--flutes: Feed marks are not computed on cylinders yet/,
      2,
    ],
    [
      ['--flutes', '2', '--fz', '0.1', '--feed-radius', '50', '--cross-radius', '40'],
      /--flutes: Feed marks are not computed on doubly curved points yet/,
      2,
    ],
    [['--x3p', 'a.x3p'], /--x3p needs --flutes <N> and --fz <mm>/, 2],
    [['--flutes', '2', '--fz', '0.1', '--x3p-size', '64,64'], /--x3p-size needs --x3p <file>/, 2],
    [
      ['--flutes', '2', '--fz', '0.1', '--x3p', 'a.x3p', '--x3p-size', '0,64'],
      /--x3p-size must be two whole numbers from 1 to 8192, as 512,256 \(got "0,64"\)/,
      2,
    ],
    [
      ['--flutes', '2', '--fz', '0.1', '--x3p', 'a.x3p', '--x3p-cells', 'two'],
      /--x3p-cells must be two whole numbers from 1 to 1000, as 2,2 \(got "two"\)/,
      2,
    ],
    [
      ['--flutes', '2', '--fz', '0.1', '--x3p', join(dir, 'no', 'such', 'dir.x3p'), '--x3p-size', '4,4'],
      /cannot write the x3p file .*ENOENT/,
      1,
    ],
  ];
  for (const [extra, message, code] of cases) {
    it(`${extra.join(' ')}: ${message.source.slice(0, 40)}`, async () => {
      const r = await runMain([...BASE, '--h', '0.01', ...extra]);
      expect(r.code).toBe(code);
      expect(r.stderr).toMatch(message);
      expect(r.stderr.trim().split('\n')).toHaveLength(1);
      expect(r.stdout).toBe('');
    });
  }

  it('a flat end upright at L = 2R: the step-over and hf answer, the areal parameters alone refused in one line (slivers no tooth cuts)', async () => {
    const flat = ['--R', '3', '--Rcr', '0', '--rho', '0', '--h', '0.05', '--flutes', '4', '--fz', '0.1'];
    const SLIVERS =
      'The areal parameters are not defined here: thin slivers between the passes are cut by no tooth (the bottom edges miss them); try a smaller step-over.';
    const table = await runMain(flat);
    expect([table.code, table.stderr]).toEqual([0, '']);
    expect(table.stdout).toMatch(/^ {2}L +6\.000000 +mm/m);
    expect(table.stdout).toMatch(/^ {2}hf +0\.000000 +mm/m);
    expect(table.stdout).toContain(`Areal parameters: ${SLIVERS}`);
    const json = JSON.parse((await runMain([...flat, '--json'])).stdout);
    expect([json.exact.interval, json.feedMarks.height, json.areal, json.arealRefusal]).toEqual([
      6,
      0,
      undefined,
      SLIVERS,
    ]);
    // No file of a surface that is not defined.
    const file = await runMain([...flat, '--x3p', join(dir, 'flat.x3p')]);
    expect([file.code, file.stdout, file.stderr.trim()]).toEqual([2, '', `error: --x3p: no file: ${SLIVERS}`]);
  });

  it('in inches, a limit is in inches', async () => {
    const r = await runMain([
      '--R',
      '0.25',
      '--Rcr',
      '0.03',
      '--rho',
      '5',
      '--h',
      '0.0004',
      '--unit',
      'inch',
      '--flutes',
      '2',
      '--fz',
      '0.5',
    ]);
    expect(r.code).toBe(2);
    expect(r.stderr).toMatch(/--fz: Feed per tooth fz must be at most the tool radius R = 0\.25 in \(got 0\.5\)/);
  });
});

describe('--batch with the finish columns', () => {
  it('writes the ten finish columns before error, empty without teeth, the error of a bad value', async () => {
    const csv = [
      'R,Rcr,rho,h,flutes,fz,runout',
      '5,1,5,0.01,2,0.1,',
      '5,1,5,0.01,,,',
      '5,1,5,0.01,2,,',
      '5,1,5,0.01,0,0.1,',
      '5,1,5,0.01,2,-1,',
      '5,0,0,0.01,2,0.1,',
    ].join('\n');
    const r = await runMain(['--batch'], csv);
    expect(r.code).toBe(0);
    const [header, ...rows] = r.stdout
      .trim()
      .split('\n')
      .map((l) => l.split(','));
    expect(header?.slice(-11)).toEqual([
      'feedMarkHeight',
      'feedPeriod',
      'balancedFz',
      'Sa',
      'Sq',
      'Sz',
      'Sp',
      'Sv',
      'Ssk',
      'Sku',
      'error',
    ]);
    const cell = (row: string[] | undefined, name: string) => row?.[header?.indexOf(name) ?? -1];
    const cli = json((await runMain([...BASE, '--h', '0.01', '--flutes', '2', '--fz', '0.1', '--json'])).stdout);
    expect(Number(cell(rows[0], 'Sa'))).toBe((cli.areal as Record<string, number>).Sa);
    expect(Number(cell(rows[0], 'feedMarkHeight'))).toBe((cli.feedMarks as Record<string, number>).height);
    expect(cell(rows[0], 'error')).toBe('');
    expect(cell(rows[1], 'Sa')).toBe('');
    expect(cell(rows[1], 'exact')).not.toBe('');
    expect(cell(rows[2], 'error')).toBe('Feed per tooth fz is missing: enter a number.');
    expect(cell(rows[3], 'error')).toMatch(/^Flutes z must be a whole number/);
    expect(cell(rows[4], 'error')).toMatch(/^Feed per tooth fz must be greater than 0/);
    // A flat end lying flat: L and hf answered, the areal cells empty and the error column says why
    // (the row's quoted notes hold commas: read from the line's end).
    const flat = r.stdout.trim().split('\n')[6] ?? '';
    expect(flat).toMatch(
      /^5,0,0,0\.01,2,0\.1,,5,.*,0,0\.1,,,,,,,,,The areal parameters are not defined here: thin slivers/,
    );
    // Its own output reads back (the finish results are ignored as input).
    const back = await runMain(['--batch'], r.stdout);
    expect(back.stdout).toBe(r.stdout);
  });

  it('a cylinder row is refused, not answered as if the tool swept continuously', async () => {
    const r = await runMain(['--batch'], 'R,Rcr,rho,h,surfaceRadius,flutes,fz\n5,1,5,0.01,50,2,0.1\n');
    expect(r.stdout.trim().split('\n')[1]).toMatch(/Feed marks are not computed on cylinders yet/);
  });
});

describe('--x3p as a process, read back by outside software', () => {
  it('writes the notes grid over whole cells; x3pio and surfalize read it; their Sa, Sq, Sz are ours to 1e-9 mm', async () => {
    const file = join(dir, 'surface.x3p');
    const args = [...BASE, '--h', '0.01', '--flutes', '2', '--fz', '0.1', '--json'];
    const r = await runProcess([...args, '--x3p', file, '--x3p-size', '96,64', '--x3p-cells', '2,1']);
    expect(r.code, r.stderr).toBe(0);
    const j = json(r.stdout);
    const interval = (j.exact as { interval: number }).interval;
    expect(j.x3p).toEqual({
      file,
      nx: 96,
      ny: 64,
      cellsX: 2,
      cellsY: 1,
      dx: (2 * 0.1) / 96,
      dy: interval / 64,
    });
    const map = arealMap(
      toothModel({ tool: TOOL, pattern: 'one-way', intervalMm: interval, finish: FINISH }),
      96,
      64,
      2,
      1,
    );
    const sampled = arealSampled(map.heightsMm);
    const ensure = fileURLToPath(new URL('../support/ensure-python-x3p.mjs', import.meta.url));
    const lines = execFileSync(process.execPath, [ensure, '--json'], { encoding: 'utf8' }).trim().split('\n');
    const python = JSON.parse(lines.at(-1) as string) as { python: string; env: Record<string, string> };
    const read = fileURLToPath(new URL('../support/x3p_read.py', import.meta.url));
    const report = JSON.parse(
      execFileSync(python.python, [read, file], { encoding: 'utf8', env: { ...process.env, ...python.env } }),
    ) as {
      files: {
        x3pio: { shape: [number, number]; xIncrement: number; yIncrement: number; offset: number[] };
        surfalize: { sa: number; sq: number; sz: number };
      }[];
    };
    const f = report.files[0];
    expect(f?.x3pio.xIncrement).toBe(map.dxMm / 1000);
    expect(f?.x3pio.yIncrement).toBe(map.dyMm / 1000);
    expect(f?.x3pio.offset[0]).toBe(map.dxMm / 2000);
    // surfalize's parameters are in micrometres; ours in mm.
    expect(Math.abs((f?.surfalize.sa ?? 0) / 1000 - sampled.saMm)).toBeLessThan(1e-9);
    expect(Math.abs((f?.surfalize.sq ?? 0) / 1000 - sampled.sqMm)).toBeLessThan(1e-9);
    expect(Math.abs((f?.surfalize.sz ?? 0) / 1000 - sampled.szMm)).toBeLessThan(1e-9);
    // The file's heights are the map's (the x3p holds float64 metres).
    const bin = readFileSync(`${file}.x3pio.bin`);
    expect(bin.length).toBe(96 * 64 * 8);
    // The sampled Sa approaches the exact one (a 96 x 64 grid: within a few percent).
    expect(Math.abs(sampled.saMm / (j.areal as { Sa: number }).Sa - 1)).toBeLessThan(0.05);
  });
});
