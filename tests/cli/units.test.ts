/**
 * The shop's units and sizes on the command line (issue 26 point 9 and the closing note): --D, the
 * page's one parser for fractions and unit suffixes, --unit mm|inch for every length in and out
 * (table, JSON, batch; the unit echoed), batch columns named `_mm` / `_in`; and inch answers that
 * are the mm answers / 25.4 to the last digit (computed in mm, converted once). In-process.
 */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { LENGTH_MEMBERS, OTHER_NUMBER_MEMBERS } from '../../src/cli/unitJson';
import { runMain } from './helpers';

type Json = { [key: string]: unknown };

/** Every number of a JSON value with its member's name and its path. */
function numbers(value: unknown, path = ''): { key: string; path: string; value: number }[] {
  if (Array.isArray(value)) return value.flatMap((v, i) => numbers(v, `${path}[${i}]`));
  if (value === null || typeof value !== 'object') return [];
  return Object.entries(value as Json).flatMap(([key, v]) =>
    typeof v === 'number' ? [{ key, path: `${path}.${key}`, value: v }] : numbers(v, `${path}.${key}`),
  );
}

async function json(args: readonly string[]): Promise<Json> {
  const r = await runMain([...args, '--json']);
  expect(r.stderr, args.join(' ')).toBe('');
  expect(r.code, args.join(' ')).toBe(0);
  return JSON.parse(r.stdout) as Json;
}

/** Questions of every kind, each as its length options in inches and the rest. */
const QUESTIONS: ReadonlyArray<{ lengths: Record<string, number>; rest: string[] }> = [
  { lengths: { '--R': 0.25, '--Rcr': 0.03, '--h': 0.0004 }, rest: ['--rho', '5'] },
  {
    lengths: { '--R': 0.25, '--Rcr': 0.03, '--h': 0.0004 },
    rest: ['--rho', '5', '--tilt', '3', '--pattern', 'zigzag'],
  },
  { lengths: { '--R': 0.25, '--Rcr': 0.03, '--h': 0.0004, '--surface-radius': 2 }, rest: ['--rho', '5'] },
  { lengths: { '--R': 0.25, '--Rcr': 0.03, '--interval': 0.05 }, rest: ['--rho', '5', '--simulate'] },
  { lengths: { '--R': 0.25, '--Rcr': 0.03, '--ra': 0.0001, '--cross-radius': 3 }, rest: ['--rho', '5'] },
  {
    lengths: { '--R': 0.125, '--Rcr': 0.04, '--h': 0.0003, '--feed-radius': 1.5, '--cross-radius': -3 },
    rest: ['--rho', '10'],
  },
  {
    lengths: { '--R': 0.125, '--Rcr': 0.04, '--ra': 0.0001, '--feed-radius': 1.5, '--cross-radius': -3 },
    rest: ['--rho', '10', '--pattern', 'zigzag'],
  },
  {
    lengths: { '--R': 0.125, '--Rcr': 0.04, '--interval': 0.03, '--feed-radius': 1.5, '--cross-radius': -3 },
    rest: ['--rho', '10'],
  },
  { lengths: { '--R': 0.25, '--Rcr': 0.03, '--h': 0.0004 }, rest: ['--slope', '30', '--raster-angle', '20'] },
  {
    lengths: { '--R': 0.25, '--Rcr': 0.03, '--h': 0.0004, '--feed-radius': 4 },
    rest: ['--slope', '30', '--passes', 'waterline'],
  },
  { lengths: { '--R': 0.25, '--Rcr': 0.03, '--h': 0.0004 }, rest: ['--slope-sweep', '--passes', 'waterline'] },
];

/** The arguments of a question in inches (--unit inch) and in mm (each length times 25.4, as the command line converts it). */
function argsOf(q: (typeof QUESTIONS)[number], unit: 'inch' | 'mm'): string[] {
  const lengths = Object.entries(q.lengths).flatMap(([option, inches]) => [
    option,
    String(unit === 'inch' ? inches : inches * 25.4),
  ]);
  return [...lengths, ...q.rest, ...(unit === 'inch' ? ['--unit', 'inch'] : [])];
}

describe('--unit inch: every length in and out in inches (issue 26 point 9)', () => {
  it('JSON: each answer is the mm answer / 25.4 to the last digit; the input reads back as typed; "unit": "inch"', async () => {
    for (const q of QUESTIONS) {
      const inch = await json(argsOf(q, 'inch'));
      const mm = await json(argsOf(q, 'mm'));
      const label = argsOf(q, 'inch').join(' ');
      expect(inch.unit, label).toBe('inch');
      expect(mm.unit, label).toBe('mm');
      const a = numbers(inch);
      const b = numbers(mm);
      expect(a.map((n) => n.path)).toEqual(b.map((n) => n.path));
      for (const [i, n] of a.entries()) {
        const m = b[i] as { value: number };
        const length = LENGTH_MEMBERS.has(n.key);
        if (n.key === 'ms') continue; // the simulation's wall-clock time
        if (!length) expect(n.value, `${n.path}: ${label}`).toBe(m.value);
        else if (n.path.startsWith('.input.')) {
          // The input as typed in inches (12 significant digits, as the page's inch table writes it).
          expect(n.value, `${n.path}: ${label}`).toBe(Number((m.value / 25.4).toPrecision(12)));
        } else expect(n.value, `${n.path}: ${label}`).toBe(m.value / 25.4);
      }
      const input = inch.input as Json;
      for (const [option, inches] of Object.entries(q.lengths)) {
        const member = { '--R': 'R', '--Rcr': 'Rcr', '--h': 'h', '--ra': 'Ra', '--interval': 'interval' }[option];
        if (member !== undefined) expect(input[member], `${member}: ${label}`).toBe(inches);
      }
    }
  });

  it('every number the JSON holds is named a length or not (the unit converts exactly the lengths)', async () => {
    const seen = new Set<string>();
    for (const q of QUESTIONS) for (const n of numbers(await json(argsOf(q, 'mm')))) seen.add(n.key);
    const errors = await runMain(['--R', '3', '--Rcr', '4', '--rho', '95', '--h', '0.01', '--json']);
    for (const n of numbers(JSON.parse(errors.stdout))) seen.add(n.key);
    const unnamed = [...seen].filter((k) => !LENGTH_MEMBERS.has(k) && !OTHER_NUMBER_MEMBERS.has(k) && k !== 'limit');
    expect(unnamed).toEqual([]);
    expect([...LENGTH_MEMBERS].filter((k) => OTHER_NUMBER_MEMBERS.has(k))).toEqual([]);
  });

  it('the table speaks inches: the case, the facts, the columns; the numbers the mm ones / 25.4', async () => {
    const r = await runMain(['--R', '0.25', '--Rcr', '0.03', '--rho', '5', '--h', '0.0004', '--unit', 'inch']);
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/^Filleted end mill R = 0\.25 in, Rcr = 0\.03 in; lead rho = 5 deg/);
    expect(r.stdout).toMatch(/^Scallop height h = 0\.0004 in$/m);
    expect(r.stdout).toMatch(/^procedure +L \[in\] +L\/2 \[in\] +dev L \[in\]/m);
    expect(r.stdout).toMatch(/^ {2}Rz +0\.0004000000 +in/m);
    expect(r.stdout).not.toMatch(/\bmm\b/);
    const mm = JSON.parse(
      (await runMain(['--R', '6.35', '--Rcr', '0.762', '--rho', '5', '--h', '0.01016', '--json'])).stdout,
    );
    const L = (mm.exact.interval as number) / 25.4;
    expect(r.stdout).toMatch(new RegExp(`^ {2}L +${L.toPrecision(7).replace('.', '\\.')} +in `, 'm'));
  });

  it('an error speaks inches too: the limit converted, the value as typed', async () => {
    const r = await runMain(['--R', '50', '--Rcr', '1', '--rho', '5', '--h', '0.001', '--unit', 'inch', '--json']);
    expect(r.code).toBe(2);
    expect(r.stderr).toBe('error: --R: Tool radius R must be at most 39.3701 in (got 50).\n');
    const out = JSON.parse(r.stdout) as { unit: string; errors: Json[] };
    const e = out.errors[0] as Json;
    expect(out.unit).toBe('inch');
    expect(e.limit).toBe(1000 / 25.4);
    expect(e.got).toBe('50');
    const three = await runMain([
      '--unit',
      'inch',
      '--slope',
      '30',
      '--R',
      '50',
      '--Rcr',
      '1',
      '--h',
      '0.001',
      '--json',
    ]);
    expect((JSON.parse(three.stdout) as { errors: Json[] }).errors[0]?.got).toBe('50');
    const half = await runMain(['--R', '3', '--Rcr', '1', '--rho', '5', '--half-interval', '4', '--json']);
    expect((JSON.parse(half.stdout) as { errors: Json[] }).errors[0]?.got).toBe('4');
  });

  it('three-axis errors too (their messages in mm written in inches), in the batch alike', async () => {
    const r = await runMain(['--unit', 'inch', '--slope', '30', '--R', '50', '--Rcr', '1', '--h', '0.001']);
    expect(r.stderr).toBe('error: --R: Tool radius R must be from 0.0000393701 in to 39.3701 in (got 50).\n');
    const h = await runMain(['--unit', 'inch', '--slope', '30', '--R', '0.25', '--Rcr', '0.03', '--h', '0.2']);
    expect(h.stderr).toMatch(
      /^error: --h: Scallop height h must be below 0\.14 in at this slope and raster angle \(got 0\.2\)/,
    );
    const b = await runMain(['--batch', '--unit', 'inch'], 'R,Rcr,h,slope\n0.25,0.03,0.2,30\n');
    expect(b.stdout).toContain('must be below 0.14 in at this slope and raster angle (got 0.2)');
    expect(b.stdout.split('\n')[0]).toBe(
      'R_in,Rcr_in,h_in,slope,interval_in,horizontalStep_in,stepDown_in,lead,tilt,note,error',
    );
  });

  it('--unit takes mm, inch (or in); another word is a usage error', async () => {
    const r = await runMain(['--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.01', '--unit', 'furlong']);
    expect(r.code).toBe(2);
    expect(r.stderr).toBe('error: --unit must be mm or inch (got "furlong") (see path-interval --help)\n');
    const a = await json(['--R', '0.25', '--Rcr', '0.03', '--rho', '5', '--h', '0.0004', '--unit', 'in']);
    expect(a.unit).toBe('inch');
  });
});

describe("the page's one parser for lengths: fractions and suffixes, and --D", () => {
  it('--D 1/2" --Rcr .030in --h 0.0004in is the half-inch tool in mm (the issue\'s example)', async () => {
    const a = await json(['--D', '1/2"', '--Rcr', '.030in', '--rho', '5', '--h', '0.0004in']);
    const input = a.input as Json;
    expect(a.unit).toBe('mm');
    expect(input.R).toBe(6.35);
    expect(input.Rcr).toBeCloseTo(0.762, 14);
    expect(input.h).toBeCloseTo(0.01016, 15);
    const same = await json(['--R', '6.35', '--Rcr', String(input.Rcr), '--rho', '5', '--h', String(input.h)]);
    expect(a.exact).toEqual(same.exact);
  });

  it('a suffix names its own unit whatever --unit says; a plain number is in --unit', async () => {
    const a = await json(['--R', '12.7mm', '--Rcr', '1/32', '--rho', '5', '--h', '5um', '--unit', 'inch']);
    expect((a.input as Json).R).toBe(0.5);
    expect((a.input as Json).Rcr).toBe(0.03125);
    expect((a.input as Json).h).toBe(Number((5e-3 / 25.4).toPrecision(12)));
    const b = await json(['--R', '1 1/4 in', '--Rcr', '0.2 thou', '--rho', '5', '--h', '0.0001']);
    expect((b.input as Json).R).toBe(31.75);
    expect((b.input as Json).Rcr).toBeCloseTo(0.00508, 15);
  });

  it('--D names the diameter in its errors and does not go with --R', async () => {
    const r = await runMain(['--D', '-1', '--Rcr', '0', '--rho', '5', '--h', '0.01']);
    expect(r.code).toBe(2);
    expect(r.stderr).toBe('error: --D: Tool diameter D must be greater than 0 mm (got -1).\n');
    const c = await runMain(['--D', '6', '--Rcr', '4', '--rho', '5', '--h', '0.01']);
    expect(c.stderr).toBe(
      'error: --Rcr: Corner radius Rcr must be at most D/2 = 3 mm (got 4); Rcr = D/2 is a ball end mill.\n',
    );
    const both = await runMain(['--R', '3', '--D', '6', '--Rcr', '1', '--rho', '5', '--h', '0.01']);
    expect(both.stderr).toBe(
      'error: --R and --D do not go together: give the tool radius R or the diameter D (see path-interval --help)\n',
    );
  });

  it('a text that is no length is refused in the one wording (the unit suffix unknown, or no number)', async () => {
    const r = await runMain(['--R', '3 furlongs', '--Rcr', '1', '--rho', '5', '--h', '0.01']);
    expect(r.stderr).toBe('error: --R: Tool radius R must be a number (got "3 furlongs").\n');
  });
});

describe('--batch in inches and with unit-named columns', () => {
  const rows = ['0.25,0.03,5,0.0004', '0.125,0.04,10,0.0003', '0.25,0.03,0,0.0004', '0.25,0.3,5,0.0004'];
  it('--unit inch: bare columns are inches, every length column named _in, each result the mm one / 25.4', async () => {
    const inch = await runMain(['--batch', '--unit', 'inch'], `R,Rcr,rho,h\n${rows.join('\n')}\n`);
    const mmRows = rows.map((r) => {
      const [R, Rcr, rho, h] = r.split(',').map(Number) as [number, number, number, number];
      return [R * 25.4, Rcr * 25.4, rho, h * 25.4].join(',');
    });
    const mm = await runMain(['--batch'], `R,Rcr,rho,h\n${mmRows.join('\n')}\n`);
    expect(inch.code).toBe(0);
    const [head, ...a] = parseCsv(inch.stdout).map((x) => x.fields);
    const [mmHead, ...b] = parseCsv(mm.stdout).map((x) => x.fields);
    expect(head?.join(',')).toBe(
      'R_in,Rcr_in,rho,h_in,exact_in,sekine_in,redonnet_in,bedi_in,interval_in,halfWidthRight_in,halfWidthLeft_in,contactOffset_in,otherCuspHeight_in,osculating_in,cornerBall_in,note,error',
    );
    expect(a.length).toBe(rows.length);
    for (const [i, row] of a.entries()) {
      expect(row.slice(0, 4).join(','), 'the echo as typed').toBe(rows[i]);
      const other = b[i] as string[];
      for (let j = 4; j < (mmHead?.length ?? 0) - 2; j++) {
        const t = other[j] as string;
        expect(row[j], `${mmHead?.[j]} row ${i}`).toBe(t === '' ? '' : String(Number(t) / 25.4));
      }
      expect(row.at(-2), 'the note').toBe(other.at(-2));
    }
    expect(a[3]?.at(-1)).toMatch(/^Corner radius Rcr must not exceed the tool radius R = 0\.25 in \(got 0\.3\)/);
  });

  it('a column may name its unit (R_in, h_mm, Ra_in) whatever the run is in', async () => {
    const r = await runMain(['--batch'], 'R_in,Rcr_mm,rho,Ra_in\n0.25,0.762,5,0.0001\n');
    const [head, row] = parseCsv(r.stdout).map((x) => x.fields);
    expect(head?.slice(0, 5)).toEqual(['R_in', 'Rcr', 'rho', 'Ra_in', 'h']);
    const a = await json(['--R', '6.35', '--Rcr', '0.762', '--rho', '5', '--ra', String(0.0001 * 25.4)]);
    expect(row?.[4]).toBe(String((a.exact as Json).scallopHeight));
    expect(row?.[9]).toBe(String((a.exact as Json).interval));
  });
});
