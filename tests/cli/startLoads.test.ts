/**
 * What a command line question loads before it answers (issue 27 point 8: one answer within
 * 100 ms of process start): the x3p writer and its zip library (whose tables cost about 8 ms to
 * build at load) only with `--x3p` (x3pOption.ts loadX3pWriter). Read from the sources' static
 * imports (src/build/staticGraph.ts), as the first result's test reads the page's.
 */
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { chainTo, staticClosure } from '../../src/build/staticGraph';

const SRC = fileURLToPath(new URL('../../src/', import.meta.url));

describe('the command line starts without what a plain question does not use', () => {
  it('loads the x3p writer only for --x3p', () => {
    const cli = staticClosure(`${SRC}cli/main.ts`, SRC);
    expect(cli.has('cli/x3pOption.ts')).toBe(true);
    expect(cli.has('core/output/x3p.ts') ? chainTo(cli, 'core/output/x3p.ts') : null).toBeNull();
  });
});
