/** Comparing two screenshots pixel by pixel, decoded by the browser (no PNG library). */
import type { Page } from 'playwright-core';
import { countPixels } from './pixels';

/** How two PNG images differ. */
export interface PngDifference {
  /** False when the sizes differ (then `changedShare` is 1). */
  readonly sameSize: boolean;
  /** Fraction of pixels, 0 to 1, whose channel differences (R + G + B + A) sum to more than the tolerance. */
  readonly changedShare: number;
  readonly width: number;
  readonly height: number;
}

/**
 * Compares two PNG images in `page` (any open page: it only decodes and draws them on a canvas).
 *
 * @param page a page to decode in; its document is not changed.
 * @param expected the reference PNG's bytes.
 * @param actual the new PNG's bytes.
 * @param tolerance sum of the channel differences a pixel may have and count as equal, 0 to 255 per
 *   channel compared (antialiasing noise stays under about 48 over all four).
 * @param channels how many channels to compare: 4 (R, G, B, A) or 3 (R, G, B).
 * @returns the share of changed pixels, and whether the sizes agree.
 */
export async function pngDifference(
  page: Page,
  expected: Buffer,
  actual: Buffer,
  tolerance = 48,
  channels: 3 | 4 = 4,
): Promise<PngDifference> {
  const { sizes, counts } = await countPixels(page, [expected, actual], { kind: 'difference', channels, tolerance });
  const [x, y] = sizes as [{ width: number; height: number }, { width: number; height: number }];
  if (counts.length === 0) return { sameSize: false, changedShare: 1, width: y.width, height: y.height };
  return {
    sameSize: true,
    changedShare: (counts[0] as number) / (x.width * x.height),
    width: x.width,
    height: x.height,
  };
}
