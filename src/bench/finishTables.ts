/**
 * Tables of the surface the teeth leave for the paper's two tools (R 3 Rcr 1 and R 6 Rcr 2, and a
 * ball end R 3 for the shop formula's own case; issue 29's closing figures): the shop formula hf ~ fz^2 / (8 R) against the exact feed-mark height at
 * leads 0, 5 and 15 degrees, and the balanced feed fz* against the step-over.
 *
 *   npx tsx src/bench/finishTables.ts
 */
import { balancedFeed, feedMarks } from '../core/finish/feedMarks';
import { toothModel } from '../core/finish/toothModel';

const TOOLS = [
  [3, 1],
  [6, 2],
  [3, 3],
] as const;
const FINISH = { flutes: 2, runoutMm: 0, runoutPhaseDeg: 0, passPhase: 0 };

/** The shop formula's error against the exact hf, in %. */
function shopTable(): string[] {
  const out = ['tool        lead  fz mm   exact hf um   fz^2/(8R) um   error %'];
  for (const [R, Rcr] of TOOLS)
    for (const lead of [0, 5, 15])
      for (const fz of [0.05, 0.1, 0.2]) {
        const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: lead, tiltAngleDeg: 0 };
        const hf = feedMarks(
          toothModel({ tool, pattern: 'one-way', intervalMm: 0.5, finish: { ...FINISH, feedPerToothMm: fz } }),
        ).heightMm;
        const shop = (fz * fz) / (8 * R);
        // Below 1 pm: the flat bottom (or a ball's tip) drags along the CC path, hf is 0.
        const pct = ((shop - hf) / hf) * 100;
        const err = hf > 1e-9 ? (Math.abs(pct) < 0.05 ? '0.0' : pct.toFixed(1)) : 'hf = 0: the end drags';
        out.push(
          `R ${R} Rcr ${Rcr}  ${String(lead).padStart(4)}  ${fz.toFixed(2)}    ${(hf * 1000).toFixed(4).padStart(10)}   ${(shop * 1000).toFixed(4).padStart(12)}   ${err}`,
        );
      }
  return out;
}

/** fz* (mm) against the step-over. */
function balancedTable(): string[] {
  const Ls = [0.1, 0.25, 0.5, 1, 2];
  const out = [`tool        lead  ${Ls.map((L) => `L ${L}`.padStart(9)).join(' ')}   (fz* mm; h um below)`];
  for (const [R, Rcr] of TOOLS)
    for (const lead of [0, 5, 15]) {
      const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: lead, tiltAngleDeg: 0 };
      const cells = Ls.map((L) => {
        const b = balancedFeed(tool, 'one-way', L, { ...FINISH, feedPerToothMm: 0.1 });
        return [
          b.ok ? b.feedPerToothMm.toFixed(4) : b.reason === 'no-scallop' ? 'no h' : 'none',
          (b.scallopHeightMm * 1000).toFixed(3),
        ];
      });
      out.push(
        `R ${R} Rcr ${Rcr}  ${String(lead).padStart(4)}  ${cells.map((c) => (c[0] as string).padStart(9)).join(' ')}`,
      );
      out.push(`                  ${cells.map((c) => (c[1] as string).padStart(9)).join(' ')}`);
    }
  return out;
}

console.log(['Feed marks: the shop formula against exact (2 teeth, one-way, L 0.5 mm)', ...shopTable()].join('\n'));
console.log(
  ['', 'Balanced feed fz* (hf = h) against the step-over L (mm), 2 teeth, one-way', ...balancedTable()].join('\n'),
);
