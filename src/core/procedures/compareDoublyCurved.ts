/**
 * What the usual shortcuts get wrong at a doubly curved point (issue 19, "Comparison rows"): beside
 * the exact step-over, the plane's answer at the same posture (both curvatures ignored), each
 * cylinder's (one radius ignored: Rf straight is the cylinder along the feed, Rc straight the one
 * across), and the usual correction of every procedure with an effective radius,
 * `1 / rho = 1 / Reff + 1 / Rc` (Rc signed; Redonnet et al. 2013, ref. 34 of the paper; as
 * compare.ts does on cylinders) with the circle's `L = 2 sqrt(2 rho h - h^2)`. Each row carries its
 * signed deviation from the exact step-over and the scallop its own step-over really leaves here
 * (the exact inverse), or null where passes that far apart leave a wall. Lengths mm.
 */

import type { DoublyCurvedForwardInput } from '../surfaces/doublyCurved/types';
import {
  type CurvedPoint,
  curvedForward,
  curvedInverse,
  curvedLimits,
  curvedMaxIntervalMm,
  curvedPoint,
  curvedPointOf,
} from '../surfaces/doublyCurvedPoint';
import type { ExactForward } from '../surfaces/surface';
import { combinedRadiusMm } from './approximations';
import { APPROXIMATIONS, CORRECTED_KEYS, type CorrectedKey } from './procedures';

/** One shortcut's step-over beside the exact one. */
export type DoublyCurvedRow =
  | {
      readonly ok: true;
      /** Its step-over L (mm). */
      readonly intervalMm: number;
      /** L minus the exact step-over: mm and % of the exact. */
      readonly deviationMm: number;
      readonly deviationPercent: number;
      /** The highest cusp its L really leaves at this point (mm); null at or beyond the widest step-over. */
      readonly realScallopMm: number | null;
    }
  | { readonly ok: false; readonly notApplicable: string };

/** The comparison rows of the forward problem at a doubly curved point. */
export interface DoublyCurvedComparison {
  readonly exact: ExactForward;
  /** The widest step-over that still leaves a scallop here (the reaches at the limit height), mm. */
  readonly maxIntervalMm: number;
  /** The plane's exact answer at the same posture. */
  readonly plane: DoublyCurvedRow;
  /** The cylinder along the feed (Rf ignored: radius Rc) and across it (Rc ignored: radius Rf). */
  readonly cylinderAlong: DoublyCurvedRow;
  readonly cylinderAcross: DoublyCurvedRow;
  /** The usual correction of each procedure with an effective radius, combined with Rc. */
  readonly corrected: { readonly [K in CorrectedKey]: DoublyCurvedRow & { readonly combinedRadiusMm?: number } };
}

function row(L: number, exactL: number, point: CurvedPoint, maxMm: number): DoublyCurvedRow & { ok: true } {
  const deviationMm = L - exactL;
  const realScallopMm = L > 0 && L < maxMm ? curvedInverse(point, L).cuspHeightMm : null;
  return { ok: true, intervalMm: L, deviationMm, deviationPercent: (100 * deviationMm) / exactL, realScallopMm };
}

/**
 * The plane's, each cylinder's and the usual correction's step-overs beside the exact one, every
 * exact answer (the point's, the plane's and the cylinders' rows, the scallops their step-overs
 * leave) the registry's model's (surfaces/doublyCurvedPoint.ts). @param input validated, not gouging.
 */
export function compareDoublyCurved(input: DoublyCurvedForwardInput): DoublyCurvedComparison {
  const point = curvedPointOf(input);
  return compareAtPoint(input, point, curvedForward(point, input.scallopHeightMm), curvedMaxIntervalMm(point));
}

/**
 * {@link compareDoublyCurved} at a point whose exact answer at h (`exact`) and widest step-over
 * (`maxMm`, mm) the caller has already found (the worker's doubly curved job), so neither is solved
 * again. @param point the point of `input` (curvedPointOf).
 */
export function compareAtPoint(
  input: DoublyCurvedForwardInput,
  point: CurvedPoint,
  exact: ExactForward,
  maxMm: number,
): DoublyCurvedComparison {
  const I = Number.POSITIVE_INFINITY;
  const h = input.scallopHeightMm;
  const other = (rf: number, rc: number): DoublyCurvedRow => {
    const s = curvedPoint(input, { feedRadiusMm: rf, crossRadiusMm: rc }, input.pattern);
    if (!(h < curvedLimits(s).limitMm))
      return { ok: false, notApplicable: 'h is at or above the flank limit of that surface.' };
    return row(curvedForward(s, h).intervalMm, exact.intervalMm, point, maxMm);
  };
  const rc = input.crossRadiusMm;
  const corrected = {} as { -readonly [K in CorrectedKey]: DoublyCurvedRow & { readonly combinedRadiusMm?: number } };
  for (const key of CORRECTED_KEYS) {
    const m = APPROXIMATIONS[key].model(input);
    if (!m.ok) {
      corrected[key] = { ok: false, notApplicable: m.notApplicable };
      continue;
    }
    const reff = m.effectiveRadiusMm;
    // The correction across the feed is the one of a cylinder along the feed of radius Rc.
    const combined = combinedRadiusMm(reff, { kind: 'cylinder', radiusMm: rc, axis: 'feed' });
    if (!(combined > 0) || !Number.isFinite(combined)) {
      corrected[key] = {
        ok: false,
        notApplicable: `its effective radius (${reff} mm) is not smaller than the concave radius across the feed, so the combined radius is not positive.`,
      };
      continue;
    }
    if (h > combined) {
      corrected[key] = {
        ok: false,
        notApplicable: `h is above the widest point of the combined circle (${combined} mm).`,
      };
      continue;
    }
    const L = 2 * Math.sqrt(h) * Math.sqrt(2 * combined - h);
    corrected[key] = { ...row(L, exact.intervalMm, point, maxMm), combinedRadiusMm: combined };
  }
  return {
    exact,
    maxIntervalMm: maxMm,
    plane: other(I, I),
    cylinderAlong: other(I, input.crossRadiusMm),
    cylinderAcross: other(input.feedRadiusMm, I),
    corrected,
  };
}
