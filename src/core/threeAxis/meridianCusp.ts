/**
 * The cusp between two waterline passes in the meridian plane (frame of meridianTool.ts), and its
 * height measured along the design surface's normal.
 *
 * The lower tool is the upper one translated by `(dS, -dz)` (meridianPasses.ts), both >= 0. The
 * material left is below both lower boundaries `z_i(s) = zT_i + g(s - sT_i)`; `g` is convex, so
 * `F(s) = z_1(s) - z_0(s)` never increases, and the cusp is its one root between the CC points.
 * On the lower tool the cusp lies on the up-slope corner between its CC point and the corner's
 * top `K1 = tip1 + (-R, Rcr)`, where the shank starts; if the upper tool's boundary passes above
 * `K1` (`F(K1_s) <= 0`), the lower tool's shank forms the cusp: outside the model (the notes'
 * shank rule), reported as such. On the upper tool the cusp lies on its up-slope corner, its
 * flat bottom or its down-slope corner: `F` at the bottom's two ends says which, and the point
 * is then in closed form:
 *
 * - corner against corner (two circles of radius Rcr, centres `C0` and `C1 = A1`, `d = C1 - C0`):
 *   the lower of the two crossings, `(C0 + C1)/2 + w (d_z, -d_s)/|d|`, `w = sqrt(Rcr^2 - |d|^2/4)`
 *   (with `d_s >= 0`, `d_z <= 0` this is the crossing of the two lower arcs);
 * - flat bottom against corner: `(A1_s - sqrt(dz (2 Rcr - dz)), tip0_z)`.
 *
 * Height along the normal, measured radially from the meridian circle's centre `M = -Rc n0` (the
 * CC point at the origin, `v` the cusp): convex `|v - M| - Rc`, concave `|Rc| - |v - M|`, both
 *
 *     h = (2 v.n0 + k |v|^2) / (1 + |n0 + k v|),   k = 1/Rc (0: straight, h = v.n0),
 *
 * free of cancellation for any Rc.
 */
import type { Meridian, PassPair } from './meridianPasses';
import { type MeridianTool, profileHeightMm } from './meridianTool';

/** Relative tolerance (of Rcr) for the upper boundary passing through the corner top K1. */
const K1_TOLERANCE = 1e-12;

/** The cusp of a pair of passes, filled in place. */
export interface MeridianCusp {
  /** The cusp point, mm (frame of meridianTool.ts). */
  s: number;
  z: number;
  /** Its height along the design surface's normal (radial from the meridian's centre), mm. */
  heightMm: number;
  /**
   * True when the lower tool's shank (its vertical side above the corner) forms the cusp: the
   * point is then where the upper tool's boundary meets that side (heights grow on with L).
   */
  onShank: boolean;
  /** True when the upper tool's flat bottom (not a corner) carries the cusp. */
  onBottom: boolean;
}

/** A cusp's scratch state. */
export function newMeridianCusp(): MeridianCusp {
  return { s: 0, z: 0, heightMm: 0, onShank: false, onBottom: false };
}

/** Height (mm) of the point `(s, z)` (relative to the upper CC point) along the design surface's normal. */
export function normalHeightMm(m: Meridian, s: number, z: number): number {
  const along = 2 * (s * m.sin0 + z * m.cos0);
  if (m.k === 0) return along / 2;
  const ns = m.sin0 + m.k * s;
  const nz = m.cos0 + m.k * z;
  return (along + m.k * (s * s + z * z)) / (1 + Math.sqrt(ns * ns + nz * nz));
}

/** Fills `out` with the cusp of `pair` (see the module comment). */
export function fillCusp(t: MeridianTool, m: Meridian, pair: PassPair, out: MeridianCusp): void {
  const { R, rcr, rb } = t;
  const dS = pair.dS;
  const dz = pair.dz;
  // The upper tool's boundary below the lower tool's corner top K1 = tip1 + (-R, Rcr)? Through K1
  // itself (to rounding) the corner's end still forms the cusp: at 90 degrees on a concave meridian
  // with Rcr = |Rc| / 2 the boundary passes through K1 at every L, and that is answered as just below 90.
  const gK = profileHeightMm(t, dS - R);
  out.onBottom = false;
  if (!(rcr - dz - gK > -K1_TOLERANCE * rcr)) {
    out.onShank = true;
    out.s = pair.tipS1 - R;
    out.z = pair.tipZ0 + gK;
    out.heightMm = Number.isFinite(out.z) ? normalHeightMm(m, out.s, out.z) : Number.POSITIVE_INFINITY;
    return;
  }
  out.onShank = false;
  // F at the ends of the upper tool's flat bottom (u = -Rb and u = +Rb about tip0).
  const fLeft = profileHeightMm(t, -rb - dS) - dz;
  let c0s: number;
  if (fLeft <= 0) c0s = pair.tipS0 - rb;
  else if (profileHeightMm(t, rb - dS) - dz <= 0) {
    out.onBottom = true;
    const q = Math.max(0, dz * (2 * rcr - dz));
    out.s = pair.tipS1 - rb - Math.sqrt(q);
    out.z = pair.tipZ0;
    out.heightMm = normalHeightMm(m, out.s, out.z);
    return;
  } else c0s = pair.tipS0 + rb;
  // Corner against corner: C0 = (c0s, tip0_z + Rcr), C1 = (tip1_s - Rb, tip1_z + Rcr).
  const c0z = pair.tipZ0 + rcr;
  const ds = pair.tipS1 - rb - c0s;
  const dzc = -dz;
  const dist = Math.sqrt(ds * ds + dzc * dzc);
  const halfD = dist / 2;
  const w = Math.sqrt(Math.max(0, (rcr - halfD) * (rcr + halfD)));
  if (dist > 0) {
    out.s = c0s + ds / 2 + (w * dzc) / dist;
    out.z = c0z + dzc / 2 - (w * ds) / dist;
  } else {
    out.s = c0s;
    out.z = c0z - rcr;
  }
  out.heightMm = normalHeightMm(m, out.s, out.z);
}
