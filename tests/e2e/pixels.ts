/** Reading colours from what the user sees (screenshots), for the theme and picture tests. */
import type { Locator, Page } from 'playwright-core';

/** What to count over decoded PNG images, in the browser: the one place that decodes them (no PNG library). */
export type PixelCount =
  /** Pixels within `tolerance` (sum of the r, g, b differences) of the colour `hex` (#rrggbb), in the first image. */
  | { readonly kind: 'colour'; readonly hex: string; readonly tolerance: number }
  /** Clearly blue (b > r + 40) and clearly orange (r > b + 60, g between) pixels, in the first image. */
  | { readonly kind: 'hues' }
  /** The r, g, b of the first image at each point (x, y in pixels, rounded and clamped to the image), flat. */
  | { readonly kind: 'at'; readonly points: ReadonlyArray<readonly [number, number]> }
  /** Pixels of the first image whose first `channels` channel differences from the second's sum to more than `tolerance`. */
  | { readonly kind: 'difference'; readonly channels: 3 | 4; readonly tolerance: number };

/** Each image's size, and the counts a {@link PixelCount} asks for (none for a difference of two sizes). */
export interface PixelCounts {
  readonly sizes: readonly { readonly width: number; readonly height: number }[];
  readonly counts: readonly number[];
}

/**
 * Decodes PNG images in `page` (drawn on a canvas; its document is not changed) and counts pixels.
 *
 * @param page any open page.
 * @param pngs the images' bytes (one, or two for a difference).
 * @param count what to count.
 * @returns the images' sizes and the counts, in the order `count` names them.
 */
export function countPixels(page: Page, pngs: readonly Buffer[], count: PixelCount): Promise<PixelCounts> {
  return page.evaluate(
    async ({ images, what }) => {
      const decode = async (b64: string) => {
        const image = new Image();
        image.src = `data:image/png;base64,${b64}`;
        await image.decode();
        const canvas = document.createElement('canvas');
        canvas.width = image.width;
        canvas.height = image.height;
        const ctx = canvas.getContext('2d');
        if (!ctx) throw new Error('no 2D canvas');
        ctx.drawImage(image, 0, 0);
        return {
          width: image.width,
          height: image.height,
          data: ctx.getImageData(0, 0, image.width, image.height).data,
        };
      };
      const decoded = await Promise.all(images.map(decode));
      const sizes = decoded.map(({ width, height }) => ({ width, height }));
      const d = (decoded[0] as (typeof decoded)[number]).data;
      if (what.kind === 'colour') {
        const want = [1, 3, 5].map((i) => Number.parseInt(what.hex.slice(i, i + 2), 16));
        let hits = 0;
        for (let i = 0; i < d.length; i += 4) {
          let sum = 0;
          for (let c = 0; c < 3; c++) sum += Math.abs((d[i + c] as number) - (want[c] as number));
          if (sum <= what.tolerance) hits++;
        }
        return { sizes, counts: [hits] };
      }
      if (what.kind === 'at') {
        const { width, height } = decoded[0] as (typeof decoded)[number];
        const rgb: number[] = [];
        for (const [x, y] of what.points) {
          const i =
            4 *
            (Math.min(height - 1, Math.max(0, Math.round(y))) * width +
              Math.min(width - 1, Math.max(0, Math.round(x))));
          rgb.push(d[i] as number, d[i + 1] as number, d[i + 2] as number);
        }
        return { sizes, counts: rgb };
      }
      if (what.kind === 'hues') {
        let blue = 0;
        let orange = 0;
        for (let i = 0; i < d.length; i += 4) {
          const [r, g, b] = [d[i] as number, d[i + 1] as number, d[i + 2] as number];
          if (b > r + 40) blue++;
          else if (r > b + 60 && g > b + 20 && g < r - 20) orange++;
        }
        return { sizes, counts: [blue, orange] };
      }
      const e = (decoded[1] as (typeof decoded)[number]).data;
      if (d.length !== e.length || sizes[0]?.width !== sizes[1]?.width) return { sizes, counts: [] };
      let changed = 0;
      for (let i = 0; i < d.length; i += 4) {
        let sum = 0;
        for (let c = 0; c < what.channels; c++) sum += Math.abs((d[i + c] as number) - (e[i + c] as number));
        if (sum > what.tolerance) changed++;
      }
      return { sizes, counts: [changed] };
    },
    { images: pngs.map((png) => png.toString('base64')), what: count },
  );
}

/** The number of pixels of an image of `size`. */
const pixelsOf = (size: { width: number; height: number } | undefined): number => (size ? size.width * size.height : 0);

/** Fraction of an element's on-screen pixels within `tolerance` (sum of channel differences) of `rgb`. */
export async function colourShare(page: Page, element: Locator, rgb: string, tolerance = 30): Promise<number> {
  const { sizes, counts } = await countPixels(page, [await element.screenshot()], {
    kind: 'colour',
    hex: rgb,
    tolerance,
  });
  return (counts[0] as number) / pixelsOf(sizes[0]);
}

/** The widest visible element's overflow: elements outside [0, innerWidth] that no scroll box holds. */
export function clippedElements(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const width = window.innerWidth;
    const inScrollBox = (e: Element): boolean => {
      for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) {
        const o = getComputedStyle(a).overflowX;
        if (o === 'auto' || o === 'scroll') return true;
      }
      return false;
    };
    const out: string[] = [];
    for (const e of document.querySelectorAll('body *')) {
      const b = e.getBoundingClientRect();
      if (b.width === 0 || b.height === 0 || (b.right <= width + 0.5 && b.left >= -0.5)) continue;
      if (e instanceof SVGElement && e.ownerSVGElement) continue; // drawn inside an SVG's own viewport
      // A 3D label's anchor is a positioning box centred on its point (which may lie outside the view,
      // clipped by the label layer); what shows is its label, checked on its own.
      if (e.classList.contains('scene-label-anchor')) continue;
      if (inScrollBox(e) || e.closest('.sr-only') || getComputedStyle(e).visibility === 'hidden') continue;
      out.push(
        `${e.tagName.toLowerCase()}.${e.getAttribute('class') ?? ''} [${Math.round(b.left)}, ${Math.round(b.right)}]`,
      );
    }
    return out.slice(0, 8);
  });
}

/** Shares of the scene's pixels that are clearly blue (b > r + 40) and clearly orange (r > b + 60, g between). */
export async function hueShares(page: Page): Promise<{ blue: number; orange: number }> {
  const { sizes, counts } = await countPixels(page, [await page.getByTestId('scene-canvas').screenshot()], {
    kind: 'hues',
  });
  const pixels = pixelsOf(sizes[0]);
  return { blue: (counts[0] as number) / pixels, orange: (counts[1] as number) / pixels };
}
