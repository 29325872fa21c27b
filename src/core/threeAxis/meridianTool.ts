/**
 * The upright tool's meridian profile, the 2D picture behind waterline passes on a surface of
 * revolution about a vertical axis (section 2b of shared/notes/doubly-curved-and-3-axis.md).
 *
 * Why 2D is exact. The tool is a solid of revolution about its vertical axis: its horizontal
 * slice at height `zeta` above the tip is a disk of radius `rho(zeta)` (`Rb + sqrt(Rcr^2 -
 * (Rcr - zeta)^2)` on the corner, `R` on the shank). Turning the tool about the surface's
 * (parallel, vertical) axis, a slice centred at distance `d` from that axis sweeps the annulus
 * of radii `|d - rho|` to `d + rho` (all radii from 0 when it covers the axis). So the swept
 * solid's section in a half-plane through the axis is `{(r, z) : |r - d| <= rho(z - zT)}`: the
 * tool's own meridian profile, with nothing else (the part of the tool across the axis sweeps
 * radii `r + d >= |r - d|`, never lower). Both passes of a waterline pair are such profiles in
 * the same meridian plane, and the cusp between them is a plane intersection of two translated
 * copies of one convex profile.
 *
 * Frame (used by all the meridian modules): in the meridian plane through the upper pass's CC
 * point, origin at that point, `s` horizontal pointing down the slope, `z` up. The surface
 * normal at slope `alpha` is `n = (sin alpha, cos alpha)`; the tool touches with the lower part
 * of its up-slope corner (outward normal `-n`), so its corner centre is `CC + Rcr n`, its axis
 * `Rb` further down-slope and its tip (the lowest point on the axis, where a CAM system puts
 * the tool) `Rcr` below the corner centre:
 *
 *     tip = CC + (Rcr sin alpha + Rb, -Rcr (1 - cos alpha)).
 *
 * Profile about the tip, `u = s - s_tip`: `g(u) = 0` for `|u| <= Rb` (flat bottom),
 * `Rcr - sqrt(Rcr^2 - (|u| - Rb)^2)` for `Rb < |u| <= R` (corner), the shank a vertical wall at
 * `|u| = R` from the height `Rcr` up; `g` is convex and even.
 */

/** The tool as the meridian modules use it (mm). */
export interface MeridianTool {
  /** Tool radius R, mm (0.001 to 1000). */
  readonly R: number;
  /** Corner radius Rcr, mm, 0 <= Rcr <= R. */
  readonly rcr: number;
  /** R - Rcr, mm: half the flat bottom. */
  readonly rb: number;
}

/** The meridian tool of radius `toolRadiusMm` and corner radius `cornerRadiusMm` (mm). */
export function meridianTool(toolRadiusMm: number, cornerRadiusMm: number): MeridianTool {
  return { R: toolRadiusMm, rcr: cornerRadiusMm, rb: toolRadiusMm - cornerRadiusMm };
}

/**
 * Height (mm) of the tool's lower boundary above its tip at horizontal offset `u` (mm) from its
 * axis: `g(u)`; +Infinity beyond the shank (`|u| > R`), where the tool does not reach down.
 * Written without cancellation near the flat bottom: `w^2 / (Rcr + sqrt(Rcr^2 - w^2))`.
 */
export function profileHeightMm(t: MeridianTool, u: number): number {
  const a = Math.abs(u);
  if (a <= t.rb) return 0;
  if (a > t.R) return Number.POSITIVE_INFINITY;
  const w = Math.min(a - t.rb, t.rcr);
  return (w * w) / (t.rcr + Math.sqrt((t.rcr - w) * (t.rcr + w)));
}
