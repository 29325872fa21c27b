/**
 * One path for a batch row and a single question (issue 26 point 8): the same questions sent as
 * command lines (--json, in-process) and as the rows of one batch give the same numbers, bit for
 * bit, and the same refusals (the batch's error column is the command line's messages), over every
 * mode: plane, posture (lead, tilt), zigzag, cylinders (given as Rs and axis, or as one principal
 * radius), doubly curved points, three-axis raster and waterline; h and Ra questions; valid and
 * refused (gouging, beyond the limits, bad text). h, Ra and step-over (L) questions.
 */
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { logUniform, pick, random, runMain } from './helpers';

/** A question as the batch's columns name its values (empty: not given). */
type Row = Readonly<Record<string, string>>;

const FIVE_AXIS = ['R', 'Rcr', 'rho', 'tilt', 'pattern', 'surfaceRadius', 'surfaceAxis', 'feedRadius', 'crossRadius'];
const THREE_AXIS = ['R', 'Rcr', 'h', 'slope', 'passes', 'rasterAngle', 'feedRadius', 'crossRadius'];

/** Each column's option. */
const OPTION: Readonly<Record<string, string>> = {
  R: '--R',
  Rcr: '--Rcr',
  rho: '--rho',
  tilt: '--tilt',
  pattern: '--pattern',
  surfaceRadius: '--surface-radius',
  surfaceAxis: '--surface-axis',
  feedRadius: '--feed-radius',
  crossRadius: '--cross-radius',
  h: '--h',
  Ra: '--ra',
  L: '--interval',
  slope: '--slope',
  passes: '--passes',
  rasterAngle: '--raster-angle',
};

const text = (x: number) => String(Number(x.toPrecision(6)));
const signed = (rand: () => number, x: number) => (rand() < 0.5 ? -x : x);

/** A five-axis question over the modes, valid or not (about a third are refused). */
function fiveAxisRow(rand: () => number, target: 'h' | 'Ra' | 'L'): Row {
  const R = logUniform(rand, 0.5, 20);
  const Rcr = pick(rand, [0, R, R * rand(), R * 0.3]);
  const rho = pick(rand, ['0', '5', text(60 * rand()), text(89 * rand())]);
  const tilt = pick(rand, ['', '', '0', text(60 * (rand() - 0.5))]);
  const pattern = pick(rand, ['', 'one-way', 'zigzag']);
  const radius = () => text(signed(rand, logUniform(rand, 0.2 * R, 500 * R)));
  const surface = pick(rand, ['plane', 'cylinder', 'feedOnly', 'crossOnly', 'doubly', 'doubly']);
  const quantity =
    target === 'h'
      ? pick(rand, [
          text(logUniform(rand, 1e-4, 0.3) * R),
          text(logUniform(rand, 1e-4, 0.1) * R),
          text(logUniform(rand, 1e-6, 2) * R),
          'abc',
          '-1',
        ])
      : target === 'Ra'
        ? pick(rand, [text(logUniform(rand, 1e-5, 0.05) * R), text(logUniform(rand, 1e-6, 1) * R), '0'])
        : pick(rand, [text(logUniform(rand, 0.01, 1.5) * R), text(logUniform(rand, 0.001, 2.5) * R), '1/2', '-1']);
  return {
    R: pick(rand, [text(R), text(R), text(R), '5um', 'x']),
    Rcr: text(Rcr),
    rho,
    tilt,
    pattern,
    surfaceRadius: surface === 'cylinder' ? radius() : '',
    surfaceAxis: surface === 'cylinder' ? pick(rand, ['', 'feed', 'cross']) : '',
    feedRadius: surface === 'feedOnly' || surface === 'doubly' ? radius() : '',
    crossRadius: surface === 'crossOnly' || surface === 'doubly' ? radius() : '',
    [target]: quantity,
  };
}

/** A three-axis question: raster (with a raster angle) or waterline (on a plane or a surface of revolution). */
function threeAxisRow(rand: () => number): Row {
  const R = logUniform(rand, 0.5, 20);
  const waterline = rand() < 0.5;
  const radius = () => (rand() < 0.3 ? '' : text(signed(rand, logUniform(rand, 0.5 * R, 500 * R))));
  return {
    R: text(R),
    Rcr: text(pick(rand, [0, R, R * rand()])),
    h: pick(rand, [text(logUniform(rand, 1e-4, 0.2) * R), text(logUniform(rand, 1e-6, 3) * R), 'abc']),
    slope: pick(rand, ['0', text(89.9 * rand()), text(60 * rand()), '95']),
    passes: waterline ? 'waterline' : pick(rand, ['', 'raster']),
    rasterAngle: waterline ? '' : pick(rand, ['', '0', text(90 * rand())]),
    feedRadius: waterline ? radius() : '',
    crossRadius: waterline ? radius() : '',
  };
}

/** The command line of a question: each value given as its option. */
function argsOf(row: Row): string[] {
  const args: string[] = [];
  for (const [column, value] of Object.entries(row)) {
    if (value !== '') args.push(OPTION[column] as string, value);
  }
  return [...args, '--json'];
}

/** The batch of the rows: one header, one record each; its output rows by column name. */
async function batch(columns: readonly string[], rows: readonly Row[]): Promise<Record<string, string>[]> {
  const csv = [columns.join(','), ...rows.map((r) => columns.map((c) => r[c] ?? '').join(','))].join('\n');
  const r = await runMain(['--batch'], `${csv}\n`);
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  const [head, ...out] = parseCsv(r.stdout).map((x) => x.fields);
  return out.map((fields) => Object.fromEntries((head ?? []).map((name, i) => [name, fields[i] ?? ''])));
}

type Json = { [key: string]: unknown };

/** A JSON number as the batch writes it ('' when absent). */
function csvOf(value: unknown): string {
  return typeof value === 'number' ? String(value === 0 ? 0 : value) : '';
}

/** The batch row's refusal beside the command line's, or its numbers beside the JSON's. */
async function compare(
  row: Row,
  out: Record<string, string>,
  numbers: (json: Json) => Record<string, unknown>,
): Promise<'answered' | 'refused'> {
  const args = argsOf(row);
  const r = await runMain(args);
  const label = `${args.join(' ')} | ${JSON.stringify(out)}`;
  const json = JSON.parse(r.stdout) as Json;
  if (r.code !== 0) {
    expect(r.code, label).toBe(2);
    const errors = json.errors as { message: string }[];
    expect(out.error, label).toBe(errors.map((e) => e.message).join(' '));
    return 'refused';
  }
  expect(out.error, label).toBe('');
  for (const [column, value] of Object.entries(numbers(json)))
    expect(out[column], `${column}: ${label}`).toBe(csvOf(value));
  return 'answered';
}

/** The numbers a five-axis batch row holds, read from the JSON answer. */
function fiveAxisNumbers(row: Row): (json: Json) => Record<string, unknown> {
  return (json) => {
    const exact = json.exact as Json;
    const doubly = row.feedRadius !== '' && row.crossRadius !== '';
    const half = (key: string) => (json[key] as Json | undefined)?.halfInterval;
    return {
      exact: exact.halfInterval,
      interval: exact.interval,
      halfWidthRight: exact.halfWidthRight,
      halfWidthLeft: exact.halfWidthLeft,
      contactOffset: exact.contactOffset,
      otherCuspHeight: exact.otherCuspHeight,
      ...(row.Ra === undefined ? {} : { h: exact.scallopHeight }),
      // A doubly curved point's JSON compares other rows; its approximation columns are the plane's.
      ...(doubly
        ? {}
        : {
            sekine: half('sekine'),
            redonnet: half('redonnet'),
            bedi: half('bedi'),
            osculating: half('osculating'),
            cornerBall: half('cornerBall'),
          }),
    };
  };
}

/** The numbers of a step-over row (the inverse), read from the JSON answer. */
function inverseNumbers(json: Json): Record<string, unknown> {
  const exact = json.exact as Json;
  return {
    h: exact.scallopHeight,
    rightCuspHeight: exact.rightCuspHeight,
    leftCuspHeight: exact.leftCuspHeight,
    otherCuspHeight: exact.otherCuspHeight,
    halfWidthRight: exact.halfWidthRight,
    halfWidthLeft: exact.halfWidthLeft,
    contactOffset: exact.contactOffset,
  };
}

function threeAxisNumbers(json: Json): Record<string, unknown> {
  const exact = json.exact as Json;
  const posture = json.posture as Json;
  return {
    interval: exact.interval,
    ...(exact.horizontalStep === undefined ? {} : { horizontalStep: exact.horizontalStep }),
    ...(exact.stepDown === undefined ? {} : { stepDown: exact.stepDown }),
    lead: posture.lead,
    tilt: posture.tilt,
  };
}

describe('a batch row and a single question go the same way (issue 26 point 8)', () => {
  it("the issue's rows: a target Ra at a doubly curved point is answered there, a gouging one refused", async () => {
    const rows: Row[] = [
      { R: '3', Rcr: '1', rho: '5', Ra: '0.01', feedRadius: '40', crossRadius: '-80' },
      { R: '3', Rcr: '1', rho: '5', Ra: '0.01', feedRadius: '-8', crossRadius: '-8' },
    ];
    const columns = ['R', 'Rcr', 'rho', 'Ra', 'feedRadius', 'crossRadius'];
    const out = await batch(columns, rows);
    // The single question's answer as the issue quotes it (h 0.04144891 mm; the plane's was 0.03995808):
    // the row must give the doubly curved point's, digit for digit the single question's (compare below).
    expect(Number(out[0]?.h)).toBeCloseTo(0.04144891, 8);
    expect(Number(out[0]?.interval)).toBeCloseTo(2.91761, 5);
    expect(out[1]?.error).toMatch(/gouges/);
    for (const [i, row] of rows.entries()) {
      await compare(row, out[i] as Record<string, string>, fiveAxisNumbers(row));
    }
  });

  for (const [target, seed] of [
    ['h', 2601],
    ['Ra', 2602],
    ['L', 2604],
  ] as const) {
    it(`five-axis ${target} questions: the same numbers and refusals (seed ${seed}, 90 questions)`, async () => {
      const rand = random(seed);
      const rows = Array.from({ length: 90 }, () => fiveAxisRow(rand, target));
      const columns = [...FIVE_AXIS, target];
      const out = await batch(columns, rows);
      const seen = { answered: 0, refused: 0 };
      const kinds = new Set<string>();
      for (const [i, row] of rows.entries()) {
        const read = target === 'L' ? inverseNumbers : fiveAxisNumbers(row);
        seen[await compare(row, out[i] as Record<string, string>, read)]++;
        kinds.add(row.surfaceRadius !== '' ? 'cylinder' : `${row.feedRadius !== ''}${row.crossRadius !== ''}`);
      }
      // Both outcomes and every surface form were met.
      expect(seen.answered).toBeGreaterThan(15);
      expect(seen.refused).toBeGreaterThan(10);
      expect(kinds.size).toBe(5);
    });
  }

  it('three-axis raster and waterline questions: the same numbers and refusals (seed 2603, 90 questions)', async () => {
    const rand = random(2603);
    const rows = Array.from({ length: 90 }, () => threeAxisRow(rand));
    const out = await batch(THREE_AXIS, rows);
    const seen = { answered: 0, refused: 0 };
    for (const [i, row] of rows.entries()) {
      seen[await compare(row, out[i] as Record<string, string>, threeAxisNumbers)]++;
    }
    expect(seen.answered).toBeGreaterThan(15);
    expect(seen.refused).toBeGreaterThan(10);
  });
});
