/**
 * The limits of waterline passes on a surface of revolution as input errors (waterlineRevolution.ts):
 * the case's own inputs, and an unsuccessful solve worded with its limit in the quantity given.
 */

import { bisect } from '../math/rootFinder';
import {
  checkTool,
  formatNumber,
  MIN_THREE_AXIS_LENGTH_MM,
  THREE_AXIS_SURFACE_RADIUS_RANGE_MM,
  type ThreeAxisError,
  type ThreeAxisField,
  threeAxisError,
} from './errors';
import { stepDownOfIntervalMm } from './meridianPasses';
import {
  type Core,
  cuspAt,
  forwardCore,
  inverseCore,
  type RevolutionCase,
  type Setup,
  setupOf,
  shankHeightAt,
  shankStartL,
  someShankL,
} from './waterlineSolve';

/**
 * Errors of the case's own inputs (tool, slope, radii). A slope of 90 degrees is answered where the
 * meridian is concave (a wall that flares out below, as into a floor fillet: adjacent passes touch
 * at different slopes and leave a scallop, continuous with 89.999); where it is straight (a
 * vertical plane or cylinder wall) the side cuts it flat, and where it is convex the surface below
 * overhangs: both refused.
 */
export function checkCase(c: RevolutionCase): ThreeAxisError[] {
  const errors = checkTool(c.toolRadiusMm, c.cornerRadiusMm);
  const a = c.slopeDeg;
  if (!(a > 0 && a <= 90))
    errors.push(
      threeAxisError(
        'slope',
        a === 0 ? 'needs-slope' : 'out-of-range',
        a,
        null,
        a === 0
          ? 'must be above 0 degrees for waterline passes: on a flat floor every level is the same, so there is no step-down.'
          : `must be above 0 and at most 90 degrees (got ${a}).`,
      ),
    );
  else if (a === 90 && c.crossRadiusMm === null)
    errors.push(
      threeAxisError(
        'slope',
        'vertical-wall',
        a,
        90,
        'of 90 degrees is a vertical wall: the side of the upright tool cuts it flat, so no scallop forms at any step-down and there is no step to compute.',
      ),
    );
  else if (a === 90 && c.crossRadiusMm !== null && c.crossRadiusMm > 0)
    errors.push(
      threeAxisError(
        'slope',
        'past-surface',
        a,
        90,
        "must be below 90 degrees on a convex meridian (got 90): below the contact the surface turns under into an overhang, so the next pass down would lie past the vertical, out of the upright tool's reach.",
      ),
    );
  const [lo, hi] = THREE_AXIS_SURFACE_RADIUS_RANGE_MM;
  for (const [field, r] of [
    ['feedRadius', c.feedRadiusMm],
    ['crossRadius', c.crossRadiusMm],
  ] as const) {
    if (r !== null && !(Math.abs(r) >= lo && Math.abs(r) <= hi))
      errors.push(
        threeAxisError(
          field,
          'out-of-range',
          r,
          null,
          `must be a radius from ${lo} mm to ${hi} mm, negative when concave, or none for a straight line (got ${r}).`,
        ),
      );
  }
  return errors;
}

/** The step of `field` (mm) for L along the meridian. */
function stepOf(s: Setup, field: ThreeAxisField, L: number): number {
  return field === 'stepDown' ? stepDownOfIntervalMm(s.tool, s.mer, L) : L;
}

const PAST_WORDS: Record<NonNullable<Setup['maxBy']>, string> = {
  vertical: 'past the vertical of the convex meridian (an overhang the upright tool cannot reach)',
  bottom: 'past the bottom of the concave meridian',
  axis: 'across the axis of revolution',
};

/**
 * The shank's limit on `field` (h, dz or L; mm) as an error. A limit below the smallest length
 * accepted (steep concave walls, whose corner is small beside the meridian: at 90 degrees the
 * limit is 0) means that the shank forms the cusp at any step: said so, without a limit to stay below.
 */
function shankError(field: ThreeAxisField, got: number, limit: number): ThreeAxisError {
  const why = "the next pass's shank (its vertical side, above the corner), not its corner,";
  return threeAxisError(
    field,
    'shank-cuts',
    got,
    limit,
    limit < MIN_THREE_AXIS_LENGTH_MM
      ? `cannot be answered at this slope (got ${got}): ${why} forms the cusp at any step, leaving a step in the wall, not a scallop (the limit here is below ${MIN_THREE_AXIS_LENGTH_MM} mm).`
      : `must be below ${formatNumber(limit)} mm at this slope (got ${got}): beyond it ${why} would form the cusp.`,
  );
}

/** Words an unsuccessful core as the error of `field` (the quantity given: h, dz or L). */
export function coreError(c: RevolutionCase, s: Setup, r: Core, field: ThreeAxisField, got: number): ThreeAxisError {
  const gotText = `(got ${got})`;
  switch (r.kind) {
    case 'wall-only':
      return threeAxisError(
        field,
        'wall-only',
        got,
        null,
        'cannot be answered with a flat end (Rcr = 0) in waterline passes: the side of the lower pass rises straight from its contact, so it cuts a step at any step-down, not a scallop. Use a corner radius.',
      );
    case 'shank':
      return shankError(field, got, field === 'h' ? shankHeightAt(s, r.limitL) : stepOf(s, field, r.limitL));
    case 'past': {
      const where = s.maxBy === null ? 'beyond the surface' : PAST_WORDS[s.maxBy];
      if (field === 'h') {
        // The largest h: the shank's or the end of the surface's, whichever comes first.
        const shankL = someShankL(s);
        if (shankL !== null) return shankError('h', got, shankHeightAt(s, shankStartL(s, shankL)));
        const limit = cuspAt(s, s.maxL * (1 - 1e-12)).heightMm;
        return threeAxisError(
          'h',
          'past-surface',
          got,
          limit,
          `must be below ${formatNumber(limit)} mm at this slope ${gotText}: a larger scallop needs the next pass ${where}.`,
        );
      }
      const limit = stepOf(s, field, s.maxL);
      return threeAxisError(
        field,
        'past-surface',
        got,
        limit,
        `must be below ${formatNumber(limit)} mm at this slope ${gotText}: a larger step puts the next pass ${where}.`,
      );
    }
    case 'gouge':
      return gougingError(c, r.pass === 0 ? 'at this slope' : 'at the next pass (further down, at its slope)', (cc) => {
        const ss = setupOf(cc);
        const kind = field === 'h' ? forwardCore(ss, got) : inverseCore(ss, { field: field as 'stepDown', mm: got });
        return kind.kind === 'gouge';
      });
    case 'ok':
      throw new Error('not an error');
  }
}

/**
 * The gouging error: which radius to change and its smallest magnitude with the other held, found
 * by bisection (on the logarithm of the magnitude) of `gouges`, the verdict of the whole question
 * (one solve, or a sweep over the slopes) for a case with that radius. `which` says where it gouges
 * ("at this slope").
 */
export function gougingError(c: RevolutionCase, which: string, gouges: (c: RevolutionCase) => boolean): ThreeAxisError {
  const fields = [
    ['crossRadius', c.crossRadiusMm],
    ['feedRadius', c.feedRadiusMm],
  ] as const;
  for (const [field, r] of fields) {
    if (r === null) continue;
    const withRadius = (m: number | null): RevolutionCase =>
      field === 'crossRadius' ? { ...c, crossRadiusMm: m } : { ...c, feedRadiusMm: m };
    if (gouges(withRadius(null))) continue;
    const sign = Math.sign(r);
    const maxMag = THREE_AXIS_SURFACE_RADIUS_RANGE_MM[1];
    let limit: number | null = null;
    if (!gouges(withRadius(sign * maxMag))) {
      const gougesAt = (logMag: number) => gouges(withRadius(sign * Math.exp(logMag)));
      limit = Math.exp(bisect(gougesAt, Math.log(Math.abs(r)), Math.log(maxMag), 80, 1e-13).hi);
    }
    const name = field === 'crossRadius' ? 'meridian' : 'horizontal circle (its normal radius)';
    const kind = sign < 0 ? 'concave' : 'convex';
    return threeAxisError(
      field,
      'gouging',
      r,
      limit === null ? null : sign * limit,
      limit === null
        ? `is too tight for this tool ${which} (got ${r}): only a straight ${name === 'meridian' ? 'meridian (no Rc)' : 'horizontal line (no Rf)'} avoids gouging.`
        : `is too tight for this tool ${which} (got ${r}): a ${kind} ${name} must have a radius of at least ${formatNumber(limit)} mm; a tighter one is gouged (the tool reaches into the surface away from the contact).`,
    );
  }
  return threeAxisError(
    'crossRadius',
    'gouging',
    c.crossRadiusMm ?? Number.POSITIVE_INFINITY,
    null,
    `and the feed radius Rf together are too tight for this tool ${which}: no single one of them, however large, avoids gouging (the tool reaches into the surface away from the contact).`,
  );
}
