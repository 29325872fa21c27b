/**
 * The lead and tilt that a sloped plane gives an upright tool (three-axis machining, section 2a
 * of shared/notes/doubly-curved-and-3-axis.md), in closed form.
 *
 * Machine frame: `Zm` up, the tool axis `Zm`. The plane has slope `alpha` (its normal makes
 * `alpha` with `Zm`); with `x` the uphill plan direction its normal is `n = (-sin a, 0, cos a)`.
 * A raster pass runs in the vertical plane whose plan direction makes `psi` with the fall line:
 * plan direction `(cos psi, -sin psi, 0)`, so the CC path (the plane cut by that vertical
 * plane) has the direction `X = (cos psi, -sin psi, tan a cos psi) / N`,
 * `N = sqrt(1 + tan^2 a cos^2 psi)`: it climbs the slope (lead >= 0) and has the uphill side on
 * its left (tilt >= 0). Local frame of posture-and-surfaces.md: `Z = n`, `X` the feed,
 * `Y = Z x X`. The tool axis `Zm` in that frame (`Zm . X`, `Zm . Y = det(Zm, Z, X)`, `Zm . Z`):
 *
 *     a_X = sin a cos psi / D,   a_Y = sin a cos a sin psi / D,   a_Z = cos a,
 *     D = sqrt(cos^2 psi + cos^2 a sin^2 psi) = sqrt(1 - sin^2 a sin^2 psi)
 *
 * (unit: `a_X^2 + a_Y^2 = sin^2 a (cos^2 psi + cos^2 a sin^2 psi) / D^2 = sin^2 a`). With
 * `a = (cos b sin r, sin b, cos b cos r)`:
 *
 *     lead  rho  = atan2(sin a cos psi, cos a D)
 *     tilt  beta = atan2(sin a cos a sin psi, sqrt(cos^2 psi + cos^4 a sin^2 psi))
 *
 * `psi = 0` (up and down the fall line): `rho = alpha`, `beta = 0`; `psi = 90` (contour,
 * waterline): `rho = 0`, `beta = alpha`. Feeding down the slope instead gives `(-rho, -beta)`:
 * the same upright tool translating along the same line, so the same surface (one-way equals
 * zigzag); the up-slope feed is the one inside the posture solver's domain `0 <= rho < 90`.
 *
 * The programmed steps. Adjacent CC paths are `L` apart along `Y` (in the plane). The vertical
 * pass planes have the horizontal normal `m = Zm x X / |Zm x X|`, so
 * `Lxy = L |Y . m| = L (Zm . Z) / sqrt(1 - a_X^2) = L cos a / (cos a / D) = L D`.
 * The height difference of adjacent paths is `L (Y . Zm) = L a_Y = L sin beta`; for waterline
 * (`psi = 90`) that is `dz = L sin alpha` (and `Lxy = L cos alpha`).
 */
import { cosDeg, sinDeg } from './angles';

/** The posture an upright tool takes on a sloped plane, at the CC point. */
export interface SlopePosture {
  /** Lead angle rho, radians, [0, pi/2) for slopes below 90 degrees. */
  readonly leadRad: number;
  /** Tilt angle beta, radians, [0, pi/2): the shank leans uphill (+Y). */
  readonly tiltRad: number;
  /** Lead and tilt in degrees. */
  readonly leadDeg: number;
  readonly tiltDeg: number;
  /** The vertical (tool axis) in the local frame: a_X, a_Y, a_Z (unit vector). */
  readonly axis: readonly [number, number, number];
  /** `Lxy / L = sqrt(cos^2 psi + cos^2 alpha sin^2 psi)`, in [cos alpha, 1]. */
  readonly horizontalStepPerInterval: number;
  /** Height difference of adjacent CC paths per unit L: `sin beta` (`sin alpha` for waterline). */
  readonly verticalStepPerInterval: number;
}

/**
 * The lead and tilt of an upright tool on a plane of slope `slopeDeg` (0 <= alpha < 90 degrees)
 * for raster passes at plan angle `rasterAngleDeg` to the fall line (0 <= psi <= 90; 90 is the
 * contour, waterline). Closed form, derived in this module's comment; feed up the slope, uphill
 * on the left (+Y). At alpha = 90 (a vertical wall) the posture is outside the posture solver's
 * domain and this returns lead 90 or a degenerate frame: callers refuse that slope first.
 */
export function slopePosture(slopeDeg: number, rasterAngleDeg: number): SlopePosture {
  const sa = sinDeg(slopeDeg);
  const ca = cosDeg(slopeDeg);
  const sp = sinDeg(rasterAngleDeg);
  const cp = cosDeg(rasterAngleDeg);
  // Exactly 1 on a flat floor (the sum of squares would round).
  const d = sa === 0 ? 1 : Math.sqrt(cp * cp + ca * ca * sp * sp);
  const leadRad = Math.atan2(sa * cp, ca * d);
  const tiltRad = Math.atan2(sa * ca * sp, Math.sqrt(cp * cp + ca * ca * ca * ca * sp * sp));
  const axis: [number, number, number] = d > 0 ? [(sa * cp) / d, (sa * ca * sp) / d, ca] : [0, sa, ca];
  return {
    leadRad,
    tiltRad,
    leadDeg: (leadRad * 180) / Math.PI,
    tiltDeg: (tiltRad * 180) / Math.PI,
    axis,
    horizontalStepPerInterval: d,
    verticalStepPerInterval: axis[1],
  };
}
