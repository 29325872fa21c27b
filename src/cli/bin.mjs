#!/usr/bin/env node
import { pathToFileURL } from 'node:url';

// Entry point of `npm run cli` and `npx path-interval`: runs the compiled command line,
// dist-cli/cli.mjs (src/cli/bundle.mjs; built by `npm ci` and `npm test`). In a checkout whose
// sources changed since that build (or without it), it is rebuilt first, silently (about 0.2 s, once);
// where it cannot be (no esbuild, a source that does not compile), the sources run through tsx.
// Never a stack trace: write errors are handled in main.ts; anything unexpected is one line, exit 1.

const oneLine = (e) => String(e instanceof Error ? e.message : e).split('\n')[0];
const fail = (e) => {
  try {
    process.stderr.write(`error: internal error: ${oneLine(e)}\n`);
  } catch {
    // stderr is gone too: nothing left to tell.
  }
  process.exit(1);
};
process.on('uncaughtException', fail);
process.on('unhandledRejection', fail);
// Write errors are reported by main.ts (through the write callbacks); these keep a late one from
// becoming an uncaught exception.
process.stdout.on('error', () => {});
process.stderr.on('error', () => {});

/** The command line's main(): compiled, rebuilt when stale, or else from the sources through tsx. */
async function loadMain() {
  const { CLI_BUNDLE, buildCliBundle, cliBundleIsCurrent } = await import('./bundle.mjs');
  try {
    if (!cliBundleIsCurrent()) await buildCliBundle();
    return await import(pathToFileURL(CLI_BUNDLE).href);
  } catch {
    const { register } = await import('tsx/esm/api');
    register();
    return import('./main.ts');
  }
}

try {
  const { main } = await loadMain();
  process.exitCode = await main(process.argv.slice(2), {
    stdin: process.stdin,
    stdout: process.stdout,
    stderr: process.stderr,
  });
} catch (e) {
  fail(e);
}
