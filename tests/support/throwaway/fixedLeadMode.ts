/**
 * A throwaway machine mode (one module), to show that the registry's promise holds: a four-axis
 * head that only leads (tilt 0), on the plane and the throwaway drum. Not a product mode: registered
 * only by the test that uses it.
 */
import type { MachineMode } from '../../../src/core/surfaces/mode';

export interface FixedLeadMode {
  readonly kind: 'throwawayFixedLead';
  readonly leadAngleDeg: number;
}

export const fixedLeadMode: MachineMode<FixedLeadMode> = {
  kind: 'throwawayFixedLead',
  parameters: [{ name: 'leadAngleDeg', field: 'rho' }],
  surfaceKinds: ['plane', 'throwawayDrum'],
  check: (m) =>
    m.leadAngleDeg >= 0 && m.leadAngleDeg <= 30
      ? []
      : [
          {
            parameter: 'rho',
            message: `Lead angle must be from 0 to 30 degrees on this head (got ${m.leadAngleDeg}).`,
          },
        ],
  posture: (m, pattern) => ({ leadAngleDeg: m.leadAngleDeg, tiltAngleDeg: 0, pattern }),
  refusal: (kind) => `The fixed-lead head has no posture on a surface of kind "${kind}": the plane or the drum only.`,
};
