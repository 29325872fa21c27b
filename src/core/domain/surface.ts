/**
 * Descriptors of the design surface at the cutter-contact point: what the user chose, as data. The
 * solvers for each kind are surfaces/models/*, found from the descriptor by surfaces/registry.ts.
 * Types and constants only: this module imports nothing (no import cycle can pass through it).
 * Lengths mm.
 */

/** Which way the cylinder's axis runs: along the feed (passes along it) or across (passes around it). */
export type SurfaceAxis = 'feed' | 'cross';

/** The plane: the paper's surface. */
export interface PlaneSurface {
  readonly kind: 'plane';
}

/** A cylinder: signed radius (convex > 0, concave < 0) and axis orientation. */
export interface CylinderSurface {
  readonly kind: 'cylinder';
  /** Signed radius `Rs`, mm: 0.001 <= |Rs| <= 1e6 (input/validate.ts's MIN_ and MAX_SURFACE_RADIUS_MM). */
  readonly radiusMm: number;
  readonly axis: SurfaceAxis;
}

/** The design surface the page, the URL, the command line and the batch take: a plane, or a cylinder. */
export type Surface = PlaneSurface | CylinderSurface;

/** The plane (one shared descriptor: compared by kind, never by identity). */
export const PLANE: Surface = { kind: 'plane' };

/**
 * A doubly curved point (shared/notes/doubly-curved-and-3-axis.md, section 1): the torus patch with
 * signed principal radii along the feed and across it (> 0 convex, < 0 concave, `Infinity` of either
 * sign straight; |R| >= 0.001 mm otherwise). Straight radii give the plane and the cylinders.
 */
export interface DoublyCurvedSurface {
  readonly kind: 'doublyCurved';
  /** Signed radius along the feed `Rf`, mm. */
  readonly feedRadiusMm: number;
  /** Signed radius across the feed `Rc`, mm. */
  readonly crossRadiusMm: number;
}

/** What every surface descriptor has: its kind, the key of its model in surfaces/registry.ts. */
export interface SurfaceDescriptorBase {
  readonly kind: string;
}
