/**
 * The tool presets: the paper's tools and common catalogue sizes, and which one the tool fields
 * hold. Pure; re-exported by state.ts.
 */
import { fieldText, formatField, parseField } from './fieldText';
import type { CalculatorState } from './stateTypes';

/** A tool preset: its name as a catalogue gives it (diameter D, corner radius), R and Rcr in mm. */
export interface Preset {
  readonly label: string;
  /** Its short name on a one-tap button (toolChips.ts): diameter and corner, e.g. `D6 R1`, `1/2 R.030`. */
  readonly chip: string;
  /** The unit the catalogue sizes it in: metric tools, or inch tools (fractional diameters). */
  readonly sizedIn: 'mm' | 'in';
  readonly R: number;
  readonly Rcr: number;
}

/** An inch tool: diameter and corner radius in inches (R and Rcr kept in mm, exact: 1 in = 25.4 mm). */
function inchTool(label: string, chip: string, diameterIn: number, cornerIn: number): Preset {
  return { label, chip, sizedIn: 'in', R: (diameterIn * 254) / 20, Rcr: (cornerIn * 254) / 10 };
}

/**
 * Presets: the paper's tools and common catalogue sizes, named by diameter and corner radius: metric
 * ones in mm, and inch bull noses of 1/4, 3/8 and 1/2 in with the corner radii US catalogues list
 * (0.015, 0.030, 0.060, 0.125 in) and their ball ends.
 */
export const PRESETS: readonly Preset[] = [
  { label: 'D6, corner R1 (paper Tool 1)', chip: 'D6 R1', sizedIn: 'mm', R: 3, Rcr: 1 },
  { label: 'D12, corner R2 (paper Tool 2)', chip: 'D12 R2', sizedIn: 'mm', R: 6, Rcr: 2 },
  { label: 'D6, corner R0.5', chip: 'D6 R0.5', sizedIn: 'mm', R: 3, Rcr: 0.5 },
  { label: 'D10, corner R1', chip: 'D10 R1', sizedIn: 'mm', R: 5, Rcr: 1 },
  { label: 'D16, corner R3', chip: 'D16 R3', sizedIn: 'mm', R: 8, Rcr: 3 },
  inchTool('D1/4 in, corner R0.015 in', '1/4 R.015', 0.25, 0.015),
  inchTool('D1/4 in, corner R0.030 in', '1/4 R.030', 0.25, 0.03),
  inchTool('D1/4 in, ball end', '1/4 ball', 0.25, 0.125),
  inchTool('D3/8 in, corner R0.030 in', '3/8 R.030', 0.375, 0.03),
  inchTool('D3/8 in, corner R0.060 in', '3/8 R.060', 0.375, 0.06),
  inchTool('D1/2 in, corner R0.030 in', '1/2 R.030', 0.5, 0.03),
  inchTool('D1/2 in, corner R0.060 in', '1/2 R.060', 0.5, 0.06),
  inchTool('D1/2 in, corner R0.125 in', '1/2 R.125', 0.5, 0.125),
  inchTool('D1/2 in, ball end', '1/2 ball', 0.5, 0.25),
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
