/**
 * The page's default values in each unit: in mm the paper's Tool 1, condition 1 (L its exact
 * step-over, rounded); in inch the shop's round values of the same kind (a 1/4 in tool with a
 * 0.030 in corner, the catalogue's `1/4 R.030`; h 0.002 in). A field that still holds its default
 * becomes the other unit's default when the unit is switched (fieldText.ts convertFields), never a
 * conversion such as 0.0019685. Angles (rho, tilt, slope, psi) are degrees in both. Pure.
 */
import type { FieldKey, ToolSize, Unit } from './stateTypes';

/** The teeth and their feed (issue 29) are optional: empty, no feed marks, in either unit. */
const NO_FINISH = { z: '', fz: '', F: '', n: '', runout: '', runoutPhase: '', passPhase: '' } as const;

/** Defaults in mm: the paper's Tool 1, condition 1 (L is its exact step-over, rounded), no tilt. */
export const DEFAULT_FIELDS_MM: Readonly<Record<FieldKey, string>> = {
  R: '3',
  Rcr: '1',
  rho: '5',
  tilt: '0',
  h: '0.05',
  L: '2.9',
  ra: '0.0125',
  sa: '0.0008',
  Rs: '50',
  slope: '30',
  psi: '0',
  Rf: '80',
  Rc: '40',
  Lxy: '2.5',
  dz: '1',
  ...NO_FINISH,
};

/**
 * Defaults in inch: D 1/4 in (R 0.125), corner 0.030 in, h 0.002 in, L 0.125 in (the exact step-over
 * of that tool and h is 0.126 in), Ra 0.0005 in, cylinder 2 in, doubly curved point Rf 3 in and
 * Rc 1.5 in, three-axis Lxy 0.1 in and dz 0.04 in; the angles as in mm.
 */
export const DEFAULT_FIELDS_IN: Readonly<Record<FieldKey, string>> = {
  R: '0.125',
  Rcr: '0.03',
  rho: '5',
  tilt: '0',
  h: '0.002',
  L: '0.125',
  ra: '0.0005',
  sa: '0.00003',
  Rs: '2',
  slope: '30',
  psi: '0',
  Rf: '3',
  Rc: '1.5',
  Lxy: '0.1',
  dz: '0.04',
  ...NO_FINISH,
};

/** A field's default text in `unit`; the size field's as the diameter (twice R) when `size` is D. */
export function defaultFieldText(key: FieldKey, unit: Unit, size: ToolSize = 'R'): string {
  const text = (unit === 'mm' ? DEFAULT_FIELDS_MM : DEFAULT_FIELDS_IN)[key];
  return key === 'R' && size === 'D' ? String(2 * Number(text)) : text;
}
