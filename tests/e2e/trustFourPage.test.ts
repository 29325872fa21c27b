/**
 * Issue 26, the page's points, in one page load: a link that repeats keys (`unit=mm ... unit=inch`,
 * a second `h=`) is read from the first of each and the notice names the values ignored (point 14);
 * a browser holding 30000 saved tools keeps the 200 newest and says the rest were over that limit,
 * not that they could not be read (point 15). The saved tools are put in the browser's storage by
 * an init script, before the page's first script runs, so one load serves both.
 */
import type { Page } from 'playwright-core';
import { afterAll, describe, expect, it } from 'vitest';
import { exactIntervalMm, forwardInput } from '../../src/core/index';
import { holdScene, useSite } from './harness';

const site = useSite('docs/trust-four-page', { scene: false });

const SAVED_TOOLS = 30_000;

let page: Page | null = null;
afterAll(async () => {
  await page?.close();
});

const text = async (p: Page, id: string) => (await p.getByTestId(id).textContent())?.trim() ?? '';

describe('issue 26 on the page: repeated link keys and saved tools over the cap (one load)', () => {
  it('says which repeated values it ignored and that 29800 saved tools were over the 200 kept', async () => {
    page = await site.browser().newPage({ viewport: { width: 1400, height: 900 } });
    await holdScene(page); // the file looks at no part of the scene
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => {
      if (m.type() === 'error') errors.push(m.text());
    });
    await page.addInitScript((count: number) => {
      try {
        const tools = Array.from({ length: count }, (_, i) => ({
          name: `T${i}`,
          diameterMm: 6,
          cornerRadiusMm: 1,
          flutes: 4,
        }));
        localStorage.setItem('path-interval.saved-tools.v1', JSON.stringify({ tools }));
      } catch {
        // about:blank has no storage of its own.
      }
    }, SAVED_TOOLS);
    await page.goto(`${site.url()}?unit=mm&R=3&Rcr=1&rho=5&h=0.05&unit=inch&h=0.07`);
    await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });

    // Point 14: the first of each key is read, and the notice names what was ignored.
    const notice = page.getByTestId('notice');
    expect(await notice.isVisible()).toBe(true);
    const said = (await notice.textContent()) ?? '';
    expect(said).toContain('unit is in the link 2 times; using the first, unit="mm" (unit="inch" ignored).');
    expect(said).toContain('h is in the link 2 times; using the first, h="0.05" (h="0.07" ignored).');
    expect(await page.locator('input[name="unit"][value="mm"]').isChecked()).toBe(true);
    expect(await page.getByTestId('input-h').inputValue()).toBe('0.05');
    const want = exactIntervalMm(
      forwardInput({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way', 0.05),
    );
    await expect.poll(() => text(page as Page, 'result-exact-interval')).toBe(`${want.toFixed(4)} mm`);

    // Point 15: over the cap, not unreadable; the 200 newest listed (the shelf loads when first opened).
    await page.locator('[data-testid="tool-shelf"] summary').click();
    await expect
      .poll(() => text(page as Page, 'tool-library-status'))
      .toBe('29800 saved tools were over the limit of 200 and left out (the 200 newest are kept).');
    const options = await page.getByTestId('saved-tools').locator('option').allTextContents();
    expect(options[0]).toBe('saved tools (200)');
    expect(options.filter((o) => /^T\d+:/.test(o))).toHaveLength(200);
    expect(options[1]).toMatch(/^T0: D 6 mm/);
    expect(errors).toEqual([]);
  });
});
