/**
 * The machine as the page holds it (issue 20; shared/notes/doubly-curved-and-3-axis.md, section 2):
 * five-axis (the lead and tilt given) or three-axis (the tool upright; the slope, the pass strategy
 * and the raster angle set the posture), and its part of a link:
 * `machine=3axis&slope=30&passes=raster&rasterAngle=0` (`passes=waterline` with the surface's radii
 * `feedRadius=&crossRadius=`); in inverse mode the programmed step `Lxy=` (raster) or `dz=`
 * (waterline). Pure (no DOM).
 */
import type { SolveMode } from '../worker/protocol';
import { choice } from './fieldText';
import type { CalculatorState, FieldKey, Machine, Passes, Target } from './stateTypes';
import { RADIUS_PARAM, signedRadiusOf } from './surfaceState';

export type { Machine, Passes } from './stateTypes';

/** The machine and the pass strategy of a link (defaults: five-axis, raster), notices for other words. */
export function parseMachine(params: URLSearchParams, notices: string[]): { machine: Machine; passes: Passes } {
  return { machine: choice(params, 'machine', notices), passes: choice(params, 'passes', notices) };
}

/** The programmed step's field of a pass strategy: Lxy for raster, dz for waterline. */
export function programmedStepKey(passes: Passes): 'Lxy' | 'dz' {
  return passes === 'waterline' ? 'dz' : 'Lxy';
}

/** The fields a three-axis link must give once it gives any: the tool, the slope and the quantity asked. */
export function threeAxisNeeded(mode: SolveMode, target: Target, passes: Passes): FieldKey[] {
  return ['R', 'Rcr', 'slope', mode === 'forward' ? target : programmedStepKey(passes)];
}

/** True when the three-axis surface is one of revolution: waterline passes with a curved radius. */
export function onRevolution(state: CalculatorState): boolean {
  return state.passes === 'waterline' && (state.feedSide !== 'straight' || state.crossSide !== 'straight');
}

/**
 * The three-axis part of a link, after R (or D) and Rcr: the machine, the slope, the strategy
 * (raster left out, the default), the raster angle (raster; 0 left out), the radii (waterline, when
 * curved), the quantity given and the unit. No lead, tilt, pattern or cylinder: the slope sets the
 * posture, and with the tool upright one-way and zigzag are the same.
 */
export function threeAxisSearch(state: CalculatorState): Array<[string, string]> {
  const out: Array<[string, string]> = [['machine', '3axis']];
  out.push(['slope', state.fields.slope]);
  if (state.passes === 'waterline') {
    out.push(['passes', 'waterline']);
    for (const key of ['Rf', 'Rc'] as const) {
      const signed = signedRadiusOf(state, key);
      if (signed !== null) out.push([RADIUS_PARAM[key], signed]);
    }
  } else if (state.fields.psi.trim() !== '0') out.push(['rasterAngle', state.fields.psi]);
  if (state.mode === 'forward' && state.target !== 'h')
    out.push(['target', state.target], [state.target, state.fields[state.target]]);
  else if (state.mode === 'forward') out.push(['h', state.fields.h]);
  else {
    out.push(['mode', 'inverse']);
    const key = programmedStepKey(state.passes);
    out.push([key === 'Lxy' ? 'Lxy' : 'dz', state.fields[key]]);
  }
  out.push(['unit', state.unit]);
  return out;
}
