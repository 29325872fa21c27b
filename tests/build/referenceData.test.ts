/**
 * The published reference data set (public/reference/scallop-reference.csv, its JSON description, written by
 * `npm run reference`): the file is the one the description's SHA-256 names, with the columns it
 * lists; every row is answered again by the current calculator (the same entry the generator used,
 * src/build/reference/answer.ts) within 1e-9 mm of its `answer` (a refused row with the same error
 * code, field and limit); every reference value lies within its bound of the answer, and each
 * polished reference within the sampled brute force's bound of its sampled value. It re-solves; it
 * does not rerun the brute forces (the generator does, and refuses to write a disagreeing row).
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { calculatorAnswer } from '../../src/build/reference/answer';
import {
  COLUMN_NAMES,
  calculatorToleranceMm,
  REFERENCE_CSV,
  REFERENCE_METHODS,
  REFERENCE_SEED,
  REFERENCE_VERSION,
  type ReferenceRow,
} from '../../src/build/reference/columns';
import { REFERENCE_CSV_PATH, REFERENCE_JSON_PATH, rowsOf, sha256Of } from '../../src/build/reference/dataset';
import { STRATA } from '../../src/build/reference/strata/index';

/** The re-solved answer must stay this close to the published one, mm (or degrees for an angle limit). */
const SAME_ANSWER_MM = 1e-9;

const csv = readFileSync(REFERENCE_CSV_PATH, 'utf8');
const description = JSON.parse(readFileSync(REFERENCE_JSON_PATH, 'utf8')) as {
  version: string;
  seed: number;
  csv: string;
  sha256: string;
  rows: number;
  columns: { name: string; unit: string; description: string }[];
  methods: Record<string, string>;
  strata: Record<string, { rows: number }>;
};
const rows = rowsOf(csv);
const num = (row: ReferenceRow, name: string): number => Number(row[name]);

/** The first few failures of a check over rows, as text (empty when every row passes). */
function failures(list: readonly ReferenceRow[], check: (row: ReferenceRow) => string | null): string[] {
  const out: string[] = [];
  for (const row of list) {
    const f = check(row);
    if (f !== null) out.push(`row ${row.id}: ${f}`);
    if (out.length >= 5) break;
  }
  return out;
}

describe('the reference data set (seed 2027)', () => {
  it('is the file its description names: SHA-256, row count, columns, version, seed', () => {
    expect(description.csv).toBe(REFERENCE_CSV);
    expect(sha256Of(csv)).toBe(description.sha256);
    expect(rows.length).toBe(description.rows);
    expect(description.columns.map((c) => c.name)).toEqual(COLUMN_NAMES);
    expect(description.version).toBe(REFERENCE_VERSION);
    expect(description.seed).toBe(REFERENCE_SEED);
    expect(description.methods).toEqual(REFERENCE_METHODS);
    expect(rows.map((r) => r.id)).toEqual(rows.map((_, i) => String(i + 1)));
  });

  it('holds at least 2,000 rows over every stratum, as many as the description says', () => {
    expect(rows.length).toBeGreaterThanOrEqual(2000);
    const counts = new Map<string, number>();
    for (const r of rows) counts.set(r.stratum as string, (counts.get(r.stratum as string) ?? 0) + 1);
    expect(Object.fromEntries(counts)).toEqual(
      Object.fromEntries(Object.entries(description.strata).map(([k, v]) => [k, v.rows])),
    );
    for (const s of STRATA) expect(counts.get(s.name), s.name).toBeGreaterThan(0);
  });

  it('is shipped as path-interval/reference', () => {
    const pkg = JSON.parse(readFileSync(new URL('../../package.json', import.meta.url), 'utf8')) as {
      exports: Record<string, unknown>;
    };
    expect(pkg.exports['./reference']).toBe('./public/reference/scallop-reference.json');
    expect(pkg.exports['./reference/*']).toBe('./public/reference/*');
  });

  for (const stratum of STRATA)
    describe(stratum.name, () => {
      const mine = rows.filter((r) => r.stratum === stratum.name);

      it('the current calculator gives every answer again (within 1e-9 mm; refusals with the same code, field and limit)', () => {
        const bad = failures(mine, (row) => {
          const a = calculatorAnswer(row);
          if (row.errorCode === '') {
            if (!a.ok) return `refused (${a.code} ${a.field})`;
            if (!Number.isFinite(a.valueMm)) return `non-finite ${a.valueMm}`;
            const d = Math.abs(a.valueMm - num(row, 'answer'));
            return d <= SAME_ANSWER_MM ? null : `answer ${a.valueMm}, published ${row.answer} (off by ${d})`;
          }
          if (a.ok) return `answered ${a.valueMm}, published ${row.errorCode}`;
          if (a.code !== row.errorCode || a.field !== row.errorField)
            return `${a.code} ${a.field}, published ${row.errorCode} ${row.errorField}`;
          if ((a.limit === null) !== (row.answer === '')) return `limit ${a.limit}, published "${row.answer}"`;
          if (a.limit !== null && !(Math.abs(a.limit - num(row, 'answer')) <= SAME_ANSWER_MM))
            return `limit ${a.limit}, published ${row.answer}`;
          return null;
        });
        expect(bad).toEqual([]);
      });

      it('every reference lies within its bound of the answer, the bound being its uncertainty plus 1e-9 mm per mm of R', () => {
        const bad = failures(mine, (row) => {
          if (row.reference === '') return row.method === '' ? null : `method ${row.method} without a reference`;
          if (!(row.method && row.method in REFERENCE_METHODS)) return `unknown method ${row.method}`;
          const R = num(row, 'R');
          const bound = num(row, 'referenceUncertainty') + calculatorToleranceMm(Number.isFinite(R) ? R : 1);
          if (Math.abs(bound - num(row, 'bound')) > 1e-6 * bound) return `bound ${row.bound}, expected ${bound}`;
          const d = Math.abs(num(row, 'answer') - num(row, 'reference'));
          if (!(d <= num(row, 'bound'))) return `|answer - reference| = ${d} > ${row.bound}`;
          if (
            row.sampled !== '' &&
            !(Math.abs(num(row, 'sampled') - num(row, 'reference')) <= num(row, 'sampledBound'))
          )
            return `sampled ${row.sampled} +- ${row.sampledBound}, reference ${row.reference}`;
          return null;
        });
        expect(bad).toEqual([]);
      });
    });
});
