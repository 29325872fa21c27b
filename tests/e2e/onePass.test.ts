/**
 * Issue 27 point 4, one pass per keystroke, in headless Chromium: each key press in a field builds
 * the page's request once, through the page's one builder (questionRequest.ts, counted by the
 * probe's requestsBuilt), and asks the solver's worker once when it changes the question (the
 * probe's calls); a half-typed text held back until the pause is built at its key press only (its
 * commit asks nothing again), and typing back to the question on screen asks nothing; a typed text
 * only the worker refuses (a gouging radius) is asked once and its message waits for the typing
 * pause. Five-axis on a plane and a concave cylinder, three-axis on a sloped plane (its builder
 * loaded by the machine switch, not with the first result) and a doubly curved point.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { TYPING_PAUSE_MS } from '../../src/ui/typing';
import { SOLVER, useSite, workerIdle } from './harness';

const site = useSite('docs/onePass', { scene: false });

type Counters = {
  __pathInterval: { requestsBuilt(): number; calls(worker: string): number; replies(w: string): number };
};

/** Requests built, calls sent to the solver and its replies, so far. */
const counters = (page: Page) =>
  page.evaluate((w) => {
    const p = (window as unknown as Counters).__pathInterval;
    return { built: p.requestsBuilt(), calls: p.calls(w), replies: p.replies(w) };
  }, SOLVER);

/** Presses one key in a field (focused, caret at the end) and returns the counters' change once the solver is idle. */
async function keyPress(page: Page, testId: string, key: string, settled: () => Promise<unknown>) {
  const input = page.getByTestId(testId);
  await input.scrollIntoViewIfNeeded();
  await input.focus();
  await page.keyboard.press('End');
  await workerIdle(page, SOLVER);
  const before = await counters(page);
  await page.keyboard.press(key);
  await settled();
  await workerIdle(page, SOLVER);
  const after = await counters(page);
  return { built: after.built - before.built, calls: after.calls - before.calls };
}

const text = (page: Page, id: string) => page.getByTestId(id).textContent();

describe('one pass per keystroke', () => {
  it('five-axis on a plane and a held-back text: one build per key press, one ask per new question', async () => {
    const { page, errors } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    const first = await text(page, 'result-exact-half');
    // h 0.05 -> 0.051: built once, asked once, answered.
    const typed = await keyPress(page, 'input-h', '1', () =>
      expect.poll(() => text(page, 'result-exact-half')).not.toBe(first),
    );
    expect(typed).toEqual({ built: 1, calls: 1 });
    // 0.051 -> "0.051." (half typed, held back until the pause): built at the key press only.
    const held = await keyPress(page, 'input-h', '.', () => expect.poll(() => text(page, 'error-h')).toMatch(/\S/));
    expect(held).toEqual({ built: 1, calls: 0 });
    // Back to 0.051, the question answered on screen: built once, nothing asked.
    const back = await keyPress(page, 'input-h', 'Backspace', () => expect.poll(() => text(page, 'error-h')).toBe(''));
    expect(back).toEqual({ built: 1, calls: 0 });

    // A concave radius typed: 50 -> 5 (Backspace), which the tool gouges (it needs more than 20 mm).
    // Only the worker finds that: the text is asked once, and its refusal waits for the typing pause
    // as the page's own errors do (no message flashes while typing), then shows.
    await page.locator('input[name="surface"][value="concave"]').check();
    await page.getByTestId('input-surface-radius').fill('50');
    await expect.poll(() => text(page, 'result-exact-half')).toMatch(/\d/);
    await page.evaluate(() => {
      const w = window as unknown as { __shown: { text: string; sinceKeyMs: number }[]; __keyAt: number };
      w.__shown = [];
      w.__keyAt = performance.now();
      const field = document.querySelector('[data-testid="input-surface-radius"]') as HTMLInputElement;
      field.addEventListener('input', () => {
        w.__keyAt = performance.now();
      });
      const error = document.querySelector('[data-testid="error-surface-radius"]') as HTMLElement;
      new MutationObserver(() =>
        w.__shown.push({ text: error.textContent ?? '', sinceKeyMs: performance.now() - w.__keyAt }),
      ).observe(error, { childList: true, characterData: true, subtree: true });
    });
    const gouged = await keyPress(page, 'input-surface-radius', 'Backspace', () =>
      expect.poll(() => text(page, 'error-surface-radius')).toMatch(/gouged/),
    );
    expect(gouged).toEqual({ built: 1, calls: 1 });
    const shown = await page.evaluate(
      () => (window as unknown as { __shown: { text: string; sinceKeyMs: number }[] }).__shown,
    );
    // A timer never fires early: every message came with the pause, none with the reply.
    const messages = shown.filter((m) => m.text !== '');
    expect(messages.length).toBeGreaterThan(0);
    for (const m of messages) expect(m.sinceKeyMs, m.text).toBeGreaterThanOrEqual(TYPING_PAUSE_MS - 1);
    site.changed();
    expect(errors).toEqual([]);
  });

  it('three-axis on a sloped plane, then a doubly curved point: one build and one ask per key press', async () => {
    // Five-axis first: three-axis machining's builder loads with the first three-axis question, not
    // with the first result (app.ts loadThreeAxis); the machine switch then asks it and it answers.
    const { page, errors } = await site.open('?R=3&Rcr=1&slope=30&h=0.05&unit=mm');
    const builderLoaded = () =>
      page.evaluate(() =>
        performance.getEntriesByType('resource').some((e) => /\/threeAxisRequest-[^/]*\.js$/.test(e.name)),
      );
    expect(await builderLoaded()).toBe(false);
    await page.getByTestId('machine-switch').getByText('3-axis').click();
    await expect.poll(() => text(page, 'result-programmed-step')).toMatch(/\d/);
    expect(await builderLoaded()).toBe(true);
    // The slope 30 -> 3 (Backspace).
    const step = await text(page, 'result-programmed-step');
    const slope = await keyPress(page, 'input-slope', 'Backspace', () =>
      expect.poll(() => text(page, 'result-programmed-step')).not.toBe(step),
    );
    expect(slope).toEqual({ built: 1, calls: 1 });

    // A doubly curved point (five-axis): h 0.05 -> 0.052.
    await page.getByTestId('machine-switch').getByText('5-axis').click();
    await page.locator('input[name="surface"][value="curved"]').check();
    await page.getByTestId('input-h').fill('0.05');
    await expect.poll(() => text(page, 'result-exact-half')).toMatch(/\d/);
    const curvedBefore = await text(page, 'result-exact-half');
    const curved = await keyPress(page, 'input-h', '2', () =>
      expect.poll(() => text(page, 'result-exact-half')).not.toBe(curvedBefore),
    );
    expect(curved).toEqual({ built: 1, calls: 1 });
    site.changed();
    expect(errors).toEqual([]);
  });
});
