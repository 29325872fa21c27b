/**
 * The profiles of the surface the teeth leave (issue 29, "a profile along the CC path and one
 * across it"): its height along pass 0's CC path (y = 0) over two feed periods, and across the
 * feed over one period of the passes at a chosen x, each sampled evenly, ends included, from the
 * height at a point (runout.ts envelopeHeightMm: the e = 0 walk, or the runout search). Lengths mm.
 */
import { envelopeHeightMm } from './runout';
import type { ToothModel } from './toothModel';

/** A sampled profile: positions and heights (mm above the design plane), the same length. */
export interface FinishProfile {
  /** x along the feed (the along profile) or y across it (the across profile), mm. */
  readonly atMm: Float64Array;
  readonly heightsMm: Float64Array;
}

/** The two profiles of a model (see the module comment). */
export interface FinishProfiles {
  /** Along the CC path y = 0, x from 0 to two feed periods. */
  readonly along: FinishProfile;
  /** Across the feed at x = `acrossAtXMm`, y from -L/2 over one cross period (L, or 2 L zigzag). */
  readonly across: FinishProfile;
  readonly acrossAtXMm: number;
}

/** `n` heights of the surface between `from` and `to` (ends included) along x at y, or along y at x. */
function sample(n: number, from: number, to: number, height: (t: number) => number): FinishProfile {
  const atMm = new Float64Array(n);
  const heightsMm = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const t = i === n - 1 ? to : from + ((to - from) * i) / (n - 1);
    atMm[i] = t;
    heightsMm[i] = height(t);
  }
  return { atMm, heightsMm };
}

/**
 * The profiles along and across the feed, `points` samples each (>= 2): along the CC path over two
 * feed periods from x = 0 (tooth 0 at the contact), across at x = `acrossAtXMm` over one cross period
 * starting half a step-over to the left of the CC path.
 */
export function finishProfiles(m: ToothModel, points: number, acrossAtXMm: number): FinishProfiles {
  const P = m.feedPeriodMm;
  const L = m.input.intervalMm;
  return {
    along: sample(points, 0, 2 * P, (x) => envelopeHeightMm(m, x, 0)),
    across: sample(points, -L / 2, -L / 2 + m.crossPeriodMm, (y) => envelopeHeightMm(m, acrossAtXMm, y)),
    acrossAtXMm,
  };
}
