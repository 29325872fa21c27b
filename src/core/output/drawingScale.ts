/** Drawing scales shared by the views and the 3D scenes: vertical exaggeration steps and scale bars (pure, so Node tests read it). */
import { formatSignificant, fromMm, type LengthUnit, readableLengthUnit, toMm } from '../input/units';

/** The steps offered: 1-2-5 series from true scale to x1000. */
export const EXAGGERATION_STEPS: readonly number[] = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000];

/**
 * The largest step at which a feature `heightMm` tall, drawn in a view `widthMm` wide, takes
 * at most `fraction` of that width (so a 5 um scallop under a 4 mm step-over is still seen);
 * true scale (1) when the feature is already that tall. Non-finite or non-positive sizes give 1.
 */
export function autoExaggeration(widthMm: number, heightMm: number, fraction = 0.35): number {
  if (!(widthMm > 0) || !(heightMm > 0) || !Number.isFinite(widthMm) || !Number.isFinite(heightMm)) return 1;
  let best = 1;
  for (const k of EXAGGERATION_STEPS) if (heightMm * k <= fraction * widthMm) best = k;
  return best;
}

/** A scale bar: its length (mm, for drawing) and its text in the user's unit. */
export interface ScaleBar {
  readonly lengthMm: number;
  readonly text: string;
}

/**
 * The scale bar for a view: the largest 1-2-5 length, in the user's unit (or its small unit, um
 * or thou, where that reads better), that is at most `targetMm` long.
 */
export function scaleBar(targetMm: number, unit: LengthUnit): ScaleBar | null {
  if (!(targetMm > 0) || !Number.isFinite(targetMm)) return null;
  const shown = readableLengthUnit(targetMm, unit);
  const target = fromMm(targetMm, unit) * shown.perUserUnit;
  const decade = 10 ** Math.floor(Math.log10(target));
  const step = [5, 2, 1].find((m) => m * decade <= target * (1 + 1e-12)) ?? 1;
  const value = step * decade;
  const text = formatSignificant(value, { digits: 1, trimZeros: true });
  return { lengthMm: toMm(value / shown.perUserUnit, unit), text: `${text} ${shown.symbol}` };
}
