/**
 * The command line's `--batch` throughput (issue 27 point 8): rows per second of the command line
 * as a process (src/cli/bin.mjs, the compiled one) on a 200,000-row CSV file on stdin, stdout to
 * /dev/null, spawn to exit; the median of a few runs. A process of its own, as a user runs it (in
 * the benchmark's process, after the solvers' rounds, the same code measured 2 to 3 times slower).
 * Two deterministic files:
 *
 * - the plane rows (`batchRowsPerSecond`, target 150,000): R 3 and Rcr 1 mm, lead 0 to 59
 *   degrees, h 0.010 to 0.059 mm, the header in another column order (h,rho,Rcr,R);
 * - varied plane rows (`batchVariedRowsPerSecond`): a new tool on every row (mulberry32, seed 1:
 *   R 0.5 to 12.5 mm, any corner, lead 0 to 89 degrees, h up to half the height limit), so no
 *   figure rests on tools that repeat.
 *
 *   npx tsx src/bench/batch.ts [--runs N]              the two figures
 *   npx tsx src/bench/batch.ts --write plane|varied    the file on stdout (for a run as a process)
 */
import { spawnSync } from 'node:child_process';
import { closeSync, mkdtempSync, openSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { seededRandom } from '../core/math/seededRandom';

/** Rows of each benchmark file. */
export const BATCH_ROWS = 200_000;

/** The plane rows: the same tool, 60 leads and 50 heights in turn. */
export function planeBatchCsv(rows: number = BATCH_ROWS): string {
  const lines = ['h,rho,Rcr,R'];
  for (let i = 0; i < rows; i++) lines.push(`${(0.01 + (i % 50) * 0.001).toFixed(3)},${i % 60},1,3`);
  return `${lines.join('\n')}\n`;
}

/** Varied plane rows: a new tool and height on every row, each number in full precision. */
export function variedBatchCsv(rows: number = BATCH_ROWS): string {
  const rand = seededRandom(1);
  const lines = ['R,Rcr,rho,h'];
  for (let i = 0; i < rows; i++) {
    const R = 0.5 + 12 * rand();
    const Rcr = R * rand();
    const rho = 89 * rand();
    // Below (R - Rcr) sin(rho) + Rcr, the height limit without tilt.
    const limit = (R - Rcr) * Math.sin((rho * Math.PI) / 180) + Rcr;
    lines.push(`${R},${Rcr},${rho},${limit * (0.001 + 0.5 * rand())}`);
  }
  return `${lines.join('\n')}\n`;
}

/** The command line as a user runs it (bin.mjs: the compiled one, rebuilt first when stale). */
const BIN = fileURLToPath(new URL('../cli/bin.mjs', import.meta.url));

/**
 * Wall seconds of one `--batch` process on the file `path` (stdin from the file, stdout to
 * /dev/null), from spawn to exit; throws unless it exits 0.
 */
function batchSeconds(path: string): number {
  const input = openSync(path, 'r');
  const output = openSync('/dev/null', 'w');
  try {
    const t0 = process.hrtime.bigint();
    const r = spawnSync(process.execPath, [BIN, '--batch'], { stdio: [input, output, 'pipe'], encoding: 'utf8' });
    const seconds = Number(process.hrtime.bigint() - t0) / 1e9;
    if (r.status !== 0) throw new Error(`--batch failed in the benchmark (exit ${r.status}): ${r.stderr}`);
    return seconds;
  } finally {
    closeSync(input);
    closeSync(output);
  }
}

function median(xs: number[]): number {
  const s = [...xs].sort((x, y) => x - y);
  const mid = s.length >> 1;
  return s.length % 2 ? (s[mid] as number) : ((s[mid - 1] as number) + (s[mid] as number)) / 2;
}

/**
 * The two figures, rows per second of the command line as a process (start-up included, as a
 * user times it), each the median of `runs` runs, the files' runs interleaved (after a warm-up run
 * that builds the compiled command line if it is stale).
 */
export function batchBench(
  runs: number,
  /** Rows of each file (npm run bench's smoke mode: fewer, solvers.ts). */
  rows: number = BATCH_ROWS,
): { batchRowsPerSecond: number; batchVariedRowsPerSecond: number } {
  const dir = mkdtempSync(join(tmpdir(), 'path-interval-batch-'));
  try {
    const plane = join(dir, 'plane.csv');
    const varied = join(dir, 'varied.csv');
    writeFileSync(plane, planeBatchCsv(rows));
    writeFileSync(varied, variedBatchCsv(rows));
    writeFileSync(join(dir, 'warm.csv'), planeBatchCsv(10));
    batchSeconds(join(dir, 'warm.csv'));
    const planeRates: number[] = [];
    const variedRates: number[] = [];
    for (let r = 0; r < runs; r++) {
      planeRates.push(rows / batchSeconds(plane));
      variedRates.push(rows / batchSeconds(varied));
    }
    return { batchRowsPerSecond: median(planeRates), batchVariedRowsPerSecond: median(variedRates) };
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

if (process.argv[1] !== undefined && import.meta.url === pathToFileURL(process.argv[1]).href) {
  const args = process.argv.slice(2);
  const write = args.indexOf('--write');
  if (write >= 0) {
    process.stdout.write(args[write + 1] === 'varied' ? variedBatchCsv() : planeBatchCsv());
  } else {
    const runsArg = args.indexOf('--runs');
    const runs = runsArg >= 0 ? Math.max(1, Number(args[runsArg + 1]) || 1) : 3;
    const b = batchBench(runs);
    console.log(
      `--batch, ${BATCH_ROWS} rows: plane ${b.batchRowsPerSecond.toFixed(0)} rows/s, varied ${b.batchVariedRowsPerSecond.toFixed(0)} rows/s (median of ${runs})`,
    );
  }
}
