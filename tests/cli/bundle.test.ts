/**
 * The compiled command line's freshness (src/cli/bundle.mjs): the launcher runs the bundle
 * only while no source it was built from changed or vanished since its build started, so a
 * checkout never answers with an earlier version of the code. Checked on a bundle and sources in
 * a temporary folder, their times set by hand.
 */
import { mkdirSync, mkdtempSync, rmSync, utimesSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { CLI_BUILD_MARK, cliBundleIsCurrent } from '../../src/cli/bundle.mjs';

const root = `${mkdtempSync(join(tmpdir(), 'cli-bundle-'))}/`;
const bundle = `${root}dist-cli/cli.mjs`;
const STARTED_MS = Date.UTC(2030, 0, 1);
const INPUTS = ['src/cli/main.ts', 'src/core/a.ts'];

/** Writes a source file with its modification time `ms`. */
function source(path: string, ms: number): void {
  mkdirSync(join(root, path, '..'), { recursive: true });
  writeFileSync(join(root, path), 'export {};\n');
  utimesSync(join(root, path), ms / 1000, ms / 1000);
}

function writeBundle(firstLine: string): void {
  mkdirSync(join(root, 'dist-cli'), { recursive: true });
  writeFileSync(bundle, `${firstLine}\nexport const main = () => 0;\n`);
}

const record = `${CLI_BUILD_MARK}${JSON.stringify({ startedMs: STARTED_MS, inputs: INPUTS })}`;

afterAll(() => rmSync(root, { recursive: true, force: true }));

describe('the compiled command line is run only while current', () => {
  it('current when every source is older than the build; stale when one changed at or after its start', () => {
    for (const input of INPUTS) source(input, STARTED_MS - 1000);
    writeBundle(record);
    expect(cliBundleIsCurrent(bundle, root)).toBe(true);
    source('src/core/a.ts', STARTED_MS);
    expect(cliBundleIsCurrent(bundle, root)).toBe(false);
    source('src/core/a.ts', STARTED_MS - 1);
    expect(cliBundleIsCurrent(bundle, root)).toBe(true);
  });

  it('stale when a source it was built from is gone, when it has no build record, or when it is missing', () => {
    for (const input of INPUTS) source(input, STARTED_MS - 1000);
    writeBundle(record);
    rmSync(join(root, 'src/core/a.ts'));
    expect(cliBundleIsCurrent(bundle, root)).toBe(false);
    source('src/core/a.ts', STARTED_MS - 1000);
    writeBundle('// built by hand');
    expect(cliBundleIsCurrent(bundle, root)).toBe(false);
    rmSync(bundle);
    expect(cliBundleIsCurrent(bundle, root)).toBe(false);
  });

  it('current without the sources (an installed copy that ships only the bundle)', () => {
    writeBundle(record);
    rmSync(join(root, 'src'), { recursive: true });
    expect(cliBundleIsCurrent(bundle, root)).toBe(true);
  });
});
