/**
 * Issue 17 in headless Chromium, as a user does it:
 *  - item 1: h 0.051, back to 0.05 (its answer is on screen) and, once the 0.051 reply has landed,
 *    0.051 again (typing `1`, Backspace, `1`): the page ends on the 0.051 answer, not on the 0.05
 *    one marked "Updating" for good; the same for the Machined surface view ("Simulating...").
 *  - item 7: after the teaching views' worker gave up (3 restarts) and works again, its notice goes.
 *
 * No fixed wait: the test holds a worker's replies (it wraps the worker's postMessage) so that the
 * 0.051 reply lands only after the Backspace, and it waits for the page to have received that reply
 * by counting the replies that reach the page (a Worker subclass installed before the page loads).
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { exactForward, forwardInput, type ToolInput } from '../../src/core/index';
import { formatLenUnit } from '../../src/ui/format';
import { holdScene, keepShot, namedWorker, useSite } from './harness';
import { heldAnswers, holdReplies, release } from './heldReplies';

const site = useSite('docs/freshness', { scene: false });
const TOOL: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
/** The headline the page must show for h (mm), from the core. */
const headline = (h: number) => formatLenUnit(exactForward(forwardInput(TOOL, 'one-way', h)).intervalMm, 'mm');

type Counted = { __answers: Record<string, number> };

/**
 * Opens the page with a counter of the answers (replies carrying a request) that reach it from
 * each named worker, installed before the page's own code runs.
 */
async function open(query: string): Promise<Page> {
  const page = await site.browser().newPage({ viewport: { width: 1400, height: 900 } });
  await holdScene(page); // the file looks at no part of the scene
  await page.addInitScript(() => {
    const counts: Record<string, number> = {};
    (window as unknown as Counted).__answers = counts;
    const Native = window.Worker;
    window.Worker = class extends Native {
      constructor(url: string | URL, options?: WorkerOptions) {
        super(url, options);
        const name = options?.name ?? '';
        counts[name] ??= 0;
        // Added before the page's own listener: counted before the page handles the reply.
        this.addEventListener('message', (e: MessageEvent) => {
          const m = e.data as { rpc?: string; value?: unknown };
          if (m?.rpc === 'ok' && typeof m.value === 'object' && m.value !== null && 'request' in m.value)
            counts[name] = (counts[name] ?? 0) + 1;
        });
      }
    };
  });
  await page.goto(`${site.url()}${query}`);
  await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
  return page;
}

/** Answers from the worker `name` that the page has received so far. */
const answersReceived = (page: Page, name: string) =>
  page.evaluate((n) => (window as unknown as Counted).__answers[n] ?? 0, name);

/**
 * Types `1` after 0.05 (0.051), then Backspace (0.05), while `workerName` holds its replies; then
 * lets the 0.051 reply reach the page (dropped: 0.05 is on screen), then types `1` again.
 * `onScreen005` checks the page shows the 0.05 answer as current in between.
 */
async function backAndForth(page: Page, workerName: string, onScreen005: () => Promise<void>): Promise<void> {
  const worker = await namedWorker(page, workerName);
  await holdReplies(worker);
  const field = page.getByTestId('input-h');
  await field.click();
  await page.keyboard.press('End');
  await page.keyboard.type('1');
  expect(await field.inputValue()).toBe('0.051');
  // The worker has answered 0.051 (held).
  await expect.poll(() => heldAnswers(worker), { timeout: 20_000 }).toBe(1);
  await page.keyboard.press('Backspace');
  expect(await field.inputValue()).toBe('0.05');
  await onScreen005();
  const before = await answersReceived(page, workerName);
  await release(worker);
  // The 0.051 reply reached the page, which dropped it (0.05 is on screen).
  await expect.poll(() => answersReceived(page, workerName)).toBe(before + 1);
  await onScreen005();
  await page.keyboard.type('1');
  expect(await field.inputValue()).toBe('0.051');
}

describe('the page ends on the answer to the inputs on screen (issue 17)', () => {
  it('results: h 0.051 -> 0.05 -> 0.051 (typing 1, Backspace, 1) shows the 0.051 answer, nothing stale', async () => {
    const page = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    const results = page.locator('section.results');
    const current = async (h: number) => {
      await expect.poll(() => page.getByTestId('result-exact-interval').textContent()).toBe(headline(h));
      await expect.poll(() => results.getAttribute('class')).not.toMatch(/stale/);
      expect(await page.getByTestId('results-status').isVisible()).toBe(false);
    };
    await current(0.05);
    expect(headline(0.05)).toBe('2.8872 mm'); // the figure
    await backAndForth(page, 'path-interval-solver', () => current(0.05));
    await current(0.051);
    await keepShot(page, 'freshness-back-and-forth');
    await page.close();
  });

  it('Machined surface view: the same back-and-forth ends on the simulation of 0.051, not "Simulating..."', async () => {
    const page = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=surface');
    const line = page.getByTestId('surface-comparison');
    const current = async (h: number) => {
      await expect
        .poll(async () => (await line.textContent()) ?? '', { timeout: 20_000 })
        .toMatch(new RegExp(`^Simulated cusp .* against exact ${(1000 * h).toFixed(3)} \u00b5m`));
      expect(await page.getByTestId('surface-status').isVisible()).toBe(false);
      expect(await page.getByTestId('surface-view').getAttribute('class')).not.toMatch(/stale/);
    };
    await current(0.05);
    await backAndForth(page, 'path-interval-simulation', () => current(0.05));
    await current(0.051);
    await page.close();
  });
});

describe("notices follow the workers' state (issue 17, item 7)", () => {
  it("the teaching views' give-up notice goes once their worker answers again", async () => {
    const page = await site.browser().newPage({ viewport: { width: 1400, height: 900 } });
    await holdScene(page); // the file looks at no part of the scene
    // While `broken`, every new worker's script throws as it loads (the worker fails at once).
    let broken = false;
    await page.route('**/solver.worker-*.js', (route) =>
      broken
        ? route.fulfill({ contentType: 'text/javascript', body: "throw new Error('broken by the test');" })
        : route.continue(),
    );
    await page.goto(`${site.url()}?R=3&Rcr=1&rho=5&h=0.05&unit=mm`);
    const teaching = page.getByTestId('teaching');
    const notice = page.getByTestId('notice');
    await page.getByTestId('profile-view').locator('polygon.scallop').waitFor();
    await expect.poll(() => teaching.getAttribute('class')).not.toMatch(/stale/);
    // The views' worker dies (closed from inside: the page has no hook for it) and every new one fails.
    broken = true;
    const views = await namedWorker(page, 'path-interval-views');
    await views.evaluate(() => (globalThis as unknown as { close(): void }).close()).catch(() => undefined);
    await page.getByTestId('input-h').fill('0.1');
    await expect
      .poll(() => notice.textContent(), { timeout: 20_000 })
      .toMatch(/teaching views' solver stopped after 3 restarts/);
    expect(await notice.isVisible()).toBe(true);
    await expect.poll(() => page.getByTestId('views-stale').textContent()).toMatch(/gave up/);
    // The worker can start again; the user changes an input, as the notice says.
    broken = false;
    await page.getByTestId('input-h').fill('0.06');
    await expect.poll(() => teaching.getAttribute('class'), { timeout: 20_000 }).not.toMatch(/stale/);
    await expect.poll(() => notice.isVisible()).toBe(false);
    // The results' worker never failed: its answer is current too.
    await expect.poll(() => page.getByTestId('result-exact-interval').textContent()).toBe(headline(0.06));
    await page.close();
  }, 60_000);
});
