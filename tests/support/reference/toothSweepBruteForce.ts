/**
 * Independent brute-force reference for the surface a z-tooth end mill leaves on a plane
 * (issue 29, notes/surface-finish.md). It shares nothing with src/core: its own vectors, its
 * own profile, its own Newton solve and its own branch and bound.
 *
 * Method: every tooth edge of every pass that can reach a window is sampled on a lattice in
 * rotation angle and edge arc length; each sample is scattered onto an (x, y) grid of cells,
 * each cell keeping its K = 6 lowest samples of distinct crossings (pass, tooth, revolution, part
 * of the profile: flat, corner or side). A
 * query point is refined by solving exactly (Newton, 2 unknowns: rotation angle and arc
 * length) for the edge point over it from every candidate of its 3 x 3 cells, then along each
 * solution's chain of crossings (tooth k + 1, 2 pi / z later: a cell wider than fz keeps the
 * crossings lowest at its other points); the height is the lowest converged solution.
 *
 * Error. (1) Always, rigorous: the value is a real edge point over the query (an upper bound
 * of the envelope, to the Newton residual, about 1e-15 mm), and every edge point over the
 * query lies within D = 1/density of a lattice sample (Lipschitz: |dP/dphi| <= z fz / 2 pi +
 * e + R per radian, |dP/ds| = 1), so the envelope is at least (lowest sample of the 3 x 3
 * cells) - D: `boundMm`, which halves when the density doubles. (2) On demand, rigorous to any
 * tolerance: `certifyAt` / `certifiedEnvelopeHeightMm`, branch and bound over (phi, s)
 * rectangles with the same Lipschitz bounds (1e-9 mm in 0.03 to 0.2 million evaluations).
 * Refined values agree with the certificate to 1e-14 mm over the tested strata.
 *
 * API: bruteEnvelopeHeightMm (one point), bruteEnvelopeGrid (the x3p grid of a window),
 * certifiedEnvelopeHeightMm, bruteFeedMarkHeightMm (hf on pass 0's CC path y = 0, extremes by
 * golden section), bruteArealParameters (midpoint grid over one cell; extremes refined on
 * request); the pieces: sweepModel, scatterSweep, refineAt, localHeights, certifyAt.
 *
 * READING OF THE NOTES (choices where they leave room; the solver's author reads them alone):
 * 1. The point that positions a pass (the "spindle axis point") is the tool centre point O of
 *    notes/posture-and-surfaces.md (the centre of the ring of corner centres, on the spindle
 *    axis), with the nominal tool (e = 0): its lowest point touches the design plane z = 0 and
 *    the CC path (the nominal contact's track) of pass 0 is y = 0, so O = (x_s, -y0, Oz) with
 *    Oz = Rcr + Rb sqrt(1 - az^2) and y0 = Rb ay az / sqrt(1 - az^2) (0 when az = 1, the flat
 *    bottom is then all lowest: O above the CC path). "Crosses x = 0" is O's x = 0 (for pass 0).
 * 2. Rotation: theta = -2 pi x_s / (z fz) (tooth 0 at theta = 0 when O's x is 0, decreasing:
 *    M3); tooth k at theta + 2 pi k / z; direction w(theta) = cos(theta) u + sin(theta) v with
 *    u = X projected normal to a (normalised) and v = a x u (right-hand about a).
 * 3. Runout: the offset e w(theta + phi_e), i.e. phi_e measured from tooth 0's half-plane in the
 *    same (right-hand about a) sense as theta, added to every edge point of every tooth.
 * 4. Passes: pass j (all integers j) has its CC path at y = j L. One-way: pass 0's motion
 *    translated by (j q P, j L). Zigzag: odd j is pass 0's motion turned by 180 degrees about
 *    the Z axis through the origin ((x, y) -> (-x, -y), so its O crosses x = 0 with its tooth 0
 *    at theta = 0 of its own frame too), then translated by (j q P, j L); even j as one-way.
 *    The pass-phase shift j q P is along +X (the frame's feed direction) for every pass,
 *    including the reversed ones.
 * 5. The feed period P of the pass phase is the period of the pattern along the feed: fz
 *    without runout, z fz with runout (e > 0); `passPhasePeriodMm` overrides it.
 * 6. The edge is the profile from the axis (s = 0) along the flat bottom (r = s), the corner
 *    arc, and the side r = R up to `sideHeightMm` (default R) above the corner-centre plane.
 * 7. Heights are along Z above the design plane; with runout they may be negative.
 */

import { goldenSection } from '../../../src/build/reference/oracles/goldenSection';

export type PassPattern = 'one-way' | 'zigzag';

/** The tool, its posture, the passes and the teeth (mm and radians). */
export interface ToothSweepParams {
  /** Tool radius R (mm). */
  radiusMm: number;
  /** Corner radius Rcr (mm), 0 <= Rcr <= R. */
  cornerRadiusMm: number;
  /** Lead rho (rad), 0 <= rho < pi/2. */
  leadRad: number;
  /** Tilt beta (rad), |beta| < pi/2. */
  tiltRad: number;
  pattern: PassPattern;
  /** Step-over L (mm) between adjacent CC paths. */
  stepOverMm: number;
  /** Number of teeth z >= 1. */
  flutes: number;
  /** Feed per tooth fz (mm). */
  fzMm: number;
  /** Radial runout e (mm) >= 0. */
  runoutMm: number;
  /** Runout phase phi_e (rad) from tooth 0's half-plane, right-hand about a. */
  runoutPhaseRad: number;
  /** Pass phase q in [0, 1): pass j shifted by j q P along +X. */
  passPhase: number;
  /** Height of the cylindrical side above the corner-centre plane (mm); default R. */
  sideHeightMm?: number;
  /** Feed period P of the pass phase (mm); default fz, or z fz with runout. */
  passPhasePeriodMm?: number;
}

/** An axis-aligned window of the design plane (mm). */
export interface Window {
  x0: number;
  x1: number;
  y0: number;
  y1: number;
}

/** A refined envelope height with its bracket. */
export interface BruteHeight {
  /** Lowest converged edge point over the query (mm): a real point, so >= the envelope. */
  heightMm: number;
  /** Rigorous lower bound of the envelope there (mm). */
  lowerBoundMm: number;
  /** heightMm - lowerBoundMm (>= 0): the envelope lies in [lowerBoundMm, heightMm]. */
  boundMm: number;
  /** Largest Newton residual estimate of the returned solution (mm), about 1e-14. */
  newtonErrorMm: number;
  /** Candidates refined and how many converged. */
  candidates: number;
  converged: number;
  /** The lowest crossing (whose edge point gives heightMm). */
  crossing: Crossing;
}

// ---------------------------------------------------------------- small vector helpers

type V3 = [number, number, number];
const dot = (p: V3, q: V3): number => p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
const cross = (p: V3, q: V3): V3 => [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]];
const scale = (p: V3, k: number): V3 => [p[0] * k, p[1] * k, p[2] * k];
const sub = (p: V3, q: V3): V3 => [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
const unit = (p: V3): V3 => scale(p, 1 / Math.sqrt(dot(p, p)));

// ---------------------------------------------------------------- the model

/** The fixed geometry of one parameter set: frame, profile, pass placement, Lipschitz constants. */
export interface SweepModel {
  params: ToothSweepParams;
  a: V3;
  u: V3;
  v: V3;
  rb: number;
  rcr: number;
  r: number;
  sArc: number;
  sMax: number;
  /** O of pass 0 at x_s = 0: (0, oy, oz). */
  oy: number;
  oz: number;
  /** x_s per radian of rotation: z fz / (2 pi). */
  feedPerRad: number;
  /** Pass-phase period P (mm). */
  periodMm: number;
  /** Bound of |dP/dphi| (mm per rad) and of |dz/dphi|. */
  lphi: number;
  lzphi: number;
  /** Largest xy distance of an edge point from O's xy. */
  reachXy: number;
}

/** Build the model, checking the inputs (one-line messages naming the constraint). */
export function sweepModel(params: ToothSweepParams): SweepModel {
  const { radiusMm: r, cornerRadiusMm: rcr, leadRad, tiltRad, flutes, fzMm, runoutMm, stepOverMm } = params;
  const bad = (msg: string): never => {
    throw new Error(`toothSweepBruteForce: ${msg}`);
  };
  if (!(r > 0)) bad('R must be > 0');
  if (!(rcr >= 0 && rcr <= r)) bad('Rcr must be in [0, R]');
  if (!(leadRad >= 0 && leadRad < Math.PI / 2)) bad('lead must be in [0, pi/2)');
  if (!(Math.abs(tiltRad) < Math.PI / 2)) bad('|tilt| must be < pi/2');
  if (!(Number.isInteger(flutes) && flutes >= 1)) bad('flutes must be an integer >= 1');
  if (!(fzMm > 0)) bad('fz must be > 0');
  if (!(runoutMm >= 0)) bad('runout must be >= 0');
  if (!(stepOverMm > 0)) bad('step-over must be > 0');
  if (!(params.passPhase >= 0 && params.passPhase < 1)) bad('pass phase must be in [0, 1)');
  const a: V3 = [Math.cos(tiltRad) * Math.sin(leadRad), Math.sin(tiltRad), Math.cos(tiltRad) * Math.cos(leadRad)];
  const u = unit(sub([1, 0, 0], scale(a, a[0])));
  const v = cross(a, u);
  const rb = r - rcr;
  const side = params.sideHeightMm ?? r;
  const sArc = rb + (rcr * Math.PI) / 2;
  const sin2 = 1 - a[2] * a[2];
  const sinA = sin2 > 1e-30 ? Math.sqrt(sin2) : 0;
  const y0 = sinA > 0 ? (rb * a[1] * a[2]) / sinA : 0;
  const feedPerRad = (flutes * fzMm) / (2 * Math.PI);
  const e = runoutMm;
  return {
    params,
    a,
    u,
    v,
    rb,
    rcr,
    r,
    sArc,
    sMax: sArc + side,
    oy: -y0,
    oz: rcr + rb * sinA,
    feedPerRad,
    periodMm: params.passPhasePeriodMm ?? (e > 0 ? flutes * fzMm : fzMm),
    lphi: feedPerRad + e + r,
    lzphi: (e + r) * sinA,
    reachXy: e + r + Math.max(rcr, side) * sinA,
  };
}

/** A smooth part of the profile (0 flat, 1 corner, 2 side, each extended beyond its ends), or -1: the whole profile. */
export type Piece = -1 | 0 | 1 | 2;

/** Profile in the half-plane: radius r(s), axial h(s) from O, and their derivatives (|(r', h')| = 1). */
function profile(m: SweepModel, s: number, out: Float64Array, piece: Piece = -1): void {
  if (piece === 0 || (piece === -1 && s <= m.rb)) {
    out[0] = s;
    out[1] = -m.rcr;
    out[2] = 1;
    out[3] = 0;
    return;
  }
  if (piece === 1 || (piece === -1 && s <= m.sArc && m.rcr > 0)) {
    const psi = (s - m.rb) / m.rcr;
    out[0] = m.rb + m.rcr * Math.sin(psi);
    out[1] = -m.rcr * Math.cos(psi);
    out[2] = Math.cos(psi);
    out[3] = Math.sin(psi);
    return;
  }
  out[0] = m.r;
  out[1] = s - m.sArc;
  out[2] = 0;
  out[3] = 1;
}

/** M3: theta decreases as the tool advances (theta = SPIN * phi, phi the rotation parameter). */
const SPIN = -1;

/** Angle theta_k of tooth k (about a from u) at rotation phi: theta = -phi, tooth 0 at 0 when O's x is 0. */
function toothAngle(phi: number, k: number, flutes: number): number {
  return SPIN * phi + (2 * Math.PI * k) / flutes;
}

/** Direction angle of the runout offset: phi_e from tooth 0's half-plane, rotating with the tool. */
function runoutAngle(phi: number, runoutPhaseRad: number): number {
  return SPIN * phi + runoutPhaseRad;
}

/** Placement of pass j: mirrored (zigzag odd) and its translation. */
function passPlacement(m: SweepModel, j: number): { mirror: boolean; dx: number; dy: number } {
  const p = m.params;
  return {
    mirror: p.pattern === 'zigzag' && Math.abs(j) % 2 === 1,
    dx: j * p.passPhase * m.periodMm,
    dy: j * p.stepOverMm,
  };
}

/**
 * Edge point of tooth k of pass j at rotation phi (rad, theta = -phi) and arc length s, global,
 * with dP/dphi and dP/ds: out = [x, y, z, xphi, yphi, zphi, xs, ys, zs].
 */
export function edgePoint(
  m: SweepModel,
  j: number,
  k: number,
  phi: number,
  s: number,
  out: Float64Array,
  piece: Piece = -1,
): void {
  const p = m.params;
  const prof = PROF;
  profile(m, s, prof, piece);
  const rr = prof[0] as number;
  const hh = prof[1] as number;
  const rp = prof[2] as number;
  const hp = prof[3] as number;
  const th = toothAngle(phi, k, p.flutes);
  const ck = Math.cos(th);
  const sk = Math.sin(th);
  const tr = runoutAngle(phi, p.runoutPhaseRad);
  const cr = Math.cos(tr);
  const sr = Math.sin(tr);
  const { u, v, a } = m;
  const e = p.runoutMm;
  const xs = m.feedPerRad * phi;
  // tooth and runout directions w and their derivatives in phi (theta = SPIN phi + const)
  const w = (c: number, sn: number, i: 0 | 1 | 2): number => c * u[i] + sn * v[i];
  const dw = (c: number, sn: number, i: 0 | 1 | 2): number => SPIN * (-sn * u[i] + c * v[i]);
  const x = xs + e * w(cr, sr, 0) + rr * w(ck, sk, 0) + hh * a[0];
  const y = m.oy + e * w(cr, sr, 1) + rr * w(ck, sk, 1) + hh * a[1];
  const zz = m.oz + e * w(cr, sr, 2) + rr * w(ck, sk, 2) + hh * a[2];
  const xp = m.feedPerRad + e * dw(cr, sr, 0) + rr * dw(ck, sk, 0);
  const yp = e * dw(cr, sr, 1) + rr * dw(ck, sk, 1);
  const zp = e * dw(cr, sr, 2) + rr * dw(ck, sk, 2);
  const pl = passPlacement(m, j);
  const sg = pl.mirror ? -1 : 1;
  out[0] = sg * x + pl.dx;
  out[1] = sg * y + pl.dy;
  out[2] = zz;
  out[3] = sg * xp;
  out[4] = sg * yp;
  out[5] = zp;
  out[6] = sg * (rp * w(ck, sk, 0) + hp * a[0]);
  out[7] = sg * (rp * w(ck, sk, 1) + hp * a[1]);
  out[8] = rp * w(ck, sk, 2) + hp * a[2];
}
const PROF = new Float64Array(4);

/**
 * Newton solve for the edge point of tooth k of pass j over (x, y), from (phi0, s0).
 * Returns [z, phi, s, errorEstimate] or null when it does not converge on the edge (0 <= s <= sMax).
 */
export function solveOver(
  m: SweepModel,
  j: number,
  k: number,
  phi0: number,
  s0: number,
  x: number,
  y: number,
  piece: Piece = -1,
): [number, number, number, number] | null {
  const out = new Float64Array(9);
  let phi = phi0;
  let s = s0;
  // the part's own range: a solution on a part's extension is no edge point
  const lo = piece === 1 ? m.rb : piece === 2 ? m.sArc : 0;
  const hi = piece === 0 ? m.rb : piece === 1 ? m.sArc : m.sMax;
  const tol = 1e-13 * (1 + Math.abs(x) + Math.abs(y));
  const maxPhiStep = 0.5;
  const maxSStep = 0.25 * m.r;
  for (let it = 0; it < 60; it++) {
    edgePoint(m, j, k, phi, s, out, piece);
    const fx = (out[0] as number) - x;
    const fy = (out[1] as number) - y;
    const a11 = out[3] as number;
    const a21 = out[4] as number;
    const a12 = out[6] as number;
    const a22 = out[7] as number;
    const det = a11 * a22 - a12 * a21;
    if (!(Math.abs(det) > 1e-300)) return null;
    let dphi = -(a22 * fx - a12 * fy) / det;
    let ds = -(-a21 * fx + a11 * fy) / det;
    const res = Math.hypot(fx, fy);
    if (res <= tol) {
      // the step that would remain, mapped to height: the error of z
      const dz = Math.abs((out[5] as number) * dphi + (out[8] as number) * ds);
      if (s < lo - 1e-12 || s > hi + 1e-12) return null;
      return [out[2] as number, phi, s, dz + 1e-15];
    }
    const f = Math.max(1, Math.abs(dphi) / maxPhiStep, Math.abs(ds) / maxSStep);
    dphi /= f;
    ds /= f;
    phi += dphi;
    s += ds;
    if (s < -0.5 * m.r || s > m.sMax + 0.5 * m.r) return null;
  }
  return null;
}

/**
 * `solveOver` on the whole profile, and where that fails (Newton across the rim of a flat end,
 * where the profile turns a sharp corner, or across the joins where the curvature jumps) on
 * each smooth part of it with its own extension: the lowest solution found, or null.
 */
export function solveAny(
  m: SweepModel,
  j: number,
  k: number,
  phi0: number,
  s0: number,
  x: number,
  y: number,
): [number, number, number, number] | null {
  const whole = solveOver(m, j, k, phi0, s0, x, y);
  if (whole !== null) return whole;
  let best: [number, number, number, number] | null = null;
  for (const piece of [0, 1, 2] as const) {
    if ((piece === 0 && m.rb === 0) || (piece === 1 && m.rcr === 0)) continue;
    const sol = solveOver(m, j, k, phi0, s0, x, y, piece);
    if (sol !== null && (best === null || sol[0] < best[0])) best = sol;
  }
  return best;
}

// ---------------------------------------------------------------- scatter

/** The sampled sweep over a window: cells of size `stepMm` keeping K distinct crossings each. */
export interface SweepScatter {
  model: SweepModel;
  stepMm: number;
  /** The 3D distance every edge point over the window has to some lattice sample (= stepMm). */
  sampleRadiusMm: number;
  gx0: number;
  gy0: number;
  ncx: number;
  ncy: number;
  keep: number;
  /** Per cell and slot: height, pass, tooth, crossing key (4 revolution + profile part), phi, s (+Infinity: empty). */
  hz: Float64Array;
  pass: Int32Array;
  tooth: Int32Array;
  rev: Float64Array;
  phi: Float64Array;
  s: Float64Array;
  samples: number;
}

/** Passes whose tool can reach the window. */
function passRange(m: SweepModel, w: Window): number[] {
  const L = m.params.stepOverMm;
  const reach = Math.abs(m.oy) + m.reachXy + 1e-9;
  const lo = Math.floor((w.y0 - reach) / L);
  const hi = Math.ceil((w.y1 + reach) / L);
  const out: number[] = [];
  for (let j = lo; j <= hi; j++) out.push(j);
  return out;
}

/**
 * Sample every tooth edge of every pass that can reach `window` with lattice step 1/density
 * (mm of edge arc length, and mm of motion of the farthest edge point per rotation step), and
 * scatter onto cells of that size, keeping the `keep` lowest distinct crossings per cell.
 */
export function scatterSweep(params: ToothSweepParams, window: Window, density: number, keep = 6): SweepScatter {
  const m = sweepModel(params);
  const step = 1 / density;
  const p = m.params;
  const z = p.flutes;
  // cells: the window and a margin of 1.5 cells (a query uses its cell's neighbours)
  const gx0 = window.x0 - 1.5 * step;
  const gy0 = window.y0 - 1.5 * step;
  const ncx = Math.floor((window.x1 - window.x0) / step) + 4;
  const ncy = Math.floor((window.y1 - window.y0) / step) + 4;
  const gx1 = gx0 + ncx * step;
  const gy1 = gy0 + ncy * step;
  const n = ncx * ncy * keep;
  const hz = new Float64Array(n).fill(Number.POSITIVE_INFINITY);
  const pass = new Int32Array(n);
  const tooth = new Int32Array(n);
  const rev = new Float64Array(n);
  const phiA = new Float64Array(n);
  const sA = new Float64Array(n);
  // edge lattice in s: nodes 0..ns at spacing ds <= step
  const ns = Math.max(1, Math.ceil(m.sMax / step));
  const ds = m.sMax / ns;
  const nr = new Float64Array(ns + 1);
  const nh = new Float64Array(ns + 1);
  const pr = new Float64Array(4);
  // the part of the profile each node lies on (flat 0, corner 1, side 2): crossings of one
  // tooth pass on different parts are kept apart (the side can be lowest where the flat is not)
  const seg = new Int32Array(ns + 1);
  for (let i = 0; i <= ns; i++) {
    profile(m, i * ds, pr);
    nr[i] = pr[0] as number;
    nh[i] = pr[1] as number;
    seg[i] = i * ds <= m.rb ? 0 : i * ds <= m.sArc ? 1 : 2;
  }
  const dphi = step / m.lphi;
  const { u, v, a } = m;
  const e = p.runoutMm;
  const cxw = (gx0 + gx1) / 2;
  const cyw = (gy0 + gy1) / 2;
  const hxw = (gx1 - gx0) / 2;
  const hyw = (gy1 - gy0) / 2;
  let samples = 0;
  for (const j of passRange(m, window)) {
    const pl = passPlacement(m, j);
    const sg = pl.mirror ? -1 : 1;
    // local x range of O that can reach the window
    const lx0 = pl.mirror ? pl.dx - gx1 : gx0 - pl.dx;
    const lx1 = pl.mirror ? pl.dx - gx0 : gx1 - pl.dx;
    const i0 = Math.floor((lx0 - m.reachXy) / m.feedPerRad / dphi) - 1;
    const i1 = Math.ceil((lx1 + m.reachXy) / m.feedPerRad / dphi) + 1;
    for (let k = 0; k < z; k++) {
      let i = i0;
      while (i <= i1) {
        const phi = i * dphi;
        const xs = m.feedPerRad * phi;
        const revKey = Math.floor(phi / (2 * Math.PI));
        const tr = runoutAngle(phi, p.runoutPhaseRad);
        const cr = Math.cos(tr);
        const sr = Math.sin(tr);
        const bx = xs + e * (cr * u[0] + sr * v[0]);
        const by = m.oy + e * (cr * u[1] + sr * v[1]);
        const bz = m.oz + e * (cr * u[2] + sr * v[2]);
        const th = toothAngle(phi, k, z);
        const ck = Math.cos(th);
        const sk = Math.sin(th);
        const wx = ck * u[0] + sk * v[0];
        const wy = ck * u[1] + sk * v[1];
        const wz = ck * u[2] + sk * v[2];
        // march along the edge, skipping (|dP/ds| = 1) what cannot reach the grid's box
        let minGap = Number.POSITIVE_INFINITY;
        let q = 0;
        while (q <= ns) {
          const rq = nr[q] as number;
          const hq = nh[q] as number;
          const px = sg * (bx + rq * wx + hq * a[0]) + pl.dx;
          const py = sg * (by + rq * wy + hq * a[1]) + pl.dy;
          const gap = Math.max(Math.abs(px - cxw) - hxw, Math.abs(py - cyw) - hyw);
          if (gap > 0) {
            const half = gap / 2;
            if (half < minGap) minGap = half;
            q += Math.max(1, Math.floor(half / ds));
            continue;
          }
          minGap = 0;
          const cx = Math.min(ncx - 1, Math.floor((px - gx0) / step));
          const cy = Math.min(ncy - 1, Math.floor((py - gy0) / step));
          q++;
          if (cx < 0 || cy < 0) continue;
          const pz = bz + rq * wz + hq * a[2];
          samples++;
          const base = (cy * ncx + cx) * keep;
          const crossingKey = 4 * revKey + (seg[q - 1] as number);
          // same crossing already kept: lower it; else replace the highest if lower
          let worst = base;
          let same = -1;
          for (let t = base; t < base + keep; t++) {
            if (hz[t] !== Number.POSITIVE_INFINITY && pass[t] === j && tooth[t] === k && rev[t] === crossingKey) {
              same = t;
              break;
            }
            if ((hz[t] as number) > (hz[worst] as number)) worst = t;
          }
          const slot = same >= 0 ? same : worst;
          if (pz < (hz[slot] as number)) {
            hz[slot] = pz;
            pass[slot] = j;
            tooth[slot] = k;
            rev[slot] = crossingKey;
            phiA[slot] = phi;
            sA[slot] = (q - 1) * ds;
          }
        }
        // every node moves at most lphi * dphi = step per rotation step
        i += Math.max(1, Math.floor(minGap / step));
      }
    }
  }
  return {
    model: m,
    stepMm: step,
    sampleRadiusMm: (m.lphi * dphi + ds) / 2,
    gx0,
    gy0,
    ncx,
    ncy,
    keep,
    hz,
    pass,
    tooth,
    rev,
    phi: phiA,
    s: sA,
    samples,
  };
}

/** A crossing: the edge point of tooth `tooth` of pass `pass` at (phi, s) over a query point, at height zMm. */
export interface Crossing {
  zMm: number;
  pass: number;
  tooth: number;
  phi: number;
  s: number;
}

/**
 * Heights near (xc, yc) from the crossings found there (every solution `refineAt` met at the
 * centre), each followed by Newton from its last solution: fast, for searches in a small box.
 * Only as good as that list; `verifiedHeight` checks a result against a full `refineAt`.
 */
export function localHeights(sc: SweepScatter, xc: number, yc: number): (x: number, y: number) => number {
  const list: Crossing[] = [];
  refineAt(sc, xc, yc, list);
  return (x, y) => {
    let best = Number.POSITIVE_INFINITY;
    for (const c of list) {
      const sol = solveAny(sc.model, c.pass, c.tooth, c.phi, c.s, x, y);
      if (sol === null) continue;
      if (sol[0] < best) best = sol[0];
    }
    return best;
  };
}

/**
 * Refine the envelope height at (x, y) from a scatter whose window contains the point: Newton
 * from every kept candidate of the 3 x 3 cells about it, then, from every solution found, a
 * walk along its chain of crossings (the next tooth to reach the same angle is tooth k + 1 a
 * rotation of 2 pi / z later, the tool fz further on): a cell wider than fz keeps the lowest
 * crossings of its other points, and the walk reaches the crossing lowest at this one. A walk
 * goes on while it improves, and z + 2 crossings past the last improvement.
 */
export function refineAt(sc: SweepScatter, x: number, y: number, solutions?: Crossing[]): BruteHeight {
  const cx = Math.floor((x - sc.gx0) / sc.stepMm);
  const cy = Math.floor((y - sc.gy0) / sc.stepMm);
  if (cx < 1 || cy < 1 || cx > sc.ncx - 2 || cy > sc.ncy - 2) {
    throw new Error(`toothSweepBruteForce: (${x}, ${y}) lies outside the scattered window`);
  }
  const m = sc.model;
  const z = m.params.flutes;
  let lowestSample = Number.POSITIVE_INFINITY;
  let best = Number.POSITIVE_INFINITY;
  let bestErr = 0;
  let candidates = 0;
  let converged = 0;
  const found = new Set<string>();
  let bestCrossing: Crossing = { zMm: Number.NaN, pass: 0, tooth: 0, phi: 0, s: 0 };
  const sols: [number, number, number, number, number, number][] = [];
  const record = (j: number, k: number, sol: [number, number, number, number]): boolean => {
    const key = `${j}:${k}:${Math.round(sol[1] * 1e7)}:${Math.round(sol[2] * 1e4)}`;
    if (found.has(key)) return false;
    found.add(key);
    converged++;
    sols.push([sol[0], j, k, sol[1], sol[2], sol[3]]);
    if (sol[0] < best) {
      best = sol[0];
      bestErr = sol[3];
      bestCrossing = { zMm: sol[0], pass: j, tooth: k, phi: sol[1], s: sol[2] };
    }
    return true;
  };
  for (let iy = cy - 1; iy <= cy + 1; iy++) {
    for (let ix = cx - 1; ix <= cx + 1; ix++) {
      const base = (iy * sc.ncx + ix) * sc.keep;
      for (let t = base; t < base + sc.keep; t++) {
        const h = sc.hz[t] as number;
        if (h === Number.POSITIVE_INFINITY) continue;
        if (h < lowestSample) lowestSample = h;
        candidates++;
        const j = sc.pass[t] as number;
        const k = sc.tooth[t] as number;
        const sol = solveAny(m, j, k, sc.phi[t] as number, sc.s[t] as number, x, y);
        if (sol !== null) record(j, k, sol);
      }
    }
  }
  // walk the chains of crossings from every solution, lowest first
  const starts = sols.slice().sort((p, q) => p[0] - q[0]);
  const patience = z + 2;
  // from the lowest solution the walk also steps over tooth passes that miss the point, for up
  // to 0.25 mm of feed: near the rim of a flat end a point can be cut by the side, then by no
  // pass, then by the flat bottom lower down (the cells hold only the rim's own samples there)
  const longGap = Math.max(patience, Math.ceil(0.25 / (z * m.params.fzMm)) * z);
  starts.forEach(([, j, k0, phi0, s0], index) => {
    const maxFails = index === 0 ? longGap : patience;
    for (const dir of [1, -1]) {
      let k = k0;
      let phi = phi0;
      let s = s0;
      let idle = 0;
      let fails = 0;
      let base = phi0;
      let steps = 0;
      while (idle < patience && fails < maxFails) {
        k = (((k + dir) % z) + z) % z;
        steps++;
        phi = base + (dir * 2 * Math.PI * steps) / z;
        const sol = solveAny(m, j, k, phi, s, x, y);
        if (sol === null) {
          fails++;
          continue;
        }
        fails = 0;
        const before = best;
        const fresh = record(j, k, sol);
        base = sol[1];
        steps = 0;
        s = sol[2];
        // a solution another walk found counts as no progress (that walk may have stopped there)
        idle = fresh && best < before ? 0 : idle + 1;
      }
    }
  });
  if (best === Number.POSITIVE_INFINITY) {
    // no seed converged (seeds on a flat end's rim, or a fold of the sweep where Newton's
    // Jacobian vanishes): branch and bound, first to the sampling step (from no upper bound),
    // then from that crossing to 1e-10 mm
    const rough = certifyAt(m, x, y, Number.POSITIVE_INFINITY, sc.sampleRadiusMm);
    const c = certifyAt(m, x, y, rough.heightMm, 1e-10);
    if (c.heightMm === Number.POSITIVE_INFINITY) {
      throw new Error(`toothSweepBruteForce: no edge point refined over (${x}, ${y})`);
    }
    best = c.heightMm;
    bestErr = 1e-15;
  }
  const lower = Math.min(best, lowestSample - sc.sampleRadiusMm);
  if (solutions !== undefined) {
    for (const [zc, j, k, phi, sv] of sols) solutions.push({ zMm: zc, pass: j, tooth: k, phi, s: sv });
  }
  return {
    heightMm: best,
    lowerBoundMm: lower,
    boundMm: best - lower,
    newtonErrorMm: bestErr,
    candidates,
    converged,
    crossing: bestCrossing,
  };
}

/** What the branch and bound of `certifyAt` did. */
export interface Certificate {
  /** Rigorous lower bound of the envelope over the query (mm). */
  lowerBoundMm: number;
  /** The lowest real edge point over the query found (mm): an upper bound, to the Newton error. */
  heightMm: number;
  /** heightMm - lowerBoundMm. */
  boundMm: number;
  /** Rectangles evaluated, and whether every one was resolved (false: the budget ran out). */
  evaluations: number;
  complete: boolean;
}

/**
 * Certify the envelope height at (x, y) to `tolMm` by branch and bound over rectangles of
 * (pass, tooth, rotation phi, arc length s), starting from a known real edge point over the
 * query at height `upperMm` (from `refineAt`). Every point of a rectangle with centre c and
 * half-widths (hphi, hs) lies within lphi hphi + hs of P(c) (|dP/dphi| <= z fz / 2 pi + e + R,
 * |dP/ds| = 1) and its height within lzphi hphi + hs of z(c) (|dz/dphi| <= (e + R) sqrt(1 - az^2)).
 * A rectangle is dropped when its xy ball misses the query or its lowest possible height is at
 * least upper - tol; otherwise it is halved along its longer side (in mm). A rectangle still
 * open when small gets a Newton solve from its centre, which may lower the upper bound. The
 * lower bound is the lowest bound of the rectangles dropped on their height (at least
 * upper - tol), or lower where the budget of evaluations ran out (then `complete` is false).
 */
export function certifyAt(
  m: SweepModel,
  x: number,
  y: number,
  upperMm: number,
  tolMm: number,
  budget = 2_000_000,
): Certificate {
  const p = m.params;
  const out = new Float64Array(9);
  let upper = upperMm;
  let openLower = Number.POSITIVE_INFINITY;
  let droppedLower = Number.POSITIVE_INFINITY;
  let evaluations = 0;
  // stack of rectangles: pass, tooth, phi centre, s centre, phi half, s half
  const stack: number[] = [];
  const reachY = Math.abs(m.oy) + m.reachXy;
  const L = p.stepOverMm;
  for (let j = Math.floor((y - reachY) / L) - 1; j <= Math.ceil((y + reachY) / L) + 1; j++) {
    const pl = passPlacement(m, j);
    const lx = pl.mirror ? pl.dx - x : x - pl.dx;
    const ly = pl.mirror ? pl.dy - y : y - pl.dy;
    if (Math.abs(ly - m.oy) > m.reachXy) continue;
    const phi0 = (lx - m.reachXy) / m.feedPerRad;
    const phi1 = (lx + m.reachXy) / m.feedPerRad;
    const nRoot = Math.max(1, Math.ceil((phi1 - phi0) / (Math.PI / 4)));
    const hphi = (phi1 - phi0) / nRoot / 2;
    for (let k = 0; k < p.flutes; k++) {
      for (let i = 0; i < nRoot; i++) stack.push(j, k, phi0 + (2 * i + 1) * hphi, m.sMax / 2, hphi, m.sMax / 2);
    }
  }
  while (stack.length > 0) {
    const hs = stack.pop() as number;
    const hphi = stack.pop() as number;
    const sc = stack.pop() as number;
    const phic = stack.pop() as number;
    const k = stack.pop() as number;
    const j = stack.pop() as number;
    if (evaluations >= budget) {
      openLower = Math.min(openLower, Number.NEGATIVE_INFINITY);
      break;
    }
    evaluations++;
    edgePoint(m, j, k, phic, sc, out);
    const rxy = m.lphi * hphi + hs;
    if (Math.hypot((out[0] as number) - x, (out[1] as number) - y) > rxy) continue;
    const lb = (out[2] as number) - (m.lzphi * hphi + hs);
    if (lb >= upper - tolMm) {
      droppedLower = Math.min(droppedLower, lb);
      continue;
    }
    if (rxy < 1e-4) {
      const sol = solveAny(m, j, k, phic, sc, x, y);
      if (sol !== null && sol[0] < upper) upper = sol[0];
      if (lb >= upper - tolMm) {
        droppedLower = Math.min(droppedLower, lb);
        continue;
      }
    }
    if (rxy < 1e-13 * (1 + Math.abs(x) + Math.abs(y))) {
      openLower = Math.min(openLower, lb);
      continue;
    }
    if (m.lphi * hphi >= hs) {
      stack.push(j, k, phic - hphi / 2, sc, hphi / 2, hs, j, k, phic + hphi / 2, sc, hphi / 2, hs);
    } else {
      stack.push(j, k, phic, sc - hs / 2, hphi, hs / 2, j, k, phic, sc + hs / 2, hphi, hs / 2);
    }
  }
  const complete = openLower === Number.POSITIVE_INFINITY || openLower > Number.NEGATIVE_INFINITY;
  // every rectangle dropped on its height had lb >= the upper bound of its time minus tol
  const lower = Math.min(upper, droppedLower, openLower);
  return { lowerBoundMm: lower, heightMm: upper, boundMm: upper - lower, evaluations, complete };
}

/**
 * The envelope height at (x, y) certified to `tolMm`: refined from a scatter at `density`, then
 * bracketed by branch and bound (`certifyAt`). The envelope lies in [lowerBoundMm, heightMm].
 */
export function certifiedEnvelopeHeightMm(
  params: ToothSweepParams,
  xMm: number,
  yMm: number,
  tolMm: number,
  density = 50,
): Certificate {
  const sc = scatterSweep(params, around(xMm, yMm, 0.5 / density), density);
  const r = refineAt(sc, xMm, yMm);
  return certifyAt(sc.model, xMm, yMm, r.heightMm, tolMm);
}

/** A window of half-width `halfMm` about (x, y). */
const around = (x: number, y: number, halfMm: number): Window => ({
  x0: x - halfMm,
  x1: x + halfMm,
  y0: y - halfMm,
  y1: y + halfMm,
});

/**
 * Height (mm, along Z above the design plane) of the surface the teeth leave at (x, y), by
 * scattering at `density` samples per mm and refining; with its rigorous bracket.
 */
export function bruteEnvelopeHeightMm(
  params: ToothSweepParams,
  xMm: number,
  yMm: number,
  density: number,
): BruteHeight {
  const sc = scatterSweep(params, around(xMm, yMm, 0.5 / density), density);
  return refineAt(sc, xMm, yMm);
}

/** Heights on an nx by ny grid of the window, sample (i, j) at x = x0 + (i + 1/2) dx (the x3p grid). */
export interface BruteGrid {
  nx: number;
  ny: number;
  dxMm: number;
  dyMm: number;
  /** Row-major by y: heights[jy * nx + ix]. */
  heightsMm: Float64Array;
  /** Largest bracket width over the grid (mm). */
  maxBoundMm: number;
  /** Largest Newton error estimate over the grid (mm). */
  maxNewtonErrorMm: number;
}

/** The envelope on a grid of the window (one scatter, every node refined). */
export function bruteEnvelopeGrid(
  params: ToothSweepParams,
  window: Window,
  nx: number,
  ny: number,
  density: number,
): BruteGrid {
  return gridFromScatter(scatterSweep(params, window, density), window, nx, ny);
}

/** The grid of `bruteEnvelopeGrid` from a scatter whose window contains `window`. */
export function gridFromScatter(sc: SweepScatter, window: Window, nx: number, ny: number): BruteGrid {
  const dx = (window.x1 - window.x0) / nx;
  const dy = (window.y1 - window.y0) / ny;
  const heights = new Float64Array(nx * ny);
  let maxBound = 0;
  let maxNewton = 0;
  for (let iy = 0; iy < ny; iy++) {
    for (let ix = 0; ix < nx; ix++) {
      const r = refineAt(sc, window.x0 + (ix + 0.5) * dx, window.y0 + (iy + 0.5) * dy);
      heights[iy * nx + ix] = r.heightMm;
      maxBound = Math.max(maxBound, r.boundMm);
      maxNewton = Math.max(maxNewton, r.newtonErrorMm);
    }
  }
  return { nx, ny, dxMm: dx, dyMm: dy, heightsMm: heights, maxBoundMm: maxBound, maxNewtonErrorMm: maxNewton };
}

// ---------------------------------------------------------------- derived quantities

/** The period of the pattern along the feed (mm): fz, or z fz with runout. */
export function feedPatternPeriodMm(params: ToothSweepParams): number {
  return params.runoutMm > 0 ? params.flutes * params.fzMm : params.fzMm;
}

/** The period of the passes across the feed (mm): L one-way, 2 L zigzag. */
export function crossPeriodMm(params: ToothSweepParams): number {
  return params.pattern === 'zigzag' ? 2 * params.stepOverMm : params.stepOverMm;
}

/** The maximum of f in [lo, hi] by golden section (the references' loop): [x, f(x), |f(c) - f(d)| at the end]. */
function goldenMax(f: (x: number) => number, lo: number, hi: number, xTol: number): [number, number, number] {
  const g = goldenSection((x) => -f(x), lo, hi, 200, 0, xTol);
  return g.fc <= g.fd ? [g.c, -g.fc, Math.abs(g.fc - g.fd)] : [g.d, -g.fd, Math.abs(g.fc - g.fd)];
}

/** Feed-mark height along the CC path of pass 0 (y = 0) over one feed period. */
export interface BruteFeedMark {
  /** hf = highest minus lowest (mm). */
  heightMm: number;
  maxMm: number;
  minMm: number;
  xMaxMm: number;
  xMinMm: number;
  periodMm: number;
  /** Estimated error of hf (mm): the golden-section brackets' height spread plus Newton errors. */
  errorMm: number;
}

/**
 * The feed-mark height hf: along y = 0 (pass 0's CC path) over one period of the pattern, the
 * highest minus the lowest envelope height. Dense sampling at spacing 1/density, each sample
 * refined exactly, then each extreme located by golden section (to 1e-11 mm in x).
 */
export function bruteFeedMarkHeightMm(params: ToothSweepParams, density: number): BruteFeedMark {
  const period = feedPatternPeriodMm(params);
  const step = 1 / density;
  const n = Math.max(8, Math.ceil(period / step));
  const dx = period / n;
  const sc = scatterSweep(params, { x0: -3 * dx, x1: period + 3 * dx, y0: -step / 2, y1: step / 2 }, density);
  let newton = 0;
  const s = (x: number): number => {
    const r = refineAt(sc, x, 0);
    newton = Math.max(newton, r.newtonErrorMm);
    return r.heightMm;
  };
  let iMax = 0;
  let iMin = 0;
  const hs: number[] = [];
  for (let i = 0; i < n; i++) {
    hs.push(s(i * dx));
    if ((hs[i] as number) > (hs[iMax] as number)) iMax = i;
    if ((hs[i] as number) < (hs[iMin] as number)) iMin = i;
  }
  const [xMax, max, eMax] = goldenMax(s, (iMax - 1) * dx, (iMax + 1) * dx, 1e-11);
  const [xMin, negMin, eMin] = goldenMax((x) => -s(x), (iMin - 1) * dx, (iMin + 1) * dx, 1e-11);
  const hiV = Math.max(max, hs[iMax] as number);
  const loV = Math.min(-negMin, hs[iMin] as number);
  return {
    heightMm: hiV - loV,
    maxMm: hiV,
    minMm: loV,
    xMaxMm: xMax,
    xMinMm: xMin,
    periodMm: period,
    errorMm: eMax + eMin + 2 * newton,
  };
}

/** ISO 25178-2 areal parameters over one period cell, by dense midpoint sampling. */
export interface BruteAreal {
  Sa: number;
  Sq: number;
  Sz: number;
  Sp: number;
  Sv: number;
  Ssk: number;
  Sku: number;
  meanMm: number;
  /** Highest and lowest heights (mm): refined (nested golden sections) when asked, else sampled. */
  maxMm: number;
  minMm: number;
  /** Where they are. */
  xMaxMm: number;
  yMaxMm: number;
  xMinMm: number;
  yMinMm: number;
  /** Whether the extremes were refined. */
  refinedExtremes: boolean;
  /** The cell: [0, P) along X, [-L/2, -L/2 + Lc) across (Lc = L or 2 L). */
  cell: Window;
  nx: number;
  ny: number;
}

/**
 * The extreme (sign +1: highest, -1: lowest) of the envelope within one grid step (dx, dy) of
 * (x, y), every height exact (Newton on the crossings `refineAt` lists at (x, y), the result checked
 * by a full `refineAt`; `sc`'s window holds the box). A peak of the surface left is a kink: the crest of the
 * cusp between passes (along X) crossed by feed-mark crests (roughly along Y), where two or
 * three crossings meet; no derivative is used. Nested searches in both orders: the outer
 * variable scanned at 12 points over the box, then narrowed by golden section about the best
 * scanned point, the inner one by golden section over the box (a crest crossed once is
 * unimodal); positions to 1e-11 mm. The better of the two orders is returned: [height, x, y].
 */
export function refinedExtreme(
  sc: SweepScatter,
  x: number,
  y: number,
  dx: number,
  dy: number,
  sign: 1 | -1,
): [number, number, number] {
  const local = localHeights(sc, x, y);
  const f = (xx: number, yy: number): number => sign * local(xx, yy);
  let best: [number, number, number] = [f(x, y), x, y];
  for (const xOuter of [true, false]) {
    const [c, h] = xOuter ? [x, dx] : [y, dy];
    const [ci, hi] = xOuter ? [y, dy] : [x, dx];
    const g = (u: number, w: number): number => (xOuter ? f(u, w) : f(w, u));
    const inner = (u: number): [number, number] => {
      const [w, v] = goldenMax((ww) => g(u, ww), ci - hi, ci + hi, 1e-11);
      return [v, w];
    };
    let bu = c;
    let bv = Number.NEGATIVE_INFINITY;
    const n = 12;
    for (let i = 0; i <= n; i++) {
      const u = c - h + (2 * h * i) / n;
      const v = inner(u)[0];
      if (v > bv) {
        bv = v;
        bu = u;
      }
    }
    const step = (2 * h) / n;
    const [u] = goldenMax((uu) => inner(uu)[0], Math.max(c - h, bu - step), Math.min(c + h, bu + step), 1e-11);
    for (const uu of [u, bu]) {
      const [v, w] = inner(uu);
      if (v > best[0]) best = xOuter ? [v, uu, w] : [v, w, uu];
    }
  }
  // the crossings listed at the centre must still be the lowest at the extreme found
  const full = refineAt(sc, best[1], best[2]).heightMm;
  if (Math.abs(full - sign * best[0]) > 1e-12) {
    throw new Error(
      `toothSweepBruteForce: the local search met a crossing it did not list (${full} against ${sign * best[0]})`,
    );
  }
  return [full, best[1], best[2]];
}

/**
 * Where to refine the extreme of sign `sign`: the crests of the sampled grid. Along every
 * column (and every row) each local extreme of the periodic samples is narrowed by golden
 * section across it with exact heights (a crest sampled off its top would rank by how far off
 * it was sampled, not by its height); the best three crest points, as [height * sign, x, y].
 */
function crestCandidates(sc: SweepScatter, g: BruteGrid, cell: Window, sign: 1 | -1): [number, number, number][] {
  const { nx, ny, dxMm: dx, dyMm: dy } = g;
  const v = (ix: number, iy: number): number =>
    sign * (g.heightsMm[(((iy % ny) + ny) % ny) * nx + (((ix % nx) + nx) % nx)] as number);
  const out: [number, number, number][] = [];
  for (let ix = 0; ix < nx; ix++) {
    const x = cell.x0 + (ix + 0.5) * dx;
    for (let iy = 0; iy < ny; iy++) {
      if (v(ix, iy) < v(ix, iy - 1) || v(ix, iy) < v(ix, iy + 1)) continue;
      const y = cell.y0 + (iy + 0.5) * dy;
      const local = localHeights(sc, x, y);
      const [yb, val] = goldenMax((yy) => sign * local(x, yy), y - dy, y + dy, 1e-6 * dy);
      out.push([val, x, yb]);
    }
  }
  for (let iy = 0; iy < ny; iy++) {
    const y = cell.y0 + (iy + 0.5) * dy;
    for (let ix = 0; ix < nx; ix++) {
      if (v(ix, iy) < v(ix - 1, iy) || v(ix, iy) < v(ix + 1, iy)) continue;
      const x = cell.x0 + (ix + 0.5) * dx;
      const local = localHeights(sc, x, y);
      const [xb, val] = goldenMax((xx) => sign * local(xx, y), x - dx, x + dx, 1e-6 * dx);
      out.push([val, xb, y]);
    }
  }
  return out.sort((a, b) => b[0] - a[0]).slice(0, 3);
}

/**
 * Sa, Sq, Sz, Sp, Sv, Ssk, Sku over one period cell (fz or z fz along, L or 2 L across) from an
 * nx by ny midpoint grid of exact (refined) heights (the x3p grid of the notes), the integral
 * means by the midpoint rule. Expected error: the rule on a continuous, piecewise-smooth periodic
 * surface converges as O(h^2) (the cusp and feed-mark kinks cost O(h^2) per kink line), so Sa,
 * Sq, Ssk, Sku carry about C (dx^2 + dy^2): compare two resolutions (about a third of their
 * difference). The extremes are the sampled ones (low by up to a slope times half a grid
 * diagonal at a kink), or, with `refineExtremes`, located from the sampled ones by nested golden
 * sections to 1e-11 mm in position with every height exact (heights to about 1e-12 mm where the
 * extreme is a single point of the sampled peak's neighbourhood).
 */
export function bruteArealParameters(
  params: ToothSweepParams,
  nx: number,
  ny: number,
  density: number,
  refineExtremes = false,
): BruteAreal {
  const p = feedPatternPeriodMm(params);
  const lc = crossPeriodMm(params);
  const cell: Window = { x0: 0, x1: p, y0: -params.stepOverMm / 2, y1: -params.stepOverMm / 2 + lc };
  const dxg = (cell.x1 - cell.x0) / nx;
  const dyg = (cell.y1 - cell.y0) / ny;
  const sc = scatterSweep(
    params,
    { x0: cell.x0 - 2 * dxg, x1: cell.x1 + 2 * dxg, y0: cell.y0 - 2 * dyg, y1: cell.y1 + 2 * dyg },
    density,
  );
  const g = gridFromScatter(sc, cell, nx, ny);
  const h = g.heightsMm;
  const n = h.length;
  let sum = 0;
  let iHi = 0;
  let iLo = 0;
  for (let i = 0; i < n; i++) {
    const v = h[i] as number;
    sum += v;
    if (v > (h[iHi] as number)) iHi = i;
    if (v < (h[iLo] as number)) iLo = i;
  }
  const mean = sum / n;
  let m1 = 0;
  let m2 = 0;
  let m3 = 0;
  let m4 = 0;
  for (let i = 0; i < n; i++) {
    const d = (h[i] as number) - mean;
    m1 += Math.abs(d);
    m2 += d * d;
    m3 += d * d * d;
    m4 += d * d * d * d;
  }
  const sq = Math.sqrt(m2 / n);
  const at = (i: number): [number, number] => [
    cell.x0 + ((i % nx) + 0.5) * g.dxMm,
    cell.y0 + (Math.floor(i / nx) + 0.5) * g.dyMm,
  ];
  let [xHi, yHi] = at(iHi);
  let [xLo, yLo] = at(iLo);
  let hi = h[iHi] as number;
  let lo = h[iLo] as number;
  if (refineExtremes) {
    for (const sign of [1, -1] as const) {
      let best: [number, number, number] = sign > 0 ? [hi, xHi, yHi] : [lo, xLo, yLo];
      for (const [, xc, yc] of crestCandidates(sc, g, cell, sign)) {
        const r = refinedExtreme(sc, xc, yc, g.dxMm, g.dyMm, sign);
        if (sign * r[0] > sign * best[0]) best = r;
      }
      if (sign > 0) [hi, xHi, yHi] = best;
      else [lo, xLo, yLo] = best;
    }
  }
  return {
    Sa: m1 / n,
    Sq: sq,
    Sz: hi - lo,
    Sp: hi - mean,
    Sv: mean - lo,
    Ssk: m3 / n / sq ** 3,
    Sku: m4 / n / sq ** 4,
    meanMm: mean,
    maxMm: hi,
    minMm: lo,
    xMaxMm: xHi,
    yMaxMm: yHi,
    xMinMm: xLo,
    yMinMm: yLo,
    refinedExtremes: refineExtremes,
    cell,
    nx,
    ny,
  };
}

// ---------------------------------------------------------------- areal means by piecewise quadrature

/** Gauss-Legendre, 8 nodes on [-1, 1]. */
const GL_X = [
  -0.960289856497536, -0.7966664774136267, -0.525532409916329, -0.1834346424956498, 0.1834346424956498,
  0.525532409916329, 0.7966664774136267, 0.960289856497536,
];
const GL_W = [
  0.10122853629037626, 0.22238103445337448, 0.31370664587788727, 0.362683783378362, 0.362683783378362,
  0.31370664587788727, 0.22238103445337448, 0.10122853629037626,
];

/** Same smooth piece: the same crossing (pass, tooth, within half a tooth pitch and 0.5 mm of edge). */
function sameCrossing(a: Crossing, b: Crossing, z: number): boolean {
  return a.pass === b.pass && a.tooth === b.tooth && Math.abs(a.phi - b.phi) < Math.PI / z && Math.abs(a.s - b.s) < 0.5;
}

/**
 * Integrals over x in [x0, x1] at y of f(s(x, y)) for each f of `fs`, the row cut into smooth
 * pieces where its lowest crossing changes (found from `samples` points, each change bisected
 * to 1e-13 mm; a change that comes and goes between two samples is missed) and where g(s)
 * (optional, e.g. s - m) changes sign, each piece by 8-point Gauss-Legendre.
 */
function rowIntegrals(
  sc: SweepScatter,
  y: number,
  x0: number,
  x1: number,
  samples: number,
  fs: ((h: number) => number)[],
  g?: (h: number) => number,
): number[] {
  const z = sc.model.params.flutes;
  const at = (x: number): BruteHeight => refineAt(sc, x, y);
  const cuts: number[] = [x0];
  let prevX = x0;
  let prev = at(x0);
  for (let i = 1; i <= samples; i++) {
    const x = x0 + ((x1 - x0) * i) / samples;
    const cur = at(x);
    if (!sameCrossing(prev.crossing, cur.crossing, z)) {
      let a = prevX;
      let b = x;
      let ca = prev.crossing;
      while (b - a > 1e-13 * (1 + Math.abs(a))) {
        const mid = (a + b) / 2;
        const cm = at(mid).crossing;
        if (sameCrossing(ca, cm, z)) {
          a = mid;
          ca = cm;
        } else b = mid;
      }
      // (a change between tied crossings, the flat bottom's, only costs a needless cut)
      cuts.push((a + b) / 2);
    }
    prevX = x;
    prev = cur;
  }
  cuts.push(x1);
  const sums = fs.map(() => 0);
  const piece = (a: number, b: number, depth: number): void => {
    const hs = GL_X.map((t) => at((a + b) / 2 + ((b - a) / 2) * t).heightMm);
    if (g !== undefined && depth < 60) {
      const ga = g(at(a).heightMm);
      const gb = g(at(b).heightMm);
      const signs = [ga, ...hs.map(g), gb];
      if (signs.some((v) => v > 0) && signs.some((v) => v < 0)) {
        // split at a sign change of g: the first one found, by bisection
        let lo = a;
        let hi = b;
        const sLo = Math.sign(ga) || Math.sign(signs[1] as number);
        for (let it = 0; it < 200 && hi - lo > 1e-13 * (1 + Math.abs(lo)); it++) {
          const mid = (lo + hi) / 2;
          if (Math.sign(g(at(mid).heightMm)) === sLo) lo = mid;
          else hi = mid;
        }
        const c = (lo + hi) / 2;
        if (c - a > 1e-13 && b - c > 1e-13) {
          piece(a, c, depth + 1);
          piece(c, b, depth + 1);
          return;
        }
      }
    }
    for (let q = 0; q < fs.length; q++) {
      const f = fs[q] as (h: number) => number;
      let acc = 0;
      for (let i = 0; i < GL_W.length; i++) acc += (GL_W[i] as number) * f(hs[i] as number);
      sums[q] = (sums[q] as number) + (acc * (b - a)) / 2;
    }
  };
  for (let i = 0; i + 1 < cuts.length; i++) piece(cuts[i] as number, cuts[i + 1] as number, 0);
  return sums;
}

/** Adaptive Simpson over y of a vector of row integrals; tolerance on the first component. */
function adaptiveRows(row: (y: number) => number[], y0: number, y1: number, tol: number): number[] {
  const add = (p: number[], q: number[], k = 1): number[] => p.map((v, i) => v + k * (q[i] as number));
  const simpson = (a: number, b: number, fa: number[], fm: number[], fb: number[]): number[] =>
    fa.map((v, i) => ((b - a) / 6) * (v + 4 * (fm[i] as number) + (fb[i] as number)));
  const rec = (
    a: number,
    b: number,
    fa: number[],
    fm: number[],
    fb: number[],
    whole: number[],
    t: number,
    depth: number,
  ): number[] => {
    const m = (a + b) / 2;
    const fl = row((a + m) / 2);
    const fr = row((m + b) / 2);
    const left = simpson(a, m, fa, fl, fm);
    const right = simpson(m, b, fm, fr, fb);
    const both = add(left, right);
    const err = Math.abs((both[0] as number) - (whole[0] as number));
    if (depth >= 40 || err <= 15 * t) return add(both, add(both, whole, -1), 1 / 15);
    return add(rec(a, m, fa, fl, fm, left, t / 2, depth + 1), rec(m, b, fm, fr, fb, right, t / 2, depth + 1));
  };
  // start from 8 panels: a crest between two rows is not missed by the first estimate
  let total: number[] | null = null;
  const n = 8;
  for (let i = 0; i < n; i++) {
    const a = y0 + ((y1 - y0) * i) / n;
    const b = y0 + ((y1 - y0) * (i + 1)) / n;
    const fa = row(a);
    const fm = row((a + b) / 2);
    const fb = row(b);
    const part = rec(a, b, fa, fm, fb, simpson(a, b, fa, fm, fb), tol / n, 0);
    total = total === null ? part : add(total, part);
  }
  return total as number[];
}

/** Areal means by piecewise quadrature, with the tolerance used. */
export interface BruteArealQuadrature {
  Sa: number;
  Sq: number;
  Ssk: number;
  Sku: number;
  meanMm: number;
  /** Absolute tolerance asked of each y-integral (mm^3 per mm^2 of cell: a height). */
  tolMm: number;
  rows: number;
}

/**
 * The integral means of the areal parameters (m, Sa, Sq, Ssk, Sku) over the period cell by
 * quadrature that follows the kinks: each row (fixed y) cut where its lowest crossing changes
 * (and, for Sa, where s = m) and integrated piecewise by Gauss-Legendre (exact to rounding on
 * each smooth piece), the rows integrated over y by adaptive Simpson to `tolMm` (a height: the
 * tolerance on the cell mean). Error: about tolMm on m and Sa, and the same relative to Sq^2
 * and its powers on Sq, Ssk, Sku (the adaptive estimate, not a bound).
 */
export function bruteArealQuadrature(
  params: ToothSweepParams,
  tolMm: number,
  density: number,
  rowSamples = 24,
): BruteArealQuadrature {
  const p = feedPatternPeriodMm(params);
  const lc = crossPeriodMm(params);
  const cell: Window = { x0: 0, x1: p, y0: -params.stepOverMm / 2, y1: -params.stepOverMm / 2 + lc };
  const sc = scatterSweep(params, cell, density);
  const area = p * lc;
  let rows = 0;
  const powers = [(h: number) => h, (h: number) => h * h, (h: number) => h * h * h, (h: number) => h * h * h * h];
  const raw = adaptiveRows(
    (y) => {
      rows++;
      return rowIntegrals(sc, y, cell.x0, cell.x1, rowSamples, powers);
    },
    cell.y0,
    cell.y1,
    tolMm * area,
  ).map((v) => v / area);
  const [e1, e2, e3, e4] = raw as [number, number, number, number];
  const m = e1;
  const c2 = e2 - m * m;
  const c3 = e3 - 3 * m * e2 + 2 * m * m * m;
  const c4 = e4 - 4 * m * e3 + 6 * m * m * e2 - 3 * m * m * m * m;
  const [sa] = adaptiveRows(
    (y) => {
      rows++;
      return rowIntegrals(sc, y, cell.x0, cell.x1, rowSamples, [(h) => Math.abs(h - m)], (h) => h - m);
    },
    cell.y0,
    cell.y1,
    tolMm * area,
  ).map((v) => v / area) as [number];
  const sq = Math.sqrt(c2);
  return { Sa: sa, Sq: sq, Ssk: c3 / sq ** 3, Sku: c4 / sq ** 4, meanMm: m, tolMm, rows };
}
