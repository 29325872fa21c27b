/**
 * The WebGL views draw what they are given (issue 17, items 3 and 4), in headless Chromium: the 3D
 * scene shows the tool at the smallest and the largest tool radii (its camera's near and far planes
 * follow the size of the drawing), and after the browser loses and restores a WebGL context the 3D
 * scene comes back on the theme's background and the Machined surface view draws its surface again,
 * both with no new input.
 */
import type { Locator, Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { keepShot, loseAndRestore, paintedFraction, useSite } from './harness';
import { colourShare } from './pixels';
import { pngDifference } from './pngDifference';

const site = useSite('docs/scene-render');

type Probe = { __pathInterval: { frames(): number } };
const frames = (page: Page) => page.evaluate(() => (window as unknown as Probe).__pathInterval.frames());

/** The backgrounds per theme (--scene-bg and --surface-bg in src/ui/theme.css). */
const SCENE_BG = { light: '#f7f8fa', dark: '#12161f' } as const;
const SURFACE_BG = { light: '#f4f6f9', dark: '#171c26' } as const;

/** Waits until the 3D scene has drawn and stopped drawing (no frame for 3 animation frames). */
async function settled(page: Page): Promise<void> {
  await expect.poll(() => frames(page)).toBeGreaterThan(0);
  await expect
    .poll(async () => {
      const before = await frames(page);
      await page.evaluate(
        () =>
          new Promise<void>((resolve) => {
            let n = 0;
            const step = () => (++n >= 3 ? resolve() : requestAnimationFrame(step));
            requestAnimationFrame(step);
          }),
      );
      return (await frames(page)) === before;
    })
    .toBe(true);
}

/** The painted fraction of the README's worked example, R = 3 mm: the share of the view a fitted tool covers. */
async function referenceFraction(): Promise<number> {
  const page = await site.browser().newPage({ viewport: { width: 1400, height: 900 } });
  await page.goto(`${site.url()}?R=3&Rcr=1&rho=5&h=0.05&unit=mm`);
  await settled(page);
  const painted = await paintedFraction(page);
  await page.close();
  console.log(`painted fraction at R = 3 mm: ${painted.toFixed(3)}`);
  return painted;
}

describe('the 3D scene at the limits of the tool radius', () => {
  /** Measured once, by the first test that needs it (expect.poll runs only inside a test). */
  let measured: Promise<number> | null = null;

  // The largest radius the brief names, 500 mm (the accepted range is 0.001 to 1000 mm), and the smallest.
  for (const [name, query] of [
    ['R = 500 mm', 'R=500&Rcr=100&rho=5&h=0.05&unit=mm'],
    ['R = 1000 mm (the largest accepted)', 'R=1000&Rcr=200&rho=5&h=0.05&unit=mm'],
    ['R = 0.001 mm (the smallest accepted)', 'R=0.001&Rcr=0.0005&rho=5&h=0.00005&unit=mm'],
  ] as const) {
    it(`${name}: the tool is drawn, not only the badge`, async () => {
      const { page } = await site.open(`?${query}`);
      await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
      expect(await page.locator('[data-testid^="error-"]:not(:empty)').count()).toBe(0);
      await settled(page);
      const painted = await paintedFraction(page);
      console.log(`painted fraction at ${name}: ${painted.toFixed(3)}`);
      measured ??= referenceFraction();
      const reference = await measured;
      expect(reference).toBeGreaterThan(0.1);
      await keepShot(page.getByTestId('scene-canvas'), `scene-${query.split('&')[0]}`);
      // Same layout, another shape (Rcr/R 0.2 or 0.5 against 1/3): fitted, about as much of the view.
      expect(painted).toBeGreaterThan(0.5 * reference);
      // Its labels are placed (none hidden behind the camera or beyond the far plane).
      expect(await page.locator('.scene-label.label-axis:visible').count()).toBe(3);
    });
  }
});

describe('the 3D scene refitted to a new tool radius', () => {
  it('R from 3 mm to 500 mm, then to 0.001 mm, in one page: the tool stays in view', async () => {
    const { page } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    await settled(page);
    const reference = await paintedFraction(page);
    const enter = async (fields: ReadonlyArray<readonly [string, string]>) => {
      for (const [key, value] of fields) {
        await page.getByTestId(`input-${key}`).fill(value);
        await expect.poll(() => new URL(page.url()).searchParams.get(key)).toBe(value);
      }
      await expect.poll(() => page.locator('section.results').getAttribute('class')).not.toMatch(/stale/);
      await settled(page);
    };
    await enter([['R', '500']]);
    const large = await paintedFraction(page);
    await enter([
      ['h', '0.00005'],
      ['Rcr', '0.0005'],
      ['R', '0.001'],
    ]);
    const small = await paintedFraction(page);
    console.log(
      `painted fraction in one page: R = 3 mm ${reference.toFixed(3)}, 500 mm ${large.toFixed(3)}, 0.001 mm ${small.toFixed(3)}`,
    );
    expect(large).toBeGreaterThan(0.5 * reference);
    expect(small).toBeGreaterThan(0.5 * reference);
  });
});

describe('a lost WebGL context', () => {
  for (const theme of ['light', 'dark'] as const) {
    it(`${theme}: the 3D scene comes back on the theme's background, the Machined surface view draws again, no input`, async () => {
      const { page } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=surface', undefined, theme);
      const scene = page.getByTestId('scene-canvas');
      await settled(page);
      const background = () => colourShare(page, scene, SCENE_BG[theme], 12);
      const before = await background();
      expect(before).toBeGreaterThan(0.3);
      const framesBefore = await frames(page);
      await loseAndRestore(page, 'scene-canvas');
      await expect.poll(() => frames(page)).toBeGreaterThan(framesBefore);
      await expect.poll(background).toBeGreaterThan(before - 0.02);
      expect(await paintedFraction(page)).toBeGreaterThan(0.05);

      // The Machined surface view: drawn, lost, restored; the same picture again with no new input.
      await page
        .getByTestId('surface-comparison')
        .filter({ hasText: /Simulated cusp/ })
        .waitFor({ timeout: 20_000 });
      const surface: Locator = page.getByTestId('surface-canvas');
      await expect.poll(async () => 1 - (await colourShare(page, surface, SURFACE_BG[theme], 12))).toBeGreaterThan(0.2);
      const drawn = await surface.screenshot();
      await loseAndRestore(page, 'surface-canvas');
      await expect
        .poll(async () => (await pngDifference(page, drawn, await surface.screenshot(), 30, 3)).changedShare)
        .toBeLessThan(0.01);
      await keepShot(page, `context-restored-${theme}`);
    });
  }
});
