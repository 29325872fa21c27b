import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));
/** tsx's command line, run by this Node (no npx start-up in between). */
const TSX = fileURLToPath(new URL('../../node_modules/tsx/dist/cli.mjs', import.meta.url));

describe('npm run bench', () => {
  // The smoke mode (`--smoke`): every figure of the full bench, at about a hundredth of its work (one
  // round, a hundredth of the calls, 2,000-row batch files instead of 200,000): this test proves
  // each figure is printed and finite, not how fast anything is (the full bench is `npm run bench`).
  it('prints a table and, with --json, a last line holding the documented keys, every figure finite', () => {
    const r = spawnSync(process.execPath, [TSX, 'src/bench/solvers.ts', '--json', '--smoke'], {
      cwd: ROOT,
      encoding: 'utf8',
    });
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    const lines = r.stdout.trim().split('\n');
    expect(r.stdout).toMatch(/exact L \(no tilt\)\s+\d+\.\d/);
    expect(r.stdout).toMatch(/teach: slope chart, 200 slopes \(three-axis\) \(ms\)\s+\d+\.\d/);
    expect(r.stdout).not.toMatch(/NaN|Infinity|undefined/);
    // Every row of the table (from its header to the checksum) ends its label with a finite figure.
    const table = lines.slice(lines.findIndex((l) => l.startsWith('solver')) + 1, -2);
    expect(table.length).toBeGreaterThanOrEqual(27);
    for (const row of table) {
      const figure = / {2,}(\d+(?:\.\d+)?)(?: {3}|$)/.exec(row)?.[1];
      expect(Number.isFinite(Number(figure)) && Number(figure) > 0, row).toBe(true);
    }
    const last = JSON.parse(lines[lines.length - 1] as string) as Record<string, unknown>;
    for (const [key, value] of Object.entries(last)) {
      expect(typeof value === 'number' && Number.isFinite(value) && value > 0, `${key}: ${value}`).toBe(true);
    }
    for (const key of [
      'exactNsPerCall',
      'exactTiltNsPerCall',
      'exactWithGeometryNsPerCall',
      'sekineNsPerCall',
      'redonnetNsPerCall',
      'bediNsPerCall',
      'exactCylinderFeedNsPerCall',
      'exactCylinderCrossNsPerCall',
      'roughnessNsPerCall',
      'targetRaNsPerCall',
      'simulationMsMedian',
      'simulationCellsPerSecond',
      'batchRowsPerSecond',
      'batchVariedRowsPerSecond',
      'teachSlopeChartMsMedian',
      'teachCurvedMsMedian',
      'cliStartMs',
      'nodeStartMs',
    ]) {
      expect(last[key], key).toBeGreaterThan(0);
    }
  }, 120_000);
});
