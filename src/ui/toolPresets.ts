/**
 * The tool presets: the paper's tools and common catalogue sizes, and which one the tool fields
 * hold. Pure; re-exported by state.ts.
 */
import { fieldText, formatField, parseField } from './fieldText';
import type { CalculatorState } from './state';

/** A tool preset: its name as a catalogue gives it (diameter D, corner radius), R and Rcr in mm. */
export interface Preset {
  readonly label: string;
  readonly R: number;
  readonly Rcr: number;
}

/** Presets: the paper's tools and a few common catalogue sizes, named by diameter and corner radius (mm). */
export const PRESETS: readonly Preset[] = [
  { label: 'D6, corner R1 (paper Tool 1)', R: 3, Rcr: 1 },
  { label: 'D12, corner R2 (paper Tool 2)', R: 6, Rcr: 2 },
  { label: 'D6, corner R0.5', R: 3, Rcr: 0.5 },
  { label: 'D10, corner R1', R: 5, Rcr: 1 },
  { label: 'D16, corner R3', R: 8, Rcr: 3 },
  { label: 'D1/2 in, corner R0.060 in', R: 6.35, Rcr: 1.524 },
];

/**
 * The preset the tool fields hold, or null ("custom") once a value was edited away from every
 * preset. Compared as the fields show them (6 significant digits in the user's unit), so a preset
 * converted to inches still matches.
 */
export function presetOf(state: CalculatorState): Preset | null {
  const same = (key: 'R' | 'Rcr', mm: number) => {
    const v = parseField(state.fields[key]);
    return v !== null && formatField(v) === fieldText(key, mm, state.unit);
  };
  const size = state.size === 'D' ? 2 : 1;
  return PRESETS.find((p) => same('R', size * p.R) && same('Rcr', p.Rcr)) ?? null;
}
