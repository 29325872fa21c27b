/** Vertical exaggeration of the profile view: pure, so Node tests read it. */

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
