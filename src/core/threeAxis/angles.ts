/**
 * Sine and cosine of an angle in degrees, exact at the multiples of 90 degrees (so that a
 * slope of 0 or a raster angle of 90 gives exactly 0, not 6e-17, and the posture has no
 * spurious lead of 4e-15 degrees). Elsewhere `Math.sin(deg * pi / 180)`.
 */
import { degToRad } from '../input/units';

/** sin of `angleDeg` (degrees, any finite value); exactly 0 or +-1 at multiples of 90. */
export function sinDeg(angleDeg: number): number {
  const q = angleDeg / 90;
  if (Number.isInteger(q)) return [0, 1, 0, -1][((q % 4) + 4) % 4] as number;
  return Math.sin(degToRad(angleDeg));
}

/** cos of `angleDeg` (degrees, any finite value); exactly 0 or +-1 at multiples of 90. */
export function cosDeg(angleDeg: number): number {
  const q = angleDeg / 90;
  if (Number.isInteger(q)) return [1, 0, -1, 0][((q % 4) + 4) % 4] as number;
  return Math.cos(degToRad(angleDeg));
}
