/**
 * Feed per tooth from the machine's feed rate and spindle speed (issue 29: "feed per tooth, or feed
 * rate and spindle speed, which give it"): per turn the tool advances F / n, per tooth F / (n z).
 * Unit-free: F in mm/min gives fz in mm, F in in/min gives fz in inches. Pure, tiny: the page's
 * fields show it with the first result, within the limits below (finishInput.ts checks them).
 */

/**
 * Largest number of teeth accepted. Solid end mills have up to about 20 flutes; 64 leaves room for
 * indexable and special cutters while keeping the per-point work (one search per tooth) bounded.
 */
export const MAX_FLUTES = 64;

/**
 * Smallest feed per tooth accepted, mm (1 nm): the feed marks it leaves (about fz^2 / (8 R)) are far
 * below anything measurable, and the tooth angles `2 pi w / (z fz)` stay well inside double range.
 */
export const MIN_FEED_PER_TOOTH_MM = 1e-6;

/** fz = F / (n z): `feedRate` a length per minute, `spindleRpm` turns per minute, `flutes` teeth. */
export function feedPerToothOfRate(feedRate: number, spindleRpm: number, flutes: number): number {
  return feedRate / (spindleRpm * flutes);
}
