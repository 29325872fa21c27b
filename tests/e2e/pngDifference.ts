/** Comparing two screenshots pixel by pixel, decoded by the browser (no PNG library). */
import type { Page } from 'playwright-core';

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
 * @param tolerance sum of the four 8-bit channel differences a pixel may have and count as equal,
 *   0 to 1020 (antialiasing noise stays under about 48).
 * @returns the share of changed pixels, and whether the sizes agree.
 */
export function pngDifference(page: Page, expected: Buffer, actual: Buffer, tolerance = 48): Promise<PngDifference> {
  return page.evaluate(
    async ({ a, b, tol }) => {
      const pixels = async (b64: string) => {
        const image = new Image();
        image.src = `data:image/png;base64,${b64}`;
        await image.decode();
        const canvas = document.createElement('canvas');
        canvas.width = image.width;
        canvas.height = image.height;
        const ctx = canvas.getContext('2d');
        if (!ctx) throw new Error('no 2D canvas');
        ctx.drawImage(image, 0, 0);
        return { w: image.width, h: image.height, data: ctx.getImageData(0, 0, image.width, image.height).data };
      };
      const [x, y] = [await pixels(a), await pixels(b)];
      if (x.w !== y.w || x.h !== y.h) return { sameSize: false, changedShare: 1, width: y.w, height: y.h };
      let changed = 0;
      for (let i = 0; i < x.data.length; i += 4) {
        let d = 0;
        for (let c = 0; c < 4; c++) d += Math.abs((x.data[i + c] as number) - (y.data[i + c] as number));
        if (d > tol) changed++;
      }
      return { sameSize: true, changedShare: changed / (x.data.length / 4), width: x.w, height: x.h };
    },
    { a: expected.toString('base64'), b: actual.toString('base64'), tol: tolerance },
  );
}
