/**
 * The paper's "3D geometrical computation" (Figure 1, Eqs. 1-3) as a recorded trace.
 *
 * It works only with torus sections and the h pseudo plane, never with the projected
 * profile of profile.ts, so its result is an independent check of the exact solver:
 *  1. start at the ring angle of Eq. 1, `Rb sin(rho) (1 - cos gamma) = h/2`;
 *  2. move along the ring until the section touches the plane at a single point
 *     (`d_s = Rcr`, Eqs. 2-3, with the in-plane distance of the notes);
 *  3. search the ring angles up to that single-contact section (from 0, or for h > 2 Rcr
 *     from the section whose top touches the plane) for the section
 *     whose crossing with the plane lies farthest in Y, refining a grid of n sections
 *     around the best one until neighbouring Y differ by less than the tolerance.
 * Lengths mm, angles radians.
 */
import { cutSection, ringTangent, sectionCentre, type TorusFrame, torusFrame } from './torus';
import type { ForwardInput } from './validate';
import { add, cross, scale, type Vec3 } from './vec';

const DEG = Math.PI / 180;

/** One step of the procedure, in the paper's terms. */
export type TraceStep =
  | {
      /** Steps 2-11: a section visited on the way to the single-contact section. */
      readonly phase: 'approach';
      readonly ringAngleRad: number;
      /** In-plane distance from the section centre to the h pseudo plane, mm. */
      readonly dsMm: number;
    }
  | {
      /** Steps 12-14: the single-contact section and its touching point on the plane. */
      readonly phase: 'single-contact';
      readonly ringAngleRad: number;
      readonly dsMm: number;
      readonly pHp: Vec3;
      /** False when every section meets the plane (no single contact before gamma = pi). */
      readonly found: boolean;
    }
  | {
      /** Steps 16-25: one pass over the search grid; `best` is the farthest crossing. */
      readonly phase: 'search';
      readonly rangeRad: readonly [number, number];
      readonly ringAnglesRad: readonly number[];
      /** Y of each section's farthest crossing with the plane (NaN-free: -Infinity where none). */
      readonly crossingYMm: readonly number[];
      readonly bestIndex: number;
      readonly pHp: Vec3;
    };

export interface Trace {
  readonly steps: readonly TraceStep[];
  /** Step 26: L/2 in mm. */
  readonly halfIntervalMm: number;
  /** The converged P_hp (mm) and its section's ring angle gamma (radians). */
  readonly pHp: Vec3;
  readonly ringAngleRad: number;
}

/** Farthest crossing (largest Y) of the section at gamma with the plane z = h, or null. */
export function farthestCrossing(f: TorusFrame, gamma: number, h: number): Vec3 | null {
  const cut = cutSection(f, gamma, h);
  const c = sectionCentre(f, gamma);
  if (f.cornerRadiusMm === 0) {
    // A flat end's section is a single ring point: it meets the plane only at its own height.
    return Math.abs(c[2] - h) <= 1e-12 * Math.max(1, h) ? c : null;
  }
  if (cut.psi === null) return null;
  const sg = Math.sin(gamma);
  const cg = Math.cos(gamma);
  let best: Vec3 | null = null;
  for (const psi of cut.psi) {
    const cp = Math.cos(psi) * f.cornerRadiusMm;
    const sp = Math.sin(psi) * f.cornerRadiusMm;
    const p: Vec3 = [c[0] + cp * cg * f.xt[0] + sp * f.zt[0], c[1] + cp * sg, h];
    if (best === null || p[1] > best[1]) best = p;
  }
  return best;
}

/** Steps 12-13: the point where the single-contact section touches the plane. */
function touchingPoint(f: TorusFrame, gamma: number): Vec3 {
  const t = ringTangent(f, gamma);
  const nh: Vec3 = [0, 0, 1];
  const m = cross(t, nh);
  const u = cross(t, m);
  const len = Math.hypot(u[0], u[1], u[2]);
  // u = t x (t x n_h) points down the section plane, towards the h pseudo plane.
  return add(sectionCentre(f, gamma), len > 0 ? scale(u, f.cornerRadiusMm / len) : [0, 0, -f.cornerRadiusMm]);
}

/**
 * Runs the procedure of Figure 1 and records every step.
 * @param input validated by validateForward.
 * @param gridSize sections per search pass (odd, >= 5); @param toleranceMm stop when the
 * best crossing and its neighbours differ in Y by less than this (default 1e-13 mm).
 */
export function traceProcedure(input: ForwardInput, gridSize = 9, toleranceMm = 1e-13): Trace {
  const f = torusFrame(input.toolRadiusMm, input.cornerRadiusMm, input.leadAngleDeg * DEG);
  const h = input.scallopHeightMm;
  const rcr = f.cornerRadiusMm;
  const b = f.ringRadiusMm * f.sinRho;
  const steps: TraceStep[] = [];
  const ds = (g: number) => cutSection(f, g, h).inPlaneDistanceMm;

  if (rcr === 0) {
    // Flat end: the ring itself cuts; it reaches height h at cos(gamma) = 1 - h/b (Eq. 1 with h).
    const gamma = Math.acos(Math.max(-1, 1 - h / b));
    const p = sectionCentre(f, gamma);
    steps.push({ phase: 'single-contact', ringAngleRad: gamma, dsMm: 0, pHp: p, found: true });
    return { steps, halfIntervalMm: p[1], pHp: [p[0], p[1], h], ringAngleRad: gamma };
  }

  // Step 2 (Eq. 1): the starting ring angle.
  const cosStart = b > 0 ? 1 - h / (2 * b) : -1;
  const gammaStart = Math.acos(Math.max(-1, Math.min(1, cosStart)));
  steps.push({ phase: 'approach', ringAngleRad: gammaStart, dsMm: ds(gammaStart) });

  /**
   * Steps 6-11 ("update gamma according to Rcr - d_s"): the first ring angle in [from, pi]
   * where d_s reaches `target`, by stepping from the start to bracket it and then regula
   * falsi (Illinois) until |target - d_s| < eps. d_s rises with gamma on [0, pi/2].
   */
  const firstReach = (target: number, from: number): number | null => {
    if (ds(from) >= target) return from;
    if (ds(Math.PI) < target) return null;
    let lo = from;
    let hi = Math.PI;
    if (gammaStart > from && ds(gammaStart) >= target) hi = gammaStart;
    else {
      let g = Math.max(from, gammaStart);
      lo = g;
      const step = Math.max(1e-3, (Math.PI - g) / 16);
      while (g < Math.PI) {
        g = Math.min(Math.PI, g + step);
        const d = ds(g);
        steps.push({ phase: 'approach', ringAngleRad: g, dsMm: d });
        if (d >= target) {
          hi = g;
          break;
        }
        lo = g;
      }
    }
    let fLo = ds(lo) - target;
    let fHi = ds(hi) - target;
    let side = 0;
    let gamma = hi;
    for (let i = 0; i < 100; i++) {
      gamma = (lo * fHi - hi * fLo) / (fHi - fLo);
      if (!(gamma > lo && gamma < hi)) gamma = 0.5 * (lo + hi);
      const fg = ds(gamma) - target;
      steps.push({ phase: 'approach', ringAngleRad: gamma, dsMm: fg + target });
      if (Math.abs(fg) < 1e-14 * rcr || hi - lo < 1e-15) break;
      if (fg < 0) {
        lo = gamma;
        fLo = fg;
        if (side === -1) fHi /= 2;
        side = -1;
      } else {
        hi = gamma;
        fHi = fg;
        if (side === 1) fLo /= 2;
        side = 1;
      }
    }
    return gamma;
  };

  // For h > 2 Rcr the first sections lie wholly below the plane: the range of sections that
  // meet it starts where the section's top touches it (d_s = -Rcr).
  const gammaEnter = firstReach(-rcr, 0) ?? 0;
  const reached = firstReach(rcr, gammaEnter);
  const found = reached !== null;
  const gammaScp = reached ?? Math.PI;
  steps.push({
    phase: 'single-contact',
    ringAngleRad: gammaScp,
    dsMm: ds(gammaScp),
    pHp: touchingPoint(f, gammaScp),
    found,
  });

  // Steps 15-25: grid search over [0, gamma_scp] for the farthest crossing, refined around the best.
  const n = Math.max(5, gridSize | 1);
  let rangeLo = gammaEnter;
  let rangeHi = gammaScp;
  let bestY = Number.NEGATIVE_INFINITY;
  let bestP: Vec3 = [0, 0, h];
  let bestGamma = 0;
  for (let pass = 0; pass < 200; pass++) {
    const angles: number[] = [];
    const ys: number[] = [];
    let bestIndex = 0;
    for (let i = 0; i < n; i++) {
      const g = rangeLo + ((rangeHi - rangeLo) * i) / (n - 1);
      const p = farthestCrossing(f, g, h);
      angles.push(g);
      ys.push(p === null ? Number.NEGATIVE_INFINITY : p[1]);
      if (p !== null && p[1] > bestY) {
        bestY = p[1];
        bestP = p;
        bestGamma = g;
      }
      if ((ys[i] as number) > (ys[bestIndex] as number)) bestIndex = i;
    }
    steps.push({
      phase: 'search',
      rangeRad: [rangeLo, rangeHi],
      ringAnglesRad: angles,
      crossingYMm: ys,
      bestIndex,
      pHp: bestP,
    });
    const left = ys[Math.max(0, bestIndex - 1)] as number;
    const right = ys[Math.min(n - 1, bestIndex + 1)] as number;
    const spread = Math.max(bestY - left, bestY - right);
    // Step 23: the new range is the neighbours of the best section.
    const width = rangeHi - rangeLo;
    rangeLo = angles[Math.max(0, bestIndex - 1)] as number;
    rangeHi = angles[Math.min(n - 1, bestIndex + 1)] as number;
    if ((spread < toleranceMm && width < 1e-3) || width < 1e-15) break;
  }
  return { steps, halfIntervalMm: bestY, pHp: bestP, ringAngleRad: bestGamma };
}
