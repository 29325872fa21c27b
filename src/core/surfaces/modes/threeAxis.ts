/**
 * Three-axis machining as a machine mode (mode.ts; shared/notes/doubly-curved-and-3-axis.md,
 * section 2a): the tool stays upright, and the slope `alpha` and the raster angle `psi` (90 for
 * waterline passes) give its lead and tilt at the CC point in closed form (threeAxis/slopePosture.ts),
 * over the plane's model: the sloped plane is the plane at that posture, not a surface of its own.
 * Feeding down the slope is the same upright tool on the same line, so zigzag passes leave what
 * one-way passes leave: the pattern is one-way. Waterline passes on a surface of revolution are
 * not congruent (surface.ts): threeAxis/waterlineRevolution.ts answers them; the programmed steps
 * (Lxy, dz) stay threeAxis/slopedPlane.ts's. Angles degrees.
 */
import type { ThreeAxisPasses } from '../../threeAxis/slopedPlane';
import { slopePosture } from '../../threeAxis/slopePosture';
import type { MachineMode, ModeError } from '../mode';

/** The upright tool over a slope `slopeDeg` (0 <= alpha < 90), with raster or waterline passes. */
export interface ThreeAxisMode {
  readonly kind: 'threeAxis';
  readonly slopeDeg: number;
  readonly passes: ThreeAxisPasses;
  /** Raster angle psi in plan from the fall line, degrees, 0 to 90; ignored for waterline (90). */
  readonly rasterAngleDeg: number;
}

function check(mode: ThreeAxisMode): ModeError[] {
  const out: ModeError[] = [];
  const a = mode.slopeDeg;
  if (!(a >= 0 && a < 90))
    out.push({
      parameter: 'slope',
      message: `Slope must be from 0 to below 90 degrees (got ${a}): a vertical wall is cut flat by the side of the tool.`,
    });
  else if (mode.passes === 'waterline' && a === 0)
    out.push({ parameter: 'slope', message: 'Slope must be above 0 degrees for waterline passes (got 0).' });
  const psi = mode.rasterAngleDeg;
  if (mode.passes === 'raster' && !(psi >= 0 && psi <= 90))
    out.push({ parameter: 'rasterAngle', message: `Raster angle must be from 0 to 90 degrees (got ${psi}).` });
  return out;
}

/** The upright tool's lead and tilt (degrees) over the slope, one-way. */
function posture(mode: ThreeAxisMode) {
  const p = slopePosture(mode.slopeDeg, mode.passes === 'waterline' ? 90 : mode.rasterAngleDeg);
  return { leadAngleDeg: p.leadDeg, tiltAngleDeg: p.tiltDeg, pattern: 'one-way' as const };
}

/** The three-axis mode: a posture on the plane (the sloped plane). */
export const threeAxisMode: MachineMode<ThreeAxisMode> = {
  kind: 'threeAxis',
  surfaceKinds: ['plane'],
  check,
  posture,
  refusal: (kind) =>
    `Three-axis machining is answered on a sloped plane (or, waterline, a surface of revolution), not on a surface of kind "${kind}": the upright tool's posture is known there only.`,
};
