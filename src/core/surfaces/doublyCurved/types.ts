/**
 * Inputs and answers of the doubly curved point (shared/notes/doubly-curved-and-3-axis.md, section 1).
 *
 * The design surface at the cutter-contact (CC) point is the torus patch with signed principal radii
 * `Rf` along the feed and `Rc` across it (> 0 convex, < 0 concave, `Infinity` straight). Local frame
 * as in posture-and-surfaces.md: X feed, Y cross-feed, Z the surface normal out of the material, the
 * CC point at the origin. Lengths mm, angles of the posture degrees (as `ToolInput`).
 */
import type { DoublyCurvedSurface } from '../../domain/surface';
import type { PassPattern, ToolInput } from '../../domain/tool';
import type { FlankLimits } from '../../tool/posture';
import type { ForwardAnswer, InverseAnswer } from '../surface';

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

/** True for a curved principal radius the model takes: a magnitude from MIN_ to MAX_PRINCIPAL_RADIUS_MM (not straight). */
export function curvedRadiusInRange(radiusMm: number): boolean {
  const r = Math.abs(radiusMm);
  return r >= MIN_PRINCIPAL_RADIUS_MM && r <= MAX_PRINCIPAL_RADIUS_MM;
}

/**
 * The two signed principal radii of the design surface at the CC point: the doubly curved surface
 * descriptor (domain/surface.ts) without its kind. `feedRadiusMm` is `Rf` along the feed,
 * `crossRadiusMm` is `Rc` across it: > 0 convex (centre of curvature below, in the material), < 0
 * concave, `Infinity` (either sign) straight. Valid: `|R| >= 0.001` or infinite.
 */
export type PrincipalRadii = Omit<DoublyCurvedSurface, 'kind'>;

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

/**
 * The forward answer, mm: the shape every surface gives (surface.ts's ForwardAnswer). Widths and L
 * are arc lengths along the equator (`|Rc|` times the polar angle about `m`; widths along Y when
 * `Rc` is infinite); the cusp heights are radial.
 */
export type DoublyCurvedForward = ForwardAnswer;

/** The inverse answer, mm (surface.ts's InverseAnswer; measured as DoublyCurvedForward). */
export type DoublyCurvedInverse = InverseAnswer;

/**
 * Where a flank stops being a scallop flank, radial heights in mm: posture.ts's FlankLimits, with
 * each flank's top its widest point seen from `m` and the shank's height where it starts to form
 * the flank.
 */
export type DoublyCurvedLimits = FlankLimits;
