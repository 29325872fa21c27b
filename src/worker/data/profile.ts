/**
 * The cross-feed profile view's data: the exact profile, the ring ellipse and each approximation's
 * curve; on a cylinder also the pass's profile in surface coordinates and where each comparison
 * row (the plane's answer, the corrected procedures) puts the next pass. Mm.
 */

import type { ForwardInput } from '../../core/input/validate';
import { toSurfaceSection } from '../../core/output/surfaceGeometry';
import type { CurvatureComparison } from '../../core/procedures/compare';
import { CORRECTED_KEYS, type CurvatureRowKey, correctedRowKey } from '../../core/procedures/procedures';
import type { ProfileCurves } from '../../core/procedures/teaching';
import { type CylinderSurface, revolvedProfile } from '../../core/surfaces/cylinder';
import type { CylinderCurves, ProfileCurveSet } from '../protocol';

/** The curves the profile view draws on any surface. */
export function profileCurveSet(c: ProfileCurves): ProfileCurveSet {
  const { exact: _exact, profile, ringEllipse, ...approximations } = c;
  return { profile, ringEllipse, approximations };
}

/** The profile view's curves on a cylinder (surface coordinates) and where each comparison row puts the next pass. */
export function cylinderCurves(
  forward: ForwardInput,
  surface: CylinderSurface,
  c: Pick<ProfileCurves, 'profile' | 'ringEllipse'>,
  k: CurvatureComparison | null,
): CylinderCurves {
  const passProfile =
    surface.axis === 'feed' ? toSurfaceSection(surface, c.profile) : revolvedProfile(forward, surface);
  const comparison: Array<{ key: CurvatureRowKey; intervalMm: number | null }> = [
    { key: 'plane', intervalMm: k?.plane.ok ? k.plane.intervalMm : null },
  ];
  for (const key of CORRECTED_KEYS) {
    const r = k?.corrected[key];
    comparison.push({ key: correctedRowKey(key), intervalMm: r?.ok ? r.intervalMm : null });
  }
  return { surface, passProfile, ringEllipse: toSurfaceSection(surface, c.ringEllipse), comparison };
}
