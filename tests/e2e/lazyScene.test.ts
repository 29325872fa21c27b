/**
 * The first result does not wait for the 3D scene: three.js and the WebGL context load after it.
 * Held back (its code's request stalled), the scene leaves the results working; released, it
 * draws the latest state, not the one it was first asked for.
 */
import type { Route } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { useSite } from './harness';

const site = useSite('lazy/path-interval');

describe('the 3D scene loads after the first result', () => {
  it('results answer inputs while the scene code is held back; released, the scene shows the latest state', async () => {
    const page = await site.browser().newPage({ viewport: { width: 1400, height: 900 } });
    const held: Route[] = [];
    // The scene's own chunk (and three.js with it) is stalled until released.
    await page.route(/\/assets\/scene-[^/]*\.js$/, (route) => {
      held.push(route);
    });
    await page.goto(`${site.url()}?R=3&Rcr=1&rho=5&h=0.05&unit=mm`);
    const half = page.getByTestId('result-exact-half');
    await expect.poll(() => half.textContent()).toBe('1.4436 mm'); // L/2 = 1.443592 mm (README's worked example)
    expect(await page.getByTestId('scene-canvas').count()).toBe(0);
    await page.getByTestId('input-h').fill('0.02');
    await expect.poll(() => half.textContent()).toMatch(/^0\.\d{4} mm$/);
    expect(held.length).toBe(1);
    for (const route of held) await route.continue();
    await page.getByTestId('scene-canvas').waitFor();
    // The scene's length label answers h = 0.02 (the headline's L), not the first h = 0.05.
    const headline = (await page.getByTestId('result-exact-interval').textContent()) ?? '';
    await expect.poll(() => page.locator('.label-dim').first().textContent()).toContain(headline.trim().split(' ')[0]);
    await page.close();
  });

  // The harness's per-test choice (site.noScene(), used by tests that look at no part of the scene):
  // held for such a test's document, served again for the next test's.
  it('the harness holds the scene for a test that says noScene(), and serves it to the next test', async () => {
    site.noScene();
    const { page } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    await expect.poll(() => page.getByTestId('result-exact-half').textContent()).toBe('1.4436 mm');
    expect(await page.getByTestId('scene-canvas').count()).toBe(0);
  });

  it('(the next test: the same shared page draws the scene)', async () => {
    const { page } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    await page.getByTestId('scene-canvas').waitFor();
    expect(await page.evaluate(() => document.querySelectorAll('[data-testid="scene-canvas"]').length)).toBe(1);
  });
});
