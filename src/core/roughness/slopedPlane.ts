/**
 * Roughness of a sloped plane machined three-axis (raster at any raster angle, waterline = raster
 * angle 90): the upright tool is the tool at the slope's lead and tilt on a plane (threeAxis/slopePosture.ts),
 * and its passes are congruent (one-way: the same upright tool whichever way it feeds), so Rz, Ra
 * and Rq are the plane's at that posture (roughness.ts), heights along the plane's normal,
 * measured along the plane across the passes. Lengths mm, angles degrees.
 */
import { effectiveRasterAngleDeg, type SlopedPlaneCase } from '../threeAxis/slopedPlane';
import { slopePosture } from '../threeAxis/slopePosture';
import { flankWidthMm, postureShape } from '../tool/posture';
import { type Roughness, roughnessOfSegments } from './roughness';

/**
 * Rz, Ra, Rq (mm) of the surface one-way passes leave on the sloped plane with cusps `cuspHeightMm`
 * high (the cusp of slopedPlaneForward or slopedPlaneInverse; 0 without a scallop gives zeros).
 * Valid cases only (a slope below 90 degrees, the cusp below the case's height limit).
 */
export function slopedPlaneRoughness(c: SlopedPlaneCase, cuspHeightMm: number): Roughness {
  if (!(cuspHeightMm > 0)) return { rzMm: 0, raMm: 0, rqMm: 0, meanMm: 0 };
  const p = slopePosture(c.slopeDeg, effectiveRasterAngleDeg(c));
  const shape = postureShape(c.toolRadiusMm, c.cornerRadiusMm, p.leadRad, p.tiltRad);
  return roughnessOfSegments(shape, [
    { flank: 'right', widthMm: flankWidthMm(shape, 'right', cuspHeightMm), heightMm: cuspHeightMm },
    { flank: 'left', widthMm: flankWidthMm(shape, 'left', cuspHeightMm), heightMm: cuspHeightMm },
  ]);
}
