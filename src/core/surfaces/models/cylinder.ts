/**
 * The cylinders (axis along the feed or across it, convex or concave) as a surface model
 * (surface.ts): congruent passes prepared by cylinder.ts's solver (scallops measured radially), and
 * gouging of concave ones by the head or the shank (cylinder.ts's concaveFit). Lengths mm.
 */
import type { CylinderSurface } from '../../domain/surface';
import type { ToolInput } from '../../domain/tool';
import { MAX_SURFACE_RADIUS_MM } from '../../input/limits';
import { congruentSurfaceModel } from '../congruentPasses';
import { concaveFit, cylinderSolver } from '../cylinder';
import { FITS, type SurfaceFit } from '../surface';

/**
 * Whether a cylinder takes the tool: a convex one always; a concave one from the smallest radius
 * concaveFit gives (the head's or the shank's, up to the axis height). A smallest radius at or beyond
 * the largest radius accepted (MAX_SURFACE_RADIUS_MM) is no radius at all: no limit ("at any radius").
 */
export function cylinderFit(tool: ToolInput, surface: CylinderSurface): SurfaceFit {
  if (surface.radiusMm > 0) return FITS;
  const fit = concaveFit(tool, surface.axis);
  const min = fit.minRadiusMm;
  if (Math.abs(surface.radiusMm) >= min) return FITS;
  const limitRadiusMm = min < MAX_SURFACE_RADIUS_MM ? -min : null;
  if (fit.limitedBy === 'head') return { gouges: true, by: 'head', limitRadiusMm };
  return {
    gouges: true,
    by: 'shank',
    limitRadiusMm,
    shankLean: { axis: surface.axis, leanDeg: fit.shankLeanDeg },
  };
}

/** The cylinders' model. */
export const cylinderModel = congruentSurfaceModel<CylinderSurface>({
  kind: 'cylinder',
  passes: cylinderSolver,
  fit: cylinderFit,
});
