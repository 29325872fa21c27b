/**
 * One wording and one number style on the command line and in the batch (issue 26 point 10), and an
 * empty radius as straight (point 12). In-process (runMain), but the directory on stdin.
 */
import { closeSync, openSync } from 'node:fs';
import { PassThrough, Readable } from 'node:stream';
import { describe, expect, it } from 'vitest';
import { ECHO_MAX_CHARS } from '../../src/cli/args';
import { parseCsv } from '../../src/cli/csv';
import { main } from '../../src/cli/main';
import { CSV_FINISH_COLUMNS, CSV_OPTIONAL_COLUMNS, CSV_THREE_AXIS_COLUMNS } from '../../src/core/input/fields';
import { APPROXIMATION_KEYS, PROCEDURES } from '../../src/core/procedures/procedures';
import { runMain } from './helpers';

/** The batch's output rows by column name. */
async function batchRows(csv: string): Promise<Record<string, string>[]> {
  const r = await runMain(['--batch'], csv);
  expect(r.code, r.stderr).toBe(0);
  const [head, ...rows] = parseCsv(r.stdout).map((x) => x.fields);
  return rows.map((f) => Object.fromEntries((head ?? []).map((n, i) => [n, f[i] ?? ''])));
}

describe('one message per kind of fault (issue 26 point 10)', () => {
  it('text that is no number reads the same for a five-axis, a three-axis field and a batch cell', async () => {
    const five = await runMain(['--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.25in x']);
    const three = await runMain(['--R', '3', '--Rcr', '1', '--slope', '30', '--h', '0.25in x']);
    const slope = await runMain(['--R', '3', '--Rcr', '1', '--slope', '5um', '--h', '0.01']);
    const wanted = 'Scallop height h must be a number (got "0.25in x").';
    expect(five.stderr).toBe(`error: --h: ${wanted}\n`);
    expect(three.stderr).toBe(`error: --h: ${wanted}\n`);
    expect(slope.stderr).toBe('error: --slope: Slope alpha must be a number (got "5um").\n');
    const [row] = await batchRows('R,Rcr,h,slope\n3,1,0.25in x,30\n');
    expect(row?.error).toBe(wanted);
  });

  it("a waterline row's error speaks of the slope, not of a raster angle it does not have", async () => {
    const rows = await batchRows(
      'R,Rcr,h,slope,passes,rho\n3,1,5,30,waterline,\n3,1,5,30,raster,\n3,1,0.01,30,waterline,5\n',
    );
    expect(rows[0]?.error).toMatch(/at this slope \(got 5\)/);
    expect(rows[0]?.error).not.toMatch(/raster/);
    expect(rows[1]?.error).toMatch(/at this slope and raster angle/);
    expect(rows[2]?.error).toMatch(/the slope sets the lead and tilt/);
    expect(rows[2]?.error).not.toMatch(/raster/);
    const single = await runMain(['--R', '3', '--Rcr', '1', '--slope', '30', '--passes', 'waterline', '--h', '5']);
    expect(single.stderr).toMatch(/at this slope \(got 5\)/);
    expect(single.stderr).not.toMatch(/raster/);
  });

  it("at rho 0 the approximations' empty cells carry a note saying why (batch, plane and doubly curved)", async () => {
    const rows = await batchRows('R,Rcr,rho,h,feedRadius,crossRadius\n3,1,0,0.01,,\n3,1,0,0.01,50,60\n');
    for (const row of rows) {
      for (const key of APPROXIMATION_KEYS) {
        if (row[key] === '') expect(row.note, key).toContain(`${PROCEDURES[key].shortLabel}`);
      }
      expect(row.sekine).toBe('');
      expect(row.note).toMatch(/Sekine et al\.: at rho = 0/);
    }
  });

  it('"no CSV on stdin" and --help\'s --batch name every optional column the registry has (doubly curved, three-axis and the teeth too)', async () => {
    const r = await runMain(['--batch'], '');
    expect(r.code).toBe(2);
    const help = (await runMain(['--help'])).stdout;
    const batch = help.slice(help.indexOf('\n  --batch'), help.indexOf('-h, --help'));
    for (const column of [...CSV_OPTIONAL_COLUMNS, ...CSV_THREE_AXIS_COLUMNS, ...CSV_FINISH_COLUMNS]) {
      expect(r.stderr, column).toContain(column);
      expect(batch, column).toMatch(new RegExp(`\\b${column}\\b`));
    }
  });

  it('--batch < a directory is a read error (exit 1), not "no CSV"', async () => {
    const fd = openSync('/tmp', 'r');
    try {
      const stdin = Object.assign(Readable.from([]), { fd });
      const stderr = new PassThrough();
      let err = '';
      stderr.setEncoding('utf8').on('data', (d: string) => {
        err += d;
      });
      const code = await main(['--batch'], { stdin, stdout: new PassThrough(), stderr });
      expect(code).toBe(1);
      expect(err).toBe('error: cannot read standard input: EISDIR: standard input is a directory\n');
    } finally {
      closeSync(fd);
    }
  });

  it(`echoed values in an error are cut to ${ECHO_MAX_CHARS} characters with an ellipsis`, async () => {
    const long = 'x'.repeat(300);
    const option = await runMain([`--${long}`, '1']);
    expect(option.stderr).toBe(`error: unknown option --${'x'.repeat(ECHO_MAX_CHARS)}... (see path-interval --help)\n`);
    const argument = await runMain([long]);
    expect(argument.stderr).toBe(
      `error: unexpected argument "${'x'.repeat(ECHO_MAX_CHARS)}..." (see path-interval --help)\n`,
    );
    const header = await runMain(['--batch'], `R,Rcr,rho,h,${long}\n`);
    expect(header.stderr).toContain(`unknown column "${'x'.repeat(ECHO_MAX_CHARS)}..."`);
    const json = await runMain(['--R', '3', '--Rcr', '1', '--slope', '30', '--h', `1${long}`, '--json']);
    const [e] = (JSON.parse(json.stdout) as { errors: { got: string }[] }).errors;
    expect(e?.got).toBe(`1${'x'.repeat(ECHO_MAX_CHARS - 1)}...`);
  });

  it('batch echo columns escape control characters as the error column does', async () => {
    const [row] = await batchRows('R,Rcr,rho,h\n3\u001b[31m,1,5,\u202e0.01\n');
    expect(row?.R).toBe('3\\x1b[31m');
    expect(row?.h).toBe('\\u202e0.01');
    expect(row?.error).toMatch(/\(got "3\\x1b\[31m"\)/);
  });
});

describe('an empty radius is straight, echoed as absent (issue 26 point 12)', () => {
  const base = ['--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.01'];
  it("--feed-radius '' answers as no radius: the same JSON, no Infinity, no null", async () => {
    const plain = await runMain([...base, '--json']);
    for (const empty of [
      ['--feed-radius', ''],
      ['--cross-radius', ' '],
      ['--feed-radius=', '--cross-radius='],
    ]) {
      const r = await runMain([...base, ...empty, '--json']);
      expect(r.code, empty.join(' ')).toBe(0);
      expect(r.stdout).toBe(plain.stdout);
      const table = await runMain([...base, ...empty]);
      expect(table.stdout).not.toMatch(/Infinity|null|Rf =|Rc =/);
    }
  });

  it('one radius given and the other empty is the cylinder of the one; beside --surface-radius, nothing', async () => {
    const cylinder = await runMain([...base, '--feed-radius', '40', '--json']);
    const r = await runMain([...base, '--feed-radius', '40', '--cross-radius', '', '--json']);
    expect(r.stdout).toBe(cylinder.stdout);
    const rs = await runMain([...base, '--surface-radius', '40', '--json']);
    const both = await runMain([...base, '--surface-radius', '40', '--feed-radius', '', '--json']);
    expect(both.stderr).toBe('');
    expect(both.stdout).toBe(rs.stdout);
  });
});
