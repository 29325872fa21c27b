/**
 * Exact step-over on cylinders (shared/notes/posture-and-surfaces.md, "Curved surfaces"): convex
 * (Rs > 0, axis Rs below the contact) or concave (Rs < 0, axis |Rs| above), with the axis along the
 * feed or across it, any posture, one-way or zigzag. Scallop heights are measured radially. Lengths
 * mm, angles radians. Frame: the contact of the pass at the origin, X feed, Z the surface normal.
 *
 * Axis along the feed. A pass translates along X, so it leaves the plane profile of posture.ts; the
 * next pass is that profile turned about the axis by phi = L / |Rs|. In polar coordinates about the
 * axis (angle measured from the contact), a flank at radius r = |Rs| + s h (s = +1 convex, -1
 * concave) lies at a polar angle A(h); the cusp of a right and a left flank sits where
 * A_R + A_L = phi (one-way) and the zigzag cusps where A = phi / 2. The flank point at that radius is
 * the section whose profile point (Y, H) satisfies
 *
 *   G(delta) = Y^2 + (H - h)(H + h + 2 Rs) = 0            (|(Y, H) - C| = r, without cancellation)
 *
 * and the angle is taken, as on the plane, as a maximum over sections: the ring point's polar angle
 * plus the half-angle its ball subtends at radius r (law of cosines in half-angle form), which is
 * second-order insensitive to the root's error.
 *
 * Axis across the feed. A pass turns the tool about the axis (along Y); revolving a ball of radius
 * Rcr centred at e gives, in the meridian plane (Y, rho = distance from the axis), the circle of
 * radius Rcr around (e_y, rho(e)). So the revolved profile is the offset by Rcr of the bottom disk's
 * image: its lower boundary B(y) = min of rho over the disk's chord at y (convex; closed form: the
 * foot of the axis on the chord, or a chord end) or upper boundary U(y) = max (concave: a chord end).
 * A flank's width at radius r is the maximum over y of y + sqrt(Rcr^2 - (B(y) - r)^2), found by a scan
 * and golden-section search to the last bits. The next pass is that profile translated by L.
 *
 * Walls. Along the feed on a convex cylinder a flank's polar angle peaks where its tangent passes
 * through the axis, below the plane's widest point: beyond, a pass reaches no farther (a wall). On a
 * concave one the wall is where the radial height stops growing, at most the plane's widest point.
 * Across the feed it is the end of the revolved profile (the disk's widest chord). Without lead the
 * ring projects onto a segment (a point for a ball end) and whole arcs of the profile hang on one
 * ring angle; those flanks are two corner balls joined by the flat bottom's edge (Stadium), in
 * closed form.
 *
 * The shank (the cylinder of radius R above the corner): along the feed, radially, where its
 * silhouette leaves the plane profile; across it, where the revolved profile's nearest (concave:
 * farthest) point moves from the corner onto the shank (crossShankHeights).
 *
 * Gouging (concave). The tool end must stay inside the cylinder except at the contact: every ring
 * point e (relative to the contact, seen along the feed for axis = feed, along the axis for
 * axis = cross) needs |Rs| >= (E^2 + E_z^2 - Rcr^2) / (2 (E_z - Rcr)), E its horizontal offset. The
 * head's smallest admissible radius is the maximum of that over the ring; the shank must not cross
 * the wall up to the axis height (shankMinConcaveRadiusMm); the larger of the two is the limit.
 *
 * The code, by concern, in ./cylinder/: feedProfile.ts (axis along the feed: profile points, reach
 * and its inverse), stadium.ts (degenerate rings in closed form), feedLimits.ts (walls and shank
 * along the feed), crossAxis.ts (axis across the feed), solvers.ts (the two CylinderSolvers),
 * concaveFit.ts (gouging on a concave cylinder), revolvedProfile.ts (the profile a view draws).
 * This module keeps the public names.
 */

import { type CylinderSurface, PLANE, type Surface, type SurfaceAxis } from '../domain/surface';

/** The surface descriptors, defined in domain/surface.ts; re-exported for the callers. */
export type { CylinderSurface, Surface, SurfaceAxis };
export { PLANE };

// ---------------------------------------------------------------------------------------------
// Public API

export { type ConcaveFit, concaveFit, minConcaveRadiusMm } from './cylinder/concaveFit';
export { revolvedProfile } from './cylinder/revolvedProfile';
export { type CylinderSolver, cylinderSolver } from './cylinder/solvers';
