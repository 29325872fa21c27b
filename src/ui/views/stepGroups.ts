/**
 * The step-through's steps from the worker's trace frames: consecutive frames of one flank and
 * phase that the scene and the d_s gauge would show alike are merged into one step (the search's
 * last passes narrow the range by far less than a pixel), and a step that looks like the one
 * before although the procedure moved on (the single contact confirmed at the last approach
 * section, a flank's convergence on its last search point) is marked so its caption says why.
 * Pure; lengths mm.
 */
import type { Vec3 } from '../../core/math/vec';
import type { TraceFrame } from '../../worker/protocol';

/** One step of the step-through: a run of frames that look the same. */
export interface Step {
  /** The frame the scene shows: the run's last (the most converged). */
  readonly frame: TraceFrame;
  /** Frames merged into this step (1 when none). */
  readonly count: number;
  /** 1-based numbers of the run's first and last frame among its flank's frames of the same phase. */
  readonly passFrom: number;
  readonly passTo: number;
  /** It shows the previous step's section and point again (another phase of the procedure). */
  readonly sameAsPrevious: boolean;
}

/** Distance below which two points are drawn alike in the scene (mm): a thousandth of the tool radius. */
export function sceneToleranceMm(toolRadiusMm: number): number {
  return 1e-3 * toolRadiusMm;
}

/** Resolution of the d_s / Rcr gauge: differences below it are not visible on its scale. */
export const GAUGE_RESOLUTION = 0.005;

/** The gauge's scale step (in d_s / Rcr). */
export const GAUGE_TICK = 0.25;

/**
 * The gauge's end: the largest d_s / Rcr of the trace (at least 1, the single contact), up to the
 * next multiple of GAUGE_TICK, so that no frame's bar is clipped.
 */
export function gaugeMax(ratios: readonly number[]): number {
  const top = Math.max(1, ...ratios.filter((r) => Number.isFinite(r)));
  return Math.ceil(top / GAUGE_TICK - 1e-9) * GAUGE_TICK;
}

function near(a: Vec3 | null, b: Vec3 | null, tol: number): boolean {
  if (a === null || b === null) return a === b;
  return Math.abs(a[0] - b[0]) <= tol && Math.abs(a[1] - b[1]) <= tol && Math.abs(a[2] - b[2]) <= tol;
}

/** Same section and same point in the scene (within `tol`, mm). */
function samePlace(a: TraceFrame, b: TraceFrame, tol: number): boolean {
  return a.flank === b.flank && near(a.sectionCentre, b.sectionCentre, tol) && near(a.point, b.point, tol);
}

/** Would the scene and the gauge show the two frames alike? */
export function looksSame(a: TraceFrame, b: TraceFrame, tol: number, cornerRadiusMm: number): boolean {
  if (!samePlace(a, b, tol) || a.candidates.length !== b.candidates.length) return false;
  if (a.candidates.some((v, i) => Math.abs(v - (b.candidates[i] ?? Number.NaN)) > tol)) return false;
  if (a.dsMm === null || b.dsMm === null) return a.dsMm === b.dsMm;
  return cornerRadiusMm > 0 ? Math.abs(a.dsMm - b.dsMm) / cornerRadiusMm < GAUGE_RESOLUTION : true;
}

/**
 * Groups the frames into steps.
 * @param tol scene tolerance (mm), see sceneToleranceMm; @param cornerRadiusMm the gauge's Rcr.
 */
export function groupSteps(frames: readonly TraceFrame[], tol: number, cornerRadiusMm: number): Step[] {
  const steps: Step[] = [];
  const counts = new Map<string, number>();
  let previous: TraceFrame | null = null;
  // Compared with the run's first frame, so that many tiny moves do not add up unseen.
  let runStart: TraceFrame | null = null;
  for (const frame of frames) {
    const phaseKey = `${frame.flank}|${frame.phase}`;
    const n = (counts.get(phaseKey) ?? 0) + 1;
    counts.set(phaseKey, n);
    const last = steps.at(-1);
    if (
      last !== undefined &&
      runStart !== null &&
      runStart.phase === frame.phase &&
      looksSame(runStart, frame, tol, cornerRadiusMm)
    ) {
      steps[steps.length - 1] = { ...last, frame, count: last.count + 1, passTo: n };
    } else {
      steps.push({
        frame,
        count: 1,
        passFrom: n,
        passTo: n,
        sameAsPrevious: previous !== null && previous.phase !== frame.phase && samePlace(previous, frame, tol),
      });
      runStart = frame;
    }
    previous = frame;
  }
  return steps;
}
