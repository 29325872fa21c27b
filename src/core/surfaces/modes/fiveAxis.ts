/**
 * Five-axis machining as a machine mode (mode.ts): the lead and tilt are given, on every registered
 * surface; the pattern is the one asked. Its angle rules are input/angleRanges.ts's, which the
 * validation (surfaces/validate.ts) asks too: stated once. Angles degrees.
 */
import { leadAngleInRange, tiltAngleInRange } from '../../input/angleRanges';
import { type MachineMode, type ModeError, shownNumber } from '../mode';

/** The tool held at a given lead `rho` (0 <= rho < 90) and tilt (-90 < tilt < 90), degrees. */
export interface FiveAxisMode {
  readonly kind: 'fiveAxis';
  readonly leadAngleDeg: number;
  readonly tiltAngleDeg: number;
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
  parameters: [
    { name: 'leadAngleDeg', field: 'rho' },
    { name: 'tiltAngleDeg', field: 'tilt' },
  ],
  surfaceKinds: null,
  check,
  posture: (mode, pattern) => ({ leadAngleDeg: mode.leadAngleDeg, tiltAngleDeg: mode.tiltAngleDeg, pattern }),
  refusal: (kind) => `Five-axis machining has no posture on a surface of kind "${kind}".`,
};
