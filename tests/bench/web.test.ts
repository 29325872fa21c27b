import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { E2E_OUT_DIR } from '../e2e/globalSetup';

const ROOT = fileURLToPath(new URL('../..', import.meta.url));

describe('npm run bench:web', () => {
  it('runs in headless Chromium and prints the three figures, with a JSON last line', () => {
    // The sites the browser tests' global set-up built: not built a second time.
    const r = spawnSync('npx', ['tsx', 'src/bench/web.ts', '--json', '--quick', '--prebuilt', E2E_OUT_DIR], {
      cwd: ROOT,
      encoding: 'utf8',
      timeout: 120_000,
    });
    expect(r.status, r.stderr).toBe(0);
    expect(r.stdout).toMatch(/input -> results \+ next frame, median\s+\d+\.\d ms/);
    const lines = r.stdout.trim().split('\n');
    const last = JSON.parse(lines[lines.length - 1] as string);
    for (const key of ['inputToFrameMsMedian', 'coldLoadMsMedian', 'jsInitialGzipKb', 'jsGzipKb'])
      expect(last[key]).toBeGreaterThan(0);
  }, 120_000);
});
