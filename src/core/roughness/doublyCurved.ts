/**
 * Roughness at a doubly curved point (issue 19): `Rz`, `Ra`, `Rq` of the cross-feed section the
 * passes leave, as roughness.ts defines them on every surface, through the registry's doubly curved
 * model (surfaces/doublyCurvedPoint.ts): heights measured along the normal (radially about `m`, the
 * line through (0, 0, -Rc) parallel to the feed), lengths as arc length along the equator, each
 * flank's width the model's `flankWidths` (a straight radius's the cylinder's or the plane's). What
 * is the point's own: the largest Ra while leaving a scallop and the scallop height a target Ra
 * needs, both over the model's limits and forward answer. Lengths mm.
 */

import { type CurvedPoint, curvedForward, curvedLimits } from '../surfaces/doublyCurvedPoint';
import type { ExactForward, ExactInverse } from '../surfaces/surface';
import { exactRoughness, exactRoughnessAtInterval, heightForRaMm, type Roughness } from './roughness';

/**
 * Roughness (mm) of the surface that passes of a forward answer (the model's) leave at the point.
 * Zigzag includes the other cusp's flank pair (two step-overs per period), as on cylinders.
 */
export function doublyCurvedRoughness(c: CurvedPoint, e: ExactForward): Roughness {
  return exactRoughness({ ...c.tool, pattern: c.pattern, surface: c.surface, scallopHeightMm: e.cuspHeightMm }, e);
}

/** Roughness (mm) of the surface that passes `e.intervalMm` apart leave (the model's inverse answer). */
export function doublyCurvedRoughnessAtInterval(c: CurvedPoint, e: ExactInverse): Roughness {
  return exactRoughnessAtInterval(c.tool, c.pattern, e, c.surface);
}

/** The Ra (mm) that the passes leaving scallop height `h` (mm, below the limits) leave. */
function raAt(c: CurvedPoint, h: number): number {
  return doublyCurvedRoughness(c, curvedForward(c, h)).raMm;
}

/**
 * The largest Ra (mm) a tool, posture and pattern leave at a doubly curved point while leaving a
 * scallop (at the limit height, as roughness.ts's maxRaMm); 0 when no scallop forms.
 * @param c the point, not gouging.
 */
export function doublyCurvedMaxRaMm(c: CurvedPoint): number {
  const limit = curvedLimits(c).limitMm;
  if (!(limit > 0)) return 0;
  return raAt(c, limit * (1 - 1e-12));
}

/**
 * The scallop height h (mm) whose passes leave roughness `targetRaMm` at a doubly curved point
 * (roughness.ts's heightForRaMm on this point's Ra). Requires 0 < target < doublyCurvedMaxRaMm.
 */
export function doublyCurvedHeightForRaMm(c: CurvedPoint, targetRaMm: number): number {
  const limit = curvedLimits(c).limitMm * (1 - 1e-12);
  return heightForRaMm((h) => raAt(c, h), targetRaMm, limit);
}
