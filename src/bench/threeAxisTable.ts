/**
 * The closing note's table (issue 20): for the paper's two tools (src/core/procedures/paper.ts, Tables 2 and
 * 3: R 3 / Rcr 1 and R 6 / Rcr 2) at h 0.01 and 0.05 mm, the programmed steps at slopes 0 to 75
 * degrees on a sloped plane (raster Lxy at psi 0 and 90, waterline dz) and the scallop that the
 * flat floor's step really leaves at each (Lxy0 as Lxy for raster; typed as dz for waterline, and,
 * as a waterline step one would actually program, the dz that leaves h at 45 degrees).
 * Markdown on stdout.
 *
 *   npx tsx src/bench/threeAxisTable.ts
 */
import { PAPER_CONDITIONS } from '../core/procedures/paper';
import {
  flatFloorStepMm,
  type SlopedPlaneAnswer,
  type SlopedPlaneCase,
  slopedPlaneForward,
  slopedPlaneInverse,
  type ThreeAxisResult,
} from '../core/threeAxis/index';

const SLOPES = [0, 15, 30, 45, 60, 75];
const HEIGHTS = [0.01, 0.05];
const tools = [...new Map(PAPER_CONDITIONS.map((c) => [`${c.R}/${c.Rcr}`, { R: c.R, Rcr: c.Rcr }])).values()];

const fmt = (v: number) => v.toFixed(4);
/** A value, or why there is none (the error's code and limit). */
function cell(r: ThreeAxisResult<SlopedPlaneAnswer>, pick: (a: SlopedPlaneAnswer) => number | null): string {
  if (r.ok) {
    const v = pick(r.value);
    return v === null ? '-' : fmt(v);
  }
  const e = r.errors[0];
  if (!e) return '-';
  const words: Record<string, string> = {
    'shank-cuts': 'shank',
    'beyond-step': 'beyond',
    'needs-slope': 'no step',
    'flank-wall': 'wall',
    'wall-only': 'wall',
  };
  return `${words[e.code] ?? e.code}${e.limit === null || e.code === 'needs-slope' ? '' : ` (< ${fmt(e.limit)})`}`;
}

console.log(
  'Three-axis steps on a sloped plane for the paper\'s tools (mm). "shank (< x)": refused, the shank (the tool\'s side) would form the cusp; x is the limit in the quantity of that column (the step for a cusp column, h for a step column). "no step": waterline on a flat floor.',
);
for (const t of tools)
  for (const h of HEIGHTS) {
    const floor = flatFloorStepMm(t.R, t.Rcr, h);
    const at45 = slopedPlaneForward(
      { toolRadiusMm: t.R, cornerRadiusMm: t.Rcr, slopeDeg: 45, passes: 'waterline', rasterAngleDeg: 0 },
      h,
    );
    const dz45 = at45.ok ? (at45.value.stepDownMm as number) : Number.NaN;
    console.log('');
    console.log(`R = ${t.R}, Rcr = ${t.Rcr}, h = ${h}: flat floor step Lxy0 = ${fmt(floor)}`);
    console.log('');
    console.log(
      `| slope | Lxy, psi 0 | h left by Lxy0, psi 0 | Lxy, psi 90 | h left by Lxy0, psi 90 | dz, waterline | h left by dz = Lxy0 | h left by dz45 = ${fmt(dz45)} |`,
    );
    console.log('|---|---|---|---|---|---|---|---|');
    for (const a of SLOPES) {
      const c = (passes: 'raster' | 'waterline', psi: number): SlopedPlaneCase => ({
        toolRadiusMm: t.R,
        cornerRadiusMm: t.Rcr,
        slopeDeg: a,
        passes,
        rasterAngleDeg: psi,
      });
      const r0 = slopedPlaneForward(c('raster', 0), h);
      const i0 = slopedPlaneInverse(c('raster', 0), { field: 'horizontalStep', mm: floor });
      const r90 = slopedPlaneForward(c('raster', 90), h);
      const i90 = slopedPlaneInverse(c('raster', 90), { field: 'horizontalStep', mm: floor });
      const w = slopedPlaneForward(c('waterline', 0), h);
      const iw = slopedPlaneInverse(c('waterline', 0), { field: 'stepDown', mm: floor });
      const i45 = slopedPlaneInverse(c('waterline', 0), { field: 'stepDown', mm: dz45 });
      console.log(
        `| ${a} | ${cell(r0, (v) => v.horizontalStepMm)} | ${cell(i0, (v) => v.cuspHeightMm)} | ${cell(r90, (v) => v.horizontalStepMm)} | ${cell(i90, (v) => v.cuspHeightMm)} | ${cell(w, (v) => v.stepDownMm)} | ${cell(iw, (v) => v.cuspHeightMm)} | ${cell(i45, (v) => v.cuspHeightMm)} |`,
      );
    }
  }
