/**
 * Where feed marks are computed (shared/notes/surface-finish.md, scope): a plane at any lead and tilt,
 * one-way and zigzag, and so the three-axis sloped plane (a plane in the posture the slope gives).
 * Everywhere else the surface the teeth leave is not computed yet, and a caller must say so rather
 * than show the continuous answer as if it were the finish.
 */

/** The surfaces a finish question can be asked about. */
export type FinishSurfaceKind =
  | 'plane'
  | 'slopedPlane'
  | 'cylinder'
  | 'doublyCurved'
  | 'waterlineRevolution'
  | (string & {});

const NAMES: Record<string, string> = {
  cylinder: 'cylinders',
  doublyCurved: 'doubly curved points',
  waterlineRevolution: 'waterline passes on surfaces of revolution',
};

/**
 * Null where feed marks are computed (a plane, a sloped plane), else the one-line refusal:
 * "Feed marks are not computed on cylinders yet: ...".
 */
export function finishScopeError(kind: FinishSurfaceKind): string | null {
  if (kind === 'plane' || kind === 'slopedPlane') return null;
  const name = NAMES[kind] ?? `this surface (${kind})`;
  return `Feed marks are not computed on ${name} yet: only on a plane (any lead and tilt, one-way or zigzag) and the three-axis sloped plane.`;
}
