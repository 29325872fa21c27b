/**
 * The chart "step against slope" for three-axis machining (issue 20): from the solved answer
 * (jobs/threeAxis.ts, which carries the 200-slope sweep of core/threeAxis/slopeSweep.ts and the
 * raster/waterline crossing), the programmed step at each slope, the other strategy's step on the
 * plane for the same h, the scallop a constant step leaves, and the crossing's step. Mm, degrees.
 */
import { slopedPlaneForward, slopedPlaneInverse } from '../../core/threeAxis/slopedPlane';
import type { SlopeSweep } from '../../core/threeAxis/slopeSweep';
import { waterlineInverse } from '../../core/threeAxis/waterlineRevolution';
import type { ThreeAxisReply } from '../pageProtocol';
import type { SlopeChartData } from '../teachProtocol';

/**
 * The programmed step (mm) of a strategy on the plane for h at a slope: Lxy for raster at
 * `rasterAngleDeg`, dz for waterline; null where refused (and waterline at slope 0, where a
 * step-down means nothing).
 */
export function planeStepMm(
  toolRadiusMm: number,
  cornerRadiusMm: number,
  hMm: number,
  passes: 'raster' | 'waterline',
  slopeDeg: number,
  rasterAngleDeg: number,
): number | null {
  if (passes === 'waterline' && slopeDeg === 0) return null;
  const r = slopedPlaneForward({ toolRadiusMm, cornerRadiusMm, slopeDeg, passes, rasterAngleDeg }, hMm);
  if (!r.ok) return null;
  return passes === 'raster' ? r.value.horizontalStepMm : r.value.stepDownMm;
}

/** The scallop (mm) the constant step leaves at the current slope (as the sweep's points), or null. */
function cuspAtConstantStep(reply: Extract<ThreeAxisReply, { ok: true }>, stepMm: number): number | null {
  const p = reply.request.input;
  if (p.surface === 'revolution') {
    if (p.case.slopeDeg === 0) return null;
    const r = waterlineInverse(p.case, { field: 'stepDown', mm: stepMm });
    return r.ok ? r.value.cuspHeightMm : null;
  }
  if (p.case.passes === 'waterline' && p.case.slopeDeg === 0) return null;
  const field = p.case.passes === 'waterline' ? 'stepDown' : 'horizontalStep';
  const r = slopedPlaneInverse(p.case, { field, mm: stepMm });
  return r.ok ? r.value.cuspHeightMm : null;
}

/** The runs of slopes where the constant step is refused, each with its reason (the core's code). */
function refusalRuns(points: SlopeSweep['points']): SlopeChartData['constantStepRefusals'] {
  const out: Array<{ fromDeg: number; toDeg: number; code: string }> = [];
  let run: { fromDeg: number; toDeg: number; code: string } | null = null;
  for (const q of points) {
    const code = q.cuspAtProgrammedStepMm === null ? (q.programmedStepRefusal ?? 'refused') : null;
    if (code !== null && run !== null && run.code === code) run.toDeg = q.slopeDeg;
    else {
      run = code === null ? null : { fromDeg: q.slopeDeg, toDeg: q.slopeDeg, code };
      if (run !== null) out.push(run);
    }
  }
  return out;
}

/** The chart's data from a solved three-axis reply, or null when it has no sweep (no scallop). */
export function slopeChart(reply: Extract<ThreeAxisReply, { ok: true }>): SlopeChartData | null {
  const sweep = reply.sweep;
  if (sweep === null) return null;
  const p = reply.request.input;
  const c = p.case;
  const a = reply.answer;
  const onPlane = p.surface === 'plane';
  const rasterAngleDeg = p.surface === 'plane' && p.case.passes === 'raster' ? p.case.rasterAngleDeg : 90;
  const crossingRasterAngleDeg = a.passes === 'raster' ? rasterAngleDeg : 0;
  const other = a.passes === 'raster' ? 'waterline' : 'raster';
  const otherAngle = other === 'raster' ? crossingRasterAngleDeg : 90;
  const slopeDeg = sweep.points.map((q) => q.slopeDeg);
  const hMm = a.cuspHeightMm;
  const R = c.toolRadiusMm;
  const Rcr = c.cornerRadiusMm;
  return {
    passes: a.passes,
    rasterAngleDeg,
    onRevolution: !onPlane,
    hMm,
    slopeDeg,
    stepMm: sweep.points.map((q) => q.stepMm),
    otherStepMm: slopeDeg.map((s) => (onPlane ? planeStepMm(R, Rcr, hMm, other, s, otherAngle) : null)),
    cuspAtConstantStepMm: sweep.points.map((q) => q.cuspAtProgrammedStepMm),
    constantStepRefusals: refusalRuns(sweep.points),
    largestSlopeDeg: sweep.largestSlopeDeg,
    flatFloorStepMm: sweep.flatFloorStepMm,
    constantStepMm: sweep.programmedStepMm,
    currentSlopeDeg: c.slopeDeg,
    currentStepMm: a.passes === 'waterline' ? a.stepDownMm : a.horizontalStepMm,
    currentOtherStepMm: onPlane ? planeStepMm(R, Rcr, hMm, other, c.slopeDeg, otherAngle) : null,
    currentCuspAtConstantStepMm: cuspAtConstantStep(reply, sweep.programmedStepMm),
    crossingRasterAngleDeg,
    crossingDeg: reply.crossingDeg,
    crossingStepMm:
      reply.crossingDeg === null ? null : planeStepMm(R, Rcr, hMm, 'raster', reply.crossingDeg, crossingRasterAngleDeg),
  };
}
