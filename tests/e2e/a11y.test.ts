/**
 * Accessibility, as axe-core (injected by the test into the instrumented build, served without a
 * CSP: the injected script is inline) sees it: zero violations on the page, in each view, in each
 * embed, light and dark. Keyboard: the view tabs take Home and End; the clickable result rows are
 * a grid's rows with aria-selected. One load for the page (its views by their tabs) and one per
 * embed; dark by the system's colour scheme.
 */
import { describe, expect, it } from 'vitest';
import { axeViolations } from './axe';
import { keepShot, pageSettled, showView, useSite, viewAs } from './harness';

const site = useSite('docs/a11y');
const STATE = 'R=3&Rcr=1&rho=5&h=0.05&unit=mm';
const VIEWS = ['profile', 'chart', 'tables', 'stepper', 'formulas', 'surface'] as const;
const THEMES = ['light', 'dark'] as const;
const FULL = { width: 1400, height: 900 };
const EMBED = { width: 480, height: 700 };

describe('axe-core', () => {
  it('zero violations: the page in each view, and each embed, light and dark', async () => {
    const { page } = await site.open(`?${STATE}`, FULL);
    for (const theme of THEMES) {
      await viewAs(page, FULL, theme);
      for (const view of VIEWS) {
        await showView(page, view);
        // Every view's data drawn and the page quiet: axe reads the final page, not one half drawn.
        await pageSettled(page);
        expect(await axeViolations(page), `view=${view} ${theme}`).toEqual([]);
      }
    }
    // A procedure highlighted (hover) keeps its contrast too.
    await showView(page, 'formulas');
    await page.locator('.formula').first().waitFor();
    await page.locator('.procedures tr[data-procedure="bedi"]').click();
    for (const theme of ['dark', 'light'] as const) {
      await viewAs(page, FULL, theme);
      expect(await axeViolations(page), `selected row ${theme}`).toEqual([]);
      await keepShot(page, `a11y-formulas-${theme}`);
    }
    for (const query of [...VIEWS.map((v) => `view=${v}&embed=1`), 'embed=1']) {
      const embedded = (await site.open(`?${STATE}&${query}`, EMBED)).page;
      const view = /view=(\w+)/.exec(query)?.[1];
      if (view) await embedded.locator(`#panel-${view} > *`).first().waitFor();
      for (const theme of THEMES) {
        await viewAs(embedded, EMBED, theme);
        expect(await axeViolations(embedded), `${query} ${theme}`).toEqual([]);
      }
    }
  }, 240_000);
});

describe('keyboard and roles', () => {
  it('the view tabs move with arrows, Home and End', async () => {
    const { page } = await site.open(`?${STATE}`);
    await page.getByRole('tab', { name: 'L against lead and tilt' }).focus();
    const selected = () => page.locator('[role="tab"][aria-selected="true"]').getAttribute('data-view');
    await page.keyboard.press('End');
    expect(await selected()).toBe('surface');
    expect(await page.evaluate(() => document.activeElement?.getAttribute('data-view'))).toBe('surface');
    await page.keyboard.press('Home');
    expect(await selected()).toBe('profile');
    await page.keyboard.press('ArrowLeft');
    expect(await selected()).toBe('surface');
    await page.keyboard.press('ArrowRight');
    expect(await selected()).toBe('profile');
  });

  it('the result rows are selectable grid rows: aria-selected follows click and Enter', async () => {
    // The page of the test before (only its tabs moved), in the tables view.
    const { page } = await site.reuse(`?${STATE}`);
    await showView(page, 'tables');
    site.changed();
    expect(await page.getByTestId('procedures-table').getAttribute('role')).toBe('grid');
    const row = (key: string) => page.locator(`.procedures tr[data-procedure="${key}"]`);
    expect(await row('sekine').getAttribute('aria-selected')).toBe('false');
    await row('sekine').click();
    expect(await row('sekine').getAttribute('aria-selected')).toBe('true');
    await row('bedi').focus();
    await page.keyboard.press('Enter');
    expect(await row('bedi').getAttribute('aria-selected')).toBe('true');
    expect(await row('sekine').getAttribute('aria-selected')).toBe('false');
    // The paper's tables: the row of the condition on screen is the selected one; Enter loads another.
    const paperRow = (i: number) => page.locator(`[data-testid="paper-table-half"] tr[data-condition="${i}"]`);
    await paperRow(0).waitFor();
    expect(await page.getByTestId('paper-table-half').getAttribute('role')).toBe('grid');
    const selectedRows = page.locator('[data-testid="paper-table-half"] tr[aria-selected="true"]');
    await expect.poll(() => selectedRows.count()).toBe(1);
    await paperRow(3).focus();
    await page.keyboard.press('Enter');
    await expect.poll(() => paperRow(3).getAttribute('aria-selected')).toBe('true');
    expect(await selectedRows.count()).toBe(1);
  });
});
