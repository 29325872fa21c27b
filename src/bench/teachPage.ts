/**
 * Benchmark of the teaching views' data for three-axis machining and a doubly curved point
 * (src/worker/jobs/teachPage.ts): wall time per call, median over rounds, for the two questions
 * tests/worker/teachPage.test.ts checks (the test checks the numbers; the time is measured here,
 * where load on the machine cannot fail a test). Targets: the slope chart (200 slopes) within
 * 500 ms, the doubly curved views (two radius sweeps and the section) within 3000 ms.
 *
 *   npx tsx src/bench/teachPage.ts                 readable lines
 *   npx tsx src/bench/teachPage.ts --json          and a last line holding one JSON object
 *   npx tsx src/bench/teachPage.ts --rounds 5      fewer rounds
 *
 * `npm run bench` prints the same figures (keys teachSlopeChartMsMedian, teachCurvedMsMedian).
 */
import { pathToFileURL } from 'node:url';
import { buildRequest } from '../ui/request';
import { parseUrl } from '../ui/state';
import { teachCurved, teachThreeAxis } from '../worker/jobs/teachPage';
import type { CurvedRequest, PageRequest, ThreeAxisRequest } from '../worker/pageProtocol';

/** The page's links the figures are for (those of tests/worker/teachPage.test.ts). */
export const TEACH_BENCH_LINKS = {
  slopeChart: '?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=40&h=0.01&unit=mm',
  curved: '?R=3&Rcr=1&rho=10&tilt=0&h=0.05&feedRadius=40&crossRadius=-20&unit=mm',
} as const;

/** The page's request for a link, from the page's one builder (it must be valid). */
function requestOf(link: string): PageRequest {
  const built = buildRequest(parseUrl(link).state);
  if (!built.ok) throw new Error(`the benchmark's link is invalid: ${link}`);
  return built.request;
}

/** Median wall time in ms of `rounds` calls of `fn` (after one call that warms it up); throws if a call fails. */
function medianMs(fn: () => boolean, rounds: number): number {
  if (!fn()) throw new Error('the teaching data was refused');
  const samples: number[] = [];
  for (let r = 0; r < rounds; r++) {
    const t0 = process.hrtime.bigint();
    const ok = fn();
    samples.push(Number(process.hrtime.bigint() - t0) / 1e6);
    if (!ok) throw new Error('the teaching data was refused');
  }
  samples.sort((x, y) => x - y);
  const mid = samples.length >> 1;
  return samples.length % 2 ? (samples[mid] as number) : ((samples[mid - 1] as number) + (samples[mid] as number)) / 2;
}

/** The teaching views' figures (ms, median of `rounds`), with the labels and JSON keys `npm run bench` prints. */
export function teachPageBench(rounds: number): Array<[label: string, key: string, ms: number]> {
  const slope = requestOf(TEACH_BENCH_LINKS.slopeChart) as ThreeAxisRequest;
  const curved = requestOf(TEACH_BENCH_LINKS.curved) as CurvedRequest;
  return [
    [
      'slope chart, 200 slopes (three-axis)',
      'teachSlopeChartMsMedian',
      medianMs(() => teachThreeAxis(slope).ok, rounds),
    ],
    ['doubly curved: 2 radius sweeps, section', 'teachCurvedMsMedian', medianMs(() => teachCurved(curved).ok, rounds)],
  ];
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  const args = process.argv.slice(2);
  const roundsArg = args.indexOf('--rounds');
  const rounds = roundsArg >= 0 ? Math.max(1, Number(args[roundsArg + 1]) || 1) : 11;
  const rows = teachPageBench(rounds);
  console.log(`Teaching views' data: median of ${rounds} rounds (ms per call)`);
  for (const [label, , ms] of rows) console.log(`${label.padEnd(44)}${ms.toFixed(1).padStart(10)}`);
  if (args.includes('--json')) console.log(JSON.stringify(Object.fromEntries(rows.map(([, k, ms]) => [k, ms]))));
}
