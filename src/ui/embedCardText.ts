/** The result card's line of inputs (embedCard.ts), written from the state: pure, no DOM. */
import type { CalculatorState } from './stateTypes';

/**
 * The inputs in one line, as the fields hold them in the state's unit (the tool, the posture or
 * the machine, the passes, the surface, and the quantity given), e.g. "R 3 mm, Rcr 1 mm, lead 5°,
 * tilt 0°, one-way, plane, h 0.05 mm" or "D 12.7 mm, Rcr 0.762 mm, 3-axis raster, slope 30°,
 * raster angle 30°, h 0.01 mm".
 */
export function cardSummary(state: CalculatorState): string {
  const f = state.fields;
  const unit = state.unit === 'in' ? 'in' : 'mm';
  const len = (text: string) => `${text} ${unit}`;
  const parts = [`${state.size === 'D' ? 'D' : 'R'} ${len(f.R)}`, `Rcr ${len(f.Rcr)}`];
  if (state.machine === '3axis') {
    parts.push(`3-axis ${state.passes}`, `slope ${f.slope}°`);
    if (state.passes === 'raster') parts.push(`raster angle ${f.psi}°`);
  } else {
    parts.push(`lead ${f.rho}°`, `tilt ${f.tilt}°`, state.pattern);
    if (state.surface === 'plane') parts.push('plane');
    else if (state.surface === 'curved') parts.push(`doubly curved point, Rf ${len(f.Rf)}, Rc ${len(f.Rc)}`);
    else parts.push(`${state.surface} cylinder Rs ${len(f.Rs)}`);
  }
  if (state.mode === 'inverse') parts.push(`L ${len(f.L)}`);
  else if (state.target !== 'h') parts.push(`${state.target === 'ra' ? 'Ra' : 'Sa'} ${len(f[state.target])}`);
  else parts.push(`h ${len(f.h)}`);
  return parts.join(', ');
}
