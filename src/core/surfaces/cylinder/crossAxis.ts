/**
 * Axis across the feed (see ../cylinder.ts's module comment): the revolved profile's chords, its
 * width at a radial height and the inverse, and where the shank starts to shape it. Lengths mm.
 */
import { bracketedRoot, maximise } from '../../math/rootFinder';
import type { Placement } from '../../tool/placement';

/**
 * The bottom disk's chords in meridian coordinates: on the chord at y, the point nearest the axis
 * (convex) or farthest from it (concave), and its radial height above the design surface.
 */
export interface Chords {
  readonly yLo: number;
  readonly yHi: number;
  /**
   * Signed radial height (mm) of the chord's chosen point: `rho - Rs` convex, `|Rs| - rho` concave,
   * computed as `(x^2 + z (z + 2 Rs)) / (rho + |Rs|)` without cancellation (x, z relative to the
   * contact), so that scallops of a nanometre on a cylinder of a kilometre keep their digits.
   */
  height(y: number): number;
}

export function crossChords(p: Placement, rs: number): Chords {
  const rb = p.ringRadiusMm;
  const { centre, v1, v2 } = p;
  const gy1 = v1[1];
  const gy2 = v2[1];
  const G = Math.sqrt(gy1 * gy1 + gy2 * gy2);
  const concave = rs < 0;
  const side = concave ? -1 : 1;
  const abs = Math.abs(rs);
  // A disk point: centre + u v1 + w v2 (u^2 + w^2 <= Rb^2), relative to the contact; the axis runs
  // along Y through (x = 0, z = -Rs). Its squared distance from the axis, and its radial height.
  const rho2 = (x: number, z: number) => x * x + (z + rs) * (z + rs);
  const heightOf = (x: number, z: number) => (side * (x * x + z * (z + 2 * rs))) / (Math.sqrt(rho2(x, z)) + abs);
  const at = (u: number, w: number, out: number[]) => {
    out[0] = centre[0] + u * v1[0] + w * v2[0];
    out[1] = centre[2] + u * v1[2] + w * v2[2];
  };
  const pa = [0, 0];
  const pb = [0, 0];
  const pf = [0, 0];
  if (!(rb > 0) || !(G > 0)) {
    // A ball end (one point), or a disk seen edge-on along Y (all at one y): a single chord.
    const y = centre[1];
    const pts: Array<[number, number]> =
      rb > 0
        ? [
            [rb, 0],
            [-rb, 0],
            [0, rb],
            [0, -rb],
          ]
        : [[0, 0]];
    const heights = pts.map(([u, w]) => {
      at(u, w, pa);
      return { r2: rho2(pa[0] as number, pa[1] as number), h: heightOf(pa[0] as number, pa[1] as number) };
    });
    heights.sort((m, n) => m.r2 - n.r2);
    const chosen = (concave ? heights[heights.length - 1] : heights[0]) as { h: number };
    return { yLo: y, yHi: y, height: () => chosen.h };
  }
  return {
    yLo: centre[1] - rb * G,
    yHi: centre[1] + rb * G,
    height(y) {
      const c = Math.min(rb * G, Math.max(-rb * G, y - centre[1]));
      // Chord: (u, w) = c g / G^2 + tau g_perp / G, |tau| <= sqrt(Rb^2 - c^2 / G^2).
      const u0 = (c * gy1) / (G * G);
      const w0 = (c * gy2) / (G * G);
      const du = -gy2 / G;
      const dw = gy1 / G;
      const tMax = Math.sqrt(Math.max(0, rb * rb - (c * c) / (G * G)));
      at(u0 + tMax * du, w0 + tMax * dw, pa);
      at(u0 - tMax * du, w0 - tMax * dw, pb);
      const ra = rho2(pa[0] as number, pa[1] as number);
      const rbb = rho2(pb[0] as number, pb[1] as number);
      if (concave)
        return ra >= rbb ? heightOf(pa[0] as number, pa[1] as number) : heightOf(pb[0] as number, pb[1] as number);
      // Convex: the distance along a straight chord is convex; its minimum is at the foot of the
      // axis on the chord's line (clipped to the chord).
      at(u0, w0, pf);
      const x0 = pf[0] as number;
      const z0 = (pf[1] as number) + rs;
      const dx = du * v1[0] + dw * v2[0];
      const dz = du * v1[2] + dw * v2[2];
      const den = dx * dx + dz * dz;
      const tau = den > 0 ? Math.min(tMax, Math.max(-tMax, -(x0 * dx + z0 * dz) / den)) : 0;
      at(u0 + tau * du, w0 + tau * dw, pf);
      const rf = rho2(pf[0] as number, pf[1] as number);
      const q = rf <= ra && rf <= rbb ? pf : ra <= rbb ? pa : pb;
      return heightOf(q[0] as number, q[1] as number);
    },
  };
}

/**
 * Width of a flank of the revolved profile at radial height h (axis across the feed): the largest
 * distance out from the contact (along Y) at which some chord's circle reaches radius |Rs| + s h.
 */
export function crossWidthAtHeight(ch: Chords, sign: number, rcr: number, h: number, contactY: number): number {
  // Reach of the chord at y: its circle (radius Rcr around its point, radial height d) at height h.
  const reach = (y: number) => {
    const gap = ch.height(y) - h;
    if (gap <= 0) return rcr;
    return gap <= rcr ? Math.sqrt((rcr - gap) * (rcr + gap)) : Number.NEGATIVE_INFINITY;
  };
  const f = (y: number) => sign * (y - contactY) + reach(y);
  if (!(ch.yHi > ch.yLo)) return f(ch.yLo);
  // The maximum is flat, so 1e-13 of the disk's span in y leaves its value exact to the last bits
  // (a kink, where the nearest point of a chord moves to its end, is handled by Brent's golden steps).
  return maximise({ value: f }, ch.yLo, ch.yHi, 16, 1e-13 * (ch.yHi - ch.yLo), undefined, contactY);
}

/** Radial height of the revolved profile at a distance w out from the contact (the inverse). */
export function crossHeightAtWidth(ch: Chords, sign: number, rcr: number, w: number, contactY: number): number {
  const Y = contactY + sign * w;
  // The profile's radial height at Y: the lowest, over chords within Rcr of Y, of the chord point's
  // height less the circle's vertical reach, d(y) - sqrt(Rcr^2 - (Y - y)^2). Scan then Brent.
  const lo = Math.max(ch.yLo, Y - rcr);
  const hi = Math.min(ch.yHi, Y + rcr);
  const f = (y: number) => {
    const d = Y - y;
    const v = Math.sqrt(Math.max(0, (rcr - d) * (rcr + d)));
    return v - ch.height(y);
  };
  if (!(hi >= lo)) return Number.POSITIVE_INFINITY;
  const top = hi > lo ? maximise({ value: f }, lo, hi, 16, 1e-13 * Math.max(hi - lo, rcr)) : f(lo);
  return -top;
}

/**
 * Radial heights (mm) at which the shank starts to shape each flank of the revolved profile (axis
 * across the feed), or null on a side where it does not. A pass turns the tool about the axis, so
 * the profile at y is the point of the tool's slice at y nearest the axis (convex; farthest,
 * concave). The shank starts to cut where that point moves from the end onto the shank, across the
 * equator (the circle of radius R at the corner's top, `O + R r(t)`), where the two surfaces share
 * the normal r(t). There the slice's boundary normal, (r_x, r_z), points at the axis (convex: the
 * nearest point of a convex slice; concave: away from it, the farthest):
 *
 *   F(t) = P_x r_z - (P_z + Rs) r_x = 0,   side (-(P_x r_x + (P_z + Rs) r_z)) > 0,
 *
 * P relative to the contact, side = sign(Rs). Roots by a scan of the ring and the shared bracketed root; on each side
 * the one nearest the contact. At the equator's points across the axis (r = +-Y: the widest point
 * of an untilted tool, where the shank joins without cutting) the slice's normal vanishes; those
 * are left out.
 */
export function crossShankHeights(p: Placement, rs: number): { right: number | null; left: number | null } {
  const R = p.ringRadiusMm + p.cornerRadiusMm;
  const { centre, v1, v2 } = p;
  const side = rs > 0 ? 1 : -1;
  const r = [0, 0, 0];
  const P = [0, 0, 0];
  const at = (t: number) => {
    const sn = Math.sin(t);
    const c = Math.cos(t);
    for (let k = 0; k < 3; k++) {
      r[k] = sn * (v1[k] as number) + c * (v2[k] as number);
      P[k] = (centre[k] as number) + R * (r[k] as number);
    }
    return (P[0] as number) * (r[2] as number) - ((P[2] as number) + rs) * (r[0] as number);
  };
  const ring = { value: at };
  let right: { y: number; h: number } | null = null;
  let left: { y: number; h: number } | null = null;
  const n = 64;
  let tPrev = 0;
  let fPrev = at(0);
  for (let i = 1; i <= n; i++) {
    const t = (2 * Math.PI * i) / n;
    const f = at(t);
    if (fPrev <= 0 !== f <= 0) {
      at(bracketedRoot(ring, tPrev, t, fPrev, f, 0));
      const [x, y, z] = P as [number, number, number];
      const rx = r[0] as number;
      const rz = r[2] as number;
      if (Math.sqrt(rx * rx + rz * rz) > 1e-9 && side * -(x * rx + (z + rs) * rz) > 0) {
        const h = (side * (x * x + z * (z + 2 * rs))) / (Math.sqrt(x * x + (z + rs) * (z + rs)) + Math.abs(rs));
        if (y > 0 && (right === null || y < right.y)) right = { y, h };
        if (y < 0 && (left === null || y > left.y)) left = { y, h };
      }
    }
    tPrev = t;
    fPrev = f;
  }
  return { right: right?.h ?? null, left: left?.h ?? null };
}
