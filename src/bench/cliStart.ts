/**
 * The command line's start-up: the wall time of one question (`path-interval --R 3 --Rcr 1 --rho 5
 * --h 0.05 --json`) from spawning Node to its exit, median over runs; beside it Node's own start
 * (`node -e 0`), the floor under it. A warm-up run first, which builds the compiled command line
 * if it is missing or stale (src/cli/bundle.mjs), so the runs measure the compiled one.
 */
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const BIN = fileURLToPath(new URL('../cli/bin.mjs', import.meta.url));
const QUESTION = ['--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.05', '--json'];

/** Wall milliseconds of one Node process with these arguments, to its exit; throws unless it exits 0. */
function processMs(args: readonly string[]): number {
  const t0 = process.hrtime.bigint();
  const r = spawnSync(process.execPath, args, { encoding: 'utf8' });
  const ms = Number(process.hrtime.bigint() - t0) / 1e6;
  if (r.status !== 0) throw new Error(`node ${args.join(' ')} exited ${r.status}: ${r.stderr.split('\n')[0]}`);
  return ms;
}

/** Median wall milliseconds of `runs` processes (after the warm-up), the CLI's and Node's alone. */
export function cliStartBench(runs: number): { cliStartMs: number; nodeStartMs: number } {
  processMs([BIN, ...QUESTION]);
  const cli: number[] = [];
  const bare: number[] = [];
  for (let i = 0; i < runs; i++) {
    cli.push(processMs([BIN, ...QUESTION]));
    bare.push(processMs(['-e', '0']));
  }
  cli.sort((x, y) => x - y);
  bare.sort((x, y) => x - y);
  return { cliStartMs: cli[cli.length >> 1] as number, nodeStartMs: bare[bare.length >> 1] as number };
}
