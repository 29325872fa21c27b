/**
 * The surface the teeth leave, from the finish box (finishPanel.ts: its areal answer while it
 * answers the inputs on screen, else null) to the Machined surface view (views/surfaceView.ts),
 * which draws it in 3D instead of the continuous passes. Both load on first use, so this small
 * seam sits in neither the page's first script nor either of theirs.
 */
import type { LengthUnit } from '../core/input/units';
import type { TeethSurface } from '../worker/teethSurface';

/** The teeth's surface current for the inputs on screen, in the unit on screen. */
export interface TeethShown {
  readonly surface: TeethSurface;
  readonly unit: LengthUnit;
}

let latest: TeethShown | null = null;
const listeners = new Set<(shown: TeethShown | null) => void>();

/** The finish box's current surface (null: none current); listeners hear only a change. */
export function publishTeethSurface(shown: TeethShown | null): void {
  if (shown === latest || (shown?.surface === latest?.surface && shown?.unit === latest?.unit)) return;
  latest = shown;
  for (const listen of listeners) listen(shown);
}

/** Calls `listen` with the current surface now and on every change. */
export function onTeethSurface(listen: (shown: TeethShown | null) => void): void {
  listeners.add(listen);
  listen(latest);
}
