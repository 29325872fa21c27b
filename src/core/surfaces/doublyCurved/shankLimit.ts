/**
 * Where the shank starts to form a flank at a doubly curved point (posture-and-surfaces.md: "the
 * shank (the cylinder of radius R above the corner) ... can reach below the scallop height; the
 * tool's side then cuts the surface ... an input error that gives the height at which the shank
 * starts to cut"), measured radially from `m` as every height here.
 *
 * Derivation. The shank's points are `p(t, s) = O + R r(t) + s a` (s >= 0); a pass maps them into
 * the plane X = 0 by `p -> (p_y, zc(p))` (passSection.ts). The boundary of that image is the fold of
 * the map, where the images of d/ds and d/dt are parallel:
 *
 *   a_y (grad zc . T(t)) - (grad zc . a) T_y(t) = 0,      grad zc = sign(Rf) (p_x, 0, p_z + Rf) / dist(p, l)
 *
 * (T the ring tangent; grad zc = (0, 0, 1) when Rf is infinite, where it reads `(a x T)_x = 0`, the
 * end of the projected ellipse's long axis of posture.ts). The shank meets the tool end along its
 * widest circle (s = 0, the corner's circle of radius R), and the material boundary passes from the
 * end's section to the shank's fold where the fold leaves that circle: at the root t* on the widest
 * circle on the side the tool leans to (`sign(a_y)`; without tilt the fold is the vertical wall above
 * the widest point, the flank's own top). Its image's radial height is the limit. Lengths mm.
 */

import type { ToolInput } from '../../domain/tool';
import { placeTool } from '../../tool/placement';
import type { PrincipalRadii } from './types';

/** Radial heights (mm) at which the shank starts to form the right / left flank; null where it never does. */
export interface ShankHeights {
  readonly rightMm: number | null;
  readonly leftMm: number | null;
}

/**
 * The shank's heights at a doubly curved point (see the module comment).
 * @param tool validated tool and posture; @param radii signed Rf, Rc (mm) or infinite.
 */
export function shankCutHeights(tool: ToolInput, radii: PrincipalRadii): ShankHeights {
  const p = placeTool(tool);
  const a = p.axis;
  if (a[1] === 0) return { rightMm: null, leftMm: null };
  const R = tool.toolRadiusMm;
  const rf = radii.feedRadiusMm;
  const rc = radii.crossRadiusMm;
  const finiteRf = Number.isFinite(rf);
  const point = (t: number, out: number[]) => {
    const st = Math.sin(t);
    const ct = Math.cos(t);
    for (let i = 0; i < 3; i++)
      out[i] = (p.centre[i] as number) + R * (st * (p.v1[i] as number) + ct * (p.v2[i] as number));
  };
  const w = [0, 0, 0];
  // The fold condition on the widest circle.
  const fold = (t: number) => {
    point(t, w);
    const st = Math.sin(t);
    const ct = Math.cos(t);
    const T = [0, 1, 2].map((i) => ct * (p.v1[i] as number) - st * (p.v2[i] as number)) as [number, number, number];
    let gx = 0;
    let gz = 1;
    if (finiteRf) {
      const qz = (w[2] as number) + rf;
      const dist = Math.hypot(w[0] as number, qz);
      gx = (Math.sign(rf) * (w[0] as number)) / dist;
      gz = (Math.sign(rf) * qz) / dist;
    }
    return a[1] * (gx * T[0] + gz * T[2]) - (gx * a[0] + gz * a[2]) * T[1];
  };
  // Roots of the fold condition around the circle: a scan, then bisection.
  const n = 720;
  let best: { t: number; y: number } | null = null;
  const side = a[1] > 0 ? 1 : -1;
  let prev = fold(0);
  for (let i = 1; i <= n; i++) {
    let hi = (2 * Math.PI * i) / n;
    const f = fold(hi);
    if (f === 0 || prev < 0 !== f < 0) {
      let lo = (2 * Math.PI * (i - 1)) / n;
      let fLo = prev;
      for (let k = 0; k < 100 && hi - lo > 1e-15; k++) {
        const m = 0.5 * (lo + hi);
        const fm = fold(m);
        if (fm < 0 === fLo < 0) {
          lo = m;
          fLo = fm;
        } else hi = m;
      }
      const t = 0.5 * (lo + hi);
      point(t, w);
      if (best === null || side * (w[1] as number) > side * best.y) best = { t, y: w[1] as number };
    }
    prev = f;
  }
  if (best === null) return { rightMm: null, leftMm: null };
  point(best.t, w);
  const x = w[0] as number;
  const y = w[1] as number;
  const z = w[2] as number;
  let zc = z;
  if (finiteRf) {
    const q = z + rf;
    zc = (Math.sign(rf) * (x * x + z * (z + 2 * rf))) / (Math.hypot(x, q) + Math.abs(rf));
  }
  let height = zc;
  if (Number.isFinite(rc)) {
    // Radial from C = (0, -Rc): convex dist - Rc, concave |Rc| - dist, as (y^2 + zc (zc + 2 Rc)) / (dist + |Rc|).
    const q = zc + rc;
    height = (Math.sign(rc) * (y * y + zc * (zc + 2 * rc))) / (Math.hypot(y, q) + Math.abs(rc));
  }
  return side > 0 ? { rightMm: height, leftMm: null } : { rightMm: null, leftMm: height };
}
