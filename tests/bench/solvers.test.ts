import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));

describe('npm run bench', () => {
  it('prints a table and, with --json, a last line holding the documented keys', () => {
    const r = spawnSync('npx', ['tsx', 'src/bench/solvers.ts', '--json', '--rounds', '1'], {
      cwd: ROOT,
      encoding: 'utf8',
    });
    expect(r.status).toBe(0);
    const lines = r.stdout.trim().split('\n');
    expect(r.stdout).toMatch(/exact L \(no tilt\)\s+\d+\.\d/);
    expect(r.stdout).toMatch(/teach: slope chart, 200 slopes \(three-axis\) \(ms\)\s+\d+\.\d/);
    const last = JSON.parse(lines[lines.length - 1] as string);
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
      expect(last[key]).toBeGreaterThan(0);
    }
  }, 120_000);
});
