/**
 * The README's screenshot of the page is kept current: the page is rendered in a fixed state (light,
 * 1280 x 800, the paper's Tool 1 as a catalogue gives it, everything settled) and compared pixel by
 * pixel with the committed PNG. When they differ the new image goes to
 * test-results/screenshots/readme-screenshot.png and the test fails; to take it as the README's:
 *
 *   UPDATE_README_SHOT=1 npx vitest run --project browser tests/e2e/readmeScreenshot.test.ts
 */
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { pageSettled, ROOT, SHOTS, useSite } from './harness';
import { pngDifference } from './pngDifference';

const site = useSite('docs/readme-shot');

/** The committed image the README shows. */
const README_SHOT = `${ROOT}tests/readme/screenshot.png`;
/** The state shown: D 6 mm, corner R1, lead 5 degrees, h 0.05 mm (the paper's Tool 1, condition 1). */
const QUERY = '?D=6&Rcr=1&rho=5&h=0.05&unit=mm&theme=light';
const VIEWPORT = { width: 1280, height: 800 };
/**
 * Largest share of pixels that may change before the image counts as out of date: 0.05 % (512 px).
 * Two renders on one machine differ by none; a heading that gains a few words changes 0.18 %.
 */
const MAX_CHANGED_SHARE = 0.0005;

/** The page in the README's state, settled (results, scene, views, URL), scrolled to the top. */
async function renderedPage(): Promise<{ page: Page; png: Buffer; errors: string[] }> {
  const { page, errors } = await site.open(QUERY, VIEWPORT, 'light');
  await page.getByTestId('scene-canvas').waitFor({ state: 'visible' });
  await pageSettled(page);
  await page.evaluate(() => window.scrollTo(0, 0));
  await pageSettled(page);
  return { page, png: await page.screenshot(), errors };
}

describe('README screenshot', () => {
  it('matches the page as it renders now (UPDATE_README_SHOT=1 takes the new one)', async () => {
    const { page, png, errors } = await renderedPage();
    expect(errors).toEqual([]);
    if (process.env.UPDATE_README_SHOT === '1' || !existsSync(README_SHOT)) {
      writeFileSync(README_SHOT, png);
      if (process.env.UPDATE_README_SHOT !== '1') throw new Error(`no ${README_SHOT}: written, check and commit it`);
      return;
    }
    const diff = await pngDifference(page, readFileSync(README_SHOT), png);
    if (!diff.sameSize || diff.changedShare > MAX_CHANGED_SHARE) writeFileSync(`${SHOTS}/readme-screenshot.png`, png);
    expect(diff.sameSize, 'image size').toBe(true);
    expect(
      diff.changedShare,
      `README screenshot out of date: ${(diff.changedShare * 100).toFixed(2)} % of pixels changed; the new one is ` +
        'test-results/screenshots/readme-screenshot.png (UPDATE_README_SHOT=1 to take it)',
    ).toBeLessThanOrEqual(MAX_CHANGED_SHARE);
  });

  it('notices a changed region of the page (the comparison is sensitive enough)', async () => {
    const { page } = await renderedPage();
    // A 40 x 20 px block (0.08 % of the image, a short word's size): the page a reader would see differs.
    await page.evaluate(() => {
      const block = document.createElement('div');
      block.setAttribute('data-testid', 'readme-shot-mutant');
      document.body.append(block);
      block.style.cssText = 'position:fixed;left:40px;top:300px;width:40px;height:20px;background:#c0392b;z-index:9';
    });
    const diff = await pngDifference(page, readFileSync(README_SHOT), await page.screenshot());
    expect(diff.sameSize).toBe(true);
    expect(diff.changedShare).toBeGreaterThan(MAX_CHANGED_SHARE);
  });
});
