/**
 * The two cylinder solvers behind ../cylinder.ts's `cylinderSolver`: axis along the feed (polar
 * angles about the axis) and across it (widths along the axis).
 */

import type { CylinderSurface } from '../../domain/surface';
import type { ToolInput } from '../../domain/tool';
import { type Placement, placeTool } from '../../tool/placement';
import { type Flank, type FlankLimits, flankSign, type PostureShape } from '../../tool/posture';
import { type Chords, crossChords, crossHeightAtWidth, crossShankHeights, crossWidthAtHeight } from './crossAxis';
import { type FeedFlankLimit, feedFlankLimit, limitsOf } from './feedLimits';
import {
  feedAngleAtHeight,
  feedHeightAtAngle,
  newProfilePoint,
  type ProfilePoint,
  planeTop,
  profilePoint,
} from './feedProfile';
import { type Stadium, stadiumHeightAtAngle, stadiumOf, stadiumReach } from './stadium';

/** A cylinder prepared for one tool and posture. */
export interface CylinderSolver {
  readonly surface: CylinderSurface;
  /** Radial height limits: each flank's wall, and the shank where it starts to cut (module comment), mm. */
  limits(): FlankLimits;
  /**
   * How far a flank reaches at radial height h: the polar angle about the axis (axis = feed,
   * radians) or the distance along the axis from the contact (axis = cross, mm).
   */
  reach(flank: Flank, heightMm: number): number;
  /** The inverse: radial height of a flank at that reach. */
  heightAt(flank: Flank, reach: number): number;
  /** Step-over (arc length on the surface for axis = feed, along the axis for cross) from reaches. */
  intervalFromReach(reachMm: number): number;
  /** The reach a step-over corresponds to. */
  reachFromInterval(intervalMm: number): number;
}
/** FeedSolver.bracket's profile point (filled and read within one call). */
const bracketPoint: ProfilePoint = newProfilePoint();

/** Axis along the feed: flank angles about the axis (classes: no closures built per call). */
class FeedSolver implements CylinderSolver {
  private cached: FlankLimits | null = null;
  /** Each flank's limits (feedFlankLimit), found once. */
  private readonly flanks: [FeedFlankLimit | null, FeedFlankLimit | null] = [null, null];
  private readonly s: PostureShape;
  private readonly rs: number;
  /** Each flank as a stadium when the ring is degenerate (no lead, or a ball end), else null. */
  private readonly stadiums: [Stadium | null, Stadium | null];

  constructor(
    readonly surface: CylinderSurface,
    p: Placement,
  ) {
    this.s = p.shape;
    this.rs = surface.radiusMm;
    this.stadiums = [stadiumOf(p.shape, 1), stadiumOf(p.shape, -1)];
  }

  private flank(sign: number): FeedFlankLimit {
    const index = sign > 0 ? 0 : 1;
    const known = this.flanks[index];
    if (known !== null && known !== undefined) return known;
    const found = feedFlankLimit(this.s, sign, this.rs);
    this.flanks[index] = found;
    return found;
  }

  limits(): FlankLimits {
    if (this.cached === null) {
      const right = this.flank(1);
      const left = this.flank(-1);
      this.cached = limitsOf(right.topMm, left.topMm, right.shankMm, left.shankMm);
    }
    return this.cached;
  }

  /**
   * An offset past the root for height h: the plane flank's widest point, where G has changed sign
   * on a convex cylinder and on a concave one that is not tight; else the concave radial top.
   */
  private bracket(sign: number, h: number): number {
    const s = this.s;
    const plane = planeTop(s, sign);
    if (this.rs > 0) return plane;
    const at = profilePoint(s, sign, plane, bracketPoint);
    if (at.y * at.y + (at.h - h) * (at.h + h + 2 * this.rs) < 0) return plane;
    return this.flank(sign).deltaTop;
  }

  reach(flank: Flank, h: number): number {
    const sign = flankSign(flank);
    const stadium = this.stadiums[sign > 0 ? 0 : 1] ?? null;
    if (stadium !== null) return stadiumReach(stadium, this.s.rcr, this.rs, h);
    return feedAngleAtHeight(this.s, flank, this.rs, h, this.bracket(sign, h));
  }

  heightAt(flank: Flank, beta: number): number {
    const sign = flankSign(flank);
    const s = this.s;
    const stadium = this.stadiums[sign > 0 ? 0 : 1] ?? null;
    if (stadium !== null) return stadiumHeightAtAngle(stadium, s.rcr, this.rs, beta);
    return feedHeightAtAngle(s, flank, this.rs, beta, this.flank(sign).deltaTop);
  }

  intervalFromReach(angle: number): number {
    return Math.abs(this.rs) * angle;
  }

  reachFromInterval(L: number): number {
    return L / Math.abs(this.rs);
  }
}

/** Axis across the feed: widths along the axis of the revolved profile. */
class CrossSolver implements CylinderSolver {
  private cached: FlankLimits | null = null;
  private readonly ch: Chords;

  constructor(
    readonly surface: CylinderSurface,
    private readonly p: Placement,
  ) {
    this.ch = crossChords(p, surface.radiusMm);
  }

  limits(): FlankLimits {
    if (this.cached === null) {
      // The widest point of each flank: the chord at the end of the disk's Y range (one ring
      // point). The shank: where the revolved profile's lowest (highest) point moves onto it.
      const topRight = this.ch.height(this.ch.yHi);
      const topLeft = this.ch.height(this.ch.yLo);
      const shank = crossShankHeights(this.p, this.surface.radiusMm);
      this.cached = limitsOf(
        topRight,
        topLeft,
        shank.right !== null && shank.right < topRight ? shank.right : null,
        shank.left !== null && shank.left < topLeft ? shank.left : null,
      );
    }
    return this.cached;
  }

  reach(flank: Flank, h: number): number {
    return crossWidthAtHeight(this.ch, flankSign(flank), this.p.cornerRadiusMm, h, 0);
  }

  heightAt(flank: Flank, w: number): number {
    return crossHeightAtWidth(this.ch, flankSign(flank), this.p.cornerRadiusMm, w, 0);
  }

  intervalFromReach(w: number): number {
    return w;
  }

  reachFromInterval(L: number): number {
    return L;
  }
}

/** Prepares the cylinder solver for a tool and posture. @param surface |Rs| > 0. */
export function cylinderSolver(tool: ToolInput, surface: CylinderSurface): CylinderSolver {
  const p = placeTool(tool);
  return surface.axis === 'feed' ? new FeedSolver(surface, p) : new CrossSolver(surface, p);
}
