/**
 * Writes the batch golden (batch.golden.json): each case of batchCases.ts with what `--batch`
 * gives for it now (exit code, stdout, stderr). Run it only when the batch's output is meant to
 * change (a solver or a wording changed on purpose), and look at the diff:
 *
 *   npx tsx tests/cli/golden/generate.ts
 */
import { execFileSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { run } from '../helpers';
import { batchCases } from './batchCases';

/** Where the golden is kept. */
export const GOLDEN = fileURLToPath(new URL('./batch.golden.json', import.meta.url));

const out = [];
for (const c of batchCases()) {
  const r = await run(c.args, c.stdin);
  out.push({ ...c, code: r.code, stdout: r.stdout, stderr: r.stderr });
}
writeFileSync(GOLDEN, `${JSON.stringify(out, null, 2)}\n`);
// In the repository's JSON format (biome), so that a check of the tree leaves it as it is.
execFileSync('npx', ['biome', 'format', '--write', GOLDEN], { stdio: 'ignore' });
console.log(`${GOLDEN}: ${out.length} cases, ${out.reduce((n, c) => n + c.stdout.split('\n').length - 2, 0)} rows`);
