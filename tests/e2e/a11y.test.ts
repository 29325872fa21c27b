/**
 * Accessibility, as axe-core (injected by the test into the instrumented build, served without a
 * CSP: the injected script is inline) sees it: zero violations on the page, in each view, in each
 * embed, light and dark. Keyboard: the view tabs take Home and End; the clickable result rows are
 * a grid's rows with aria-selected.
 */
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { pageSettled, ROOT, SHOTS, useSite } from './harness';

const site = useSite('docs/a11y');
const AXE = readFileSync(`${ROOT}node_modules/axe-core/axe.min.js`, 'utf8');
const STATE = 'R=3&Rcr=1&rho=5&h=0.05&unit=mm';
const VIEWS = ['profile', 'chart', 'tables', 'stepper', 'formulas', 'surface'] as const;

interface AxeViolation {
  readonly id: string;
  readonly nodes: ReadonlyArray<{ readonly target: readonly string[] }>;
}

/** axe-core's violations on the page as it is, one line each (rule, count, first targets). */
async function violations(page: Page): Promise<string[]> {
  await page.addScriptTag({ content: AXE });
  const found = await page.evaluate(async () => {
    const axe = (window as unknown as { axe: { run(): Promise<{ violations: AxeViolation[] }> } }).axe;
    return (await axe.run()).violations;
  });
  return found.map(
    (v) =>
      `${v.id} x${v.nodes.length}: ${v.nodes
        .slice(0, 3)
        .map((n) => n.target.join(' '))
        .join(', ')}`,
  );
}

describe('axe-core', () => {
  it('zero violations: the page in each view, and each embed, light and dark', async () => {
    for (const theme of ['light', 'dark'] as const) {
      const pages: Array<[string, { width: number; height: number }]> = [
        ...VIEWS.map((v): [string, { width: number; height: number }] => [`view=${v}`, { width: 1400, height: 900 }]),
        ...VIEWS.map((v): [string, { width: number; height: number }] => [
          `view=${v}&embed=1`,
          { width: 480, height: 700 },
        ]),
        ['embed=1', { width: 480, height: 700 }],
      ];
      const page = await site.browser().newPage({ colorScheme: theme });
      for (const [query, viewport] of pages) {
        await page.setViewportSize(viewport);
        await page.goto(`${site.url()}?${STATE}&${query}`);
        await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
        const view = /view=(\w+)/.exec(query)?.[1];
        if (view) await page.locator(`#panel-${view} > *`).first().waitFor();
        // Every view's data drawn and the page quiet: axe reads the final page, not one half drawn.
        await pageSettled(page);
        expect(await violations(page), `${query} ${theme}`).toEqual([]);
      }
      // A procedure highlighted (hover) keeps its contrast too.
      await page.setViewportSize({ width: 1400, height: 900 });
      await page.goto(`${site.url()}?${STATE}&view=formulas`);
      await page.locator('.formula').first().waitFor();
      await page.locator('.procedures tr[data-procedure="bedi"]').click();
      expect(await violations(page), `selected row ${theme}`).toEqual([]);
      await page.screenshot({ path: `${SHOTS}/a11y-formulas-${theme}.png` });
      await page.close();
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
    const { page } = await site.open(`?${STATE}&view=tables`);
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
