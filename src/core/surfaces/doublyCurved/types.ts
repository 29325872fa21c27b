/**
 * Inputs and answers of the doubly curved point (shared/notes/doubly-curved-and-3-axis.md, section 1).
 *
 * The design surface at the cutter-contact (CC) point is the torus patch with signed principal radii
 * `Rf` along the feed and `Rc` across it (> 0 convex, < 0 concave, `Infinity` straight). Local frame
 * as in posture-and-surfaces.md: X feed, Y cross-feed, Z the surface normal out of the material, the
 * CC point at the origin. Lengths mm, angles of the posture degrees (as `ToolInput`).
 */
import type { PassPattern, ToolInput } from '../../domain/tool';

/**
 * Smallest |radius| accepted for `Rf` and `Rc`, mm (the notes: `|R| >= 0.001 mm`). Source:
 * shared/notes/doubly-curved-and-3-axis.md, section 1.
 */
export const MIN_PRINCIPAL_RADIUS_MM = 0.001;

/**
 * Largest |radius| that is not straight, mm: as validate.ts's MAX_SURFACE_RADIUS_MM for cylinders
 * (beyond it the plane answers to 1e-9 mm). Gouging limits beyond it mean no radius of that side.
 */
export const MAX_PRINCIPAL_RADIUS_MM = 1e6;

/** The two signed principal radii of the design surface at the CC point. */
export interface PrincipalRadii {
  /**
   * Signed radius along the feed `Rf`, mm: > 0 convex (centre of curvature below, in the material),
   * < 0 concave, `Infinity` (either sign) straight. Valid: `|Rf| >= 0.001` or infinite.
   */
  readonly feedRadiusMm: number;
  /** Signed radius across the feed `Rc`, mm; same conventions as `feedRadiusMm`. */
  readonly crossRadiusMm: number;
}

/** Tool, posture, pass pattern and the doubly curved point. */
export interface DoublyCurvedPass extends ToolInput, PrincipalRadii {
  readonly pattern: PassPattern;
}

/** Forward problem: scallop height `h` (mm, radial, 0 < h below the flank limits) to step-over. */
export interface DoublyCurvedForwardInput extends DoublyCurvedPass {
  readonly scallopHeightMm: number;
}

/** Inverse problem: step-over `L` (mm, arc length along the equator, 0 < L below the widest) to cusp heights. */
export interface DoublyCurvedInverseInput extends DoublyCurvedPass {
  readonly intervalMm: number;
}

/** The forward answer, mm. */
export interface DoublyCurvedForward {
  /** Step-over `L`: arc length along the equator between adjacent CC paths (width along Y when `Rc` is infinite). */
  readonly intervalMm: number;
  /**
   * How far the right (+Y) and left flank reach at the scallop height, from the CC point, as arc
   * length along the equator (`|Rc|` times the polar angle about `m`; a width along Y when `Rc` is
   * infinite). One-way `L = wR + wL`, zigzag `L = 2 min(wR, wL)`.
   */
  readonly halfWidthRightMm: number;
  readonly halfWidthLeftMm: number;
  /** Contact offset `y0`: Y of the CC point minus Y of the tool centre point O (as on the plane). */
  readonly contactOffsetMm: number;
  /** The highest cusp, radial: `h`. */
  readonly cuspHeightMm: number;
  /** Zigzag: the other (lower or equal) cusp's radial height; null for one-way. */
  readonly otherCuspHeightMm: number | null;
}

/** The inverse answer, mm. */
export interface DoublyCurvedInverse {
  readonly intervalMm: number;
  /** Radial height of the highest cusp (the scallop height). */
  readonly cuspHeightMm: number;
  /** Zigzag: the other cusp's radial height; null for one-way. */
  readonly otherCuspHeightMm: number | null;
  /** Heights of the cusps formed by two right flanks and by two left flanks (equal for one-way). */
  readonly rightCuspHeightMm: number;
  readonly leftCuspHeightMm: number;
  /** Reaches of the two flanks at their cusps (arc length along the equator). */
  readonly halfWidthRightMm: number;
  readonly halfWidthLeftMm: number;
  readonly contactOffsetMm: number;
}

/** Where a flank stops being a scallop flank, radial heights in mm (as posture.ts's FlankLimits). */
export interface DoublyCurvedLimits {
  /** Radial height of each flank's top: its widest point seen from `m` (a wall beyond it). */
  readonly topRightMm: number;
  readonly topLeftMm: number;
  /** Radial height at which the shank starts to form the flank, or null where it never does. */
  readonly shankRightMm: number | null;
  readonly shankLeftMm: number | null;
  /** The binding limit: scallop heights must stay below it. */
  readonly limitMm: number;
  readonly limitBy: 'right-flank' | 'left-flank' | 'shank-right' | 'shank-left';
}
