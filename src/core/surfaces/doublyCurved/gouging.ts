/**
 * Gouging at a doubly curved point (shared/notes/doubly-curved-and-3-axis.md, section 1): decided in
 * the cross-feed plane X = 0, where the section of the swept tool (passSection.ts) must not reach
 * inside the equator circle (radius |Rc| about C = (0, -Rc); the line Z = 0 when Rc is infinite)
 * anywhere but at the CC point. The shank counts as in troughs: its points up to the height of the
 * nearest concave axis (`l` at |Rf| when Rf < 0, `m` at |Rc| when Rc < 0) above the CC point.
 *
 * Derivation. Write `kc = 1 / Rc` (signed, 0 when straight). A disk of radius k = Rcr centred at
 * (y, k + rise) (the image of a ball centre, rise measured from the CC point's ball centre) stays out
 * of the material (convex: outside the circle; concave: inside it) iff
 *
 *   kc (y^2 + rise (rise + 2 k)) >= -2 rise,
 *
 * which is linear in kc: with `N = y^2 + rise (rise + 2 k)` (> 0 when the disk leaves the CC point
 * out), `kc >= -2 rise / N`; N <= 0 with rise < 0 (the disk reaches below the CC point) fails at any
 * Rc. A point of the shank's image (no disk) at (y, z) needs `kc (y^2 + z^2) >= -2 z`. Every ball
 * centre of the ring disk must pass, and on a chord the lowest image is the worst, so it is enough to
 * take the ring (ring points are chord ends) and, for Rf > 0, the line of feet of `l` on the chords
 * (all chords are parallel, so the feet lie on one line of the disk). The ring is parametrised by the
 * offset delta from the contact's ring point, and the rise is computed from the chord
 * `2 Rb sin(delta/2) (cos(t0 + delta/2) v1 - sin(t0 + delta/2) v2)` and
 * `zc(c0 + D) - zc(c0) = sign(Rf) (D_x^2 + D_z (D_z + 2 (Rcr + Rf))) / (dist + |Rcr + Rf|)`, free of
 * cancellation, so that the bound keeps its digits next to the CC point, where it tends to minus the
 * section's curvature there (the existing cylinder rule, cylinder.ts's minConcaveRadiusMm).
 *
 * So the admissible cross curvature is `kc >= kMin(Rf)`, a maximum over the tool. Raising either
 * curvature (more convex) lifts the swept section (zc grows with 1/Rf) or lowers the equator, so the
 * admissible set in each curvature, the other held, is a half-line `[kMin, +inf)`: a concave radius
 * must be at least `1 / |kMin|` (kMin < 0), or the radius must be convex and at most `1 / kMin`
 * (kMin > 0, a saddle), or no radius helps. The feed curvature's bound is found by bisection on that
 * predicate. Lengths mm, curvatures 1/mm.
 */

import type { ToolInput } from '../../domain/tool';
import { maximise, type Objective } from '../../math/rootFinder';
import { placeTool } from '../../tool/placement';
import { MAX_PRINCIPAL_RADIUS_MM, MIN_PRINCIPAL_RADIUS_MM, type PrincipalRadii } from './types';

/** Largest |curvature| a principal radius can have: 1 / 0.001 mm. */
const MAX_CURVATURE_PER_MM = 1 / MIN_PRINCIPAL_RADIUS_MM;

/** What one principal radius must be, the other held, for the tool not to gouge. */
export interface RadiusLimit {
  /**
   * The smallest admissible signed curvature `1/R` (1/mm): admissible radii are those with
   * `1/R >= minCurvaturePerMm` (straight is 0). Below -1000 every radius passes; above 1000 none.
   */
  readonly minCurvaturePerMm: number;
  /**
   * `any`: every radius passes; `concave-at-least`: a concave radius needs |R| >= radiusMm (convex and
   * straight pass); `not-concave`: straight and every convex radius pass, no concave one;
   * `convex-at-most`: the radius must be convex with R <= radiusMm; `none`: no radius passes ("at any
   * radius").
   */
  readonly kind: 'any' | 'concave-at-least' | 'not-concave' | 'convex-at-most' | 'none';
  /** The limiting magnitude (mm) for the two bounded kinds, else null. */
  readonly radiusMm: number | null;
}

/** The gouging verdict at a doubly curved point, with each radius's limit (the other held). */
export interface GougingCheck {
  /** True when the swept tool reaches inside the surface anywhere but at the CC point. */
  readonly gouges: boolean;
  /** What Rf must be with Rc held. */
  readonly feed: RadiusLimit;
  /** What Rc must be with Rf held. */
  readonly cross: RadiusLimit;
}

function limitOf(kMin: number): RadiusLimit {
  if (kMin < -MAX_CURVATURE_PER_MM) return { minCurvaturePerMm: kMin, kind: 'any', radiusMm: null };
  if (kMin > MAX_CURVATURE_PER_MM) return { minCurvaturePerMm: kMin, kind: 'none', radiusMm: null };
  // Limits beyond the largest radius accepted (1e6 mm) are no radius of that side at all.
  if (kMin < -1 / MAX_PRINCIPAL_RADIUS_MM)
    return { minCurvaturePerMm: kMin, kind: 'concave-at-least', radiusMm: -1 / kMin };
  if (kMin > 1 / MAX_PRINCIPAL_RADIUS_MM)
    return { minCurvaturePerMm: kMin, kind: 'convex-at-most', radiusMm: 1 / kMin };
  // kMin = 0: straight passes, every convex radius too; no concave one.
  return { minCurvaturePerMm: 0, kind: 'not-concave', radiusMm: null };
}

const curvature = (radiusMm: number) => (Number.isFinite(radiusMm) ? 1 / radiusMm : 0);

/** The tool's ring, contact and shank, placed once. */
export class ToolGeometry {
  readonly rb: number;
  readonly k: number;
  readonly R: number;
  readonly t0: number;
  readonly flat: boolean;
  readonly O: readonly [number, number, number];
  readonly a: readonly [number, number, number];
  readonly v1: readonly [number, number, number];
  readonly v2: readonly [number, number, number];

  constructor(tool: ToolInput) {
    const p = placeTool(tool);
    this.rb = p.ringRadiusMm;
    this.k = p.cornerRadiusMm;
    this.R = tool.toolRadiusMm;
    this.t0 = p.contactRingAngleRad;
    this.flat = p.shape.flatOnPlane;
    this.O = p.centre;
    this.a = p.axis;
    this.v1 = p.v1;
    this.v2 = p.v2;
  }
}

/**
 * `-2 rise / N` for a ball centre at offset D (3D) from the CC point's ball centre (0, 0, Rcr), on a
 * feed circle of curvature kf: the smallest admissible cross curvature it imposes. +Infinity when it
 * reaches below the CC point (no Rc helps).
 */
function centreBound(dx: number, dy: number, dz: number, k: number, kf: number): number {
  // The contact's own ball: no bound (its neighbourhood gives the curvature limit).
  if (dx === 0 && dy === 0 && dz === 0) return Number.NEGATIVE_INFINITY;
  let rise: number;
  if (kf === 0) rise = dz;
  else {
    const rf = 1 / kf;
    const q0 = k + rf;
    const q = dz + q0;
    const num = dx * dx + dz * (dz + 2 * q0);
    rise = (Math.sign(rf) * num) / (Math.sqrt(dx * dx + q * q) + Math.abs(q0));
  }
  const n = dy * dy + rise * (rise + 2 * k);
  if (n > 0) return (-2 * rise) / n;
  if (rise < 0) return Number.POSITIVE_INFINITY;
  return Number.NEGATIVE_INFINITY;
}

/** The ring's bound at offset delta from the contact's ring point. */
export class RingBound implements Objective {
  kf = 0;
  constructor(private readonly g: ToolGeometry) {}
  value(delta: number): number {
    const g = this.g;
    let dx: number;
    let dy: number;
    let dz: number;
    if (g.flat) {
      // The contact is the face's centre: D = Rb r(t).
      const s = Math.sin(delta);
      const c = Math.cos(delta);
      dx = g.rb * (s * g.v1[0] + c * g.v2[0]);
      dy = g.rb * (s * g.v1[1] + c * g.v2[1]);
      dz = g.rb * (s * g.v1[2] + c * g.v2[2]);
    } else {
      const half = 2 * g.rb * Math.sin(0.5 * delta);
      const m = g.t0 + 0.5 * delta;
      const cm = Math.cos(m);
      const sm = Math.sin(m);
      dx = half * (cm * g.v1[0] - sm * g.v2[0]);
      dy = half * (cm * g.v1[1] - sm * g.v2[1]);
      dz = half * (cm * g.v1[2] - sm * g.v2[2]);
    }
    return centreBound(dx, dy, dz, g.k, this.kf);
  }
}

/** The feet of l on the chords (Rf > 0): the line O + s g + tau* d of the disk, its bound at s. */
export class FootBound implements Objective {
  kf = 0;
  /** The line's point nearest the contact's ball centre, relative to it, and its unit direction. */
  private px = 0;
  private py = 0;
  private pz = 0;
  constructor(private readonly g: ToolGeometry) {}
  /** Places the foot line for a feed curvature; false when it misses the disk. */
  prepare(kf: number): boolean {
    this.kf = kf;
    const g = this.g;
    const G = Math.hypot(g.v1[1], g.v2[1]);
    if (!(kf > 0) || !(g.rb > 0) || !(G > 0)) return false;
    const rf = 1 / kf;
    // Chord direction d (unit, no Y), and gh the disk's unit direction along Y.
    const d = [0, 1, 2].map((i) => (-g.v2[1] * (g.v1[i] as number) + g.v1[1] * (g.v2[i] as number)) / G);
    const gh = [0, 1, 2].map((i) => (g.v1[1] * (g.v1[i] as number) + g.v2[1] * (g.v2[i] as number)) / G);
    // tau* = -(O - F) . d, F = (0, 0, -Rf).
    const tau = -((g.O[0] as number) * (d[0] as number) + ((g.O[2] as number) + rf) * (d[2] as number));
    if (!(Math.abs(tau) < g.rb)) return false;
    const half = Math.sqrt((g.rb - tau) * (g.rb + tau));
    // The line's point at s, relative to the contact's ball centre (0, 0, Rcr): P0 + s gh.
    let px = (g.O[0] as number) + tau * (d[0] as number);
    let py = (g.O[1] as number) + tau * (d[1] as number);
    let pz = (g.O[2] as number) + tau * (d[2] as number) - g.k;
    this.gx = gh[0] as number;
    this.gy = gh[1] as number;
    this.gz = gh[2] as number;
    // Through the contact's ball centre (a contact on the line of feet): measure from it exactly.
    const s0 = -(px * this.gx + py * this.gy + pz * this.gz);
    const rx = px + s0 * this.gx;
    const ry = py + s0 * this.gy;
    const rz = pz + s0 * this.gz;
    this.shift = 0;
    if (Math.hypot(rx, ry, rz) <= 1e-12 * g.R) {
      px = 0;
      py = 0;
      pz = 0;
      this.shift = s0;
    }
    this.px = px;
    this.py = py;
    this.pz = pz;
    this.lo = -half - this.shift;
    this.hi = half - this.shift;
    return true;
  }
  /** The line's parameter range, measured from the contact's foot when the contact is on it. */
  lo = 0;
  hi = 0;
  private shift = 0;
  private gx = 0;
  private gy = 0;
  private gz = 0;
  value(s: number): number {
    return centreBound(this.px + s * this.gx, this.py + s * this.gy, this.pz + s * this.gz, this.g.k, this.kf);
  }
}

/**
 * The smallest admissible cross curvature (1/mm) the tool end imposes on a feed circle of curvature
 * kf (1/Rf, 0 straight): the largest bound over the ring and the line of feet; +Infinity when some
 * ball reaches below the CC point.
 */
export function endBound(g: ToolGeometry, kf: number, ring: RingBound, foot: FootBound): number {
  // Near the contact the bound tends to minus the section's curvature there.
  if (!(g.rb > 0)) return -1 / g.k;
  ring.kf = kf;
  const n = 720;
  let best = Number.NEGATIVE_INFINITY;
  for (const d of [1e-6, -1e-6]) best = Math.max(best, ring.value(d));
  best = Math.max(best, maximise(ring, 1e-6, 2 * Math.PI - 1e-6, n, 1e-13));
  if (foot.prepare(kf)) {
    const span = foot.hi - foot.lo;
    best = Math.max(best, maximise(foot, foot.lo, foot.hi, 200, 1e-13 * span));
    for (const s of [1e-6 * g.R, -1e-6 * g.R]) if (s > foot.lo && s < foot.hi) best = Math.max(best, foot.value(s));
  }
  return best;
}

/** The shank's bound: its points (radius R, heights s >= 0 along the axis) up to a height cap. */
export class ShankBound {
  constructor(private readonly g: ToolGeometry) {}
  /** `-2 z / (y^2 + z^2)` at ring angle t and height s on a feed circle of curvature kf; -Infinity above the cap. */
  at(t: number, s: number, kf: number, cap: number): number {
    const g = this.g;
    const st = Math.sin(t);
    const ct = Math.cos(t);
    const x = g.O[0] + g.R * (st * g.v1[0] + ct * g.v2[0]) + s * g.a[0];
    const y = g.O[1] + g.R * (st * g.v1[1] + ct * g.v2[1]) + s * g.a[1];
    const z = g.O[2] + g.R * (st * g.v1[2] + ct * g.v2[2]) + s * g.a[2];
    // Up to the nearest concave axis: the point's height and its image's (a concave feed circle lowers it).
    if (z > cap) return Number.NEGATIVE_INFINITY;
    let zc = z;
    if (kf !== 0) {
      const rf = 1 / kf;
      const q = z + rf;
      zc = (Math.sign(rf) * (x * x + z * (z + 2 * rf))) / (Math.sqrt(x * x + q * q) + Math.abs(rf));
    }
    if (zc > cap) return Number.NEGATIVE_INFINITY;
    const n = y * y + zc * zc;
    // Next to the CC point (a flat end's shank starts on the ring) the end's own bound, computed free
    // of cancellation, decides; rounding would spoil this one there.
    if (!(n > 1e-6 * g.R * g.R)) return Number.NEGATIVE_INFINITY;
    return (-2 * zc) / n;
  }

  /**
   * Largest bound over the shank up to `cap` (mm above the CC point): along each generator (ring
   * angle t) the heights s from 0 to where the point or its image reaches the cap (bisection), a
   * scan and Brent's method in s; over t a scan and Brent's method of that maximum.
   */
  bound(kf: number, cap: number): number {
    const g = this.g;
    if (!Number.isFinite(cap) || !(g.a[2] > 0)) return Number.NEGATIVE_INFINITY;
    this.kf = kf;
    this.cap = cap;
    return maximise(this.outer, 0, 2 * Math.PI, 72, 1e-10);
  }

  private kf = 0;
  private cap = 0;
  private t = 0;
  /** The bound along the generator at t (its best height). */
  private readonly inner: Objective = { value: (s: number) => this.at(this.t, s, this.kf, this.cap) };
  private readonly outer: Objective = { value: (t: number) => this.generator(t) };

  /** Height of the point at (t, s) or of its image, whichever is higher, above the CC point. */
  private height(t: number, s: number): number {
    const g = this.g;
    const st = Math.sin(t);
    const ct = Math.cos(t);
    const x = g.O[0] + g.R * (st * g.v1[0] + ct * g.v2[0]) + s * g.a[0];
    const z = g.O[2] + g.R * (st * g.v1[2] + ct * g.v2[2]) + s * g.a[2];
    if (this.kf === 0) return z;
    const rf = 1 / this.kf;
    const q = z + rf;
    const zc = (Math.sign(rf) * (x * x + z * (z + 2 * rf))) / (Math.sqrt(x * x + q * q) + Math.abs(rf));
    return Math.max(z, zc);
  }

  private generator(t: number): number {
    const g = this.g;
    this.t = t;
    if (this.height(t, 0) > this.cap) return Number.NEGATIVE_INFINITY;
    // The heights below the cap: [0, sMax], sMax by doubling then bisection (both heights grow with s).
    let lo = 0;
    let hi = Math.max(g.R, this.cap);
    for (let i = 0; i < 60 && this.height(t, hi) <= this.cap; i++) {
      lo = hi;
      hi *= 2;
    }
    for (let i = 0; i < 60 && hi - lo > 1e-13 * hi; i++) {
      const m = 0.5 * (lo + hi);
      if (this.height(t, m) <= this.cap) lo = m;
      else hi = m;
    }
    return maximise(this.inner, 0, lo, 8, 1e-10 * Math.max(lo, g.R));
  }
}

/** Height of the nearest concave axis above the CC point (mm), Infinity when neither radius is concave. */
function capOf(kf: number, kc: number): number {
  let cap = Number.POSITIVE_INFINITY;
  if (kf < 0) cap = Math.min(cap, -1 / kf);
  if (kc < 0) cap = Math.min(cap, -1 / kc);
  return cap;
}

/** The predicate of one point (Rf, Rc): the tool end's bound and the shank's, prepared once. */
class Checker {
  private readonly g: ToolGeometry;
  private readonly ring: RingBound;
  private readonly foot: FootBound;
  private readonly shank: ShankBound;
  private endKf = Number.NaN;
  private endValue = 0;

  constructor(tool: ToolInput) {
    this.g = new ToolGeometry(tool);
    this.ring = new RingBound(this.g);
    this.foot = new FootBound(this.g);
    this.shank = new ShankBound(this.g);
  }

  /** The end's bound on the cross curvature for a feed curvature (the last one kept). */
  end(kf: number): number {
    if (kf !== this.endKf) {
      this.endValue = endBound(this.g, kf, this.ring, this.foot);
      this.endKf = kf;
    }
    return this.endValue;
  }

  /** True when the curvatures (kf, kc) leave the surface untouched but at the CC point. */
  passes(kf: number, kc: number): boolean {
    const endF = this.end(kf);
    // A relative tolerance of 1e-12 keeps the CC point's own curvature limit (bound = -curvature) in.
    if (!(kc >= endF - 1e-12 * Math.max(1, Math.abs(endF)))) return false;
    return !(this.shankBound(kf, capOf(kf, kc)) > kc + 1e-12 * Math.max(1, Math.abs(kc)));
  }

  private readonly shankCache = new Map<string, number>();

  /** The shank's bound, kept per feed curvature and cap (a search over the shank costs milliseconds). */
  private shankBound(kf: number, cap: number): number {
    if (!Number.isFinite(cap)) return Number.NEGATIVE_INFINITY;
    const key = `${kf} ${cap}`;
    let v = this.shankCache.get(key);
    if (v === undefined) {
      v = this.shank.bound(kf, cap);
      this.shankCache.set(key, v);
    }
    return v;
  }
}

/**
 * True when the tool gouges the doubly curved point (see the module comment): one evaluation of the
 * predicate, a few milliseconds. Radii signed (mm, |R| >= 0.001, or infinite).
 */
export function doublyCurvedGouges(tool: ToolInput, radii: PrincipalRadii): boolean {
  return !new Checker(tool).passes(curvature(radii.feedRadiusMm), curvature(radii.crossRadiusMm));
}

/**
 * Gouging at a doubly curved point and, for each principal radius with the other held, the limit
 * that avoids it (see the module comment): from the given curvature the search walks towards the
 * more convex side until the predicate passes (or, when it passes, towards the concave side until it
 * fails) over radii from 0.001 mm to 1e6 mm doubling, then bisects the radius to 1e-13 of itself.
 * So the limit is the boundary nearest the given radius on that side. Radii signed (mm, |R| >=
 * 0.001, or infinite). Tens of predicate evaluations: milliseconds to a few hundred.
 * @param tool validated tool and posture.
 */
export function doublyCurvedGouging(tool: ToolInput, radii: PrincipalRadii): GougingCheck {
  const c = new Checker(tool);
  const kf = curvature(radii.feedRadiusMm);
  const kc = curvature(radii.crossRadiusMm);
  const gouges = !c.passes(kf, kc);
  return {
    gouges,
    feed: limitOf(boundary((k) => c.passes(k, kc), kf, !gouges)),
    cross: limitOf(boundary((k) => c.passes(kf, k), kc, !gouges)),
  };
}

/**
 * The limit of one principal radius, the other held (one of the two searches of
 * {@link doublyCurvedGouging}).
 * @param which `feed` (Rf) or `cross` (Rc).
 */
export function doublyCurvedRadiusLimit(tool: ToolInput, radii: PrincipalRadii, which: 'feed' | 'cross'): RadiusLimit {
  const c = new Checker(tool);
  const kf = curvature(radii.feedRadiusMm);
  const kc = curvature(radii.crossRadiusMm);
  const ok = c.passes(kf, kc);
  if (which === 'feed') return limitOf(boundary((k) => c.passes(k, kc), kf, ok));
  return limitOf(boundary((k) => c.passes(kf, k), kc, ok));
}

/** Curvatures from -1000 to 1000 per mm: radii 0.001 mm to 1e6 mm doubling, both signs, and 0. */
const GRID: readonly number[] = (() => {
  const radii: number[] = [];
  for (let r = MIN_PRINCIPAL_RADIUS_MM; r <= MAX_PRINCIPAL_RADIUS_MM; r *= 2) radii.push(r);
  radii.push(MAX_PRINCIPAL_RADIUS_MM);
  const k = [...radii.map((r) => -1 / r), 0, ...radii.map((r) => 1 / r)];
  return k.sort((a, b) => a - b);
})();

/**
 * The smallest passing curvature of the run of passing curvatures next to k0 (when k0 passes: going
 * down to the first failure; else going up to the first pass). -Infinity when nothing fails below,
 * +Infinity when nothing passes above.
 */
function boundary(ok: (k: number) => boolean, k0: number, passesHere: boolean): number {
  if (passesHere) {
    let pass = k0;
    for (let i = GRID.length - 1; i >= 0; i--) {
      const k = GRID[i] as number;
      if (k >= pass) continue;
      if (!ok(k)) return bisectCurvature(ok, k, pass);
      pass = k;
    }
    return Number.NEGATIVE_INFINITY;
  }
  let fail = k0;
  for (const k of GRID) {
    if (k <= fail) continue;
    if (ok(k)) return bisectCurvature(ok, fail, k);
    fail = k;
  }
  return Number.POSITIVE_INFINITY;
}

/**
 * The boundary between a failing curvature `a` and a passing one `b > a`, bisected in the radius on
 * its side of straight (so the limit radius keeps its digits), to 1e-13 of the radius.
 */
function bisectCurvature(ok: (k: number) => boolean, a: number, b: number): number {
  if (a < 0 && b > 0) {
    if (ok(0)) b = 0;
    else a = 0;
  }
  if (b <= 0) {
    // Concave: radii from -1/a (fails) to -1/b (passes; infinite at b = 0, capped at 1e12 mm).
    let lo = -1 / a;
    let hi = b < 0 ? -1 / b : 1e12;
    for (let i = 0; i < 200 && hi - lo > 1e-13 * hi; i++) {
      const m = hi / lo > 4 ? Math.sqrt(lo * hi) : 0.5 * (lo + hi);
      if (ok(-1 / m)) hi = m;
      else lo = m;
    }
    return -1 / hi;
  }
  // Convex: radii from 1/b (passes) to 1/a (fails; infinite at a = 0).
  let lo = 1 / b;
  let hi = a > 0 ? 1 / a : 1e12;
  for (let i = 0; i < 200 && hi - lo > 1e-13 * hi; i++) {
    const m = hi / lo > 4 ? Math.sqrt(lo * hi) : 0.5 * (lo + hi);
    if (ok(1 / m)) lo = m;
    else hi = m;
  }
  return 1 / lo;
}
