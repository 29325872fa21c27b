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
 * Both steps assume the contact's chord (Y = 0) keeps its lowest ball centre at the contact's own,
 * (0, Rcr): a concave feed circle tighter than the tool along the feed breaks that (the contact's
 * ball centre lies beyond `l`, or the far end of the chord falls below the CC point), and its swept
 * image holds the CC point inside the disks: that gouges at any Rc (gougingBounds.ts's
 * gougesAlongFeed; issue 26, where such points were answered with -Infinity).
 *
 * So the admissible cross curvature is `kc >= kMin(Rf)`, a maximum over the tool. Raising either
 * curvature (more convex) lifts the swept section (zc grows with 1/Rf) or lowers the equator, so the
 * admissible set in each curvature, the other held, is a half-line `[kMin, +inf)`: a concave radius
 * must be at least `1 / |kMin|` (kMin < 0), or the radius must be convex and at most `1 / kMin`
 * (kMin > 0, a saddle), or no radius helps. The feed curvature's bound is found by bisection on that
 * predicate. Lengths mm, curvatures 1/mm.
 *
 * The parts: the tool's bounds (gougingBounds.ts) and the search of each radius's limit
 * (radiusLimitSearch.ts); this module holds the check that joins them.
 */

import type { ToolInput } from '../../domain/tool';
import { capOf, endBound, FootBound, RingBound, ShankBound, ToolGeometry } from './gougingBounds';
import { boundary, limitOf, type RadiusLimit } from './radiusLimitSearch';
import type { PrincipalRadii } from './types';

/** The tool's bounds (gougingBounds.ts) and the limit's type (radiusLimitSearch.ts), re-exported for the callers. */
export type { RadiusLimit };
export { endBound, FootBound, RingBound, ShankBound, ToolGeometry };

/** The gouging verdict at a doubly curved point, with each radius's limit (the other held). */
export interface GougingCheck {
  /** True when the swept tool reaches inside the surface anywhere but at the CC point. */
  readonly gouges: boolean;
  /** What Rf must be with Rc held. */
  readonly feed: RadiusLimit;
  /** What Rc must be with Rf held. */
  readonly cross: RadiusLimit;
}

const curvature = (radiusMm: number) => (Number.isFinite(radiusMm) ? 1 / radiusMm : 0);

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
