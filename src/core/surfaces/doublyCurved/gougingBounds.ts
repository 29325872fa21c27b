/**
 * The bounds the tool puts on the cross curvature at a doubly curved point (gouging.ts, whose module
 * comment gives the derivation): its ring and line of feet (the end) and its shank up to a height
 * cap, each the largest `-2 rise / N` over the tool. Lengths mm, curvatures 1/mm.
 */
import type { ToolInput } from '../../domain/tool';
import { maximise, type Objective } from '../../math/rootFinder';
import { placeTool } from '../../tool/placement';
import { passSection } from './passSection';

/** The tool's ring, contact and shank, placed once. */
export class ToolGeometry {
  readonly tool: ToolInput;
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
    this.tool = tool;
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
  if (gougesAlongFeed(g, kf)) return Number.POSITIVE_INFINITY;
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

/**
 * True when a concave feed circle is tighter than the tool along the feed: the section's lowest ball
 * centre on the contact's chord (Y = 0) lies below the contact's own (passSection.ts: B(0) < Rcr).
 * The chord's image runs continuously from the contact's ball centre down to it, so the disks along
 * it hold the CC point inside: the tool reaches below the CC point at any Rc. (The bounds above
 * measure every rise from the contact's ball centre at (0, Rcr), and take the lowest image of a
 * chord as its worst: neither holds then. With Rcr > |Rf| the contact's ball centre lies beyond `l`
 * and its own image falls to 2 |Rf| - Rcr; with a tool wider than the feed circle the far end of
 * the contact's chord falls below the CC point, and on a small convex equator that end's disk can
 * lie wholly below the circle, which the bounds would pass.) Straight and convex feeds never: every
 * ball centre's image is then at least Rcr high.
 */
function gougesAlongFeed(g: ToolGeometry, kf: number): boolean {
  if (!(kf < 0)) return false;
  const lowest = passSection(g.tool, 1 / kf).lowestCentreMm(0);
  return lowest < g.k - 1e-12 * g.R;
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
export function capOf(kf: number, kc: number): number {
  let cap = Number.POSITIVE_INFINITY;
  if (kf < 0) cap = Math.min(cap, -1 / kf);
  if (kc < 0) cap = Math.min(cap, -1 / kc);
  return cap;
}
