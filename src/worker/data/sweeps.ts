/**
 * The chart view's data: every procedure's step-over along the lead angle (0.5 to 89 degrees,
 * dense at small angles) and along the tilt (-60 to 60 degrees, widened to the current one), each
 * through the current posture, with the runs of angles where a procedure has none and why. Mm, degrees.
 */

import type { ForwardInput } from '../../core/input/validate';
import { stepOverSweep } from '../../core/procedures/teaching';
import type { Sweep } from '../protocol';

/** Samples per sweep (the current angle is added to them). */
const SWEEP_STEPS = 120;

/** The sweep of one posture angle through the forward state. */
export function sweep(input: ForwardInput, axis: 'lead' | 'tilt'): Sweep {
  const current = axis === 'lead' ? input.leadAngleDeg : input.tiltAngleDeg;
  const [fromDeg, toDeg] = axis === 'lead' ? [0.5, 89] : [Math.min(-60, current), Math.max(60, current)];
  const s = stepOverSweep(
    input,
    input.pattern,
    input.scallopHeightMm,
    axis,
    fromDeg,
    toDeg,
    SWEEP_STEPS,
    current,
    input.surface,
  );
  return { angleDeg: s.angleDeg, values: s.values, gaps: s.gaps };
}

/** Both sweeps: along the lead and along the tilt. */
export function sweeps(input: ForwardInput): { readonly lead: Sweep; readonly tilt: Sweep } {
  return { lead: sweep(input, 'lead'), tilt: sweep(input, 'tilt') };
}
