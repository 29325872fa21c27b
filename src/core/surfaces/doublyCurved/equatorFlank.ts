/**
 * One flank of a pass's section, seen from the main axis `m` (shared/notes/doubly-curved-and-3-axis.md,
 * section 1). The next pass is this pass turned about `m` (the line through (0, 0, -Rc) parallel to
 * X), which maps the plane X = 0 to itself: in that plane it is the rotation about `C = (0, -Rc)` by
 * `phi = L / |Rc|` (with Rc infinite, the translation by L along Y). So, as for a cylinder with its
 * axis along the feed (cylinder.ts), the cusp of a right and a left flank lies where their polar
 * angles about C at the same radius add up to phi (one-way), and a zigzag cusp where one flank's angle
 * is phi / 2. Scallop heights are radial: `r = |Rc + h|` (convex `Rc + h`, concave `|Rc| - h`).
 *
 * The section (passSection.ts) facing the material is the lower envelope of disks of radius `k = Rcr`
 * around the centres `c(u) = (u, B(u))` (the flank's side mirrored to +Y: u >= 0 from the CC point,
 * whose disk is centred at (0, k)). Seen from C the material boundary of a pass is that envelope (a
 * ray from C enters it there on a convex equator and leaves it there on a concave one), and while
 * the flank rises monotonically:
 *
 * - Reach at height h: the largest polar angle of the section's points within radius r of C (convex;
 *   beyond r, concave), a maximum over the disks of `alpha(u) + omega(u)`: alpha the centre's polar
 *   angle, omega the half-angle the disk subtends at radius r (law of cosines in half-angle form,
 *   `2 asin(sqrt((k^2 - (d - r)^2) / (4 d r)))`, with `d^2 - r^2 = u^2 + (B - h)(B + h + 2 Rc)`
 *   free of cancellation), or `asin(k / d)` when the disk's tangent point from C lies inside r. Only
 *   disks whose nearest point is within r count: `u` in [0, u_f], u_f the root of e(u) = h with e
 *   the radial height of the disk's nearest point. A maximum is second-order insensitive to the error
 *   of its argument. Rc infinite: the largest Y of the section below z = h (cylinder.ts, across).
 * - Height at a polar angle theta (the inverse): the ray from C at theta meets each disk it crosses
 *   (`|p| <= k`, p the disk centre's offset from the ray); the material boundary is the first entry
 *   (convex) or the last exit (concave), a minimum over those disks of
 *   `u sin theta + B cos theta -+ 2 |Rc| sin^2(theta / 2) - sqrt(k^2 - p^2)` (upper sign convex);
 *   where that reads a height above the top (the crossing disks not one run of u: the far side),
 *   the height whose reach is theta's, by a bracketed root (the flank rises with its reach).
 * - Top: convex, the ray from C tangent to the section (the largest polar angle of any point);
 *   concave, the first point where the envelope's normal passes through C (the disk whose farthest
 *   point is nearest C) or, before that, the section's widest point; Rc infinite, the widest point.
 *
 * Reaches are returned as arc length along the equator, `|Rc|` times the angle (a width when Rc is
 * infinite). Lengths mm, angles radians.
 */

import { bracketedRoot, maximise, newSearchEnd, type Objective } from '../../math/rootFinder';
import type { PassSection } from './passSection';

/** A flank of the section seen from `m`. */
export interface EquatorFlank {
  /** Reach (arc length along the equator, mm) of the flank at radial height `h` (0 < h below the top). */
  reachMm(heightMm: number): number;
  /**
   * Radial height (mm) of the flank at reach `reachMm` (arc length along the equator from the CC
   * point). @param atMostMm a height below the top the caller knows the answer not to exceed (a
   * zigzag's other cusp, below h): a reading within it needs no search for the top.
   */
  heightAtMm(reachMm: number, atMostMm?: number): number;
  /** Radial height (mm) of the flank's top (its widest point seen from m). */
  topMm(): number;
}

/**
 * A flank of a pass's section.
 * @param section the pass's section (passSection.ts).
 * @param sign +1 right (+Y), -1 left.
 * @param crossRadiusMm signed `Rc` (mm, |Rc| >= 0.001) or +-Infinity.
 */
export function equatorFlank(section: PassSection, sign: 1 | -1, crossRadiusMm: number): EquatorFlank {
  return new Flank(section, sign, crossRadiusMm);
}

/** The objective `alpha + omega` of the reach (see the module comment). */
class ReachObjective implements Objective {
  h = 0;
  constructor(private readonly f: Flank) {}
  value(u: number): number {
    return this.f.reachAngle(u, this.h);
  }
}

/** e(u) - h: the radial height of a disk's nearest point above h. */
class BottomObjective implements Objective {
  h = 0;
  constructor(private readonly f: Flank) {}
  value(u: number): number {
    return this.f.bottom(u) - this.h;
  }
}

/** p(u) - target: the disk centre's signed offset from the ray at theta. */
class OffsetObjective implements Objective {
  theta = 0;
  target = 0;
  constructor(private readonly f: Flank) {}
  value(u: number): number {
    return this.f.offset(u, this.theta) - this.target;
  }
}

/** Minus the radial height where the ray at theta meets a disk. */
class RayObjective implements Objective {
  theta = 0;
  constructor(private readonly f: Flank) {}
  value(u: number): number {
    return -this.f.rayHeight(u, this.theta);
  }
}

/** reach(u^2) - w: a flank's reach at height u^2 (u in sqrt(mm)) beyond the reach asked. */
class ReachMismatch implements Objective {
  w = 0;
  constructor(private readonly f: Flank) {}
  value(u: number): number {
    return this.f.reachMm(u * u) - this.w;
  }
}

/** The top: convex, the largest polar angle of a disk; concave, minus the distance of its farthest point from C. */
class TopObjective implements Objective {
  constructor(private readonly f: Flank) {}
  value(u: number): number {
    return this.f.topValue(u);
  }
}

class Flank implements EquatorFlank {
  /** 0: Rc infinite; +1 convex; -1 concave. */
  private readonly mode: 0 | 1 | -1;
  private readonly rc: number;
  private readonly absRc: number;
  private readonly k: number;
  private readonly end: number;
  private readonly reachObj = new ReachObjective(this);
  private readonly bottomObj = new BottomObjective(this);
  private readonly offsetObj = new OffsetObjective(this);
  private readonly rayObj = new RayObjective(this);
  private readonly reachMismatch = new ReachMismatch(this);
  private top: { heightMm: number; u: number } | null = null;

  constructor(
    private readonly section: PassSection,
    private readonly sign: 1 | -1,
    crossRadiusMm: number,
  ) {
    this.mode = Number.isFinite(crossRadiusMm) ? (crossRadiusMm > 0 ? 1 : -1) : 0;
    this.rc = crossRadiusMm;
    this.absRc = Math.abs(crossRadiusMm);
    this.k = section.cornerRadiusMm;
    this.end = sign > 0 ? section.yHiMm : -section.yLoMm;
  }

  /** B at the mirrored offset u. */
  private centre(u: number): number {
    return this.section.lowestCentreMm(this.sign * u);
  }

  /** Radial height (mm) of the nearest point of disk u: e(u). */
  bottom(u: number): number {
    const cz = this.centre(u);
    if (this.mode === 0) return cz - this.k;
    const q = cz + this.rc;
    const d = Math.sqrt(u * u + q * q);
    return (this.mode * (u * u + cz * (cz + 2 * this.rc))) / (d + this.absRc) - this.k;
  }

  /** The reach of disk u at radial height h: an angle (radians), or a width (mm) when Rc is infinite; -Infinity if it cannot reach. */
  reachAngle(u: number, h: number): number {
    const cz = this.centre(u);
    const k = this.k;
    if (this.mode === 0) {
      const gap = cz - h;
      if (gap <= 0) return u + k;
      // As below: a disk that just touches h may miss it by a rounding.
      return gap <= k * (1 + 1e-14) ? u + Math.sqrt(Math.max(0, (k - gap) * (k + gap))) : Number.NEGATIVE_INFINITY;
    }
    const rc = this.rc;
    const q = cz + rc;
    const alpha = Math.atan2(u, this.mode * q);
    const d = Math.sqrt(u * u + q * q);
    const r = Math.abs(rc + h);
    const d2r2 = u * u + (cz - h) * (cz + h + 2 * rc);
    // Convex: the tangent point from C lies within r; concave: beyond r.
    if (this.mode * (d2r2 - k * k) <= 0) return alpha + Math.asin(Math.min(1, k / d));
    const diff = d2r2 / (d + r);
    // A disk that just touches the radius r (the contact's own at h = 0) may miss it by a rounding.
    if (!(Math.abs(diff) <= k * (1 + 1e-14))) return Number.NEGATIVE_INFINITY;
    const half = Math.sqrt(Math.max(0, (k - diff) * (k + diff)) / (4 * d * r));
    return alpha + 2 * Math.asin(Math.min(1, half));
  }

  /** Signed offset of disk u's centre from the ray at theta (mm): negative before the ray, positive past it. */
  offset(u: number, theta: number): number {
    const cz = this.centre(u);
    if (this.mode === 0) return u - theta;
    // Convex: u cos - (Rc + B) sin; concave: u cos - (|Rc| - B) sin.
    return u * Math.cos(theta) - (this.absRc + this.mode * cz) * Math.sin(theta);
  }

  /** Radial height (mm) where the ray at theta first meets (convex) or last leaves (concave) disk u. */
  rayHeight(u: number, theta: number): number {
    const cz = this.centre(u);
    const k = this.k;
    if (this.mode === 0) {
      const p = theta - u;
      return cz - Math.sqrt(Math.max(0, (k - p) * (k + p)));
    }
    const s = Math.sin(theta);
    const c = Math.cos(theta);
    const half = Math.sin(0.5 * theta);
    const p = u * c - (this.absRc + this.mode * cz) * s;
    const across = Math.sqrt(Math.max(0, (k - p) * (k + p)));
    return this.mode * u * s + cz * c - this.mode * 2 * this.absRc * half * half - across;
  }

  topValue(u: number): number {
    const cz = this.centre(u);
    const q = cz + this.rc;
    const d = Math.sqrt(u * u + q * q);
    if (this.mode > 0) return Math.atan2(u, q) + Math.asin(Math.min(1, this.k / d));
    // Concave: |Rc| - d - k, the radial height of the disk's farthest point from C.
    return -(u * u + cz * (cz + 2 * this.rc)) / (d + this.absRc) - this.k;
  }

  private findTop(): { heightMm: number; u: number } {
    if (this.top !== null) return this.top;
    const U = this.end;
    let result: { heightMm: number; u: number };
    if (this.mode > 0) {
      // Convex: the tangent from C with the largest polar angle.
      let u = 0;
      if (U > 0) {
        const at = newSearchEnd();
        maximise(new TopObjective(this), 0, U, 32, 1e-12 * U, at);
        u = at.x;
      }
      result = { heightMm: this.tangentHeight(u), u };
    } else if (this.mode < 0 && U > 0) {
      // Concave: the first maximum of the radial height (a normal through C), unless it rises to the widest point.
      const at = newSearchEnd();
      const best = maximise(new TopObjective(this), 0, U, 32, 1e-12 * U, at);
      const u = at.x;
      result = u >= U * (1 - 1e-9) ? { heightMm: this.widestHeight(U), u: U } : { heightMm: best, u };
    } else {
      result = { heightMm: this.widestHeight(U), u: U };
    }
    this.top = result;
    return result;
  }

  /** Radial height of the tangent point from C of disk u (convex). */
  private tangentHeight(u: number): number {
    const cz = this.centre(u);
    const k = this.k;
    const q = cz + this.rc;
    const t = Math.sqrt(Math.max(0, u * u + q * q - k * k));
    return (u * u + cz * (cz + 2 * this.rc) - k * k) / (t + this.rc);
  }

  /** Radial height of the section's widest point (the end disk's point farthest along +u). */
  private widestHeight(U: number): number {
    const cz = this.centre(U);
    if (this.mode === 0) return cz;
    const y = U + this.k;
    const q = cz + this.rc;
    const dist = Math.sqrt(y * y + q * q);
    return (this.mode * (y * y + cz * (cz + 2 * this.rc))) / (dist + this.absRc);
  }

  topMm(): number {
    return this.findTop().heightMm;
  }

  private scale(): number {
    return this.mode === 0 ? 1 : this.absRc;
  }

  reachMm(h: number): number {
    const U = this.end;
    const k = this.k;
    const scale = this.scale();
    if (!(U > 0)) return scale * this.reachAngle(0, h);
    // The disks that reach r: [0, uF], the first root of e(u) = h. On a concave equator e is the
    // radial height of the disk's farthest point from C, largest at the top: search up to it.
    const uEnd = this.searchEnd();
    this.bottomObj.h = h;
    const eEnd = this.bottomObj.value(uEnd);
    const uF = eEnd <= 0 ? uEnd : bracketedRoot(this.bottomObj, 0, uEnd, -h, eEnd);
    if (!(k > 0)) {
      // A flat end: the flank is the centre curve itself, its point at radius r is the root.
      const cz = this.centre(uF);
      return this.mode === 0 ? uF : scale * Math.atan2(uF, this.mode * (cz + this.rc));
    }
    this.reachObj.h = h;
    if (!(uF > 0)) return scale * this.reachAngle(0, h);
    return scale * maximise(this.reachObj, 0, uF, 4, 1e-10 * uF);
  }

  /** Where the searches along the flank end: the top's disk on a concave equator (past it the flank falls), else the chord range's end. */
  private searchEnd(): number {
    return this.mode < 0 ? this.findTop().u : this.end;
  }

  heightAtMm(reachMm: number, atMostMm = Number.NEGATIVE_INFINITY): number {
    const h = this.rayHeightAtMm(reachMm);
    if (h <= atMostMm) return h;
    // The ray's first entry can be read past the flank's top, on its far side (a section whose disk
    // centres rise steeply, as at a high lead over a convex Rc below the tool radius: the disks the
    // ray crosses are then not one run of u). Below the top the flank rises with its reach, so the
    // height there is the one whose reach is reachMm.
    return h <= this.topMm() ? h : this.heightByReachMm(reachMm);
  }

  /**
   * The height (mm) whose reach is reachMm, by bisection of the reach in sqrt(h) up to the top (to
   * 1e-16 sqrt(mm), at most 200 halvings). Not the shared bracketedRoot: one more objective class
   * through its call sites made them megamorphic, and every doubly curved forward answer 45 % slower
   * in a process that had met this rare case (npm run bench: 11 -> 16 us).
   */
  private heightByReachMm(reachMm: number): number {
    const top = this.topMm();
    const f = this.reachMismatch;
    f.w = reachMm;
    const hi = Math.sqrt(top);
    const fHi = f.value(hi);
    if (!(fHi > 0)) return top;
    const at0 = f.value(0);
    const fLo = Number.isFinite(at0) ? at0 : -reachMm;
    if (fLo >= 0) return 0;
    let a = 0;
    let b = hi;
    for (let i = 0; i < 200 && b - a > 1e-16; i++) {
      const m = 0.5 * (a + b);
      if (f.value(m) < 0) a = m;
      else b = m;
    }
    return (0.5 * (a + b)) ** 2;
  }

  /** The height (mm) where the ray from C at the reach's angle first enters (convex) or last leaves (concave) the section. */
  private rayHeightAtMm(reachMm: number): number {
    const U = this.searchEnd();
    const theta = reachMm / this.scale();
    const k = this.k;
    if (!(U > 0)) return this.rayHeight(0, theta);
    const o = this.offsetObj;
    o.theta = theta;
    // The disks the ray crosses: p(u) in [-k, k].
    o.target = -k;
    const p0 = o.value(0);
    const pEnd = o.value(U);
    const uA = p0 >= 0 ? 0 : pEnd <= 0 ? U : bracketedRoot(o, 0, U, p0, pEnd);
    if (!(k > 0)) return this.rayHeight(uA, theta);
    o.target = k;
    const q0 = p0 - 2 * k;
    const qEnd = pEnd - 2 * k;
    const uB = qEnd <= 0 ? U : q0 >= 0 ? 0 : bracketedRoot(o, 0, U, q0, qEnd);
    this.rayObj.theta = theta;
    if (!(uB > uA)) return this.rayHeight(uA, theta);
    return -maximise(this.rayObj, uA, uB, 4, 1e-10 * (uB - uA));
  }
}
