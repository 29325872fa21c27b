/**
 * The batch's output, byte for byte, on 487 varied records (golden/batchCases.ts: plane, cylinders,
 * doubly curved points, target Ra, step-over L, three-axis, inches, refused and malformed records),
 * as the code wrote it before the batch was made faster (issue 27 point 8): a speed-up must not
 * change one byte. The golden (golden/batch.golden.json) holds each case's input and output; when
 * an output is meant to change (a solver or a wording, on purpose), write it again with
 * `npx tsx tests/cli/golden/generate.ts` and read the diff.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { run } from './helpers';

interface GoldenCase {
  readonly name: string;
  readonly args: readonly string[];
  readonly stdin: string;
  readonly code: number;
  readonly stdout: string;
  readonly stderr: string;
}

const GOLDEN: readonly GoldenCase[] = JSON.parse(
  readFileSync(new URL('./golden/batch.golden.json', import.meta.url), 'utf8'),
);

describe('--batch output is the golden, byte for byte', () => {
  it('holds the cases (a golden that lost them would pass anything)', () => {
    expect(GOLDEN.length).toBe(13);
    const rows = GOLDEN.reduce((n, c) => n + c.stdout.split('\n').length - 2, 0);
    expect(rows).toBe(487);
  });

  it.each(GOLDEN.map((c) => [c.name, c] as const))('%s', async (_name, c) => {
    const r = await run(c.args, c.stdin);
    expect(r.code).toBe(c.code);
    expect(r.stderr).toBe(c.stderr);
    // Row by row first, so a failure names the first differing row rather than a 20 kB string.
    const got = r.stdout.split('\n');
    const want = c.stdout.split('\n');
    for (let i = 0; i < Math.max(got.length, want.length); i++) expect(got[i], `row ${i}`).toBe(want[i]);
    expect(r.stdout).toBe(c.stdout);
  });
});
