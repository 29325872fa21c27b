/**
 * Feed per tooth from the machine's feed rate and spindle speed (issue 29: "feed per tooth, or feed
 * rate and spindle speed, which give it"): per turn the tool advances F / n, per tooth F / (n z).
 * Unit-free: F in mm/min gives fz in mm, F in in/min gives fz in inches. Pure, tiny: the page's
 * fields show it with the first result.
 */

/** fz = F / (n z): `feedRate` a length per minute, `spindleRpm` turns per minute, `flutes` teeth. */
export function feedPerToothOfRate(feedRate: number, spindleRpm: number, flutes: number): number {
  return feedRate / (spindleRpm * flutes);
}
