import { spawn } from 'node:child_process';
import { closeSync, openSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import {
  compareForward,
  compareInverse,
  exactForward,
  forwardInput,
  inverseInput,
  scallopHeightLimits,
  validateForward,
} from '../../src/core/index';
import { PAPER_CONDITIONS } from '../../src/core/procedures/paper';
import { exactHalfIntervalMm } from '../../src/core/surfaces/solve';
import { BIN, checkResultFields, logUniform, pick, random, randomHeight, randomTool, run, runProcess } from './helpers';

const STACK = /\n\s+at |node:internal|Error:/;
const tool = (R: number, Rcr: number, rho: number, tilt = 0) => ({
  toolRadiusMm: R,
  cornerRadiusMm: Rcr,
  leadAngleDeg: rho,
  tiltAngleDeg: tilt,
});

describe('command line', () => {
  it('prints a readable table of every procedure with deviations', async () => {
    const r = await runProcess(['--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.05']);
    expect(r.code).toBe(0);
    // Format changed by issues 7 and 9: L first, 7 significant digits, the deviation is L's.
    expect(r.stdout).toMatch(/Exact \(3D geometry\)\s+2\.887185\s+1\.443592/);
    expect(r.stdout).toMatch(/Sekine et al\. \(Eqs\. 4-8\)\s+2\.171474\s+1\.085737\s+-0\.7157108\s+-24\.79/);
    expect(r.stdout).toMatch(/Redonnet et al\.[^\n]+1\.546688/);
    expect(r.stdout).toMatch(/Bedi et al\.[^\n]+1\.437229/);
    expect(r.stdout).toMatch(/Osculating circle at the contact\s+3\.093375/);
    expect(r.stdout).toMatch(/Ball of the corner radius\s+0\.6244998/);
    expect(r.stdout).toMatch(/^ {2}y0 +0\.000000 +mm/m);
    expect(r.stderr).toBe('');
  });

  it('--json prints one object with exact, sekine, redonnet and bedi; values match the solver core', async () => {
    const c = PAPER_CONDITIONS[5];
    if (!c) throw new Error('missing condition');
    const r = await run(['--R', `${c.R}`, '--Rcr', `${c.Rcr}`, '--rho', `${c.rho}`, '--h', `${c.h}`, '--json']);
    expect(r.code).toBe(0);
    const out = JSON.parse(r.stdout);
    const exact = exactHalfIntervalMm(forwardInput(tool(c.R, c.Rcr, c.rho), 'one-way', c.h));
    expect(out.exact.halfInterval).toBe(exact);
    expect(out.exact.interval).toBe(2 * exact);
    for (const name of ['sekine', 'redonnet', 'bedi'] as const) {
      expect(Math.abs(out[name].halfInterval - c.printedHalf[name])).toBeLessThanOrEqual(0.0005);
      expect(out[name].interval).toBeCloseTo(2 * out[name].halfInterval, 14);
      // `deviation` keeps its meaning: the deviation of L/2.
      expect(out[name].deviation).toBe(out[name].halfInterval - exact);
      expect(out[name].intervalDeviation).toBeCloseTo(2 * out[name].deviation, 14);
    }
  });

  it('--json reports "not applicable" with a reason at rho = 0', async () => {
    const r = await run(['--R=3', '--Rcr=1', '--rho=0', '--h=0.05', '--json']);
    const out = JSON.parse(r.stdout);
    expect(out.exact.halfInterval).toBeCloseTo(2 + Math.sqrt(0.1 - 0.0025), 12);
    for (const name of ['sekine', 'redonnet', 'bedi', 'osculating']) expect(out[name].notApplicable).toMatch(/rho = 0/);
    expect(r.stdout).not.toMatch(/NaN|null/);
  });

  it('--inverse --half-interval prints the scallop height of each procedure', async () => {
    const [r, table] = await Promise.all([
      run(['--inverse', '--R', '3', '--Rcr', '1', '--rho', '5', '--half-interval', '1.443592412967', '--json']),
      run(['--inverse', '--R', '3', '--Rcr', '1', '--rho', '5', '--half-interval', '1.5']),
    ]);
    expect(r.code).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(Math.abs(out.exact.scallopHeight - 0.05)).toBeLessThan(1e-9);
    expect(out.sekine.scallopHeight).toBeGreaterThan(0.05);
    expect(out.input).toEqual({
      R: 3,
      Rcr: 1,
      rho: 5,
      tilt: 0,
      pattern: 'one-way',
      interval: 2 * 1.443592412967,
      halfInterval: 1.443592412967,
    });
    expect(table.stdout).toMatch(/Bedi et al\. \(Eq\. 13\)\s+0\.0554/);
  });

  it('--json with tilt 5 (one-way) and zigzag: the exact fields are the core values', async () => {
    const args = ['--R', '3', '--Rcr', '1', '--rho', '5', '--tilt', '5', '--json'];
    const [oneWay, zigzag, inverse] = await Promise.all([
      run([...args, '--h', '0.05']),
      run([...args, '--pattern', 'zigzag', '--h', '0.05']),
      run([...args, '--pattern', 'zigzag', '--interval', '1.8']),
    ]);
    for (const [r, pattern] of [
      [oneWay, 'one-way'],
      [zigzag, 'zigzag'],
    ] as const) {
      expect(r.code).toBe(0);
      const out = JSON.parse(r.stdout);
      const c = compareForward(forwardInput(tool(3, 1, 5, 5), pattern, 0.05));
      expect(out.input).toEqual({ R: 3, Rcr: 1, rho: 5, tilt: 5, pattern, h: 0.05 });
      expect(out.exact).toEqual({
        halfInterval: c.exact.halfIntervalMm,
        interval: c.exact.intervalMm,
        halfWidthRight: c.exact.halfWidthRightMm,
        halfWidthLeft: c.exact.halfWidthLeftMm,
        contactOffset: c.exact.contactOffsetMm,
        scallopHeight: 0.05,
        ...(pattern === 'zigzag' ? { otherCuspHeight: c.exact.otherCuspHeightMm } : {}),
        noScallop: false,
      });
      for (const key of ['sekine', 'redonnet', 'bedi', 'osculating', 'cornerBall'] as const) {
        const a = c.approximations[key];
        if (!a.ok) throw new Error(`${key} not applicable`);
        expect(out[key]).toMatchObject({
          halfInterval: a.halfIntervalMm,
          interval: a.intervalMm,
          intervalDeviation: a.deviationMm,
          deviationPercent: a.deviationPercent,
        });
        expect(out[key].realScallopHeight).toBe(a.realScallopMm);
      }
    }
    // Issue 9's figure: lead 5, tilt 5, h 0.05, one-way L = 1.8789 mm.
    expect(JSON.parse(oneWay.stdout).exact.interval).toBeCloseTo(1.8789, 4);
    const out = JSON.parse(inverse.stdout);
    const c = compareInverse(inverseInput(tool(3, 1, 5, 5), 'zigzag', 1.8));
    expect(out.exact).toEqual({
      scallopHeight: c.exact.cuspHeightMm,
      rightCuspHeight: c.exact.rightCuspHeightMm,
      leftCuspHeight: c.exact.leftCuspHeightMm,
      otherCuspHeight: c.exact.otherCuspHeightMm,
      interval: 1.8,
      halfInterval: 0.9,
      halfWidthRight: c.exact.halfWidthRightMm,
      halfWidthLeft: c.exact.halfWidthLeftMm,
      contactOffset: c.exact.contactOffsetMm,
    });
    expect(out.exact.otherCuspHeight).toBeLessThan(out.exact.scallopHeight);
  });

  it('issue examples: a subnormal lead, an L/2 beyond R, a micro tool; every output finite and flagged', async () => {
    const [subnormal, beyond, beyondTable, micro] = await Promise.all([
      run(['--R', '3', '--Rcr', '1', '--rho', '1e-320', '--h', '0.05', '--json']),
      run(['--R', '3', '--Rcr', '1', '--rho', '0.01', '--h', '0.05', '--json']),
      run(['--R', '3', '--Rcr', '1', '--rho', '0.01', '--h', '0.05']),
      run(['--R', '0.001', '--Rcr', '0.0002', '--rho', '3', '--tilt', '2', '--pattern', 'zigzag', '--h', '1e-9']),
    ]);
    const s = JSON.parse(subnormal.stdout);
    expect(s.input.rho).toBe(1e-320);
    expect(s.sekine.notApplicable).toMatch(/overflows/);
    expect(s.redonnet.notApplicable).toMatch(/overflows/);
    expect(subnormal.stdout).not.toMatch(/null|NaN|Infinity/);
    const b = JSON.parse(beyond.stdout);
    expect(b.redonnet.halfInterval).toBeCloseTo(33.85, 2);
    expect(b.redonnet.warning).toMatch(/leave a wall/);
    expect(b.redonnet.realScallopHeight).toBeUndefined();
    expect(b.cornerBall.warning).toBeUndefined();
    expect(beyondTable.stdout).toMatch(/^Redonnet et al\. \(Eqs\. 9, 8\) .* wall +\[\d\]$/m);
    expect(micro.code).toBe(0);
    // Tables never in exponent notation (issue 26 point 10).
    expect(micro.stdout).toMatch(/^ {2}L +0\.000008469680 +mm/m);
    expect(micro.stdout).toMatch(/^ {2}h2 +0\.0000000009919293 +mm/m);
    expect(micro.stdout).not.toMatch(/\de-\d/);
    for (const r of [subnormal, beyond, beyondTable, micro]) expect(r.stdout).not.toMatch(/NaN|Infinity|undefined/);
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

  it('invalid input: each error on its own line naming the option, the text as typed; --json also on stdout', async () => {
    const [overflow, json, half, tilt] = await Promise.all([
      runProcess(['--R', '1e-400', '--Rcr', '1', '--rho', '5', '--h', '0.05']),
      runProcess(['--R', '3', '--Rcr', '4', '--rho', '95', '--h', '0.05', '--json']),
      runProcess(['--R', '3', '--Rcr', '1', '--rho', '5', '--half-interval', '1e308']),
      runProcess(['--R', '3', '--Rcr', '1', '--rho', '5', '--tilt', '90', '--pattern', 'spiral', '--h', '0.05']),
    ]);
    expect(overflow.stderr).toBe('error: --R: Tool radius R must be greater than 0 mm (got 1e-400).\n');
    expect(json.code).toBe(2);
    const lines = json.stderr.trimEnd().split('\n');
    expect(lines).toEqual([expect.stringMatching(/^error: --Rcr: /), expect.stringMatching(/^error: --rho: /)]);
    const out = JSON.parse(json.stdout);
    expect(out.errors.map((e: { field: string }) => e.field)).toEqual(['Rcr', 'rho']);
    expect(out.errors.map((e: { field: string; message: string }) => `error: --${e.field}: ${e.message}`)).toEqual(
      lines,
    );
    expect(half.stderr).toBe(
      'error: --half-interval: Half path interval L/2 must be below the tool radius R = 3 mm (got 1e308); at or beyond it adjacent passes leave a wall.\n',
    );
    expect(tilt.stderr).toMatch(
      /^error: --tilt: Tilt angle beta must be above -90 and below 90 degrees \(got 90\)\.\n/,
    );
    expect(tilt.stderr).toMatch(/\nerror: --pattern: Pass pattern must be one-way or zigzag \(got "spiral"\)\.\n$/);
    for (const r of [overflow, json, half, tilt]) expect(r.code).toBe(2);
  });

  it('usage errors (repeated option, --json with --batch) are one line and exit 2; -h is --help', async () => {
    const [repeated, jsonBatch, help, helpLong] = await Promise.all([
      runProcess(['--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.05', '--h', '0.1']),
      runProcess(['--batch', '--json'], 'R,Rcr,rho,h\n3,1,5,0.05\n'),
      runProcess(['-h']),
      runProcess(['--help']),
    ]);
    expect(repeated).toEqual({
      code: 2,
      stdout: '',
      stderr: 'error: --h is given more than once (see path-interval --help)\n',
    });
    expect(jsonBatch.code).toBe(2);
    expect(jsonBatch.stdout).toBe('');
    expect(jsonBatch.stderr).toMatch(/^error: --json does not go with --batch[^\n]*\n$/);
    expect(help.code).toBe(0);
    expect(help.stdout).toMatch(/^Usage: path-interval /);
    expect(help.stdout).toMatch(/--tilt <deg>/);
    expect(help.stdout).toMatch(/--pattern <p>/);
    expect(help.stdout).toMatch(/--interval <mm>/);
    expect(help).toEqual(helpLong);
  });

  it('--batch streams CSV: good rows get full-precision values, a bad row gets its message and the run goes on', async () => {
    const input = ['R,Rcr,rho,h', '3,1,5,0.05', '3,4,5,0.05', '3,1,0,0.05', 'x,y', '6,2,10,0.1', ''].join('\n');
    const r = await run(['--batch'], input);
    expect(r.code).toBe(0);
    const lines = r.stdout.trim().split('\n');
    // Columns added by issue 9; numbers in full precision (issue 7) instead of 9 decimals.
    expect(lines[0]).toBe(
      'R,Rcr,rho,h,exact,sekine,redonnet,bedi,interval,halfWidthRight,halfWidthLeft,contactOffset,otherCuspHeight,osculating,cornerBall,note,error',
    );
    const c = compareForward(forwardInput(tool(3, 1, 5), 'one-way', 0.05));
    const a = c.approximations;
    const full = (r: { ok: true; halfIntervalMm: number } | { ok: false }) => (r.ok ? String(r.halfIntervalMm) : '');
    const e = c.exact;
    expect(lines[1]).toBe(
      `3,1,5,0.05,${e.halfIntervalMm},${full(a.sekine)},${full(a.redonnet)},${full(a.bedi)},${e.intervalMm},${e.halfWidthRightMm},${e.halfWidthLeftMm},0,,${full(a.osculating)},${full(a.cornerBall)},,`,
    );
    expect(lines[2]).toMatch(/^3,4,5,0\.05,{13}"?Corner radius Rcr must not exceed/);
    expect(lines[3]).toMatch(
      new RegExp(`^3,1,0,0\\.05,${String(2 + Math.sqrt(0.1 - 0.0025)).replace('.', '\\.')},,,,`),
    );
    expect(lines[4]).toMatch(/^x,y,{15}"line 5: expected 4 values \(R,Rcr,rho,h\), got 2"$/);
    expect(lines[5]).toMatch(/^6,2,10,0\.1,2\.16897669433985/);
    expect(lines).toHaveLength(6);
  });

  it('--batch streams a batch of many stdin chunks, with a header in another column order: every row answered in order', async () => {
    // 20 000 rows (about 290 kB of CSV, several 64 kB pipe chunks, so records straddle chunk
    // boundaries): the point is correctness. Throughput is a benchmark figure (npm run bench: batch rows/s).
    const count = 20_000;
    const rows = ['h,rho,Rcr,R'];
    const h = (i: number) => (0.01 + (i % 50) * 0.001).toFixed(3);
    for (let i = 0; i < count; i++) rows.push(`${h(i)},${i % 60},1,3`);
    const r = await runProcess(['--batch'], rows.join('\n'));
    expect(r.code).toBe(0);
    expect(r.stderr).toBe('');
    const lines = r.stdout.trim().split('\n');
    expect(lines).toHaveLength(count + 1);
    // rho = 0 closed form: Rb + sqrt(2 Rcr h - h^2).
    expect(lines[1]).toMatch(
      new RegExp(`^3,1,0,0\\.010,${String(2 + Math.sqrt(0.02 - 0.0001)).replace('.', '\\.')},,,,`),
    );
    // Each row echoes its own inputs in the canonical order (none lost, merged or split), and the
    // 300 distinct cases (h repeats every 50 rows, rho every 60) give the core's exact L/2 each time.
    const expected = new Map<string, string>();
    for (let i = 0; i < count; i++) {
      const key = `3,1,${i % 60},${h(i)}`;
      const line = lines[i + 1] as string;
      expect(line.startsWith(`${key},`), `row ${i + 1}: ${line.slice(0, 40)}`).toBe(true);
      let want = expected.get(key);
      if (want === undefined) {
        const v = validateForward({ R: 3, Rcr: 1, rho: i % 60, h: Number(h(i)) });
        if (!v.ok) throw new Error(`row ${i + 1} is valid: ${key}`);
        want = String(exactHalfIntervalMm(v.value));
        expected.set(key, want);
      }
      if (line.split(',')[4] !== want) expect(line.split(',')[4], `row ${i + 1}`).toBe(want);
    }
    expect(expected.size).toBe(300);
  });

  it('--batch with a wrong header is a usage error (exit 2)', async () => {
    const [r, unknown, empty] = await Promise.all([
      run(['--batch'], 'a,b,c\n1,2,3\n'),
      run(['--batch'], 'R,Rcr,rho,h,tlit\n3,1,5,0.05,5\n'),
      run(['--batch'], '\n\n'),
    ]);
    expect(r.code).toBe(2);
    expect(r.stderr).toMatch(/header must be R,Rcr,rho,h/);
    expect(unknown.code).toBe(2);
    expect(unknown.stderr).toMatch(/unknown column "tlit"/);
    expect(unknown.stdout).toBe('');
    expect(empty.code).toBe(2);
    expect(empty.stderr).toMatch(/no CSV on stdin/);
  });

  it('--batch reads tilt and pattern columns in any order; an empty field takes the default', async () => {
    const r = await run(
      ['--batch'],
      'pattern,h,tilt,rho,Rcr,R\nzigzag,0.05,5,5,1,3\n,0.05,,5,1,3\none-way,0.05,-5,5,1,3\n',
    );
    expect(r.code).toBe(0);
    const [header, zig, plain, left] = parseCsv(r.stdout).map((x) => x.fields);
    expect(header?.slice(0, 6)).toEqual(['R', 'Rcr', 'rho', 'h', 'tilt', 'pattern']);
    const z = compareForward(forwardInput(tool(3, 1, 5, 5), 'zigzag', 0.05)).exact;
    expect(zig?.slice(0, 6)).toEqual(['3', '1', '5', '0.05', '5', 'zigzag']);
    expect(zig?.[6]).toBe(String(z.halfIntervalMm));
    expect(zig?.[14]).toBe(String(z.otherCuspHeightMm));
    expect(plain?.[6]).toBe(String(exactHalfIntervalMm(forwardInput(tool(3, 1, 5), 'one-way', 0.05))));
    expect(plain?.[14]).toBe('');
    expect(Number(left?.[13])).toBe(-z.contactOffsetMm);
  });

  it('--batch per RFC 4180: quoted fields, line breaks in quotes, unterminated quotes, 1 MB lines, formulas', async () => {
    const long = '9'.repeat(2_000_000);
    const input = [
      '\uFEFFR,"Rcr",rho,h\r',
      '"3","1","5","0.05"\r', // 2: quoted numbers
      '', // 3: blank lines are skipped
      '   ',
      '"3,5",1,5,0.05', // 5: a comma inside quotes is one field
      '"=HYPERLINK(""x"")",1,5,0.05', // 6: doubled quotes; a formula is echoed as text
      '3,"1', // 7: a line break inside quotes: one record
      '",5,0.05',
      `${long},1,5,0.05`, // 9: longer than 1 MiB
      '3,1,5,0.05', // 10: read as usual after it
      '-3,@1,+5,0.05', // 11
      '3,1,5,"0.05', // 12: never closed
      '3,1,5,0.05',
    ].join('\n');
    const r = await run(['--batch'], input);
    expect(r.code).toBe(0);
    expect(r.stderr).toBe('');
    const out = parseCsv(r.stdout);
    expect(out.every((x) => x.error === null && x.fields.length === 17)).toBe(true);
    const rows = out.map((x) => x.fields);
    const good = String(exactHalfIntervalMm(forwardInput(tool(3, 1, 5), 'one-way', 0.05)));
    expect(rows.map((f) => f[4])).toEqual(['exact', good, '', '', '', '', good, '', '']);
    expect(rows[2]?.[0]).toBe('3,5');
    expect(rows[2]?.[16]).toMatch(/Tool radius R must be a number \(got "3,5"\)/);
    expect(rows[3]?.[0]).toBe(`'=HYPERLINK("x")`);
    expect(r.stdout).toContain(`"'=HYPERLINK(""x"")"`);
    // The echo escapes control characters as the error column does (issue 26 point 10).
    expect(rows[4]?.[1]).toBe('1\\n');
    expect(rows[4]?.[16]).toBe('line 7: the Rcr field holds a line break');
    expect(rows[5]?.slice(0, 4)).toEqual(['', '', '', '']);
    expect(rows[5]?.[16]).toBe('line 9: the record is longer than 1048576 characters: not read');
    expect(rows[7]?.slice(0, 4)).toEqual(['-3', "'@1", '+5', '0.05']);
    expect(rows[8]?.[16]).toBe('line 12: a quoted field opened on line 12 is never closed');
    expect(rows[8]?.[3]).toBe('0.05\\n3,1,5,0.05');
  });

  it('--batch: the 1 MiB limit counts the record, not the line break after it (issue 17)', async () => {
    // Records of exactly 1,048,576 characters (spaces before h are trimmed) and one more.
    const record = (chars: number) => `3,1,5,${' '.repeat(chars - '3,1,5,0.05'.length)}0.05`;
    const quoted = (chars: number) => `3,1,5,"${' '.repeat(chars - '3,1,5,"0.05"'.length)}0.05"`;
    const limit = 1 << 20;
    expect(record(limit)).toHaveLength(1_048_576);
    const [mixed, lastAtLimit, lastOver] = await Promise.all([
      run(
        ['--batch'],
        `R,Rcr,rho,h\n${record(limit)}\n${record(limit)}\r\n${quoted(limit)}\r${record(limit + 1)}\n${quoted(limit + 1)}\n`,
      ),
      run(['--batch'], `R,Rcr,rho,h\n${record(limit)}`),
      run(['--batch'], `R,Rcr,rho,h\n${record(limit + 1)}`),
    ]);
    const good = String(exactHalfIntervalMm(forwardInput(tool(3, 1, 5), 'one-way', 0.05)));
    const rows = (r: { stdout: string }) => parseCsv(r.stdout).map((x) => x.fields);
    const tooLong = (line: number) => `line ${line}: the record is longer than 1048576 characters: not read`;
    expect(rows(mixed).map((f) => [f[3], f[4], f[16]])).toEqual([
      ['h', 'exact', 'error'],
      ['0.05', good, ''],
      ['0.05', good, ''],
      ['0.05', good, ''],
      ['', '', tooLong(5)],
      ['', '', tooLong(6)],
    ]);
    expect(rows(lastAtLimit)[1]?.[4]).toBe(good);
    expect(rows(lastOver)[1]?.[16]).toBe(tooLong(2));
    for (const r of [mixed, lastAtLimit, lastOver]) expect(r.code).toBe(0);
  });

  it('--batch | head -1 ends quietly (exit 0); a closed pipe on a table too', async () => {
    const rows = ['R,Rcr,rho,h'];
    for (let i = 0; i < 100_000; i++) rows.push(`3,1,${i % 60},0.05`);
    const closeEarly = (args: string[], stdin: string) =>
      new Promise<{ code: number | null; stderr: string; got: number }>((resolve, reject) => {
        const child = spawn(process.execPath, [BIN, ...args], { stdio: ['pipe', 'pipe', 'pipe'] });
        let stderr = '';
        let got = 0;
        child.stderr.setEncoding('utf8').on('data', (d: string) => {
          stderr += d;
        });
        child.stdout.once('data', (d: Buffer) => {
          got = d.length;
          child.stdout.destroy(); // as head -1 does once it has its line
        });
        child.on('error', reject);
        child.on('close', (code) => resolve({ code, stderr, got }));
        child.stdin.on('error', () => {});
        child.stdin.end(stdin);
      });
    const closedBeforeTable = new Promise<{ code: number | null; stderr: string }>((resolve, reject) => {
      const child = spawn(process.execPath, [BIN, '--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.05'], {
        stdio: ['pipe', 'pipe', 'pipe'],
      });
      child.stdout.destroy();
      let stderr = '';
      child.stderr.setEncoding('utf8').on('data', (d: string) => {
        stderr += d;
      });
      child.on('error', reject);
      child.on('close', (code) => resolve({ code, stderr }));
      child.stdin.end();
    });
    const [batch, table] = await Promise.all([closeEarly(['--batch'], rows.join('\n')), closedBeforeTable]);
    expect(batch.got).toBeGreaterThan(0);
    expect(batch).toMatchObject({ code: 0, stderr: '' });
    expect(table).toEqual({ code: 0, stderr: '' });
  });

  it('a write error (a full disk, /dev/full) is one line naming it, exit 1, no stack trace', async () => {
    const toFull = (args: string[], stdin: string) =>
      new Promise<{ code: number | null; stderr: string }>((resolve, reject) => {
        const full = openSync('/dev/full', 'w');
        const child = spawn(process.execPath, [BIN, ...args], { stdio: ['pipe', full, 'pipe'] });
        closeSync(full);
        const { stdin: input, stderr: errors } = child;
        if (input === null || errors === null) throw new Error('no pipes');
        let stderr = '';
        errors.setEncoding('utf8').on('data', (d: string) => {
          stderr += d;
        });
        child.on('error', reject);
        child.on('close', (code) => resolve({ code, stderr }));
        input.on('error', () => {});
        input.end(stdin);
      });
    const rows = ['R,Rcr,rho,h'];
    for (let i = 0; i < 20_000; i++) rows.push(`3,1,${i % 60},0.05`);
    const results = await Promise.all([
      toFull(['--batch'], rows.join('\n')),
      toFull(['--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.05'], ''),
      toFull(['--help'], ''),
    ]);
    for (const r of results) {
      expect(r.code).toBe(1);
      expect(r.stderr).toMatch(/^error: cannot write to standard output: ENOSPC: no space left on device[^\n]*\n$/);
    }
  });

  const seed = 9001;
  const ROWS = 20_000;
  it(`fuzz: ${ROWS} random valid and invalid CSV rows give finite numbers and whole rows (seed ${seed})`, async () => {
    const rand = random(seed);
    const garbage = [
      '',
      ' ',
      'abc',
      '-1',
      '0',
      '1e400',
      '-1e400',
      '1e-400',
      '1e-320',
      '5e-324',
      '1e308',
      'NaN',
      'Infinity',
      '-Infinity',
      '0x10',
      '1,5',
      '=1+2',
      '@SUM(1)',
      '+-1',
      '"q"',
      'zig zag',
      '90',
      '-90',
      '89.9999999',
      '1000.0001',
      '0.0009',
      'one-way',
      'zigzag',
      'ONE-WAY',
      'line\nbreak',
    ];
    const quote = (s: string) => (/[",\r\n]/.test(s) ? `"${s.replaceAll('"', '""')}"` : s);
    const columns = ['pattern', 'h', 'R', 'tilt', 'Rcr', 'rho'] as const;
    const lines = [columns.join(',')];
    const records: Record<(typeof columns)[number], string>[] = [];
    let valid = 0;
    for (let i = 0; i < ROWS; i++) {
      const t = randomTool(rand);
      const limit = scallopHeightLimits(tool(t.R, t.Rcr, t.rho, t.tilt)).limitMm;
      const h = randomHeight(rand, limit);
      // As typed: shortest, 17 digits (both exact) or, now and then, rounded to 4 digits (may cross a limit).
      const num = (x: number) => (rand() < 0.05 ? x.toExponential(3) : rand() < 0.5 ? String(x) : x.toPrecision(17));
      const rec = {
        pattern: pick(rand, ['one-way', 'zigzag', '']),
        h: num(h),
        R: num(t.R),
        tilt: t.tilt === 0 && rand() < 0.3 ? '' : num(t.tilt),
        Rcr: num(t.Rcr),
        rho: num(t.rho),
      };
      const kind = rand();
      if (kind < 0.3) rec[pick(rand, columns)] = pick(rand, garbage);
      else if (kind < 0.33) rec.h = num(logUniform(rand, 1e-12, 2000));
      else if (kind < 0.35) {
        // a row with a missing or an extra field
        const fields = columns.map((c) => quote(rec[c]));
        if (rand() < 0.5) fields.pop();
        else fields.push('7');
        lines.push(fields.join(','));
        records.push(rec);
        continue;
      } else valid++;
      if (rand() < 0.01) lines.push(''); // blank lines: skipped
      lines.push(columns.map((c) => quote(rec[c])).join(','));
      records.push(rec);
    }
    const r = await run(['--batch'], `${lines.join('\r\n')}\r\n`);
    expect(r.code).toBe(0);
    expect(r.stderr).toBe('');
    const out = parseCsv(r.stdout);
    expect(out).toHaveLength(ROWS + 1);
    const header = out[0]?.fields ?? [];
    expect(header).toHaveLength(6 + 13);
    let ok = 0;
    let numbers = 0;
    for (let i = 1; i <= ROWS; i++) {
      const rec = out[i];
      const f = rec?.fields ?? [];
      expect(rec?.error).toBeNull();
      expect(f, `row ${i}`).toHaveLength(19);
      const values = f.slice(6, 17);
      const note = f[17] as string;
      const error = f[18] as string;
      expect(`${values.join(',')},${note}`, `row ${i}`).not.toMatch(/NaN|Infinity|undefined|null/);
      numbers += checkResultFields(values, error, `row ${i}`);
      if (error !== '') continue;
      ok++;
      // A valid row: the exact fields are there, and are the core's.
      const raw = records[i - 1] as Record<(typeof columns)[number], string>;
      const v = validateForward({
        R: raw.R,
        Rcr: raw.Rcr,
        rho: raw.rho,
        tilt: raw.tilt.trim() === '' ? undefined : raw.tilt,
        pattern: raw.pattern.trim() === '' ? undefined : raw.pattern,
        h: raw.h,
      });
      if (!v.ok) throw new Error(`row ${i} is valid in the CLI but not here: ${JSON.stringify(raw)}`);
      const e = exactForward(v.value);
      expect(values.slice(0, 1).concat(values.slice(4, 9)), `row ${i}`).toEqual([
        String(e.halfIntervalMm),
        String(e.intervalMm),
        String(e.halfWidthRightMm),
        String(e.halfWidthLeftMm),
        e.contactOffsetMm === 0 ? '0' : String(e.contactOffsetMm),
        e.otherCuspHeightMm === null ? '' : String(e.otherCuspHeightMm),
      ]);
      expect(v.value.pattern === 'zigzag').toBe(values[8] !== '');
    }
    expect(ok).toBeGreaterThan(0.6 * valid);
    expect(ok).toBeLessThan(ROWS);
    expect(numbers).toBeGreaterThan(5 * ok);
    expect(r.stdout).not.toMatch(STACK);
  }, 120_000);
});
