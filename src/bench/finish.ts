/**
 * Benchmark of the surface the teeth leave (issue 29, src/core/finish): medians over repeated rounds.
 *
 *   npx tsx src/bench/finish.ts                 readable table
 *   npx tsx src/bench/finish.ts --json          the same, and a last line holding one JSON object
 *   npx tsx src/bench/finish.ts --rounds 3      fewer rounds (quick smoke run)
 *
 * Keys (targets of issue 29): arealMapMs (the 256 x 256 map of one cell; target 200 ms),
 * feedMarkNsPerCall (hf along the CC path, model prepared each call; target 50,000 ns),
 * balancedFeedNsPerCall (fz*; target 1,000,000 ns), balancedFeedRunoutNsPerCall (fz* of the same four
 * cases with radial runout e 0.002-0.01 mm; target within 10 times balancedFeedNsPerCall), arealRunoutMs (the
 * areal parameters Sa ... Sku with runout, one of the same four cases a round, in turn). Each also as CPU time of this process
 * (`...CpuMs` / `...CpuNsPerCall`): the machine is shared, and wall time includes other load.
 * Inputs: the paper's tools R 3 Rcr 1 and R 6 Rcr 2, leads 5 and 15 degrees, tilt 0 and 10, both
 * patterns, 2 and 4 flutes, fz 0.05 to 0.2 mm, step-over 1 mm (seeded, the same every run).
 */
import { pathToFileURL } from 'node:url';
import type { PassPattern, ToolInput } from '../core/domain/tool';
import { arealParameters } from '../core/finish/areal';
import { arealMap } from '../core/finish/arealMap';
import { balancedFeed, feedMarks } from '../core/finish/feedMarks';
import type { FinishInput } from '../core/finish/finishInput';
import { toothModel } from '../core/finish/toothModel';
import { seededRandom } from '../core/math/seededRandom';

interface Case {
  readonly tool: ToolInput;
  readonly pattern: PassPattern;
  readonly intervalMm: number;
  readonly finish: FinishInput;
}

function cases(count: number): Case[] {
  const rand = seededRandom(29);
  const out: Case[] = [];
  for (let i = 0; i < count; i++) {
    const big = i % 2 === 1;
    out.push({
      tool: {
        toolRadiusMm: big ? 6 : 3,
        cornerRadiusMm: big ? 2 : 1,
        leadAngleDeg: i % 4 < 2 ? 5 : 15,
        tiltAngleDeg: i % 8 < 4 ? 0 : 10,
      },
      pattern: i % 3 === 0 ? 'zigzag' : 'one-way',
      intervalMm: 1,
      finish: {
        flutes: i % 2 === 0 ? 2 : 4,
        feedPerToothMm: 0.05 + 0.15 * rand(),
        runoutMm: 0,
        runoutPhaseDeg: 0,
        passPhase: 0,
      },
    });
  }
  return out;
}

function median(values: number[]): number {
  const s = [...values].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 === 1 ? (s[(n - 1) / 2] as number) : 0.5 * ((s[n / 2 - 1] as number) + (s[n / 2] as number));
}

/** Wall and CPU time (ms) of one run of f. */
function timed(f: () => void): [number, number] {
  const c = process.cpuUsage();
  const t = performance.now();
  f();
  const wall = performance.now() - t;
  const u = process.cpuUsage(c);
  return [wall, (u.user + u.system) / 1000];
}

/** Wall and CPU time (ms) of the balanced feed of each case; the feeds found are summed into `sink.value`. */
function timedBalanced(list: readonly Case[], sink: { value: number }): [number, number] {
  return timed(() => {
    for (const k of list) {
      const b = balancedFeed(k.tool, k.pattern, k.intervalMm, k.finish);
      sink.value += b.ok ? b.feedPerToothMm : 0;
    }
  });
}

/** The medians (see the module comment). */
export function finishBench(rounds: number): Record<string, number> {
  const list = cases(16);
  const map: number[] = [];
  const mapCpu: number[] = [];
  const marks: number[] = [];
  const marksCpu: number[] = [];
  const balanced: number[] = [];
  const balancedCpu: number[] = [];
  const balancedRunout: number[] = [];
  const balancedRunoutCpu: number[] = [];
  const arealRunout: number[] = [];
  const arealRunoutCpu: number[] = [];
  let sink = 0;
  const fed = { value: 0 };
  for (let r = 0; r < rounds; r++) {
    const c = list[r % list.length] as Case;
    const [w, u] = timed(() => {
      sink += arealMap(toothModel(c), 256, 256).heightsMm[0] as number;
    });
    map.push(w);
    mapCpu.push(u);
    const [w2, u2] = timed(() => {
      for (const k of list) sink += feedMarks(toothModel(k)).heightMm;
    });
    marks.push((w2 * 1e6) / list.length);
    marksCpu.push((u2 * 1e6) / list.length);
    const few = list.slice(0, 4);
    const [w3, u3] = timedBalanced(few, fed);
    balanced.push((w3 * 1e6) / few.length);
    balancedCpu.push((u3 * 1e6) / few.length);
    // The same four with radial runout (e 0.002 to 0.01 mm, phases 0 to 270 degrees).
    const withRunout = few.map((k, i) => ({
      ...k,
      finish: { ...k.finish, runoutMm: 0.002 * (1 + ((i * 3) % 5)), runoutPhaseDeg: 90 * i },
    }));
    const [w4, u4] = timedBalanced(withRunout, fed);
    balancedRunout.push((w4 * 1e6) / few.length);
    balancedRunoutCpu.push((u4 * 1e6) / few.length);
    const [w5, u5] = timed(() => {
      sink += arealParameters(toothModel(withRunout[r % withRunout.length] as Case)).saMm;
    });
    arealRunout.push(w5);
    arealRunoutCpu.push(u5);
  }
  if (!Number.isFinite(sink + fed.value)) throw new Error('non-finite result');
  return {
    arealMapMs: median(map),
    arealMapCpuMs: median(mapCpu),
    feedMarkNsPerCall: median(marks),
    feedMarkCpuNsPerCall: median(marksCpu),
    balancedFeedNsPerCall: median(balanced),
    balancedFeedCpuNsPerCall: median(balancedCpu),
    balancedFeedRunoutNsPerCall: median(balancedRunout),
    balancedFeedRunoutCpuNsPerCall: median(balancedRunoutCpu),
    arealRunoutMs: median(arealRunout),
    arealRunoutCpuMs: median(arealRunoutCpu),
  };
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  const args = process.argv.slice(2);
  const i = args.indexOf('--rounds');
  const rounds = i >= 0 ? Number(args[i + 1]) : 9;
  const result = finishBench(rounds);
  for (const [k, v] of Object.entries(result)) console.log(`${k.padEnd(28)} ${v.toFixed(k.endsWith('Ms') ? 1 : 0)}`);
  if (args.includes('--json')) console.log(JSON.stringify(result));
}
