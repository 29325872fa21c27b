/**
 * The balanced feed fz* as the page sets it (issue 29's "use the balanced feed"). Pure.
 */
import { fromMm, type LengthUnit, toMm } from '../core/input/units';

/**
 * The balanced feed as a shop types it (mm), rounded down to the step-over's resolution in `unit`
 * (0.1 µm in mm, 10 µin in inch): hf then stays at or just below h, and the field reads 0.9274, not
 * 0.92741345796649899. A feed below that resolution is kept as it is.
 */
export function shopFeed(fzMm: number, unit: LengthUnit): number {
  const scale = unit === 'mm' ? 1e4 : 1e5;
  // To 12 digits first: 1.13 mm * 1e4 is 11299.999..., which would floor a whole step down.
  const rounded = Math.floor(Number((fromMm(fzMm, unit) * scale).toPrecision(12))) / scale;
  return rounded > 0 ? toMm(rounded, unit) : fzMm;
}
