/**
 * Polished cusp heights at a doubly curved point (shared/notes/doubly-curved-and-3-axis.md, section
 * 1), to about 1e-13 mm, from the same real tool as the sampled brute force
 * (doublyCurvedBruteForce.ts: torus corner, flat bottom, shank up to `shankLengthMm`, placed with its
 * lowest point at the CC point) and sharing nothing with src/core/surfaces/doublyCurved (no chords of
 * the ring disk, no disks of radius Rcr, no envelope, no flank reach): the tool surface is searched
 * continuously over its own parameters, as the three-axis reference's `cuspSearch` does
 * (threeAxisBruteForce.ts).
 *
 * The tool surface. One meridian per angle `t` about the tool axis (from e1 towards e2), run by the
 * profile length `u`: the bottom disk's radius `u` in [0, Rb], the corner's quarter (corner angle
 * `-pi/2 + (u - Rb) / Rcr`) up to `Rb + Rcr pi/2`, the shank above it. The pieces meet at their seams
 * (tangentially unless Rcr = 0 or Rb = 0), so `u` is continuous across them.
 *
 * A pass. Pass 0 turns the tool about `l` (through (0, 0, -Rf), parallel to Y); a tool point p keeps
 * its Y and its distance d from `l`, so its path meets X = 0 on the CC point's side of `l` at exactly
 * `(p_y, -Rf + sign(Rf) d)` (`(p_y, p_z)` when Rf is infinite: a translation along X). No chord of
 * the path is interpolated. In X = 0 the point's polar angle about m's trace `(0, -Rc)`, times
 * `|Rc|`, is its equator position `s` (Y when Rc is infinite), its radial height `H` (convex
 * `dist - Rc`, concave `|Rc| - dist`, Z when Rc is infinite). Pass 1 is pass 0 of the tool mirrored
 * in Y for zigzag, turned about m by `phi = L / |Rc|` (translated by L along Y): its section is pass
 * 0's shifted by L in `s`, so `e1(s) = E1(s - L)`.
 *
 * The column function. `E(s*)` is the lowest H of the pass's section on the ray `s = s*`: the least
 * `H(t, u)` subject to `s(t, u) = s*` over the whole surface. For a given t the constraint is solved
 * for u by a sign-change search outwards from a guess and bisection (to the last bit); the least over
 * t by golden section in a bracket around the current minimiser (a smooth minimum at a fold of the
 * section, or a V-shaped one at a crease: both unimodal). The minimiser is tracked from the sampled
 * brute force's winning sample in the cusp's bin (its `winners`).
 *
 * The cusp. Bisection on the sign of `e0(s) - e1(s)` (negative at pass 0's CC point, positive at
 * pass 1's; each pass's section lies above one flank there, so it changes sign once between them), in
 * a bracket around the sampled cusp grown until the signs differ; the cusp is the lower pass's height
 * at the crossing.
 *
 * Guard against a narrow minimum the tracking would miss: at the crossing each pass's column is also
 * computed globally (every meridian of a dense fan, every sign change of `s - s*` along it, the three
 * best local minima over t polished as above); if that finds a lower point, the tracking restarts from
 * it and the bisection is redone (at most three times, then it throws). Lengths mm.
 */

import {
  type DoublyCurvedBruteForce,
  type ToolGeometry,
  type ToolSample,
  toolGeometry,
} from './doublyCurvedBruteForce';
import { goldenSection } from './goldenSection';

/** The tool and posture (mm, degrees), as bruteForceDoublyCurved takes it. */
export interface PolishTool {
  readonly R: number;
  readonly Rcr: number;
  readonly leadDeg: number;
  readonly tiltDeg: number;
}

/** The polished answer. */
export interface DoublyCurvedPolished {
  /** Radial height of the cusp between pass 0 and pass 1, mm. */
  readonly polishedMm: number;
  /** Its equator position from pass 0's CC point (arc length), mm. */
  readonly atMm: number;
  /** How many times the global guard restarted the tracking (0: the brute force's starts held). */
  readonly restarts: number;
}

/** A minimiser on one pass's section: tool parameters (t rad, u mm) and its radial height H (mm). */
interface ColumnPoint {
  t: number;
  u: number;
  H: number;
}

/** One pass's map from tool-surface parameters (t, u) to the section's (s, H), see the module comment. */
class PassMap {
  readonly uDisk: number;
  readonly uCorner: number;
  readonly uEnd: number;
  /** Profile lengths of the seams (bottom rim, corner top), increasing. */
  private readonly seams: number[];
  /** Outputs of {@link PassMap.at}. */
  s = 0;
  H = 0;
  private readonly g: ToolGeometry;
  private readonly rf: number;
  private readonly rc: number;
  private readonly absRc: number;
  private ct = 1;
  private st = 0;

  constructor(tool: PolishTool, tiltDeg: number, rf: number, rc: number, shankMm: number) {
    this.g = toolGeometry(tool.R, tool.Rcr, tool.leadDeg, tiltDeg);
    this.rf = rf;
    this.rc = rc;
    this.absRc = Math.abs(rc);
    this.uDisk = this.g.rb;
    this.uCorner = this.g.rb + 0.5 * Math.PI * this.g.rcr;
    this.uEnd = this.uCorner + shankMm;
    this.seams = [this.uDisk, this.uCorner].filter((u, i, all) => u > 0 && u < this.uEnd && all.indexOf(u) === i);
  }

  /** Profile length u of a brute-force sample. */
  uOf(sample: ToolSample): number {
    if (sample.piece === 1) return sample.v;
    if (sample.piece === 0) return this.g.rb + this.g.rcr * (sample.v + 0.5 * Math.PI);
    return this.uCorner + sample.v;
  }

  /** Sets the meridian angle t (radians) for the following calls of {@link PassMap.at}. */
  meridian(t: number): void {
    this.ct = Math.cos(t);
    this.st = Math.sin(t);
  }

  /** s and H (mm) of the point u of the current meridian, into this.s and this.H. */
  at(u: number): void {
    const g = this.g;
    let radial: number;
    let axial: number;
    if (u <= this.uDisk) {
      radial = u;
      axial = -g.rcr;
    } else if (u <= this.uCorner) {
      const v = -0.5 * Math.PI + (u - g.rb) / g.rcr;
      radial = g.rb + g.rcr * Math.cos(v);
      axial = g.rcr * Math.sin(v);
    } else {
      radial = g.R;
      axial = u - this.uCorner;
    }
    const dx = this.ct * g.e1[0] + this.st * g.e2[0];
    const dy = this.ct * g.e1[1] + this.st * g.e2[1];
    const dz = this.ct * g.e1[2] + this.st * g.e2[2];
    const px = g.O[0] + radial * dx + axial * g.a[0];
    const py = g.O[1] + radial * dy + axial * g.a[1];
    const pz = g.O[2] + radial * dz + axial * g.a[2];
    // Where the point's circle about l meets X = 0 on the CC point's side of l.
    let Z = pz;
    if (Number.isFinite(this.rf)) Z = -this.rf + Math.sign(this.rf) * Math.hypot(px, pz + this.rf);
    if (!Number.isFinite(this.rc)) {
      this.s = py;
      this.H = Z;
      return;
    }
    const q = Z + this.rc;
    const dist = Math.hypot(py, q);
    if (this.rc > 0) {
      this.s = this.absRc * Math.atan2(py, q);
      this.H = dist - this.absRc;
    } else {
      this.s = this.absRc * Math.atan2(py, -q);
      this.H = this.absRc - dist;
    }
  }

  /** Bisection of s(u) - target on [a, b] (signs fa, fb differ): u and H at the root. */
  private bisect(target: number, a0: number, fa0: number, b0: number): { u: number; H: number } {
    let a = a0;
    let b = b0;
    let fa = fa0;
    for (let k = 0; k < 200; k++) {
      const m = 0.5 * (a + b);
      if (m <= Math.min(a, b) || m >= Math.max(a, b)) break;
      this.at(m);
      const fm = this.s - target;
      if (fm === 0) return { u: m, H: this.H };
      if (fm < 0 === fa < 0) {
        a = m;
        fa = fm;
      } else b = m;
    }
    const m = 0.5 * (a + b);
    this.at(m);
    return { u: m, H: this.H };
  }

  /**
   * The step from `from` to `to` cut at the first seam strictly between them: where a seam is a
   * crease (Rcr = 0: the bottom's rim meets the shank) s(u) can turn back there, and two roots on
   * either side of it would cancel within one step.
   */
  private toSeam(from: number, to: number): number {
    for (const seam of to > from ? this.seams : [...this.seams].reverse())
      if ((seam - from) * (seam - to) < 0) return seam;
    return to;
  }

  /**
   * On meridian t, the root of s(u) = target found first searching outwards from `uGuess` (steps
   * doubling from 1e-6 R, stopping at the seams): u and H, or null when the meridian does not reach
   * the ray.
   */
  rootNear(t: number, target: number, uGuess: number): { u: number; H: number } | null {
    this.meridian(t);
    const u0 = Math.min(this.uEnd, Math.max(0, uGuess));
    this.at(u0);
    const f0 = this.s - target;
    if (f0 === 0) return { u: u0, H: this.H };
    // The two ends of the search, each walked outwards in turn: the right one up to uEnd, the left one down to 0.
    const ends = [
      { u: u0, f: f0, right: true },
      { u: u0, f: f0, right: false },
    ];
    const open = (e: { u: number; right: boolean }) => (e.right ? e.u < this.uEnd : e.u > 0);
    let step = 1e-6 * this.g.R;
    while (ends.some(open)) {
      for (const e of ends) {
        if (!open(e)) continue;
        const u = this.toSeam(e.u, e.right ? Math.min(this.uEnd, e.u + step) : Math.max(0, e.u - step));
        this.at(u);
        const f = this.s - target;
        if (f === 0) return { u, H: this.H };
        if (f < 0 !== e.f < 0) return this.bisect(target, e.u, e.f, u);
        e.u = u;
        e.f = f;
      }
      step *= 2;
    }
    return null;
  }

  /** All roots of s(u) = target on meridian t, from `samples` sign-change intervals: the lowest H and its u. */
  lowestRoot(t: number, target: number, samples: number): { u: number; H: number } | null {
    this.meridian(t);
    let best: { u: number; H: number } | null = null;
    this.at(0);
    let ua = 0;
    let fa = this.s - target;
    const grid: number[] = [];
    for (let i = 1; i <= samples; i++) grid.push((this.uEnd * i) / samples);
    grid.push(...this.seams);
    grid.sort((x, y) => x - y);
    for (const ub of grid) {
      this.at(ub);
      const fb = this.s - target;
      if (fa < 0 !== fb < 0 || fa === 0) {
        const r = this.bisect(target, ua, fa, ub);
        if (best === null || r.H < best.H) best = r;
      }
      ua = ub;
      fa = fb;
    }
    return best;
  }
}

/**
 * The least H on the ray s = target near a start: golden section over t in [t - half, t + half], the
 * constraint solved on each meridian from the last root (re-centred while the least lands near an
 * end). Null when no meridian of the bracket reaches the ray.
 */
function localColumn(map: PassMap, target: number, start: ColumnPoint, half: number): ColumnPoint | null {
  let uCur = start.u;
  let best: ColumnPoint | null = null;
  const f = (t: number): number => {
    const r = map.rootNear(t, target, uCur);
    if (r === null) return Number.POSITIVE_INFINITY;
    uCur = r.u;
    if (best === null || r.H < best.H) best = { t, u: r.u, H: r.H };
    return r.H;
  };
  let centre = start.t;
  for (let round = 0; round < 6; round++) {
    goldenSection(f, centre - half, centre + half, 200, 2e-16, 1e-300);
    const found = best as ColumnPoint | null;
    if (found === null) return null;
    // Re-centre while the least sits within 10% of the bracket's ends (the minimiser moved with s).
    if (Math.abs(found.t - centre) < 0.9 * half) return found;
    centre = found.t;
    uCur = found.u;
  }
  return best;
}

/**
 * The least H on the ray s = target over the whole tool: `fan` meridians, on each every sign change
 * of s - target among `samples` points of the profile; the three best local minima over t polished
 * by {@link localColumn}.
 */
function globalColumn(map: PassMap, target: number, fan = 240, samples = 120): ColumnPoint | null {
  const rows: Array<{ u: number; H: number } | null> = [];
  const dt = (2 * Math.PI) / fan;
  for (let i = 0; i < fan; i++) rows.push(map.lowestRoot(i * dt, target, samples));
  const minima: ColumnPoint[] = [];
  for (let i = 0; i < fan; i++) {
    const r = rows[i];
    if (r === null || r === undefined) continue;
    const p = rows[(i + fan - 1) % fan];
    const n = rows[(i + 1) % fan];
    if ((p === null || p === undefined || r.H <= p.H) && (n === null || n === undefined || r.H <= n.H))
      minima.push({ t: i * dt, u: r.u, H: r.H });
  }
  minima.sort((x, y) => x.H - y.H);
  let best: ColumnPoint | null = null;
  for (const m of minima.slice(0, 3)) {
    const r = localColumn(map, target, m, 1.5 * dt);
    const cand = r !== null && r.H <= m.H ? r : m;
    if (best === null || cand.H < best.H) best = cand;
  }
  return best;
}

/**
 * The polished cusp between pass 0 and pass 1 L apart (module comment), from the sampled brute
 * force's answer for the same tool, pattern and radii (its winning samples start the tracking, its
 * cusp position centres the bisection's first bracket).
 * @param rf, rc signed radii (mm) or Infinity; @param intervalMm L, arc length along the equator.
 * @param shankLengthMm shank length above the corner, as the brute force's (default R).
 */
export function polishDoublyCurvedCusp(
  tool: PolishTool,
  pattern: 'one-way' | 'zigzag',
  rf: number,
  rc: number,
  intervalMm: number,
  brute: DoublyCurvedBruteForce,
  shankLengthMm = tool.R,
): DoublyCurvedPolished {
  const L = intervalMm;
  const maps: [PassMap, PassMap] = [
    new PassMap(tool, tool.tiltDeg, rf, rc, shankLengthMm),
    new PassMap(tool, pattern === 'zigzag' ? -tool.tiltDeg : tool.tiltDeg, rf, rc, shankLengthMm),
  ];
  // Pass k's ray: s for pass 0, s - L for pass 1 (its own frame before the turn about m).
  const shift = [0, L] as const;
  const state: Array<ColumnPoint | null> = [0, 1].map((k) => {
    const w = brute.winners[k as 0 | 1];
    const map = maps[k] as PassMap;
    return w === null ? null : { t: w.t, u: map.uOf(w), H: Number.NaN };
  });
  const HALF = 0.05;
  const column = (k: 0 | 1, s: number): number => {
    const map = maps[k];
    const target = s - shift[k];
    const st = state[k] ?? null;
    let r = st === null ? null : localColumn(map, target, st, HALF);
    if (r === null) r = globalColumn(map, target);
    if (r === null) return Number.POSITIVE_INFINITY;
    state[k] = r;
    return r.H;
  };
  const lead = 1e-9 * L;
  for (let restarts = 0; restarts <= 3; restarts++) {
    // First bracket: around the sampled cusp, grown until e0 - e1 changes sign.
    let w = 1e-3 * L;
    let lo = 0;
    let hi = 0;
    for (;;) {
      lo = Math.max(lead, brute.cuspReachMm - w);
      hi = Math.min(L - lead, brute.cuspReachMm + w);
      const dLo = column(0, lo) - column(1, lo);
      const dHi = column(0, hi) - column(1, hi);
      if (dLo < 0 && dHi > 0) break;
      if (lo === lead && hi === L - lead) throw new Error('polish: e0 - e1 does not change sign between the CC points');
      w *= 4;
    }
    for (let k = 0; k < 200; k++) {
      const m = 0.5 * (lo + hi);
      if (m <= lo || m >= hi) break;
      if (column(0, m) - column(1, m) < 0) lo = m;
      else hi = m;
    }
    const at = 0.5 * (lo + hi);
    const e: [number, number] = [column(0, at), column(1, at)];
    // Guard: the whole tool on the same ray, per pass.
    let restart = false;
    for (const k of [0, 1] as const) {
      const g = globalColumn(maps[k], at - shift[k]);
      if (g !== null && g.H < e[k] - 1e-12) {
        state[k] = g;
        restart = true;
      }
    }
    if (!restart) return { polishedMm: Math.min(e[0], e[1]), atMm: at, restarts };
  }
  throw new Error('polish: the tracked column kept missing a lower point of the tool');
}
