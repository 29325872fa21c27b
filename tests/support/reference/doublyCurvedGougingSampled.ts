/**
 * A quick independent gouging check at a doubly curved point (shared/notes/doubly-curved-and-3-axis.md,
 * section 1), sharing nothing with src/core/surfaces/doublyCurved: the tool surface is sampled (the
 * torus corner's lower outer quarter, the bottom disk, the shank up to the nearest concave axis), placed
 * by the reference's own support point (doublyCurvedBruteForce.ts's toolGeometry), and each sample is
 * carried by the pass to the plane X = 0 in closed form (a turn about `l` keeps its Y and its distance
 * to `l`; the crossing on the CC point's side of `l`, as the brute force's sweep takes it). Its radial
 * height above the equator circle (z with Rc straight) is read; the lowest one farther than
 * `excludeMm` from the CC point (in the plane X = 0) is returned. The samples lie on the tool, so the
 * true lowest height is at most the value returned: a clearly negative value proves gouging; a
 * positive one is evidence (up to the sampling) that the tool clears the surface. Lengths mm.
 */
import { toolGeometry } from './doublyCurvedBruteForce';

/** Options: sample spacing along the end (mm), samples along each shank generator, the contact's exclusion (mm). */
export interface SampledGougingOptions {
  readonly spacingMm: number;
  /** Samples along each generator of the shank, denser near the corner (quadratic spacing). */
  readonly shankSamples: number;
  readonly excludeMm: number;
  /** The shank is sampled up to this length above the corner when no axis caps it (mm). */
  readonly shankLengthMm: number;
}

/**
 * The lowest radial height (mm, negative: inside the material) of the swept tool's samples in X = 0,
 * away from the CC point.
 * @param rf signed Rf (mm) or Infinity; @param rc signed Rc (mm) or Infinity.
 */
export function sampledLowestRadialHeightMm(
  tool: { R: number; Rcr: number; leadDeg: number; tiltDeg: number },
  rf: number,
  rc: number,
  o: SampledGougingOptions,
): number {
  const g = toolGeometry(tool.R, tool.Rcr, tool.leadDeg, tool.tiltDeg);
  // The nearest concave axis's height above the CC point (the shank counts up to it).
  const cap = Math.min(rf < 0 ? -rf : Number.POSITIVE_INFINITY, rc < 0 ? -rc : Number.POSITIVE_INFINITY);
  let lowest = Number.POSITIVE_INFINITY;
  const visit = (radial: number, axial: number, t: number, shank: boolean) => {
    const c = Math.cos(t);
    const s = Math.sin(t);
    const x = g.O[0] + radial * (c * g.e1[0] + s * g.e2[0]) + axial * g.a[0];
    const y = g.O[1] + radial * (c * g.e1[1] + s * g.e2[1]) + axial * g.a[1];
    const z = g.O[2] + radial * (c * g.e1[2] + s * g.e2[2]) + axial * g.a[2];
    if (shank && z > cap) return;
    let zc = z;
    if (Number.isFinite(rf)) {
      // l passes through (0, 0, -Rf); the crossing on the CC point's side keeps the distance to l.
      const dist = Math.hypot(x, z + rf);
      zc = rf > 0 ? dist - rf : -rf - dist;
    }
    if (shank && zc > cap) return;
    if (Math.hypot(y, zc) <= o.excludeMm) return;
    let H = zc;
    if (Number.isFinite(rc)) {
      const d = Math.hypot(y, zc + rc);
      H = rc > 0 ? d - rc : -rc - d;
    }
    if (H < lowest) lowest = H;
  };
  const nT = Math.max(16, Math.ceil((2 * Math.PI * g.R) / o.spacingMm));
  for (let i = 0; i < nT; i++) {
    const t = (2 * Math.PI * i) / nT;
    if (g.rcr > 0) {
      const nV = Math.max(2, Math.ceil((0.5 * Math.PI * g.rcr) / o.spacingMm));
      for (let j = 0; j <= nV; j++) {
        const v = -0.5 * Math.PI + (0.5 * Math.PI * j) / nV;
        visit(g.rb + g.rcr * Math.cos(v), g.rcr * Math.sin(v), t, false);
      }
    }
    if (g.rb > 0) {
      const nB = Math.max(1, Math.ceil(g.rb / o.spacingMm));
      for (let j = 0; j <= nB; j++) visit((g.rb * j) / nB, -g.rcr, t, false);
    }
    // The shank: up to the cap (its generators rise at most along the axis), else a fixed length.
    const length = Number.isFinite(cap) ? (cap + 2 * g.R) / Math.max(0.05, g.a[2]) : o.shankLengthMm;
    const nS = o.shankSamples;
    for (let j = 0; j <= nS; j++) visit(g.R, length * (j / nS) ** 2, t, true);
  }
  return lowest;
}
