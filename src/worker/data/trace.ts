/**
 * The step-through view's data: the trace of the paper's 3D procedure (Figure 1) on both flanks as
 * frames (the section visited, d_s, the candidates, the converged P_hp), beside the exact solver's
 * widths. Mm and radians.
 */

import type { ForwardInput } from '../../core/input/validate';
import { traceProcedure } from '../../core/procedures/trace';
import { exactForward } from '../../core/surfaces/solve';
import { ringTangent, sectionCentre } from '../../core/tool/placement';
import type { Flank } from '../../core/tool/posture';
import type { TeachData, TraceFrame } from '../protocol';

/** The trace of the paper's procedure on both flanks as frames for the 3D step-through. */
export function traceFrames(input: ForwardInput): Pick<TeachData, 'frames' | 'traceResult'> {
  const trace = traceProcedure(input);
  const p = trace.placement;
  const section = (t: number) => ({ sectionCentre: sectionCentre(p, t), sectionNormal: ringTangent(p, t) });
  const frames: TraceFrame[] = [];
  const base = {
    dsMm: null,
    found: false,
    rangeRad: null,
    sectionCount: 0,
    candidates: [],
    point: null,
    outMm: null,
    approachIndex: 0,
  } as const;
  const approaches = { right: 0, left: 0 };
  const converge = (flank: Flank) => {
    const f = trace[flank];
    frames.push({
      ...base,
      phase: 'converged',
      flank,
      ringAngleRad: f.ringAngleRad,
      ...section(f.ringAngleRad),
      point: f.pHp,
      outMm: f.widthMm,
    });
  };
  let previous: Flank | null = null;
  for (const step of trace.steps) {
    if (previous !== null && step.flank !== previous) converge(previous);
    previous = step.flank;
    if (step.phase === 'approach') {
      frames.push({
        ...base,
        phase: 'approach',
        flank: step.flank,
        approachIndex: approaches[step.flank]++,
        ringAngleRad: step.ringAngleRad,
        dsMm: step.dsMm,
        ...section(step.ringAngleRad),
      });
    } else if (step.phase === 'single-contact') {
      frames.push({
        ...base,
        phase: 'single-contact',
        flank: step.flank,
        ringAngleRad: step.ringAngleRad,
        dsMm: step.dsMm,
        ...section(step.ringAngleRad),
        found: step.found,
        point: step.found ? step.pHp : null,
      });
    } else {
      const best = step.ringAnglesRad[step.bestIndex] ?? step.rangeRad[0];
      frames.push({
        ...base,
        phase: 'search',
        flank: step.flank,
        ringAngleRad: best,
        ...section(best),
        rangeRad: step.rangeRad,
        sectionCount: step.ringAnglesRad.length,
        candidates: [...step.candidates],
        point: step.pHp,
        outMm: step.crossingOutMm[step.bestIndex] ?? null,
      });
    }
  }
  if (previous !== null) converge(previous);
  // The closing frame: both flanks' points.
  frames.push({
    ...base,
    phase: 'converged',
    flank: null,
    ringAngleRad: trace.right.ringAngleRad,
    ...section(trace.right.ringAngleRad),
    candidates: [...trace.right.pHp, ...trace.left.pHp],
    point: trace.right.pHp,
    outMm: trace.right.widthMm,
  });
  const exact = exactForward(input);
  return {
    frames,
    traceResult: {
      widthRightMm: trace.right.widthMm,
      widthLeftMm: trace.left.widthMm,
      exactWidthRightMm: exact.halfWidthRightMm,
      exactWidthLeftMm: exact.halfWidthLeftMm,
    },
  };
}
