/**
 * Issue 26, point 1 on the page: a doubly curved point the tool gouges (the concave feed circle is
 * tighter than the tool along the feed) shows the gouging message naming the radius to change, with
 * no NaN anywhere, no console error and no solve left pending (the page used to show "—" with no
 * message, stall until the worker was restarted and log 29 errors: SVG attributes NaN, three.js
 * "bounding sphere radius is NaN"). One page load.
 */
import { describe, expect, it } from 'vitest';
import { holdScene, useSite } from './harness';

const site = useSite('docs/trust-four', { scene: false });

type Probe = { __pathInterval: { pending(worker?: string): number } };

describe('trust, round four (issue 26): the page', () => {
  it('a gouging doubly curved point: the gouging message, nothing NaN, no console error, nothing pending', async () => {
    const page = await site.browser().newPage({ viewport: { width: 1400, height: 900 } });
    await holdScene(page); // the file looks at no part of the scene
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => {
      if (m.type() === 'error') errors.push(m.text());
    });
    await page.goto(`${site.url()}?R=3&Rcr=1&rho=60&h=0.01&feedRadius=-0.1&crossRadius=0.5`);
    const message = page.locator('[data-testid^="error-"]').filter({ hasText: /gouge/ });
    await message.first().waitFor();
    expect(await message.allTextContents()).toEqual([
      expect.stringMatching(
        /^Feed radius Rf must be convex or straight, with Rc = 0\.5 mm held .*any concave one is gouged/,
      ),
    ]);
    // Every solve answered (the worker not stalled), and nothing on the page reads NaN or Infinity.
    await expect.poll(() => page.evaluate(() => (window as unknown as Probe).__pathInterval.pending())).toBe(0);
    expect((await page.locator('body').allInnerTexts()).join(' ')).not.toMatch(/NaN|Infinity/);
    expect(errors).toEqual([]);
    await page.close();
  });
});
