/**
 * Five-axis machining as a machine mode (mode.ts): the lead and tilt are given, on every registered
 * surface; the pattern is the one asked. The one place of the posture's angle rules: their bounds
 * are the field registry's (input/fields.ts rho and tilt ranges) and surfaces/validate.ts asks
 * leadAngleInRange and tiltAngleInRange here. Angles degrees.
 */
import { FIELDS, type FieldRange } from '../../input/fields';
import { type MachineMode, type ModeError, shownNumber } from '../mode';

/** The tool held at a given lead `rho` (0 <= rho < 90) and tilt (-90 < tilt < 90), degrees. */
export interface FiveAxisMode {
  readonly kind: 'fiveAxis';
  readonly leadAngleDeg: number;
  readonly tiltAngleDeg: number;
}

/** True when `v` lies inside a range (its bounds included or not as the range says); NaN is outside. */
function inRange(range: FieldRange | undefined, v: number): boolean {
  if (range === undefined || Number.isNaN(v)) return false;
  const aboveMin = range.min === null || (range.minIncluded ? v >= range.min : v > range.min);
  const belowMax = range.max === null || (range.maxIncluded ? v <= range.max : v < range.max);
  return aboveMin && belowMax;
}

/** True for a lead angle the posture takes: 0 <= rho < 90 degrees. */
export function leadAngleInRange(deg: number): boolean {
  return inRange(FIELDS.rho.range, deg);
}

/** True for a tilt angle the posture takes: -90 < tilt < 90 degrees. */
export function tiltAngleInRange(deg: number): boolean {
  return inRange(FIELDS.tilt.range, deg);
}

function check(mode: FiveAxisMode): ModeError[] {
  const out: ModeError[] = [];
  const { leadAngleDeg: rho, tiltAngleDeg: tilt } = mode;
  if (!leadAngleInRange(rho))
    out.push({ parameter: 'rho', message: `Lead angle must be from 0 to below 90 degrees (got ${shownNumber(rho)}).` });
  if (!tiltAngleInRange(tilt))
    out.push({
      parameter: 'tilt',
      message: `Tilt angle must be between -90 and 90 degrees (got ${shownNumber(tilt)}).`,
    });
  return out;
}

/** The five-axis mode. */
export const fiveAxisMode: MachineMode<FiveAxisMode> = {
  kind: 'fiveAxis',
  name: '5-axis',
  parameters: [
    { name: 'leadAngleDeg', field: 'rho' },
    { name: 'tiltAngleDeg', field: 'tilt' },
  ],
  surfaceKinds: null,
  check,
  posture: (mode, pattern) => ({ leadAngleDeg: mode.leadAngleDeg, tiltAngleDeg: mode.tiltAngleDeg, pattern }),
  refusal: (kind) => `Five-axis machining has no posture on a surface of kind "${kind}".`,
};
