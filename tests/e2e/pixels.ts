/** Reading colours from what the user sees (screenshots), for the theme tests. */
import type { Locator, Page } from 'playwright-core';

/** Fraction of an element's on-screen pixels within `tolerance` (sum of channel differences) of `rgb`. */
export async function colourShare(page: Page, element: Locator, rgb: string, tolerance = 30): Promise<number> {
  const png = (await element.screenshot()).toString('base64');
  return page.evaluate(
    async ({ b64, hex, tol }) => {
      const want = [1, 3, 5].map((i) => Number.parseInt(hex.slice(i, i + 2), 16));
      const image = new Image();
      image.src = `data:image/png;base64,${b64}`;
      await image.decode();
      const canvas = document.createElement('canvas');
      canvas.width = image.width;
      canvas.height = image.height;
      const ctx = canvas.getContext('2d');
      if (!ctx) return 0;
      ctx.drawImage(image, 0, 0);
      const data = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
      let hits = 0;
      for (let i = 0; i < data.length; i += 4) {
        let d = 0;
        for (let c = 0; c < 3; c++) d += Math.abs((data[i + c] as number) - (want[c] as number));
        if (d <= tol) hits++;
      }
      return hits / (data.length / 4);
    },
    { b64: png, hex: rgb, tol: tolerance },
  );
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
  const png = (await page.getByTestId('scene-canvas').screenshot()).toString('base64');
  return page.evaluate(async (b64) => {
    const image = new Image();
    image.src = `data:image/png;base64,${b64}`;
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = image.width;
    canvas.height = image.height;
    const ctx = canvas.getContext('2d');
    if (!ctx) return { blue: 0, orange: 0 };
    ctx.drawImage(image, 0, 0);
    const d = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
    let blue = 0;
    let orange = 0;
    for (let i = 0; i < d.length; i += 4) {
      const [r, g, b] = [d[i] as number, d[i + 1] as number, d[i + 2] as number];
      if (b > r + 40) blue++;
      else if (r > b + 60 && g > b + 20 && g < r - 20) orange++;
    }
    return { blue: blue / (d.length / 4), orange: orange / (d.length / 4) };
  }, png);
}
