import { describe, expect, it } from 'vitest';
import { forwardJson, forwardTable, inverseJson, inverseTable } from '../../src/cli/report';
import { deviation, echo, length, percent, renderTable } from '../../src/cli/table';
import {
  compareForward,
  compareInverse,
  maxIntervalMm,
  PASS_PATTERNS,
  scallopHeightLimits,
  validateForward,
  validateInverse,
} from '../../src/core/index';
import { everyNumberFinite } from '../support/finite';
import { pick, random, randomHeight, randomTool } from './helpers';

interface Cell {
  readonly text: string;
  readonly start: number;
  readonly end: number;
}

/** Cells of a table line: runs of text separated by two or more spaces. */
function cells(line: string): Cell[] {
  const out: Cell[] = [];
  for (const m of line.matchAll(/\S+(?: \S+)*/g)) out.push({ text: m[0], start: m.index, end: m.index + m[0].length });
  return out;
}

/** The lines of the block that starts with a line matching `first`, up to the next blank line. */
function block(text: string, first: RegExp): string[] {
  const lines = text.split('\n');
  const i = lines.findIndex((l) => first.test(l));
  if (i < 0) throw new Error(`no block ${first} in\n${text}`);
  const end = lines.indexOf('', i);
  return lines.slice(i, end < 0 ? undefined : end);
}

const BAD = /NaN|Infinity|undefined|null|\u2014|(^|\s)[-+]0(\.0*)?(e[-+]?\d+)?(\s|$)/;

/** Significant digits of a number as printed (zero: its zeros). */
function significantDigits(text: string): number {
  const mantissa = text.replace(/^[-+]/, '').replace(/e.*$/, '');
  if (/^0\.0+$/.test(mantissa)) return mantissa.length - 1;
  return mantissa.replace('.', '').replace(/^0+/, '').length;
}

/**
 * Checks a procedure table: every row has a cell under each numeric column ending where the
 * header's ends (right-aligned), the label and note start where theirs do, and lengths print
 * at least 6 significant digits. Returns the number of rows checked.
 */
function checkTable(lines: readonly string[], lengthColumns: readonly number[]): number {
  const header = cells(lines[0] as string);
  const last = header.length - 1; // the note column
  for (const line of lines.slice(1)) {
    const row = cells(line);
    if (row.length !== header.length && row.length !== header.length - 1)
      expect.fail(`a row of ${row.length} cells under ${header.length} heads:\n${line}\n${lines[0]}`);
    expect(row[0]?.start).toBe(0);
    // The table is written into the message only when a column is off (joined per cell, it cost more than the check).
    for (let j = 1; j < last; j++)
      if (row[j]?.end !== header[j]?.end)
        expect(row[j]?.end, `column ${j} of\n${lines.join('\n')}`).toBe(header[j]?.end);
    if (row.length === header.length) expect(row[last]?.start).toBe(header[last]?.start);
    for (const j of lengthColumns) {
      const t = row[j]?.text as string;
      if (/^\s*[-+]?\d/.test(t)) expect(significantDigits(t), t).toBeGreaterThanOrEqual(6);
    }
  }
  return lines.length - 1;
}

/** The exact block: name, value (right-aligned), unit, description. */
function checkFacts(lines: readonly string[]): void {
  const rows = lines.slice(1).filter((l) => /^ {2}\S+ +\S/.test(l) && !/^ {2}[A-Z]/.test(l));
  const ends = rows.map((l) => cells(l)[1]?.end);
  expect(new Set(ends).size, lines.join('\n')).toBe(1);
  for (const l of rows) expect(significantDigits(cells(l)[1]?.text as string), l).toBeGreaterThanOrEqual(6);
}

describe('table cells', () => {
  it('lengths and deviations: 7 significant digits at any magnitude, never -0', () => {
    expect(length(1.4435924129671018)).toBe('1.443592');
    expect(length(0.000336)).toBe('0.0003360000');
    // Never exponent notation (issue 26 point 10).
    expect(length(0.0000336)).toBe('0.00003360000');
    expect(deviation(-6.713918e-5)).toBe('-0.00006713918');
    expect(length(1234.56789)).toBe('1234.568');
    expect(length(-0)).toBe('0.000000');
    expect(deviation(-1e-30)).toBe(`-0.${'0'.repeat(29)}1000000`);
    expect(deviation(0)).toBe('0.000000');
    expect(deviation(-0)).toBe('0.000000');
    expect(deviation(2.5)).toBe('+2.500000');
    expect(percent(-0.001)).toBe('0.00');
    expect(percent(null)).toBe('-');
    // An input echoed as given, but as a plain decimal that reads back to the same double.
    expect(echo(1e-9)).toBe('0.000000001');
    expect(echo(-3.5e-12)).toBe('-0.0000000000035');
    expect(echo(1.5e22)).toBe('15000000000000000000000');
    for (const x of [5e-324, 1.7976931348623157e308, 2.5e-5, 0.1, -0]) expect(Number(echo(x))).toBe(x === 0 ? 0 : x);
  });

  it('renderTable sizes each column to its widest cell', () => {
    const lines = renderTable(
      [
        { header: 'name', align: 'left' },
        { header: 'x', align: 'right' },
      ],
      [
        ['a', '1.5'],
        ['longer name', '-123456.7'],
      ],
    );
    expect(lines).toEqual(['name                 x', 'a                  1.5', 'longer name  -123456.7']);
  });
});

describe('tables and JSON of random cases (in process)', () => {
  const seed = 4242;
  const N = 2500;
  it(`forward: aligned columns, >= 6 significant digits, no NaN/Infinity/-0, finite JSON without null (seed ${seed}, ${N} cases)`, () => {
    const rand = random(seed);
    let valid = 0;
    let rows = 0;
    for (let k = 0; k < N; k++) {
      const t = randomTool(rand);
      const tool = { toolRadiusMm: t.R, cornerRadiusMm: t.Rcr, leadAngleDeg: t.rho, tiltAngleDeg: t.tilt };
      const h = randomHeight(rand, Math.min(scallopHeightLimits(tool).limitMm, 1e300));
      const v = validateForward({ ...t, pattern: pick(rand, PASS_PATTERNS), h });
      if (!v.ok) continue;
      valid++;
      const c = compareForward(v.value);
      const text = forwardTable(c);
      expect(text, text).not.toMatch(BAD);
      checkFacts(block(text, /^Exact \(3D geometry\):$/));
      rows += checkTable(block(text, /^procedure/), [1, 2, 3, 5]);
      const json = forwardJson(c);
      expect(everyNumberFinite(json)).toBe(true);
      expect(JSON.stringify(json)).not.toMatch(/null|NaN|Infinity/);
    }
    expect(valid).toBeGreaterThan(0.75 * N); // the rest: h = 1e-9 at or above a limit that is lower
    expect(rows).toBe(6 * valid);
  });

  const seed2 = 777;
  it(`inverse: aligned columns, >= 6 significant digits, no NaN/Infinity/-0, finite JSON without null (seed ${seed2}, ${N} cases)`, () => {
    const rand = random(seed2);
    let valid = 0;
    for (let k = 0; k < N; k++) {
      const t = randomTool(rand);
      const tool = { toolRadiusMm: t.R, cornerRadiusMm: t.Rcr, leadAngleDeg: t.rho, tiltAngleDeg: t.tilt };
      const pattern = pick(rand, PASS_PATTERNS);
      const interval = Math.max(2e-9, maxIntervalMm(tool, pattern) * pick(rand, [rand(), 1e-9 ** rand(), 1 - 1e-9]));
      const v = validateInverse({ ...t, pattern, interval });
      if (!v.ok) continue;
      valid++;
      const c = compareInverse(v.value);
      const text = inverseTable(c);
      expect(text, text).not.toMatch(BAD);
      checkFacts(block(text, /^Exact \(3D geometry\):$/));
      checkTable(block(text, /^procedure/), [1, 2]);
      const json = inverseJson(c);
      expect(everyNumberFinite(json)).toBe(true);
      expect(JSON.stringify(json)).not.toMatch(/null|NaN|Infinity/);
    }
    expect(valid).toBeGreaterThan(0.75 * N); // the rest: h = 1e-9 at or above a limit that is lower
  });

  it('lead-only labels under tilt; notes for warnings and for not applicable', () => {
    const v = validateForward({ R: 3, Rcr: 1, rho: 0.01, tilt: 0, h: 0.05 });
    if (!v.ok) throw new Error('invalid');
    const text = forwardTable(compareForward(v.value));
    expect(text).toMatch(
      /^Redonnet et al\. \(Eqs\. 9, 8\) +67\.70563 +33\.85282 +\+63\.08326 +\+1364\.74 +wall +\[2\]$/m,
    );
    expect(text).toMatch(/^\[2\] Redonnet et al\.: its step-over L = 67\.7056 mm is not below/m);
    expect(text).toMatch(/^Bedi et al\. \(Eqs\. 10-11\) +n\/a +n\/a +- +- +- +\[3\]$/m);
    expect(text).toMatch(/^\[3\] Bedi et al\.: h = 0\.05 mm is above the widest point/m);
    const tilted = validateForward({ R: 3, Rcr: 1, rho: 5, tilt: 5, h: 0.05 });
    if (!tilted.ok) throw new Error('invalid');
    const t2 = forwardTable(compareForward(tilted.value));
    expect(t2).toMatch(/^Sekine et al\. \(Eqs\. 4-8\), lead only +2\.171474/m);
    expect(t2).toMatch(/^Osculating circle at the contact +1\.905004/m);
    expect(t2).not.toMatch(/Osculating circle at the contact, lead only/);
  });

  it('says so when a flat end lying flat leaves no scallop', () => {
    const v = validateForward({ R: 3, Rcr: 0, rho: 0, h: 5 });
    if (!v.ok) throw new Error('invalid');
    const c = compareForward(v.value);
    expect(forwardTable(c)).toMatch(/leaves no scallop at any step-over up to its diameter: L = 2R/);
    expect(forwardJson(c)).toMatchObject({ exact: { interval: 6, noScallop: true, scallopHeight: 0 } });
  });
});
