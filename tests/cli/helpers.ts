/** Helpers of the command-line tests: run the CLI in this process or as one, seeded random numbers. */
import { spawn } from 'node:child_process';
import { PassThrough, Readable } from 'node:stream';
import { text } from 'node:stream/consumers';
import { fileURLToPath } from 'node:url';
import { expect } from 'vitest';
import { main } from '../../src/cli/main';
import { seededRandom } from '../../src/core/math/seededRandom';

export const BIN = fileURLToPath(new URL('../../src/cli/bin.mjs', import.meta.url));

export interface RunResult {
  readonly code: number | null;
  readonly stdout: string;
  readonly stderr: string;
}

/**
 * Runs the command line as a separate process, as a user would, with `stdin` as its input: for
 * the few tests of the process contract (exit codes, stdout and stderr, a closed pipe, stdin).
 * It runs the compiled command line (bin.mjs; `npm test` builds it first).
 */
export function runProcess(args: readonly string[], stdin = ''): Promise<RunResult> {
  return new Promise((resolve, reject) => {
    const child = spawn(process.execPath, [BIN, ...args], { stdio: ['pipe', 'pipe', 'pipe'] });
    let stdout = '';
    let stderr = '';
    child.stdout.setEncoding('utf8').on('data', (d: string) => {
      stdout += d;
    });
    child.stderr.setEncoding('utf8').on('data', (d: string) => {
      stderr += d;
    });
    child.on('error', reject);
    child.on('close', (code) => resolve({ code, stdout, stderr }));
    child.stdin.on('error', () => {}); // the CLI may stop reading early (a usage error)
    child.stdin.end(stdin);
  });
}

/** What a pipe hands a reader at once (Linux: 64 KiB): stdin arrives in pieces of this size. */
const PIPE_BYTES = 1 << 16;

/**
 * Runs the command line's main() in this process (no process start-up: most tests), with the
 * streams a process has: stdin from `stdin` as bytes in pipe-sized pieces (so a multi-byte
 * character may fall across two), stdout and stderr gathered. The exit code is main()'s.
 */
export async function run(args: readonly string[], stdin = ''): Promise<RunResult> {
  const stdout = new PassThrough();
  const stderr = new PassThrough();
  const out = text(stdout);
  const err = text(stderr);
  const bytes = Buffer.from(stdin, 'utf8');
  const pieces: Buffer[] = [];
  for (let at = 0; at < bytes.length; at += PIPE_BYTES) pieces.push(bytes.subarray(at, at + PIPE_BYTES));
  const code = await main(args, { stdin: Readable.from(pieces), stdout, stderr });
  stdout.end();
  stderr.end();
  return { code, stdout: await out, stderr: await err };
}

/** The same as {@link run} (its earlier name). */
export const runMain = run;

/** A seeded generator of uniform numbers in [0, 1) (mulberry32, core/math/seededRandom.ts): the same seed, the same cases. */
export const random = seededRandom;

/** One item of a list, at random. */
export function pick<T>(rand: () => number, items: readonly T[]): T {
  return items[Math.floor(rand() * items.length)] as T;
}

/** A number log-uniform between lo and hi (both > 0). */
export function logUniform(rand: () => number, lo: number, hi: number): number {
  return lo * (hi / lo) ** rand();
}

/** Raw values of one case as the user types them (text). */
export interface RawCase {
  readonly R: string;
  readonly Rcr: string;
  readonly rho: string;
  readonly tilt: string;
  readonly pattern: string;
  readonly h: string;
}

/**
 * A tool and posture inside the valid domain, over its strata: R from 0.001 to 1000 mm; ball,
 * flat, tiny and ordinary corners; rho 0, subnormal, tiny, ordinary and near 90; tilt 0, tiny,
 * ordinary, near +-90.
 */
export function randomTool(rand: () => number): { R: number; Rcr: number; rho: number; tilt: number } {
  const R = logUniform(rand, 0.001, 1000);
  const Rcr = pick(rand, [0, R, R * rand(), R * logUniform(rand, 1e-15, 1e-3), R * (1 - 1e-9)]);
  const rho = pick(rand, [0, 1e-320, 5e-324, logUniform(rand, 1e-12, 1), 90 * rand(), 90 - logUniform(rand, 1e-9, 1)]);
  const tilt = pick(rand, [0, 0, (rand() - 0.5) * 180 * 0.999, (rand() < 0.5 ? -1 : 1) * logUniform(rand, 1e-12, 1)]);
  return { R, Rcr: Math.min(Rcr, R), rho: Math.min(rho, 89.999999), tilt };
}

/** A scallop height below `limit` over its strata (1e-9 mm up to just below the limit). */
export function randomHeight(rand: () => number, limit: number): number {
  const h = pick(rand, [1e-9, limit * rand(), limit * logUniform(rand, 1e-12, 1), limit * (1 - 1e-9)]);
  return Math.max(1e-9, h);
}

/** A number as the batch writes it: full precision, never NaN or Infinity. */
const CSV_NUMBER = /^-?(\d+\.?\d*|\.\d+)(e[-+]\d+)?$/;

/**
 * Checks the result fields of a batch row: each empty or a finite number in full precision; a row
 * with an `error` has none. Returns how many numbers it holds.
 */
export function checkResultFields(values: readonly string[], error: string, label: string): number {
  let numbers = 0;
  for (const v of values) {
    if (v === '') continue;
    numbers++;
    // Asserted only when wrong: an assertion per field cost more than the batch itself.
    if (!CSV_NUMBER.test(v) || !Number.isFinite(Number(v))) expect(v, label).toBe('a finite number in full precision');
  }
  if (error !== '') expect(numbers, `${label}: an error row has no values`).toBe(0);
  return numbers;
}
