/**
 * The shop floor without a network: the production site (what ships, with its Workbox service
 * worker) is loaded once, the browser goes offline, the page is reloaded and still computes.
 * Also the installable web app's manifest (name, icons, theme colour).
 */
import { describe, expect, it } from 'vitest';
import { compareForward, forwardInput } from '../../src/core/index';
import { keepShot, useSite } from './harness';

const site = useSite('shop/offline', { build: 'production' });

describe('offline after the first visit', () => {
  it('load once, go offline, reload: the calculator still computes', async () => {
    const context = await site.browser().newContext({ viewport: { width: 390, height: 844 } });
    const page = await context.newPage();
    await page.goto(`${site.url()}?R=3&Rcr=1&rho=5&h=0.05&unit=mm`);
    await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    // The service worker has installed (precached the site) and controls the page.
    await expect
      .poll(() => page.evaluate(() => navigator.serviceWorker.controller?.state ?? 'none'), { timeout: 20_000 })
      .toBe('activated');
    await context.setOffline(true);
    await page.reload();
    await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    await page.getByTestId('input-h').fill('0.1');
    const expected = compareForward(
      forwardInput({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way', 0.1),
    );
    await expect
      .poll(() => page.getByTestId('result-exact-half').textContent())
      .toBe(`${expected.exact.halfIntervalMm.toFixed(4)} mm`);
    // Another address of the page (another state in the query) opens offline too.
    await page.goto(`${site.url()}?R=5&Rcr=1&rho=10&h=0.02&unit=mm&view=profile`);
    await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    await page.getByTestId('profile-view').locator('polygon.scallop').waitFor();
    await keepShot(page, 'offline-390');
    await context.close();
  }, 60_000);

  it('is installable: a manifest with name, icons and theme colour', async () => {
    const { page } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    const href = await page.locator('link[rel="manifest"]').getAttribute('href');
    const manifestUrl = new URL(href ?? '', page.url()).href;
    const manifest = await page.evaluate(async (url) => (await fetch(url)).json(), manifestUrl);
    expect(manifest.name).toMatch(/Step-over/);
    expect(manifest.theme_color).toBe('#1d4ed8');
    expect(manifest.display).toBe('standalone');
    const sizes = (manifest.icons as Array<{ src: string; sizes: string }>).map((i) => i.sizes);
    expect(sizes).toEqual(expect.arrayContaining(['192x192', '512x512']));
    for (const icon of manifest.icons as Array<{ src: string }>) {
      const status = await page.evaluate(async (url) => (await fetch(url)).status, new URL(icon.src, manifestUrl).href);
      expect(status, icon.src).toBe(200);
    }
    await page.close();
  });
});
