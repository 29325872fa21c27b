/**
 * The production site under a strict Content-Security-Policy, sent as a documentation host would
 * send it: the page and each of its six views must work with zero violations (no inline style
 * attribute, no inline script, workers from the same origin): the views of the full page one after
 * the other by their tabs in one document (each tab runs its view's code, as a load with view= does),
 * each embedded view in its own.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { animationFrames, STRICT_CSP, showView, useSite } from './harness';

const site = useSite('docs/csp', { build: 'production', headers: { 'Content-Security-Policy': STRICT_CSP } });
const VIEWS = ['profile', 'chart', 'tables', 'stepper', 'formulas', 'surface'] as const;
const STATE = 'R=3&Rcr=1&rho=5&tilt=3&h=0.05&unit=mm';

/** The file's tab, shared by its tests (each open is a fresh document in it), and where its console lines go. */
let shared: Page | null = null;
let consoleLines: string[] = [];

/**
 * Opens a page that records every CSP violation (the recorder is injected by the test, not
 * shipped), in the file's shared tab.
 */
async function openRecorded(query: string): Promise<{ page: Page; violations: () => Promise<string[]> }> {
  if (shared === null || shared.isClosed()) {
    const created = await site.browser().newPage({ viewport: { width: 1400, height: 900 } });
    created.on('console', (m) => {
      if (/Content Security Policy|Refused to/i.test(m.text())) consoleLines.push(m.text());
    });
    await created.addInitScript(() => {
      const seen: string[] = [];
      (window as unknown as { __violations: string[] }).__violations = seen;
      document.addEventListener('securitypolicyviolation', (e) =>
        seen.push(`${e.violatedDirective}: ${e.blockedURI} ${e.sample}`.trim()),
      );
    });
    shared = created;
  } else if (shared.url() !== 'about:blank') await shared.goto('about:blank');
  const page = shared;
  const console: string[] = [];
  consoleLines = console;
  await page.goto(`${site.url()}${query}`);
  await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
  const violations = async () => [
    ...(await page.evaluate(() => (window as unknown as { __violations: string[] }).__violations)),
    ...console,
  ];
  return { page, violations };
}

describe('strict Content-Security-Policy', () => {
  it(`the page works under "${STRICT_CSP}" with zero violations`, async () => {
    const { page, violations } = await openRecorded('?R=3&Rcr=1&rho=5&tilt=5&pattern=zigzag&h=0.05&unit=mm');
    expect(page.workers().length).toBeGreaterThan(0);
    await page.getByTestId('profile-view').locator('polygon.scallop').waitFor();
    await page.locator('.procedures tr[data-procedure="bedi"]').hover();
    await page.locator('input[name="unit"][value="in"]').check();
    await page.getByTestId('result-exact-interval').filter({ hasText: / in$/ }).waitFor();
    await page.getByTestId('input-Rcr').fill('9'); // invalid: messages, dashes, stale marks
    await page
      .getByTestId('error-Rcr')
      .filter({ hasText: /must not exceed/ })
      .waitFor();
    expect(await violations()).toEqual([]);
  });

  /** Waits until a view's panel shows its content, then does what a user does there; then frames pass. */
  const exercise = async (page: Page, view: (typeof VIEWS)[number]) => {
    const panel = page.locator(`#panel-${view}`);
    const ready = {
      profile: panel.locator('polygon.scallop'),
      chart: panel.locator('svg.chart-svg').first(),
      tables: panel.locator('table').first(),
      stepper: page.getByTestId('stepper-caption').filter({ hasText: /\d/ }),
      formulas: panel.locator('math').first(),
      surface: page.getByTestId('surface-comparison').filter({ hasText: /Simulated cusp/ }),
    };
    await ready[view].waitFor();
    if (view === 'stepper') {
      await page.getByTestId('stepper-forward').click();
      await page.getByTestId('stepper-last').click();
    }
    if (view === 'profile') await page.getByTestId('profile-cusp').click();
    if (view === 'chart') await page.getByTestId('chart-error-unit').selectOption('mm');
    // What the clicks changed is drawn, and any violation event it raised has been dispatched.
    await animationFrames(page, 3);
  };

  it('each view of the full page, opened by its tab in one document, logs zero violations', async () => {
    const { page, violations } = await openRecorded(`?${STATE}&view=${VIEWS[0]}`);
    for (const view of VIEWS) {
      if (view !== VIEWS[0]) await showView(page, view);
      await exercise(page, view);
      expect(await violations(), view).toEqual([]);
    }
  });

  for (const view of VIEWS)
    it(`the ${view} view embedded (its own document) logs zero violations`, async () => {
      const { page, violations } = await openRecorded(`?${STATE}&view=${view}&embed=1`);
      await exercise(page, view);
      expect(await violations(), `${view}&embed=1`).toEqual([]);
    });
});
