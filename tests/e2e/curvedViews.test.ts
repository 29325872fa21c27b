/**
 * The teaching views of a doubly curved point (issue 28 leftovers): no view shows the red
 * out-of-date box for a question it was not made for. The Profile and the chart draw the point (the
 * chart's tab named for what it draws, L against each radius); the tables, the step-through, the
 * formulas and the simulation say neutrally what they work on and where the point is answered, their
 * last picture (of other inputs) hidden. Desktop, one page.
 */
import { describe, expect, it } from 'vitest';
import { typeInto, useSite } from './harness';

const site = useSite('docs/curved-views', { scene: false });

const DOME = '?R=3&Rcr=1&rho=5&h=0.05&feedRadius=8&crossRadius=12&unit=mm';

describe('the views of a doubly curved point', { timeout: 60_000 }, () => {
  it('each tab draws the point or says neutrally what it shows; no red box; the chart tab named for its radii', async () => {
    const { page, errors } = await site.open(DOME, { width: 1400, height: 900 });
    const teaching = page.getByTestId('teaching');
    const note = page.getByTestId('views-page-note');
    await expect.poll(() => page.locator('#tab-chart').textContent()).toBe('L against each radius');
    for (const view of ['profile', 'chart', 'tables', 'stepper', 'formulas', 'surface']) {
      // The tab chosen (its panel may stay hidden: harness.ts showView waits for a visible one).
      const tab = page.locator(`#tab-${view}`);
      await tab.click();
      await expect.poll(() => tab.getAttribute('aria-selected')).toBe('true');
      // The red box never shows (no stale marking) once the views answer the inputs.
      await expect.poll(() => page.getByTestId('views-stale').isVisible(), { message: view }).toBe(false);
      expect(await teaching.getAttribute('class'), view).not.toMatch(/\bstale\b/);
      if (view === 'profile' || view === 'chart') {
        expect(await note.isVisible(), view).toBe(false);
        expect(await page.locator(`#panel-${view}`).isVisible(), view).toBe(true);
      } else {
        await expect.poll(() => note.textContent(), { message: view }).toMatch(/doubly curved point is answered by/);
        expect(await note.isVisible(), view).toBe(true);
        expect(await page.locator(`#panel-${view}`).isVisible(), view).toBe(false);
      }
    }
    // Invalid inputs (a corner radius above R): every view, the Profile too, says the inputs are
    // invalid, not that it draws other questions (issue 28 leftover: teaching.ts said the latter).
    await typeInto(page, 'input-Rcr', '5');
    await page.keyboard.press('Enter');
    for (const view of ['profile', 'stepper']) {
      await page.locator(`#tab-${view}`).click();
      await expect
        .poll(() => page.getByTestId('views-stale').textContent(), { message: view })
        .toMatch(/^Out of date: the inputs are invalid/);
    }
    expect(errors).toEqual([]);
  });
});
