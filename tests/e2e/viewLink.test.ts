/**
 * A link that names a teaching view (`?view=`, issue 21) scrolls the page to the views once they are
 * built, on a phone (390 x 844) and on a laptop (1440 x 900): the opened view's tab, its heading, is
 * in the viewport after load. A link without a view stays at the top of the page.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { FIELDS } from '../../src/core/input/fields';
import { keepShot, PHONE, pageSettled, useSite } from './harness';

const { open } = useSite('docs/view-link', { scene: false });

const LAPTOP = { width: 1440, height: 900 };

/** True when the whole of the element lies inside the viewport. */
const inViewport = (page: Page, selector: string) =>
  page.locator(selector).evaluate((e) => {
    const r = e.getBoundingClientRect();
    // A pixel of slack: layout in fractions of a pixel.
    return r.height > 0 && r.top >= -1 && r.bottom <= window.innerHeight + 1;
  });

describe('?view= scrolls to the view it opens', () => {
  for (const [name, viewport] of [
    ['phone', PHONE],
    ['laptop', LAPTOP],
  ] as const) {
    it(`every view at ${viewport.width} x ${viewport.height} (${name})`, async () => {
      // The teaching views (`result` is an embed's card, not a tab: tests/viewList.test.ts).
      for (const view of FIELDS.view.values.filter((v) => v !== 'result')) {
        const { page, errors } = await open(`?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=${view}`, viewport);
        const tab = `#tab-${view}`;
        await page.locator(tab).waitFor();
        await pageSettled(page);
        expect(await page.locator(tab).getAttribute('aria-selected')).toBe('true');
        expect(await inViewport(page, tab), `${view} at ${name}`).toBe(true);
        expect(await page.evaluate(() => window.scrollY)).toBeGreaterThan(0);
        if (view === 'profile') await keepShot(page, `view-link-${name}`);
        expect(errors).toEqual([]);
      }
      // No view asked: the page opens at its top.
      const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm', viewport);
      await page.locator('#tab-profile').waitFor();
      await pageSettled(page);
      expect(await page.evaluate(() => window.scrollY)).toBe(0);
    }, 120_000);
  }
});
