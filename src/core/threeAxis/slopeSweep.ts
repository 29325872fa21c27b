/**
 * The slope sweep (issue 20): for a tool, a scallop height and a pass strategy, the programmed
 * step (`Lxy` for raster, `dz` for waterline) against the slope from 0 to the largest valid one,
 * and the scallop that one constant programmed step really leaves at each slope: the picture a
 * CAM programmer needs before choosing between raster and waterline for a steep area.
 *
 * - Raster: the sloped plane at the raster angle psi (slopedPlane.ts).
 * - Waterline: the sloped plane (the default), or a surface of revolution whose radii Rf and Rc
 *   are held at every slope (exact for a sphere, Rf = Rc; a local model otherwise).
 * - h is valid at a slope where the single question (`--slope`) is answered there: below the
 *   slope's limit (the shank's, or a flank's, or the end of the surface) and, on a surface of
 *   revolution, without gouging. The largest valid slope is found by a scan in 0.5 degree steps
 *   and bisection; just below 90 degrees (open: a vertical wall leaves no scallop) when h never
 *   reaches a limit, 90 itself where the meridian is concave and h is valid there. Slopes
 *   `largest k / (count - 1)`, the last one a hair inside (`1e-9` relative) below 90.
 * - No valid slope is an input error, as the single question's: the gouging error when the tool
 *   gouges at every slope (naming the radius that must grow for it to fit at some slope, or "only
 *   a straight one"), else h's, with the largest limit over the slopes.
 * - The constant step: given, or by default the flat floor's step-over for h,
 *   `Lxy0 = 2 (R - Rcr + sqrt(2 Rcr h - h^2))` (2R for a flat end), used as `Lxy` (raster) or, for
 *   waterline, typed as the step-down `dz` (a common practice to compare; on a flat floor a
 *   step-down means nothing, so the waterline sweep has no step and no cusp at slope 0).
 */
import { bisect } from '../math/rootFinder';
import { flankLimits, postureShape } from '../tool/posture';
import {
  checkHeight,
  checkStep,
  formatNumber,
  MIN_THREE_AXIS_LENGTH_MM,
  type ThreeAxisError,
  type ThreeAxisErrorCode,
  type ThreeAxisResult,
  threeAxisError,
} from './errors';
import { type SlopedPlaneCase, slopedPlaneForward, slopedPlaneInverse, type ThreeAxisPasses } from './slopedPlane';
import { slopePosture } from './slopePosture';
import { checkCase, gougingError } from './waterlineErrors';
import { type RevolutionCase, waterlineForward, waterlineHeightLimitMm, waterlineInverse } from './waterlineRevolution';
import { forwardCore, setupOf } from './waterlineSolve';

/** Input of the slope sweep (mm, degrees). */
export interface SlopeSweepInput {
  /** Tool radius R, mm, and corner radius Rcr, mm (0 <= Rcr <= R). */
  readonly toolRadiusMm: number;
  readonly cornerRadiusMm: number;
  /** Scallop height h, mm (at least 1e-9). */
  readonly hMm: number;
  readonly passes: ThreeAxisPasses;
  /** Raster angle psi from the fall line, degrees, 0 to 90 (raster only). */
  readonly rasterAngleDeg: number;
  /** Waterline only: the surface of revolution's signed radii, mm (null: straight); default a plane. */
  readonly feedRadiusMm?: number | null;
  readonly crossRadiusMm?: number | null;
  /** The constant programmed step (Lxy or dz), mm; default the flat floor's step-over for h. */
  readonly programmedStepMm?: number;
  /** Number of slopes, default 200 (at least 2). */
  readonly count?: number;
}

/** One slope of the sweep. */
export interface SlopeSweepPoint {
  readonly slopeDeg: number;
  /** The programmed step that leaves h at this slope (Lxy or dz), mm; null where refused. */
  readonly stepMm: number | null;
  /** L along the surface for h, mm; null where refused. */
  readonly intervalMm: number | null;
  /** The equivalent posture at the CC point, degrees. */
  readonly leadDeg: number;
  readonly tiltDeg: number;
  /** The largest scallop height at this slope (shank, flank or surface limit), mm. */
  readonly heightLimitMm: number;
  /** The cusp the constant programmed step leaves here, mm; null where that step is refused. */
  readonly cuspAtProgrammedStepMm: number | null;
  /** Why the constant step has no cusp here (shank, wall, beyond the surface...), or null. */
  readonly programmedStepRefusal: ThreeAxisErrorCode | null;
}

/** The sweep. */
export interface SlopeSweep {
  readonly points: readonly SlopeSweepPoint[];
  /** The largest slope at which h is valid, degrees (90 when h never reaches a limit below it). */
  readonly largestSlopeDeg: number;
  /** The flat floor's step-over for h (Lxy0), mm. */
  readonly flatFloorStepMm: number;
  /** The constant programmed step used, mm (Lxy for raster, dz for waterline). */
  readonly programmedStepMm: number;
}

/** The flat floor's step-over (mm) for h: `2 (R - Rcr + sqrt(2 Rcr h - h^2))`, 2R for a flat end or h >= Rcr. */
export function flatFloorStepMm(toolRadiusMm: number, cornerRadiusMm: number, hMm: number): number {
  const rb = toolRadiusMm - cornerRadiusMm;
  if (cornerRadiusMm === 0 || hMm >= cornerRadiusMm) return 2 * toolRadiusMm;
  return 2 * (rb + Math.sqrt(hMm * (2 * cornerRadiusMm - hMm)));
}

/** True for waterline on a surface of revolution (a radius given), false for the plane. */
function onRevolution(input: SlopeSweepInput): boolean {
  return (
    input.passes === 'waterline' && ((input.feedRadiusMm ?? null) !== null || (input.crossRadiusMm ?? null) !== null)
  );
}

/** The sweep's surface of revolution at a slope (degrees). */
function revolutionCase(input: SlopeSweepInput, slopeDeg: number): RevolutionCase {
  return {
    toolRadiusMm: input.toolRadiusMm,
    cornerRadiusMm: input.cornerRadiusMm,
    slopeDeg,
    feedRadiusMm: input.feedRadiusMm ?? null,
    crossRadiusMm: input.crossRadiusMm ?? null,
  };
}

/** The sweep's sloped plane at a slope (degrees). */
function planeCase(input: SlopeSweepInput, slopeDeg: number): SlopedPlaneCase {
  return {
    toolRadiusMm: input.toolRadiusMm,
    cornerRadiusMm: input.cornerRadiusMm,
    slopeDeg,
    passes: input.passes,
    rasterAngleDeg: input.rasterAngleDeg,
  };
}

/** What h meets at one slope: an answer, gouging (a surface of revolution only), or a limit (or a refused slope). */
type SlopeVerdict = 'ok' | 'gouge' | 'limit';

/** The single question's verdict on h at a slope (without wording its error: the scan asks it often). */
function verdictAt(input: SlopeSweepInput, slopeDeg: number): SlopeVerdict {
  if (onRevolution(input)) {
    const c = revolutionCase(input, slopeDeg);
    if (checkCase(c).length > 0) return 'limit';
    const kind = forwardCore(setupOf(c), input.hMm).kind;
    return kind === 'ok' ? 'ok' : kind === 'gouge' ? 'gouge' : 'limit';
  }
  return slopeDeg < 90 && input.hMm < heightLimitAt(input, slopeDeg) ? 'ok' : 'limit';
}

/** The scan's slopes (degrees): 0.5 apart below 90 (from 0.5 for waterline), and 90 on a concave meridian. */
function scanSlopes(input: SlopeSweepInput): number[] {
  const out: number[] = [];
  for (let a = input.passes === 'waterline' ? 0.5 : 0; a < 90; a += 0.5) out.push(a);
  if (onRevolution(input) && (input.crossRadiusMm ?? 0) < 0) out.push(90);
  return out;
}

/** The verdicts over the scan's slopes. */
function scan(input: SlopeSweepInput): Array<{ readonly slopeDeg: number; readonly verdict: SlopeVerdict }> {
  return scanSlopes(input).map((slopeDeg) => ({ slopeDeg, verdict: verdictAt(input, slopeDeg) }));
}

/** The height limit (mm) at a slope, for the sweep's strategy (Infinity: none, a flat end on a flat floor). */
function heightLimitAt(input: SlopeSweepInput, slopeDeg: number): number {
  if (onRevolution(input)) return revolutionLimit(input, slopeDeg);
  const p = slopePosture(slopeDeg, input.passes === 'waterline' ? 90 : input.rasterAngleDeg);
  const s = postureShape(input.toolRadiusMm, input.cornerRadiusMm, p.leadRad, p.tiltRad);
  if (s.flatOnPlane && s.rcr === 0) return Number.POSITIVE_INFINITY;
  return flankLimits(s).limitMm;
}

function revolutionLimit(input: SlopeSweepInput, slopeDeg: number): number {
  if (slopeDeg === 0) return Number.POSITIVE_INFINITY;
  return waterlineHeightLimitMm(revolutionCase(input, slopeDeg));
}

/**
 * The largest slope (degrees) at which h is valid (the single question answered, {@link verdictAt}):
 * 90 where that is valid (a concave meridian), else a scan in 0.5 degree steps for the last valid
 * one (a bowl's range starts above 0: its next pass would be past the bottom at small slopes), then
 * bisection up to the first invalid one (below 90: a vertical wall). 0 when no slope is valid.
 */
export function largestValidSlopeDeg(input: SlopeSweepInput): number {
  return largestOfScan(input, scan(input));
}

function largestOfScan(input: SlopeSweepInput, verdicts: ReturnType<typeof scan>): number {
  const ok = (a: number) => verdictAt(input, a) === 'ok';
  let last = -1;
  for (const v of verdicts) if (v.verdict === 'ok') last = v.slopeDeg;
  if (last < 0) return 0;
  if (last === 90) return 90;
  return bisect(ok, last, Math.min(90, last + 0.5), 60, 1e-12).lo;
}

/**
 * The slope (degrees) where raster passes at `rasterAngleDeg` and waterline passes on the plane
 * program the same step for h (`Lxy` of raster = `dz` of waterline): below it raster steps over
 * more, above it waterline steps down more. `Lxy` falls and `dz` rises with the slope, so the
 * crossing is found by bisection; null when they do not cross where both are valid.
 */
export function rasterWaterlineCrossingDeg(
  toolRadiusMm: number,
  cornerRadiusMm: number,
  hMm: number,
  rasterAngleDeg = 0,
): number | null {
  const base = { toolRadiusMm, cornerRadiusMm, rasterAngleDeg };
  const diff = (a: number): number | null => {
    const r = slopedPlaneForward({ ...base, slopeDeg: a, passes: 'raster' }, hMm);
    const w = slopedPlaneForward({ ...base, slopeDeg: a, passes: 'waterline' }, hMm);
    return r.ok && w.ok ? r.value.horizontalStepMm - (w.value.stepDownMm ?? 0) : null;
  };
  const top = Math.min(
    largestValidSlopeDeg({ ...base, hMm, passes: 'raster' }),
    largestValidSlopeDeg({ ...base, hMm, passes: 'waterline' }),
  );
  const dTop = diff(top * (1 - 1e-9));
  if (dTop === null || dTop > 0) return null;
  const rasterMore = (a: number) => {
    const d = diff(a);
    return d !== null && d > 0;
  };
  const { lo, hi } = bisect(rasterMore, 1e-9, top * (1 - 1e-9), 80, 1e-12);
  return 0.5 * (lo + hi);
}

/**
 * The sweep (see the module comment), or the input errors: the tool, the raster angle, the radii
 * and h (at least 1e-9 mm) and the constant step out of their fixed ranges, or no slope at which h
 * is valid (gouging at every slope; h at or above the limit at every slope). Refused slopes inside
 * the range carry nulls.
 */
export function slopeSweep(input: SlopeSweepInput): ThreeAxisResult<SlopeSweep> {
  const errors = rangeErrors(input);
  if (errors.length > 0) return { ok: false, errors };
  const verdicts = scan(input);
  if (!verdicts.some((v) => v.verdict === 'ok')) return { ok: false, errors: [noSlopeError(input, verdicts)] };
  const count = Math.max(2, Math.round(input.count ?? 200));
  const floor = flatFloorStepMm(input.toolRadiusMm, input.cornerRadiusMm, input.hMm);
  const programmed = input.programmedStepMm ?? floor;
  const largest = largestOfScan(input, verdicts);
  const points: SlopeSweepPoint[] = [];
  const revolution = onRevolution(input);
  for (let i = 0; i < count; i++) {
    let a = (largest * i) / (count - 1);
    if (i === count - 1 && a > 0 && a < 90) a *= 1 - 1e-9;
    points.push(revolution ? revolutionPoint(input, a, programmed) : planePoint(input, a, programmed));
  }
  return {
    ok: true,
    value: { points, largestSlopeDeg: largest, flatFloorStepMm: floor, programmedStepMm: programmed },
  };
}

/** The errors of the fixed ranges (tool, raster angle, radii; h and the constant step at least 1e-9 mm). */
function rangeErrors(input: SlopeSweepInput): ThreeAxisError[] {
  const slopeFree = (e: ThreeAxisError) => e.field !== 'slope' && e.field !== 'h';
  let fixed: readonly ThreeAxisError[];
  if (onRevolution(input)) fixed = checkCase(revolutionCase(input, 45));
  else {
    // At 45 degrees (valid for both strategies) with an h below any limit: only the ranges can fail.
    const r = slopedPlaneForward(planeCase(input, 45), MIN_THREE_AXIS_LENGTH_MM);
    fixed = r.ok ? [] : r.errors;
  }
  const step = input.programmedStepMm;
  return [
    ...fixed.filter(slopeFree),
    ...checkHeight(input.hMm),
    ...(step === undefined ? [] : checkStep(input.passes === 'waterline' ? 'stepDown' : 'horizontalStep', step)),
  ];
}

/**
 * The error when h is valid at no slope: gouging at every slope (the radius that must grow for the
 * tool to fit at some slope), or h at or above the limit wherever the tool does not gouge (the
 * largest limit over the scan, where it is; a slope's own error where that limit is below 1e-9 mm,
 * as for a flat end in waterline passes).
 */
function noSlopeError(input: SlopeSweepInput, verdicts: ReturnType<typeof scan>): ThreeAxisError {
  const limited = verdicts.filter((v) => v.verdict === 'limit');
  if (limited.length === 0) {
    return gougingError(revolutionCase(input, 45), 'at every slope', (cc) => {
      const other = { ...input, feedRadiusMm: cc.feedRadiusMm, crossRadiusMm: cc.crossRadiusMm };
      return scanSlopes(other).every((a) => verdictAt(other, a) === 'gouge');
    });
  }
  let best = limited[0] as (typeof limited)[number];
  let bestMm = Number.NEGATIVE_INFINITY;
  for (const v of limited) {
    const mm = heightLimitAt(input, v.slopeDeg);
    if (mm > bestMm) {
      best = v;
      bestMm = mm;
    }
  }
  const own = onRevolution(input)
    ? waterlineForward(revolutionCase(input, best.slopeDeg), input.hMm)
    : slopedPlaneForward(planeCase(input, best.slopeDeg), input.hMm);
  const error = own.ok ? null : own.errors[0];
  if (!(bestMm >= MIN_THREE_AXIS_LENGTH_MM)) {
    // A flat end in waterline passes: its own error holds at every slope.
    if (error?.code === 'wall-only') return error;
    return threeAxisError(
      'h',
      error?.code ?? 'shank-cuts',
      input.hMm,
      bestMm,
      `cannot be answered at any slope (got ${input.hMm}): at every slope the tool gouges or the scallop it can leave is below ${MIN_THREE_AXIS_LENGTH_MM} mm (the shank or a flank, not the corner, forms the cusp at any step).`,
    );
  }
  const where = onRevolution(input) ? 'the flanks, the shank or the end of the surface' : 'the flanks or the shank';
  return threeAxisError(
    'h',
    error?.code ?? 'flank-wall',
    input.hMm,
    bestMm,
    `must be below ${formatNumber(bestMm)} mm to be answered at some slope (got ${input.hMm}): at every slope it is at or above the limit, where ${where} leave a wall, not a scallop (the largest limit on slopes 0.5 degrees apart: ${formatNumber(bestMm)} mm, at ${formatNumber(best.slopeDeg)} degrees).`,
  );
}

function planePoint(input: SlopeSweepInput, slopeDeg: number, programmed: number): SlopeSweepPoint {
  const c = planeCase(input, slopeDeg);
  const waterlineFloor = input.passes === 'waterline' && slopeDeg === 0;
  const posture = slopePosture(slopeDeg, input.passes === 'waterline' ? 90 : input.rasterAngleDeg);
  const f = waterlineFloor
    ? slopedPlaneForward({ ...c, passes: 'raster', rasterAngleDeg: 90 }, input.hMm)
    : slopedPlaneForward(c, input.hMm);
  const inv = waterlineFloor
    ? null
    : slopedPlaneInverse(c, { field: input.passes === 'waterline' ? 'stepDown' : 'horizontalStep', mm: programmed });
  return {
    slopeDeg,
    stepMm: f.ok ? (input.passes === 'waterline' ? (f.value.stepDownMm ?? 0) : f.value.horizontalStepMm) : null,
    intervalMm: f.ok ? f.value.intervalMm : null,
    leadDeg: posture.leadDeg,
    tiltDeg: posture.tiltDeg,
    heightLimitMm: heightLimitAt(input, slopeDeg),
    cuspAtProgrammedStepMm: inv?.ok ? inv.value.cuspHeightMm : null,
    programmedStepRefusal: inv === null || inv.ok ? null : (inv.errors[0]?.code ?? null),
  };
}

function revolutionPoint(input: SlopeSweepInput, slopeDeg: number, programmed: number): SlopeSweepPoint {
  const c = revolutionCase(input, slopeDeg);
  // At slope 0 (a dome's top, a bowl's bottom) every level is the same: dz 0 where the slopes just
  // above it are answered (a dome), no number where they are not (a bowl: past its bottom).
  if (slopeDeg === 0)
    return {
      slopeDeg,
      stepMm: verdictAt(input, 1e-6) === 'ok' ? 0 : null,
      intervalMm: null,
      leadDeg: 0,
      tiltDeg: 0,
      heightLimitMm: Number.POSITIVE_INFINITY,
      cuspAtProgrammedStepMm: null,
      programmedStepRefusal: 'needs-slope',
    };
  const f = waterlineForward(c, input.hMm);
  const inv = waterlineInverse(c, { field: 'stepDown', mm: programmed });
  return {
    slopeDeg,
    stepMm: f.ok ? f.value.stepDownMm : null,
    intervalMm: f.ok ? f.value.intervalMm : null,
    leadDeg: 0,
    tiltDeg: slopeDeg,
    heightLimitMm: revolutionLimit(input, slopeDeg),
    cuspAtProgrammedStepMm: inv.ok ? inv.value.cuspHeightMm : null,
    programmedStepRefusal: inv.ok ? null : (inv.errors[0]?.code ?? null),
  };
}
