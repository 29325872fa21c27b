/**
 * Benchmark of the three-axis solvers (issue 20): median time per call over repeated rounds.
 *
 *   npx tsx src/bench/threeAxis.ts                 readable table
 *   npx tsx src/bench/threeAxis.ts --json          the same, and a last line holding one JSON object
 *   npx tsx src/bench/threeAxis.ts --rounds 5      fewer rounds (quick smoke run)
 *
 * Keys: exact3AxisPlaneNsPerCall (sloped plane, validated forward: posture in closed form, limits,
 * both flanks; target 1500 ns), exact3AxisWaterlineNsPerCall (waterline on a surface of revolution,
 * validated forward with both gouging checks; target 50000 ns), and the 200-slope sweeps in ms
 * (target: within one 16 ms frame).
 */
import { pathToFileURL } from 'node:url';
import { type ForwardInput, forwardInput } from '../core/input/validate';
import { seededRandom } from '../core/math/seededRandom';
import { exactIntervalMm } from '../core/surfaces/solve';
import {
  type RevolutionCase,
  type SlopedPlaneCase,
  type SlopeSweepInput,
  slopedPlaneForward,
  slopedPlaneIntervalMm,
  slopeSweep,
  waterlineForward,
} from '../core/threeAxis/index';

/** mulberry32: the same inputs on every run. */
const random = seededRandom;

interface Timed<T> {
  readonly input: T;
  readonly h: number;
}

/** A validated answer's number, 0 for a refusal (the bench's cases are valid: it reads the number so none is optimised away). */
function answered<T>(
  r: { readonly ok: true; readonly value: T } | { readonly ok: false },
  pick: (value: T) => number,
): number {
  return r.ok ? pick(r.value) : 0;
}

/** Valid sloped-plane cases: R 0.5 to 12.5, any corner, slope 0 to 85, raster angle 0 to 90 or waterline. */
function planeCases(count: number): Timed<SlopedPlaneCase>[] {
  const rand = random(1);
  const out: Timed<SlopedPlaneCase>[] = [];
  while (out.length < count) {
    const R = 0.5 + 12 * rand();
    const input: SlopedPlaneCase = {
      toolRadiusMm: R,
      cornerRadiusMm: R * (0.05 + 0.95 * rand()),
      slopeDeg: 0.1 + 85 * rand(),
      passes: rand() < 0.25 ? 'waterline' : 'raster',
      rasterAngleDeg: 90 * rand(),
    };
    const probe = slopedPlaneForward(input, 1e-9);
    if (!probe.ok) continue;
    const h = Math.min(probe.value.heightLimitMm, input.cornerRadiusMm) * (0.001 + 0.5 * rand());
    if (slopedPlaneForward(input, h).ok) out.push({ input, h });
  }
  return out;
}

/** Valid waterline cases on domes, bowls, fillets and cones (radii 2 to 100 R). */
function revolutionCases(count: number): Timed<RevolutionCase>[] {
  const rand = random(2);
  const out: Timed<RevolutionCase>[] = [];
  while (out.length < count) {
    const R = 0.5 + 12 * rand();
    const radius = () => (rand() < 0.15 ? null : (rand() < 0.5 ? 1 : -1) * R * (2 + 98 * rand()));
    const input: RevolutionCase = {
      toolRadiusMm: R,
      cornerRadiusMm: R * (0.05 + 0.95 * rand()),
      slopeDeg: 1 + 84 * rand(),
      feedRadiusMm: radius(),
      crossRadiusMm: radius(),
    };
    const h = input.cornerRadiusMm * (0.001 + 0.05 * rand());
    if (waterlineForward(input, h).ok) out.push({ input, h });
  }
  return out;
}

let sink = 0;

/**
 * Median over `rounds` of the mean ns per call within one round of `perRound` calls: wall clock
 * and CPU time (process.cpuUsage, user + system). On a machine shared with other work the wall
 * clock counts the time slices given to others; the CPU time does not.
 */
function measure<T>(
  fn: (c: Timed<T>) => number,
  cases: Timed<T>[],
  perRound: number,
  rounds: number,
): { wall: number; cpu: number } {
  const wall: number[] = [];
  const cpu: number[] = [];
  for (let w = 0; w < Math.min(perRound, 2000); w++) sink += fn(cases[w % cases.length] as Timed<T>);
  for (let r = 0; r < rounds; r++) {
    const c0 = process.cpuUsage();
    const t0 = process.hrtime.bigint();
    for (let i = 0; i < perRound; i++) sink += fn(cases[i % cases.length] as Timed<T>);
    wall.push(Number(process.hrtime.bigint() - t0) / perRound);
    const c = process.cpuUsage(c0);
    cpu.push(((c.user + c.system) * 1000) / perRound);
  }
  return { wall: median(wall), cpu: median(cpu) };
}

function median(xs: number[]): number {
  xs.sort((x, y) => x - y);
  const mid = xs.length >> 1;
  return xs.length % 2 ? (xs[mid] as number) : ((xs[mid - 1] as number) + (xs[mid] as number)) / 2;
}

/** A figure: wall clock and CPU time. */
export type Figure = { wall: number; cpu: number };

/**
 * The three-axis figures (median of `rounds`): ns per call of the solvers (keys
 * exact3AxisPlaneNsPerCall, target 1.5 us; exact3AxisWaterlineNsPerCall, target 50 us...) and the
 * 200-slope sweeps in ms. Also run by `npm run bench`.
 */
export function threeAxisBench(
  rounds: number,
  /** Calls per round for a round of `n` (npm run bench: all `n`; its smoke mode a hundredth, solvers.ts). */
  calls: (n: number) => number = (n) => n,
): {
  rows: Array<[string, string, Figure]>;
  sweeps: Array<[string, string, Figure]>;
} {
  const plane = planeCases(1024);
  const revolution = revolutionCases(512);

  // The posture solver alone on the same postures (lead and tilt from the slope): the reference the
  // three-axis figures ride on, so that a loaded machine shows as a ratio.
  const postures: Timed<ForwardInput>[] = plane.map((c) => {
    const r = slopedPlaneForward(c.input, c.h);
    const tool = {
      toolRadiusMm: c.input.toolRadiusMm,
      cornerRadiusMm: c.input.cornerRadiusMm,
      leadAngleDeg: r.ok ? r.value.leadDeg : 0,
      tiltAngleDeg: r.ok ? r.value.tiltDeg : 0,
    };
    return { input: forwardInput(tool, 'one-way', c.h), h: c.h };
  });

  const rows: Array<[string, string, { wall: number; cpu: number }]> = [
    [
      'posture solver alone, same postures',
      'postureSolverSamePosturesNsPerCall',
      measure((c) => exactIntervalMm(c.input), postures, calls(100_000), rounds),
    ],
    [
      'sloped plane, validated forward',
      'exact3AxisPlaneNsPerCall',
      measure(
        (c) => answered(slopedPlaneForward(c.input, c.h), (v) => v.horizontalStepMm),
        plane,
        calls(100_000),
        rounds,
      ),
    ],
    [
      'sloped plane, L only (no validation)',
      'exact3AxisPlaneFastNsPerCall',
      measure((c) => slopedPlaneIntervalMm(c.input, c.h), plane, calls(100_000), rounds),
    ],
    [
      'waterline on a surface of revolution',
      'exact3AxisWaterlineNsPerCall',
      measure((c) => answered(waterlineForward(c.input, c.h), (v) => v.stepDownMm), revolution, calls(10_000), rounds),
    ],
  ];

  // The 200-slope sweeps, each call timed on its own (ms, wall and CPU).
  function sweepMs(make: () => number): { wall: number; cpu: number } {
    const wall: number[] = [];
    const cpu: number[] = [];
    for (let i = 0; i < calls(3); i++) sink += make();
    for (let r = 0; r < Math.max(calls(5), rounds); r++) {
      const c0 = process.cpuUsage();
      const t0 = process.hrtime.bigint();
      sink += make();
      wall.push(Number(process.hrtime.bigint() - t0) / 1e6);
      const c = process.cpuUsage(c0);
      cpu.push((c.user + c.system) / 1000);
    }
    return { wall: median(wall), cpu: median(cpu) };
  }
  const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, hMm: 0.05 } as const;
  const largest = (input: SlopeSweepInput): number => {
    const r = slopeSweep(input);
    return r.ok ? r.value.largestSlopeDeg : Number.NaN;
  };
  const sweeps: Array<[string, string, { wall: number; cpu: number }]> = [
    ['raster psi 30', 'sweep3AxisRasterMs', sweepMs(() => largest({ ...tool, passes: 'raster', rasterAngleDeg: 30 }))],
    [
      'waterline on the plane',
      'sweep3AxisWaterlinePlaneMs',
      sweepMs(() => largest({ ...tool, passes: 'waterline', rasterAngleDeg: 0 })),
    ],
    [
      'waterline on a dome R30',
      'sweep3AxisWaterlineDomeMs',
      sweepMs(() => largest({ ...tool, passes: 'waterline', rasterAngleDeg: 0, feedRadiusMm: 30, crossRadiusMm: 30 })),
    ],
  ];

  return { rows, sweeps };
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  const args = process.argv.slice(2);
  const json = args.includes('--json');
  const roundsArg = args.indexOf('--rounds');
  const rounds = roundsArg >= 0 ? Math.max(1, Number(args[roundsArg + 1]) || 1) : 21;
  const { rows, sweeps } = threeAxisBench(rounds);
  console.log(`Three-axis benchmark: median of ${rounds} rounds (1024 plane, 512 revolution inputs)`);
  console.log(`Node ${process.version}, ${process.platform}/${process.arch}`);
  console.log('');
  console.log(`${'solver'.padEnd(40)}${'ns per call'.padStart(14)}${'CPU ns'.padStart(12)}`);
  for (const [label, , v] of rows)
    console.log(`${label.padEnd(40)}${v.wall.toFixed(1).padStart(14)}${v.cpu.toFixed(1).padStart(12)}`);
  console.log(`${'sweep (200 slopes)'.padEnd(40)}${'ms'.padStart(14)}${'CPU ms'.padStart(12)}`);
  for (const [label, , v] of sweeps)
    console.log(`${label.padEnd(40)}${v.wall.toFixed(2).padStart(14)}${v.cpu.toFixed(2).padStart(12)}`);
  console.log(`(checksum ${sink.toExponential(3)})`);
  if (json) {
    const out: Record<string, number> = { rounds };
    for (const [, key, v] of [...rows, ...sweeps]) {
      out[key] = Number(v.wall.toFixed(2));
      out[`${key}Cpu`] = Number(v.cpu.toFixed(2));
    }
    console.log(JSON.stringify(out));
  }
}
