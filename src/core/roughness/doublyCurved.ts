/**
 * Roughness at a doubly curved point (issue 19): `Rz`, `Ra`, `Rq` of the cross-feed section the
 * passes leave, as roughness.ts defines them on cylinders (shared/notes/posture-and-surfaces.md),
 * with heights measured along the normal (radially about `m`, the line through (0, 0, -Rc) parallel
 * to the feed) and lengths as arc length along the equator, so the mean line is the circle about `m`
 * at the mean height. A period is made of flank segments, each from a CC point out to a cusp, and
 * roughness.ts's integration by parts applies unchanged with each flank's reach
 * (equatorFlank.ts `reachMm`) as its width function. Rf infinite gives the cylinder with its axis
 * along the feed, Rc infinite the one across (the tests check those limits). Lengths mm.
 */

import type { PassPattern, ToolInput } from '../input/validate';
import { type DoublyCurvedSolver, doublyCurvedSolver, forwardWith } from '../surfaces/doublyCurved/solve';
import type { DoublyCurvedForward, DoublyCurvedInverse, PrincipalRadii } from '../surfaces/doublyCurved/types';
import { type FlankSegment, heightForRaMm, type Roughness, roughnessOfSegments, type WidthAt } from './roughness';

const NONE: Roughness = { rzMm: 0, raMm: 0, rqMm: 0, meanMm: 0 };

/**
 * Each flank's reach (arc length along the equator, mm) at a radial height (mm). Below the rounding
 * of the radial heights (about 1e-16 mm at the CC point's disk) a reach is -Infinity, and within a
 * few hundred times that it carries percent-level noise; roughnessOfSegments counts a non-finite
 * width as 0 and stops its quadrature at that noise (its share of Ra and Rq is below 1e-20 mm).
 */
function widthsOf(solver: DoublyCurvedSolver): WidthAt {
  return (flank) => {
    const f = flank === 'right' ? solver.right : solver.left;
    return (z) => f.reachMm(z);
  };
}

/**
 * Roughness (mm) of the surface that passes of a forward solution leave at a doubly curved point.
 * Zigzag includes the other cusp's flank pair (two step-overs per period), as on cylinders.
 * @param solver the point's solver (doublyCurvedSolver); @param e its forward answer (forwardWith).
 */
export function doublyCurvedRoughness(
  solver: DoublyCurvedSolver,
  pattern: PassPattern,
  e: DoublyCurvedForward,
): Roughness {
  if (!(e.cuspHeightMm > 0)) return NONE;
  let segments: FlankSegment[];
  if (pattern === 'zigzag') {
    // The narrower flank's cusp is h; the wider flank meets its mirror lower, at L/2.
    const rightNarrow = e.halfWidthRightMm <= e.halfWidthLeftMm;
    const other = e.otherCuspHeightMm ?? e.cuspHeightMm;
    const half = e.intervalMm / 2;
    segments = [
      { flank: 'right', widthMm: half, heightMm: rightNarrow ? e.cuspHeightMm : other },
      { flank: 'left', widthMm: half, heightMm: rightNarrow ? other : e.cuspHeightMm },
    ];
  } else {
    segments = [
      { flank: 'right', widthMm: e.halfWidthRightMm, heightMm: e.cuspHeightMm },
      { flank: 'left', widthMm: e.halfWidthLeftMm, heightMm: e.cuspHeightMm },
    ];
  }
  return roughnessOfSegments(widthsOf(solver), segments);
}

/** Roughness (mm) of the surface that passes `e.intervalMm` apart leave (inverse answer, inverseWith). */
export function doublyCurvedRoughnessAtInterval(
  solver: DoublyCurvedSolver,
  pattern: PassPattern,
  e: DoublyCurvedInverse,
): Roughness {
  if (!(e.cuspHeightMm > 0)) return NONE;
  const segments: FlankSegment[] =
    pattern === 'zigzag'
      ? [
          { flank: 'right', widthMm: e.intervalMm / 2, heightMm: e.rightCuspHeightMm },
          { flank: 'left', widthMm: e.intervalMm / 2, heightMm: e.leftCuspHeightMm },
        ]
      : [
          { flank: 'right', widthMm: e.halfWidthRightMm, heightMm: e.cuspHeightMm },
          { flank: 'left', widthMm: e.halfWidthLeftMm, heightMm: e.cuspHeightMm },
        ];
  return roughnessOfSegments(widthsOf(solver), segments);
}

/** The Ra (mm) that the passes leaving scallop height `h` (mm, below the limits) leave. */
function raAt(solver: DoublyCurvedSolver, pattern: PassPattern, h: number): number {
  return doublyCurvedRoughness(solver, pattern, forwardWith(solver, pattern, h)).raMm;
}

/**
 * The largest Ra (mm) a tool, posture and pattern leave at a doubly curved point while leaving a
 * scallop (at the limit height, as roughness.ts's maxRaMm); 0 when no scallop forms.
 * @param tool validated tool and posture; @param radii signed Rf, Rc (mm) or infinite, not gouging.
 */
export function doublyCurvedMaxRaMm(tool: ToolInput, pattern: PassPattern, radii: PrincipalRadii): number {
  const solver = doublyCurvedSolver(tool, radii);
  const limit = solver.limits().limitMm;
  if (!(limit > 0)) return 0;
  return raAt(solver, pattern, limit * (1 - 1e-12));
}

/**
 * The scallop height h (mm) whose passes leave roughness `targetRaMm` at a doubly curved point
 * (roughness.ts's heightForRaMm on this point's Ra). Requires 0 < target < doublyCurvedMaxRaMm.
 */
export function doublyCurvedHeightForRaMm(
  tool: ToolInput,
  pattern: PassPattern,
  radii: PrincipalRadii,
  targetRaMm: number,
): number {
  const solver = doublyCurvedSolver(tool, radii);
  const limit = solver.limits().limitMm * (1 - 1e-12);
  return heightForRaMm((h) => raAt(solver, pattern, h), targetRaMm, limit);
}
