/**
 * The core's finish inputs (src/core/finish/finishInput.ts FinishInput) for tests: z flutes, fz and
 * optional runout e (mm) at phase phi_e (degrees) and pass phase q (lengths mm).
 */
import type { FinishInput } from '../../src/core/finish/finishInput';

export function teethFinish(flutes: number, fz: number, runoutMm = 0, runoutPhaseDeg = 0, passPhase = 0): FinishInput {
  return { flutes, feedPerToothMm: fz, runoutMm, runoutPhaseDeg, passPhase };
}
