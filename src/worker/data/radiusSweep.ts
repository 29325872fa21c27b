/**
 * The chart of L against each principal radius at a doubly curved point (issue 19): with the other
 * radius held, L (the registry's model: core surfaces/doublyCurvedPoint.ts) at |radius| on a log grid,
 * convex and concave, at the current posture and h. Where the tool gouges (the radius's limit with
 * the other held, core doublyCurvedRadiusLimit: admissible where 1/R >= its curvature limit) or h is
 * at or above the flank and shank limits, there is no L: those runs are the chart's gaps. Mm.
 */
import type { PassPattern, ToolInput } from '../../core/input/validate';
import {
  doublyCurvedRadiusLimit,
  MAX_PRINCIPAL_RADIUS_MM,
  MIN_PRINCIPAL_RADIUS_MM,
  type PrincipalRadii,
} from '../../core/surfaces/doublyCurved';
import { curvedForward, curvedLimits, curvedPoint } from '../../core/surfaces/doublyCurvedPoint';
import type { RadiusGap, RadiusGapReason, RadiusSweepData } from '../teachProtocol';

/** Samples per side (the current |radius| is added to them). */
export const RADIUS_SAMPLES = 72;

/**
 * The |radius| grid (mm, ascending, log-spaced): from a fifth of the tool radius (or half the
 * current |radius|) to 200 tool radii (or twice the current), within 0.001 mm to 1e6 mm, with the
 * current |radius| among the samples.
 */
export function radiusGridMm(toolRadiusMm: number, currentAbsMm: number, count = RADIUS_SAMPLES): number[] {
  const cur = Number.isFinite(currentAbsMm) ? currentAbsMm : 200 * toolRadiusMm;
  const lo = Math.max(MIN_PRINCIPAL_RADIUS_MM, Math.min(toolRadiusMm / 5, cur / 2));
  const hi = Math.min(MAX_PRINCIPAL_RADIUS_MM, Math.max(200 * toolRadiusMm, 2 * cur));
  const out: number[] = [];
  const a = Math.log(lo);
  const b = Math.log(hi);
  for (let i = 0; i < count; i++) out.push(Math.exp(a + ((b - a) * i) / (count - 1)));
  if (Number.isFinite(currentAbsMm) && !out.includes(currentAbsMm)) out.push(currentAbsMm);
  return out.sort((x, y) => x - y);
}

/** L (mm) at one point, or why there is none. */
function intervalAt(
  tool: ToolInput,
  radii: PrincipalRadii,
  pattern: PassPattern,
  hMm: number,
  admissible: boolean,
): number | RadiusGapReason {
  if (!admissible) return 'gouging';
  const point = curvedPoint(tool, radii, pattern);
  if (!(hMm < curvedLimits(point).limitMm)) return 'above-limit';
  const L = curvedForward(point, hMm).intervalMm;
  return Number.isFinite(L) && L > 0 ? L : 'above-limit';
}

/** The runs of missing values of one side as gaps (|radius| from the first to the last missing sample). */
function gapsOf(
  radiusMm: readonly number[],
  reasons: ReadonlyArray<RadiusGapReason | null>,
  side: RadiusGap['side'],
): RadiusGap[] {
  const out: RadiusGap[] = [];
  let run: { from: number; to: number; reason: RadiusGapReason } | null = null;
  radiusMm.forEach((r, i) => {
    const why = reasons[i] ?? null;
    if (run !== null && why === run.reason) run.to = r;
    else {
      if (run !== null) out.push({ side, fromMm: run.from, toMm: run.to, reason: run.reason });
      run = why === null ? null : { from: r, to: r, reason: why };
    }
  });
  const last = run as { from: number; to: number; reason: RadiusGapReason } | null;
  if (last !== null) out.push({ side, fromMm: last.from, toMm: last.to, reason: last.reason });
  return out;
}

/**
 * L against one radius, the other held (see the module comment).
 * @param tool validated tool and posture; @param radii the current signed radii (mm);
 * @param hMm scallop height (mm, radial), valid at the current point.
 */
export function radiusSweep(
  tool: ToolInput,
  radii: PrincipalRadii,
  pattern: PassPattern,
  hMm: number,
  which: 'feed' | 'cross',
): RadiusSweepData {
  const currentMm = which === 'feed' ? radii.feedRadiusMm : radii.crossRadiusMm;
  const heldMm = which === 'feed' ? radii.crossRadiusMm : radii.feedRadiusMm;
  const with_ = (r: number): PrincipalRadii =>
    which === 'feed' ? { feedRadiusMm: r, crossRadiusMm: heldMm } : { feedRadiusMm: heldMm, crossRadiusMm: r };
  // One search for this radius's gouging limit, the other held: admissible where 1/R >= kMin.
  const kMin = doublyCurvedRadiusLimit(tool, radii, which).minCurvaturePerMm;
  const admissible = (r: number) => (Number.isFinite(r) ? 1 / r : 0) >= kMin;
  const radiusMm = radiusGridMm(tool.toolRadiusMm, Math.abs(currentMm));
  const side = (sign: 1 | -1) => {
    const values: Array<number | null> = [];
    const reasons: Array<RadiusGapReason | null> = [];
    for (const r of radiusMm) {
      const v = intervalAt(tool, with_(sign * r), pattern, hMm, admissible(sign * r));
      values.push(typeof v === 'number' ? v : null);
      reasons.push(typeof v === 'number' ? null : v);
    }
    return { values, gaps: gapsOf(radiusMm, reasons, sign > 0 ? 'convex' : 'concave') };
  };
  const convex = side(1);
  const concave = side(-1);
  const straight = intervalAt(
    tool,
    with_(Number.POSITIVE_INFINITY),
    pattern,
    hMm,
    admissible(Number.POSITIVE_INFINITY),
  );
  const current = intervalAt(tool, radii, pattern, hMm, true);
  return {
    which,
    heldMm,
    radiusMm,
    convex: convex.values,
    concave: concave.values,
    gaps: [...convex.gaps, ...concave.gaps],
    straightMm: typeof straight === 'number' ? straight : null,
    currentMm,
    currentIntervalMm: typeof current === 'number' ? current : null,
  };
}
