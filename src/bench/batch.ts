/**
 * The command line's `--batch` throughput (issue 27 point 8): rows per second of main() on a
 * 200,000-row CSV, in process, stdin in 64 kB chunks as a pipe hands them, stdout counted and
 * dropped; the median of a few runs. Two deterministic files:
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
import { Readable, Writable } from 'node:stream';
import { pathToFileURL } from 'node:url';
import { seededRandom } from '../build/reference/oracles/bruteForce';
import { main } from '../cli/main';

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

/** Seconds of one `--batch` run of main() on `text`; throws unless it exits 0 and writes. */
async function batchSeconds(text: string): Promise<number> {
  const chunks: string[] = [];
  for (let at = 0; at < text.length; at += 65_536) chunks.push(text.slice(at, at + 65_536));
  let bytes = 0;
  const drop = () =>
    new Writable({
      write(chunk: Buffer | string, _encoding, done) {
        bytes += chunk.length;
        done();
      },
    });
  const t0 = process.hrtime.bigint();
  const code = await main(['--batch'], { stdin: Readable.from(chunks), stdout: drop(), stderr: drop() });
  const seconds = Number(process.hrtime.bigint() - t0) / 1e9;
  if (code !== 0 || bytes === 0) throw new Error(`--batch failed in the benchmark (exit ${code})`);
  return seconds;
}

function median(xs: number[]): number {
  const s = [...xs].sort((x, y) => x - y);
  const mid = s.length >> 1;
  return s.length % 2 ? (s[mid] as number) : ((s[mid - 1] as number) + (s[mid] as number)) / 2;
}

/** The two figures, rows per second, each the median of `runs` runs (the files' runs interleaved). */
export async function batchBench(
  runs: number,
): Promise<{ batchRowsPerSecond: number; batchVariedRowsPerSecond: number }> {
  const plane = planeBatchCsv();
  const varied = variedBatchCsv();
  const planeRates: number[] = [];
  const variedRates: number[] = [];
  for (let r = 0; r < runs; r++) {
    planeRates.push(BATCH_ROWS / (await batchSeconds(plane)));
    variedRates.push(BATCH_ROWS / (await batchSeconds(varied)));
  }
  return { batchRowsPerSecond: median(planeRates), batchVariedRowsPerSecond: median(variedRates) };
}

if (process.argv[1] !== undefined && import.meta.url === pathToFileURL(process.argv[1]).href) {
  const args = process.argv.slice(2);
  const write = args.indexOf('--write');
  if (write >= 0) {
    process.stdout.write(args[write + 1] === 'varied' ? variedBatchCsv() : planeBatchCsv());
  } else {
    const runsArg = args.indexOf('--runs');
    const runs = runsArg >= 0 ? Math.max(1, Number(args[runsArg + 1]) || 1) : 3;
    const b = await batchBench(runs);
    console.log(
      `--batch, ${BATCH_ROWS} rows: plane ${b.batchRowsPerSecond.toFixed(0)} rows/s, varied ${b.batchVariedRowsPerSecond.toFixed(0)} rows/s (median of ${runs})`,
    );
  }
}
