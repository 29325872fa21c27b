/**
 * A feed length of the finish box (the period, fz*, the cell's sides, the x of a profile) in the
 * user's unit (mm or in) with its symbol, never a sub-unit: they compare at a glance with fz as
 * typed and with each other (heights stay in µm or µin, format.ts formatRoughness). Pure.
 */
import { type LengthUnit, NO_VALUE, unitSymbol } from '../core/input/units';
import { formatFineLen } from './format';

/**
 * `mm` in `unit` at the fine resolution (0.000001 mm, 0.0000001 in), at least four significant
 * digits in plain decimals, with its symbol; below a picometre (a position's rounding noise) 0; a
 * dash for none.
 */
export function feedLength(mm: number | null, unit: LengthUnit): string {
  const v = formatFineLen(mm !== null && Math.abs(mm) < 1e-9 ? 0 : mm, unit);
  return v === NO_VALUE ? NO_VALUE : `${v} ${unitSymbol(unit)}`;
}
