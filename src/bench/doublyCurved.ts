/**
 * Benchmark of the doubly curved solver (issue 19): median time per exact forward call at a doubly
 * curved point, over repeated rounds of deterministic inputs (dome, bowl, saddle, sphere; ball,
 * flat and bull-nose ends; tilt from -40 to 40 degrees; both patterns), the same statistic as
 * src/bench/solvers.ts. Target: at most 30 us per call (issue 19, "Performance"). It times the
 * point's own solver with both radii curved, where the registry's model (models/doublyCurved.ts,
 * which the product asks) adds a check of the radii and a memo of the last point's solver.
 *
 *   npx tsx src/bench/doublyCurved.ts              readable lines
 *   npx tsx src/bench/doublyCurved.ts --json       and a last line holding one JSON object
 *   npx tsx src/bench/doublyCurved.ts --rounds 5   fewer rounds
 *   npx tsx src/bench/doublyCurved.ts --table      and the comparison table of issue 19 (the paper's
 *                                                   two tools, lead 10 degrees, h = 0.05 mm, one-way,
 *                                                   |Rf|, |Rc| in {10, 50, 200} mm, dome, bowl, saddle)
 */
import { pathToFileURL } from 'node:url';
import { seededRandom } from '../core/math/seededRandom';
import { compareDoublyCurved, type DoublyCurvedRow } from '../core/procedures/compareDoublyCurved';
import { doublyCurvedGouging } from '../core/surfaces/doublyCurved/gouging';
import {
  doublyCurvedForward,
  doublyCurvedLimits,
  doublyCurvedSolver,
  intervalWith,
} from '../core/surfaces/doublyCurved/solve';
import type { DoublyCurvedForwardInput } from '../core/surfaces/doublyCurved/types';

/** Deterministic inputs (mulberry32, seed 19): the radii 3 to 30 tool radii, both signs. */
function inputs(count: number): DoublyCurvedForwardInput[] {
  const rand = seededRandom(19);
  const out: DoublyCurvedForwardInput[] = [];
  while (out.length < count) {
    const R = 0.5 + 12 * rand();
    const kind = rand();
    const Rcr = kind < 0.2 ? R : kind < 0.35 ? 0 : R * (0.05 + 0.9 * rand());
    const tool = {
      toolRadiusMm: R,
      cornerRadiusMm: Rcr,
      leadAngleDeg: 3 + 40 * rand(),
      tiltAngleDeg: 80 * rand() - 40,
    };
    // Convex radii anywhere; concave ones wide enough not to gouge.
    const rf = (rand() < 0.5 ? 1 : -1) * R * (10 + 20 * rand());
    const rc = rand() < 0.15 ? rf : (rand() < 0.5 ? 1 : -1) * R * (10 + 20 * rand());
    const limit = doublyCurvedLimits({ ...tool, feedRadiusMm: rf, crossRadiusMm: rc }).limitMm;
    if (!(limit > 0)) continue;
    out.push({
      ...tool,
      pattern: rand() < 0.5 ? 'zigzag' : 'one-way',
      feedRadiusMm: rf,
      crossRadiusMm: rc,
      scallopHeightMm: limit * (0.001 + 0.5 * rand()),
    });
  }
  return out;
}

let sink = 0;

/** Median over `rounds` of the mean ns per call within one round of `perRound` calls. */
function measure(
  fn: (input: DoublyCurvedForwardInput) => number,
  cases: DoublyCurvedForwardInput[],
  perRound: number,
  rounds: number,
): number {
  for (let w = 0; w < Math.min(perRound, 500); w++) sink += fn(cases[w % cases.length] as DoublyCurvedForwardInput);
  const samples: number[] = [];
  for (let r = 0; r < rounds; r++) {
    const t0 = performance.now();
    for (let i = 0; i < perRound; i++) sink += fn(cases[(r * perRound + i) % cases.length] as DoublyCurvedForwardInput);
    samples.push(((performance.now() - t0) * 1e6) / perRound);
  }
  samples.sort((x, y) => x - y);
  return samples[Math.floor(samples.length / 2)] as number;
}

/**
 * The doubly curved figures (ns per call, median of `rounds`): the exact forward answer (key
 * exactDoublyCurvedNsPerCall, target 30 us) and the step-over alone. Also run by `npm run bench`.
 */
export function doublyCurvedBench(rounds: number): {
  exactDoublyCurvedNsPerCall: number;
  exactDoublyCurvedIntervalNsPerCall: number;
} {
  const cases = inputs(400);
  return {
    exactDoublyCurvedNsPerCall: measure((x) => doublyCurvedForward(x).intervalMm, cases, 400, rounds),
    exactDoublyCurvedIntervalNsPerCall: measure(
      (x) => intervalWith(doublyCurvedSolver(x, x), x.pattern, x.scallopHeightMm),
      cases,
      400,
      rounds,
    ),
  };
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  const args = process.argv.slice(2);
  const roundsAt = args.indexOf('--rounds');
  const rounds = roundsAt >= 0 ? Math.max(1, Number(args[roundsAt + 1]) || 15) : 15;
  const result = doublyCurvedBench(rounds);
  console.log(
    `exact forward at a doubly curved point: ${(result.exactDoublyCurvedNsPerCall / 1000).toFixed(2)} us per call (median of ${rounds} rounds)`,
  );
  console.log(
    `exact step-over alone:                   ${(result.exactDoublyCurvedIntervalNsPerCall / 1000).toFixed(2)} us per call`,
  );
  if (args.includes('--json')) console.log(JSON.stringify(result));
  if (args.includes('--table')) table();
}

/** Markdown table: each shortcut's deviation from the exact step-over and the scallop its L leaves. */
function table(): void {
  const cell = (r: DoublyCurvedRow) =>
    r.ok
      ? `${r.deviationPercent >= 0 ? '+' : ''}${r.deviationPercent.toFixed(2)} % (leaves ${r.realScallopMm === null ? 'a wall' : r.realScallopMm.toFixed(4)})`
      : 'n/a';
  console.log(
    '| tool | surface | Rf | Rc | exact L | plane | cylinder along (Rc) | cylinder across (Rf) | Redonnet corrected | Sekine corrected | osculating corrected |',
  );
  console.log('|---|---|---|---|---|---|---|---|---|---|---|');
  const tools: Array<[string, number, number]> = [
    ['R 3, Rcr 1', 3, 1],
    ['R 6, Rcr 2', 6, 2],
  ];
  const families: Array<[string, number, number]> = [
    ['dome', 1, 1],
    ['bowl', -1, -1],
    ['saddle', 1, -1],
  ];
  for (const [name, R, Rcr] of tools)
    for (const [family, sf, sc] of families)
      for (const f of [10, 50, 200])
        for (const c of [10, 50, 200]) {
          const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: 10, tiltAngleDeg: 0 };
          const radii = { feedRadiusMm: sf * f, crossRadiusMm: sc * c };
          const head = `| ${name} | ${family} | ${radii.feedRadiusMm} | ${radii.crossRadiusMm}`;
          const g = doublyCurvedGouging(tool, radii);
          if (g.gouges) {
            const what = (l: typeof g.feed, which: string) =>
              l.kind === 'concave-at-least'
                ? `|${which}| >= ${(l.radiusMm as number).toFixed(2)}`
                : l.kind === 'convex-at-most'
                  ? `${which} convex <= ${(l.radiusMm as number).toFixed(2)}`
                  : l.kind === 'none'
                    ? `no ${which} helps`
                    : `${which}: ${l.kind}`;
            console.log(`${head} | gouges (${what(g.feed, 'Rf')}; ${what(g.cross, 'Rc')}) | | | | | | |`);
            continue;
          }
          const r = compareDoublyCurved({ ...tool, ...radii, pattern: 'one-way', scallopHeightMm: 0.05 });
          console.log(
            `${head} | ${r.exact.intervalMm.toFixed(4)} | ${cell(r.plane)} | ${cell(r.cylinderAlong)} | ${cell(r.cylinderAcross)} | ${cell(r.corrected.redonnet)} | ${cell(r.corrected.sekine)} | ${cell(r.corrected.osculating)} |`,
          );
        }
}
if (sink === 42) console.log('');
