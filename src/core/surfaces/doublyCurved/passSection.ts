/**
 * The section of one pass's swept tool end in the cross-feed plane X = 0 (derivation below; the
 * definitions are shared/notes/doubly-curved-and-3-axis.md, section 1).
 *
 * A pass turns the tool rigidly about `l`, the line through `F = (0, 0, -Rf)` parallel to Y. A tool
 * point p keeps its Y and its distance `dist(p, l) = sqrt(p_x^2 + (p_z + Rf)^2)` from `l`, and meets
 * the plane X = 0 (on the CC point's side of `l`) at height
 *
 *   zc(p) = sign(Rf) dist(p, l) - Rf = sign(Rf) (p_x^2 + p_z (p_z + 2 Rf)) / (dist(p, l) + |Rf|)
 *
 * (the second form keeps its digits for any |Rf|); with Rf infinite the pass translates along X and
 * zc(p) = p_z. So the section is the image of the tool under p -> (p_y, zc(p)). The tool end is the
 * ring disk D (radius Rb = R - Rcr, centre O, normal the tool axis) grown by a ball of radius Rcr; a
 * ball revolved about `l` is a torus whose section in X = 0 is the disk of radius Rcr around its
 * centre's image. So the section is the union of disks of radius Rcr around the image of D, and its
 * side facing the material (the lower side, whatever the sign of Rc: the material lies below the
 * tool) is the lower envelope of the disks around the lowest image point of each chord of D at
 * constant Y:
 *
 *   B(y) = min { zc(e) : e in D, e_y = y }.
 *
 * All chords of D are parallel (their direction is the unit vector of D's plane normal to Y), and
 * `dist(., l)` is a convex function along a straight chord (the distance to a line). So for Rf > 0
 * the minimum is the foot of `l` on the chord, clipped to the chord; for Rf < 0 (the largest
 * distance) and for Rf infinite (zc linear) it is a chord end, a point of the ring. With Rf infinite
 * B is the lower half of the projected ring ellipse (the plane profile of posture.ts); with Rc
 * infinite this is the cylinder-across construction of cylinder.ts. Heights are relative to the CC
 * point; the CC point's ball centre is (0, Rcr). Lengths mm.
 */

import type { ToolInput } from '../../domain/tool';
import { placeTool } from '../../tool/placement';

/** The lowest ball centres of one pass's section, chord by chord (see the module comment). */
export interface PassSection {
  /** Corner radius `Rcr`, mm (the disks' radius). */
  readonly cornerRadiusMm: number;
  /** Range of Y covered by the ring disk's chords, mm, relative to the CC point: yLo <= 0 <= yHi. */
  readonly yLoMm: number;
  readonly yHiMm: number;
  /**
   * Height (mm, along Z from the CC point, in the plane X = 0) of the lowest ball centre's image on
   * the chord at `yMm`, clamped into [yLo, yHi]: B(y). B(0) = Rcr unless the pass gouges along the feed.
   */
  lowestCentreMm(yMm: number): number;
}

/**
 * The swept section of the tool end for one pass along a feed circle of signed radius `Rf`.
 * @param tool validated tool and posture (mm, degrees).
 * @param feedRadiusMm signed `Rf` in mm, `|Rf| >= 0.001`, or +-Infinity (straight feed).
 */
export function passSection(tool: ToolInput, feedRadiusMm: number): PassSection {
  return new ChordSection(tool, feedRadiusMm);
}

class ChordSection implements PassSection {
  readonly cornerRadiusMm: number;
  readonly yLoMm: number;
  readonly yHiMm: number;
  private readonly rf: number;
  private readonly absRf: number;
  private readonly mode: 0 | 1 | -1;
  private readonly ox: number;
  private readonly oy: number;
  private readonly oz: number;
  private readonly rb: number;
  private readonly g: number;
  /** Chord midpoint per unit of (y - O_y): its x and z. */
  private readonly mx: number;
  private readonly mz: number;
  /** Unit chord direction (x, z components; its y component is 0). */
  private readonly dx: number;
  private readonly dz: number;

  constructor(tool: ToolInput, feedRadiusMm: number) {
    const p = placeTool(tool);
    const rb = p.ringRadiusMm;
    this.cornerRadiusMm = p.cornerRadiusMm;
    this.rb = rb;
    this.rf = feedRadiusMm;
    this.absRf = Math.abs(feedRadiusMm);
    this.mode = Number.isFinite(feedRadiusMm) ? (feedRadiusMm > 0 ? 1 : -1) : 0;
    [this.ox, this.oy, this.oz] = p.centre;
    const gy1 = p.v1[1];
    const gy2 = p.v2[1];
    const G = Math.sqrt(gy1 * gy1 + gy2 * gy2);
    this.g = G;
    // The chord at c = y - O_y: (u, w) = c (gy1, gy2) / G^2 + tau (-gy2, gy1) / G, |tau| <= sqrt(Rb^2 - c^2 / G^2).
    this.mx = G > 0 ? (gy1 * p.v1[0] + gy2 * p.v2[0]) / (G * G) : 0;
    this.mz = G > 0 ? (gy1 * p.v1[2] + gy2 * p.v2[2]) / (G * G) : 0;
    this.dx = G > 0 ? (-gy2 * p.v1[0] + gy1 * p.v2[0]) / G : 1;
    this.dz = G > 0 ? (-gy2 * p.v1[2] + gy1 * p.v2[2]) / G : 0;
    const half = rb > 0 && G > 0 ? rb * G : 0;
    // `0 -` and `0 +` keep a zero range +0.
    this.yLoMm = Math.min(0, 0 + this.oy - half);
    this.yHiMm = Math.max(0, 0 + this.oy + half);
  }

  /** zc of a point (x, z) relative to the CC point. */
  private zc(x: number, z: number): number {
    if (this.mode === 0) return z;
    const rf = this.rf;
    const q = z + rf;
    const num = x * x + z * (z + 2 * rf);
    return (this.mode * num) / (Math.sqrt(x * x + q * q) + this.absRf);
  }

  lowestCentreMm(yMm: number): number {
    const rb = this.rb;
    const G = this.g;
    if (!(rb > 0) || !(G > 0)) return this.zc(this.ox, this.oz);
    const span = rb * G;
    const c = Math.min(span, Math.max(-span, yMm - this.oy));
    const x0 = this.ox + c * this.mx;
    const z0 = this.oz + c * this.mz;
    const tMax = Math.sqrt(Math.max(0, (rb - c / G) * (rb + c / G)));
    if (this.mode === 1) {
      // Convex feed circle: the foot of l on the chord (the chord direction is a unit vector).
      const tau = Math.min(tMax, Math.max(-tMax, -(x0 * this.dx + (z0 + this.rf) * this.dz)));
      return this.zc(x0 + tau * this.dx, z0 + tau * this.dz);
    }
    const a = this.zc(x0 + tMax * this.dx, z0 + tMax * this.dz);
    const b = this.zc(x0 - tMax * this.dx, z0 - tMax * this.dz);
    return Math.min(a, b);
  }
}
