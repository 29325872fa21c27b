/**
 * What the command line echoes of its input (issue 17): an error is one line whatever
 * the value holds (a line break, a terminal escape sequence: shown escaped, on stderr, in the JSON
 * message and in a batch row's `error`), and a JSON error leaves out what does not exist, as the
 * results do, never `null`.
 */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { escapeControls } from '../../src/cli/output';
import { run } from './helpers';

const ESC = '\u001b';
/** Any control character but the line break that ends each line. */
// biome-ignore lint/suspicious/noControlCharactersInRegex: looking for control characters is the point
const CONTROL = /[\u0000-\u0009\u000b-\u001f\u007f-\u009f\u2028\u2029\u202a-\u202e\u2066-\u2069]/;
const TOOL = ['--R', '3', '--Rcr', '1', '--rho', '5'];

/** The lines of stderr: each `error: ` and one line, no control character in any. */
function errorLines(stderr: string): string[] {
  expect(stderr.endsWith('\n')).toBe(true);
  const lines = stderr.slice(0, -1).split('\n');
  for (const line of lines) {
    expect(line).toMatch(/^error: /);
    expect(CONTROL.test(line), JSON.stringify(line)).toBe(false);
  }
  return lines;
}

describe('errors are one line; what the user typed is shown with its control characters escaped', () => {
  it('escapeControls: C0, DEL, C1, line separators and bidirectional controls; other text as it is', () => {
    expect(escapeControls(`zig\nzag\r\t${ESC}[31m\u0000\u007f\u009b\u2028\u202e`)).toBe(
      'zig\\nzag\\r\\t\\x1b[31m\\x00\\x7f\\x9b\\u2028\\u202e',
    );
    expect(escapeControls('a\\n "b" é 3,5 ±')).toBe('a\\n "b" é 3,5 ±');
  });

  it('an option value holding a line break or an escape sequence: one line each, escaped, also in --json', async () => {
    const [pattern, red, json] = await Promise.all([
      run([...TOOL, '--h', '0.05', '--pattern', 'zig\nzag']),
      run([...TOOL, '--h', `${ESC}[31m0.05`]),
      run([...TOOL, '--h', '0.05', '--pattern', `a\r\nb${ESC}[2J`, '--json']),
    ]);
    expect(pattern).toEqual({
      code: 2,
      stdout: '',
      stderr: 'error: --pattern: Pass pattern must be one-way or zigzag (got "zig\\nzag").\n',
    });
    expect(red.code).toBe(2);
    expect(errorLines(red.stderr)).toEqual(['error: --h: Scallop height h must be a number (got "\\x1b[31m0.05").']);
    expect(json.code).toBe(2);
    const [line] = errorLines(json.stderr);
    expect(line).toBe('error: --pattern: Pass pattern must be one-way or zigzag (got "a\\r\\nb\\x1b[2J").');
    expect(json.stdout.split('\n')).toHaveLength(2); // one line and its break
    const [e] = JSON.parse(json.stdout).errors;
    expect(`error: ${e.option}: ${e.message}`).toBe(line);
    expect(e.got).toBe(`a\r\nb${ESC}[2J`); // the value itself, which JSON escapes
  });

  it('usage errors echo an argument or an option name escaped', async () => {
    const [argument, option, flag] = await Promise.all([
      run([...TOOL, '--h', '0.05', `oops${ESC}[2J\nmore`]),
      run([...TOOL, '--h', '0.05', `--ti\nlt`, '5']),
      run(['--batch', `--json=${ESC}]0;title\u0007`]),
    ]);
    expect(errorLines(argument.stderr)).toEqual([
      'error: unexpected argument "oops\\x1b[2J\\nmore" (see path-interval --help)',
    ]);
    expect(errorLines(option.stderr)).toEqual(['error: unknown option --ti\\nlt (see path-interval --help)']);
    expect(errorLines(flag.stderr)).toEqual(['error: --json takes no value (see path-interval --help)']);
    for (const r of [argument, option, flag]) expect(r.code).toBe(2);
  });

  it('--batch: a row error and a header error hold no control character either', async () => {
    const [rows, header] = await Promise.all([
      run(['--batch'], `R,Rcr,rho,h,pattern\n3,1,5,${ESC}[31m0.05,one-way\n3,1,5,0.05,"zig\u2028zag${ESC}[0m"\n`),
      run(['--batch'], `R,Rcr,rho,h,"col\r\n${ESC}[31m"\n3,1,5,0.05,x\n`),
    ]);
    expect(rows.code).toBe(0);
    const [, first, second] = parseCsv(rows.stdout).filter((r) => !r.blank);
    expect(first?.fields.at(-1)).toBe('Scallop height h must be a number (got "\\x1b[31m0.05").');
    expect(second?.fields.at(-1)).toBe('Pass pattern must be one-way or zigzag (got "zig\\u2028zag\\x1b[0m").');
    expect(header.code).toBe(2);
    expect(errorLines(header.stderr)).toEqual([expect.stringMatching(/\(unknown column "col\\r\\n\\x1b\[31m"\)$/)]);
  });
});

describe('JSON errors leave out what does not exist', () => {
  it('no null member: no limit for "at any radius", no side on a plane without tilt; present where they exist', async () => {
    const [anyRadius, flank, shank, corner] = await Promise.all([
      run([
        '--R',
        '3',
        '--Rcr',
        '1',
        '--rho',
        '0',
        '--h',
        '0.05',
        '--surface-radius',
        '-30',
        '--surface-axis',
        'cross',
        '--json',
      ]),
      run([...TOOL, '--h', '5', '--json']),
      run([...TOOL, '--tilt', '30', '--h', '2', '--json']),
      run(['--R', '3', '--Rcr', '4', '--rho', 'x', '--json']),
    ]);
    const errors = (r: { stdout: string }) => JSON.parse(r.stdout).errors as Array<Record<string, unknown>>;
    expect(errors(anyRadius)).toEqual([
      {
        field: 'surfaceRadius',
        option: '--surface-radius',
        code: 'gouging',
        got: '-30',
        message: expect.stringMatching(/^This tool gouges a concave cylinder of any radius/),
      },
    ]);
    const [f] = errors(flank);
    expect(Object.keys(f ?? {})).toEqual(['field', 'option', 'code', 'got', 'limit', 'message']);
    expect(f?.limit).toBeCloseTo(1.17431, 5);
    expect(errors(shank)).toEqual([expect.objectContaining({ code: 'shank-cuts', side: 'right' })]);
    expect(errors(corner).map((e) => [e.field, Object.keys(e)])).toEqual([
      ['rho', ['field', 'option', 'code', 'got', 'message']],
      ['h', ['field', 'option', 'code', 'got', 'message']],
      ['Rcr', ['field', 'option', 'code', 'got', 'limit', 'message']],
    ]);
    for (const r of [anyRadius, flank, shank, corner]) {
      expect(r.code).toBe(2);
      expect(r.stdout).not.toMatch(/null/);
    }
  });

  it("a trough whose wall the shank crosses: no limit, the shank's lean seen along the axis (closed form)", async () => {
    const r = await run([
      ...TOOL,
      '--tilt',
      '50',
      '--h',
      '0.01',
      '--surface-radius',
      '-3.7',
      '--surface-axis',
      'feed',
      '--json',
    ]);
    expect(r.code).toBe(2);
    const [e] = JSON.parse(r.stdout).errors as Array<Record<string, unknown>>;
    expect(Object.keys(e ?? {})).toEqual(['field', 'option', 'code', 'got', 'shankLean', 'message']);
    expect(e?.code).toBe('shank-gouging');
    // Seen along the cylinder's axis (X), the tool axis (cos b sin r, sin b, cos b cos r) leans
    // atan2(|sin b|, cos b cos r) from the normal: 50.1075 degrees for b = 50, r = 5.
    const rad = Math.PI / 180;
    const lean = Math.atan2(Math.sin(50 * rad), Math.cos(50 * rad) * Math.cos(5 * rad)) / rad;
    const shankLean = e?.shankLean as { axis: string; leanDeg: number };
    expect(shankLean.axis).toBe('feed');
    expect(shankLean.leanDeg).toBeCloseTo(lean, 9);
  });
});
