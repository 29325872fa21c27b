/**
 * The balanced feed fz* as the page sets it (issue 29's "use the balanced feed"): fz, or, while the
 * feed rate and spindle speed give fz, the feed rate at that spindle speed. Pure.
 */
import { fromMm, type LengthUnit, toMm } from '../core/input/units';
import type { FinishInputs } from './finishRequest';

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

/**
 * What "use the balanced feed" sets (mm, mm/min): fz as {@link shopFeed} rounds it; or, while the
 * feed rate and spindle speed give fz (fz empty, F and n numbers), the feed rate F = fz* n z at that
 * spindle speed, rounded down to 1 mm/min (0.1 in/min): the fz it gives is then at or just below fz*
 * (hf <= h), and the spindle speed, set by the tool's cutting speed, stays.
 */
export function balancedFeedFields(
  fzMm: number,
  inputs: FinishInputs,
): { readonly fz: number } | { readonly F: number } {
  const { fz, feedRate, spindleSpeed, flutes } = inputs.values;
  if (
    fz === undefined &&
    typeof feedRate === 'number' &&
    typeof spindleSpeed === 'number' &&
    typeof flutes === 'number'
  ) {
    const step = inputs.unit === 'mm' ? 1 : 0.1;
    const perMinute = fromMm(fzMm * spindleSpeed * flutes, inputs.unit) / step;
    const rate = Math.floor(Number(perMinute.toPrecision(12))) * step;
    if (rate > 0) return { F: toMm(rate, inputs.unit) };
  }
  return { fz: shopFeed(fzMm, inputs.unit) };
}
