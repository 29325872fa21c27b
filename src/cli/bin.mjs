#!/usr/bin/env node
// Entry point of `npm run cli` and `npx path-interval`: runs the TypeScript command line through tsx.
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

try {
  const { register } = await import('tsx/esm/api');
  register();
  const { main } = await import('./main.ts');
  process.exitCode = await main(process.argv.slice(2), {
    stdin: process.stdin,
    stdout: process.stdout,
    stderr: process.stderr,
  });
} catch (e) {
  fail(e);
}
