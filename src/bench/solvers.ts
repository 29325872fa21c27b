/**
 * Benchmark of the solver core: median time per call over repeated rounds; and the command line's
 * `--batch` throughput on 200,000-row files (rows per second, as a process, src/bench/batch.ts);
 * the command line's start-up, one answer as a process (src/bench/cliStart.ts).
 *
 *   npm run bench                 readable table
 *   npm run bench -- --json       the same, and a last line holding one JSON object
 *   npm run bench -- --rounds 5   fewer rounds
 *   npm run bench -- --smoke      every figure at about a hundredth of the work (one round, a
 *                                 hundredth of the calls, 2,000-row batch files): proves each is
 *                                 printed and finite (tests/bench/solvers.test.ts); no measurement
 *
 * Also the three-axis and doubly curved solvers (threeAxis.ts, doublyCurved.ts) and the teaching
 * views' data (teachPage.ts: teachSlopeChartMsMedian, target 500 ms; teachCurvedMsMedian, 3000 ms).
 */
import {
  bediHalfInterval,
  exactIntervalMm,
  exactRoughness,
  type ForwardInput,
  forwardInput,
  maxRaMm,
  passGeometry,
  redonnetHalfInterval,
  scallopHeightForRaMm,
  scallopHeightLimits,
  sekineHalfInterval,
  simulatePasses,
  traceProcedure,
  validateForward,
} from '../core/index';
import { PASS_FIELDS } from '../core/input/fields';
import { rawOf } from '../core/input/raw';
import { seededRandom } from '../core/math/seededRandom';
import { BATCH_ROWS, batchBench } from './batch';
import { cliStartBench } from './cliStart';
import { doublyCurvedBench } from './doublyCurved';
import { teachPageBench } from './teachPage';
import { threeAxisBench } from './threeAxis';

/**
 * Deterministic inputs spread over the valid domain (mulberry32, seed 1); with `tilt`, tilts
 * from -60 to 60 degrees and both pass patterns.
 */
function inputs(count: number, tilt: boolean): ForwardInput[] {
  const rand = seededRandom(1);
  const out: ForwardInput[] = [];
  for (let i = 0; i < count; i++) {
    const R = 0.5 + 12 * rand();
    const Rcr = R * rand();
    const rho = 89 * rand();
    const tool = {
      toolRadiusMm: R,
      cornerRadiusMm: Rcr,
      leadAngleDeg: rho,
      tiltAngleDeg: tilt ? 120 * rand() - 60 : 0,
    };
    const limit = scallopHeightLimits(tool).limitMm;
    out.push(forwardInput(tool, tilt && rand() < 0.5 ? 'zigzag' : 'one-way', limit * (0.001 + 0.5 * rand())));
  }
  return out;
}

let sink = 0;

/** Median over `rounds` of the mean ns per call within one round of `perRound` calls. */
function measure(fn: (input: ForwardInput) => number, cases: ForwardInput[], perRound: number, rounds: number): number {
  const samples: number[] = [];
  for (let w = 0; w < Math.min(perRound, 2000); w++) sink += fn(cases[w % cases.length] as ForwardInput);
  for (let r = 0; r < rounds; r++) {
    const t0 = process.hrtime.bigint();
    for (let i = 0; i < perRound; i++) sink += fn(cases[i % cases.length] as ForwardInput);
    samples.push(Number(process.hrtime.bigint() - t0) / perRound);
  }
  samples.sort((x, y) => x - y);
  const mid = samples.length >> 1;
  return samples.length % 2 ? (samples[mid] as number) : ((samples[mid - 1] as number) + (samples[mid] as number)) / 2;
}

const args = process.argv.slice(2);
const json = args.includes('--json');
const smoke = args.includes('--smoke');
const roundsArg = args.indexOf('--rounds');
const rounds = smoke ? 1 : roundsArg >= 0 ? Math.max(1, Number(args[roundsArg + 1]) || 1) : 21;
/** Calls (or runs) for a figure that takes `n`: all of them, or a hundredth (at least one) in the smoke mode. */
const calls = (n: number): number => (smoke ? Math.max(1, Math.ceil(n / 100)) : n);
/** Rows of each `--batch` file: 200,000 (BATCH_ROWS), 2,000 in the smoke mode. */
const batchRows = smoke ? BATCH_ROWS / 100 : BATCH_ROWS;
const cases = inputs(1024, false);
const tilted = inputs(1024, true);
const half = (r: { ok: true; halfIntervalMm: number } | { ok: false }) => (r.ok ? r.halfIntervalMm : 0);

const rows: Array<[string, string, number]> = [
  ['exact L (no tilt)', 'exactNsPerCall', measure(exactIntervalMm, cases, calls(200_000), rounds)],
  ['exact L (tilt, both flanks)', 'exactTiltNsPerCall', measure(exactIntervalMm, tilted, calls(200_000), rounds)],
  [
    'exact with geometry (96 samples)',
    'exactWithGeometryNsPerCall',
    measure((c) => passGeometry(c, c.scallopHeightMm, c.scallopHeightMm).right.pHp[1], cases, calls(2_000), rounds),
  ],
  ['Sekine et al.', 'sekineNsPerCall', measure((c) => half(sekineHalfInterval(c)), cases, calls(500_000), rounds)],
  [
    'Redonnet et al.',
    'redonnetNsPerCall',
    measure((c) => half(redonnetHalfInterval(c)), cases, calls(500_000), rounds),
  ],
  ['Bedi et al.', 'bediNsPerCall', measure((c) => half(bediHalfInterval(c)), cases, calls(500_000), rounds)],
  [
    'trace of the 3D procedure',
    'traceNsPerCall',
    measure((c) => traceProcedure(c).right.widthMm, cases, calls(500), rounds),
  ],
];

// Cylinders: convex and concave (|Rs| 10 to 100 R), the axis along or across the feed.
function onCylinders(source: ForwardInput[], axis: 'feed' | 'cross'): ForwardInput[] {
  const out: ForwardInput[] = [];
  source.forEach((c, i) => {
    const rs = (i % 2 === 0 ? 1 : -1) * c.toolRadiusMm * (10 + (i % 90));
    const surface = { kind: 'cylinder' as const, radiusMm: rs, axis };
    const v = validateForward(rawOf({ ...c, surface }, [...PASS_FIELDS, 'h']));
    if (v.ok) out.push(v.value);
  });
  return out;
}
const feedCases = onCylinders(tilted, 'feed');
const crossCases = onCylinders(tilted, 'cross');
rows.push(
  [
    'exact L on a cylinder, axis along the feed',
    'exactCylinderFeedNsPerCall',
    measure(exactIntervalMm, feedCases, calls(20_000), rounds),
  ],
  [
    'exact L on a cylinder, axis across the feed',
    'exactCylinderCrossNsPerCall',
    measure(exactIntervalMm, crossCases, calls(5_000), rounds),
  ],
);

// Exact roughness and the Ra solve: fewer calls (each integrates both flanks).
const fewer = cases.slice(0, 64);
rows.push(
  [
    'exact roughness (Rz, Ra, Rq)',
    'roughnessNsPerCall',
    measure((c) => exactRoughness(c).raMm, fewer, calls(200), rounds),
  ],
  [
    'step-over for a target Ra',
    'targetRaNsPerCall',
    measure((c) => scallopHeightForRaMm(c, c.pattern, 0.3 * maxRaMm(c, c.pattern)), fewer, calls(20), rounds),
  ],
);

// A target Ra across a cylinder's axis, as the page asks it: the largest Ra (validation) and the
// scallop height for 30 % of it, wall clock per case (ms), median over cases and rounds. Issue 19:
// at most 50 ms (it took 2.4 to 3 s).
const raCrossMs: number[] = [];
for (let r = 0; r < Math.max(calls(3), Math.min(rounds, 7)); r++) {
  for (const c of crossCases.slice(0, calls(16))) {
    const t0 = process.hrtime.bigint();
    const max = maxRaMm(c, c.pattern, c.surface);
    sink += scallopHeightForRaMm(c, c.pattern, 0.3 * max, c.surface);
    raCrossMs.push(Number(process.hrtime.bigint() - t0) / 1e6);
  }
}
raCrossMs.sort((x, y) => x - y);
const targetRaCylinderCrossMsMedian = raCrossMs[raCrossMs.length >> 1] as number;
const targetRaCylinderCrossMsMax = raCrossMs.at(-1) as number;

// Issue 19 and 20: the doubly curved point and three-axis machining (src/bench/doublyCurved.ts, threeAxis.ts).
const doubly = doublyCurvedBench(Math.max(calls(3), Math.min(rounds, 15)));
rows.push(
  ['exact at a doubly curved point', 'exactDoublyCurvedNsPerCall', doubly.exactDoublyCurvedNsPerCall],
  ['  its step-over alone', 'exactDoublyCurvedIntervalNsPerCall', doubly.exactDoublyCurvedIntervalNsPerCall],
);
const three = threeAxisBench(rounds, calls);
for (const [label, key, v] of three.rows) rows.push([`three-axis: ${label}`, key, v.wall]);

// The teaching views' data (src/bench/teachPage.ts): the slope chart and the doubly curved views, ms per call.
const teach = teachPageBench(Math.max(calls(3), Math.min(rounds, 11)));

// The page's default simulation: 512 x 512 cells, 5 one-way passes, the paper's Tool 1 at h = 0.05 mm.
const simTool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const simInterval = exactIntervalMm(forwardInput(simTool, 'one-way', 0.05));
const simMs: number[] = [];
let simCells = 0;
for (let r = 0; r < Math.max(calls(5), rounds); r++) {
  const t0 = process.hrtime.bigint();
  const sim = simulatePasses({ tool: simTool, pattern: 'one-way', intervalMm: simInterval });
  simMs.push(Number(process.hrtime.bigint() - t0) / 1e6);
  simCells = sim.cells;
  sink += sim.cuspHeightMm;
}
simMs.sort((x, y) => x - y);
const simulationMsMedian = simMs[simMs.length >> 1] as number;

// `--batch` on the 200,000-row files (src/bench/batch.ts): median of a few runs, rows per second.
const batchRuns = Math.min(rounds, 3);
const { batchRowsPerSecond, batchVariedRowsPerSecond } = batchBench(batchRuns, batchRows);

const start = cliStartBench(Math.min(rounds, 11));

console.log(
  `Solver benchmark${smoke ? ' (smoke: a hundredth of the work, no measurement)' : ''}: median of ${rounds} rounds, ${cases.length} inputs spread over the valid domain`,
);
console.log(`Node ${process.version}, ${process.platform}/${process.arch}`);
console.log('');
console.log(`${'solver'.padEnd(36)}${'ns per call'.padStart(14)}`);
for (const [label, , ns] of rows) console.log(`${label.padEnd(36)}${ns.toFixed(1).padStart(14)}`);
console.log(
  `${'simulation 512 x 512, 5 passes (ms)'.padEnd(36)}${simulationMsMedian.toFixed(1).padStart(14)}   ${((simCells / simulationMsMedian) * 1000).toExponential(2)} cells/s`,
);
console.log(
  `${'--batch, plane rows (rows/s)'.padEnd(36)}${batchRowsPerSecond.toFixed(0).padStart(14)}   ${batchRows} rows, median of ${batchRuns} runs`,
);
console.log(
  `${'--batch, varied plane rows (rows/s)'.padEnd(36)}${batchVariedRowsPerSecond.toFixed(0).padStart(14)}   a new tool on every row`,
);
console.log(
  `${'command line, one answer (ms)'.padEnd(36)}${start.cliStartMs.toFixed(1).padStart(14)}   process start to exit; node -e 0: ${start.nodeStartMs.toFixed(1)} ms`,
);
console.log(
  `${'target Ra across a cylinder (ms)'.padEnd(36)}${targetRaCylinderCrossMsMedian.toFixed(1).padStart(14)}   median; slowest ${targetRaCylinderCrossMsMax.toFixed(1)} ms (maxRa and the solve)`,
);
for (const [label, , v] of three.sweeps) {
  console.log(`${`three-axis sweep, ${label} (ms)`.padEnd(36)}${v.wall.toFixed(2).padStart(14)}`);
}
for (const [label, , ms] of teach) console.log(`${`teach: ${label} (ms)`.padEnd(36)}${ms.toFixed(1).padStart(14)}`);
console.log(`(checksum ${sink.toExponential(3)})`);
if (json) {
  const out: Record<string, number> = { rounds };
  for (const [, key, ns] of rows) out[key] = Number(ns.toFixed(1));
  out.simulationMsMedian = Number(simulationMsMedian.toFixed(1));
  out.simulationCellsPerSecond = Math.round((simCells / simulationMsMedian) * 1000);
  out.batchRowsPerSecond = Math.round(batchRowsPerSecond);
  out.batchVariedRowsPerSecond = Math.round(batchVariedRowsPerSecond);
  out.cliStartMs = Number(start.cliStartMs.toFixed(1));
  out.nodeStartMs = Number(start.nodeStartMs.toFixed(1));
  out.targetRaCylinderCrossMsMedian = Number(targetRaCylinderCrossMsMedian.toFixed(2));
  out.targetRaCylinderCrossMsMax = Number(targetRaCylinderCrossMsMax.toFixed(2));
  for (const [, key, v] of three.sweeps) out[key] = Number(v.wall.toFixed(2));
  for (const [, key, ms] of teach) out[key] = Number(ms.toFixed(2));
  console.log(JSON.stringify(out));
}
