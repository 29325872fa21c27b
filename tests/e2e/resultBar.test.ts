/**
 * The result bar (issue 21) at 390 x 844: while a field has focus the headline answer stays in view
 * at the bottom of the screen, the same text as the results panel's headline (it mirrors, it does
 * not compute), a dash when the input is invalid, marked while typing, with a Copy button that
 * copies the headline's value; three-axis shows the programmed step; axe finds nothing on it.
 * Issue 28: once no field has focus (Enter, then a tap elsewhere) the headline lies below the fold,
 * and the bar stays while a result exists, its label whole (never cut with an ellipsis), on the
 * top edge of the on-screen keyboard (a visual viewport shorter than the window, emulated in the
 * page: its height and offset set, its resize event dispatched, as a phone's keyboard does).
 */
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { keepShot, pageSettled, ROOT, retype, usePhonePage, useSite } from './harness';

const site = useSite('docs/result-bar', { scene: false });
const AXE = readFileSync(`${ROOT}node_modules/axe-core/axe.min.js`, 'utf8');

const open = usePhonePage(site);

const text = async (page: Page, id: string) => (await page.getByTestId(id).textContent())?.trim() ?? '';

/** True when the whole of the element lies inside the viewport. */
const inViewport = (page: Page, id: string) =>
  page.getByTestId(id).evaluate((e) => {
    const r = e.getBoundingClientRect();
    return r.height > 0 && r.top >= 0 && r.bottom <= window.innerHeight && r.left >= 0 && r.right <= window.innerWidth;
  });

/** True when the result bar's Copy button can be pressed. */
const copyEnabled = (page: Page) => page.getByTestId('result-bar').getByRole('button').isEnabled();

/**
 * The lines of `selector`'s text that are not wholly inside it and the bar (each as "top text"):
 * cut by an ellipsis, an overflow or the bar's edge. Empty when every character is shown.
 */
const cut = (page: Page, selector: string) =>
  page.locator(selector).evaluate((e) => {
    const out: string[] = [];
    if (e.scrollWidth > e.clientWidth + 1) out.push(`scrollWidth ${e.scrollWidth} > ${e.clientWidth}`);
    const bar = (e.closest('[data-testid="result-bar"]') as HTMLElement).getBoundingClientRect();
    const range = document.createRange();
    range.selectNodeContents(e);
    for (const r of range.getClientRects())
      if (r.left < bar.left - 0.5 || r.right > bar.right + 0.5 || r.top < bar.top - 0.5 || r.bottom > bar.bottom + 0.5)
        out.push(`${Math.round(r.top)} ${Math.round(r.left)}-${Math.round(r.right)}`);
    return out;
  });

/**
 * Emulates a phone's on-screen keyboard `heightPx` high (0: closed): the visual viewport as the
 * browser then reports it (shorter by that much, not scrolled) and its resize event.
 */
const keyboard = (page: Page, heightPx: number) =>
  page.evaluate((px) => {
    const viewport = window.visualViewport as VisualViewport;
    Object.defineProperty(viewport, 'height', { configurable: true, get: () => window.innerHeight - px });
    Object.defineProperty(viewport, 'offsetTop', { configurable: true, get: () => 0 });
    viewport.dispatchEvent(new Event('resize'));
  }, heightPx);

describe('result bar on a phone', () => {
  it('keeps the headline in view while h has focus, follows the results, dashes when invalid, copies', async () => {
    const page = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    const bar = page.getByTestId('result-bar');
    // A result exists: the bar shows it before any field has focus (issue 28).
    await expect.poll(() => bar.isVisible()).toBe(true);
    const h = page.getByTestId('input-h');
    await h.scrollIntoViewIfNeeded();
    await h.tap();
    await expect.poll(() => bar.isVisible()).toBe(true);
    expect(await inViewport(page, 'result-bar')).toBe(true);
    // The bar shows the same text as the results' headline.
    const first = await text(page, 'result-exact-interval');
    expect(first).toMatch(/\d mm$/);
    expect(await text(page, 'result-bar-value')).toBe(first);
    expect(await bar.getAttribute('data-mark')).toBe('');
    await keepShot(page, 'result-bar-phone');

    // A new h: the bar follows the results.
    await retype(page, '0.01');
    await expect.poll(() => text(page, 'result-exact-interval')).not.toBe(first);
    await expect.poll(() => page.locator('.results').getAttribute('aria-busy')).toBe('false');
    const second = await text(page, 'result-exact-interval');
    expect(second).toMatch(/\d/);
    expect(await text(page, 'result-bar-value')).toBe(second);

    // Copy: the headline's value, in mm, as the results panel's Copy gives it.
    const copy = bar.getByRole('button');
    expect(await copy.getAttribute('aria-label')).toBe('Copy Step-over L');
    await copy.tap();
    await expect.poll(() => copy.textContent()).toBe('Copied');
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    expect(copied).toBe(await page.getByTestId('result-exact-interval').getAttribute('data-copy'));
    expect(Number.parseFloat(second)).toBeCloseTo(Number(copied), 4);

    // Half-typed: held back, the bar says typing and shows no number.
    await retype(page, '-');
    expect(await bar.getAttribute('data-mark')).toBe('typing');
    expect(await text(page, 'result-bar-mark')).toBe('typing');
    expect(await text(page, 'result-bar-value')).not.toMatch(/\d/);
    // Invalid once committed: a dash, no number, Copy disabled.
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, 'error-h')).toMatch(/must be/);
    expect(await bar.getAttribute('data-mark')).not.toBe('typing');
    expect(await text(page, 'result-bar-value')).toBe('\u2014');
    expect(await copy.isDisabled()).toBe(true);
    expect(await bar.isVisible()).toBe(true);

    // Focus leaves the inputs with no result: the bar goes (it stays only while a result exists).
    await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
    await expect.poll(() => bar.isVisible()).toBe(false);
  });

  it('three-axis: the bar shows the programmed step; axe finds nothing with the bar shown', async () => {
    const page = await open('?R=3&Rcr=1&machine=3axis&slope=30&h=0.05&unit=mm');
    await page.getByTestId('result-programmed-step').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
    const h = page.getByTestId('input-h');
    await h.scrollIntoViewIfNeeded();
    await h.tap();
    const bar = page.getByTestId('result-bar');
    await expect.poll(() => bar.isVisible()).toBe(true);
    const step = await text(page, 'result-programmed-step');
    expect(step).toMatch(/\d mm$/);
    expect(await text(page, 'result-bar-value')).toBe(step);
    expect(await page.locator('[data-testid="result-bar"] [data-role="bar-label"]').textContent()).toMatch(
      /\(as programmed\)$/,
    );
    // The question the answer answers, under the label (questionWords.ts).
    expect(await text(page, 'result-bar-question')).toMatch(/^3-axis, /);
    await pageSettled(page);
    await page.addScriptTag({ content: AXE });
    const violations = await page.evaluate(async () => {
      const axe = (
        window as unknown as {
          axe: { run(ctx: unknown): Promise<{ violations: Array<{ id: string; nodes: unknown[] }> }> };
        }
      ).axe;
      return (await axe.run({ include: [['[data-testid="result-bar"]']] })).violations.map(
        (v) => `${v.id} x${v.nodes.length}`,
      );
    });
    expect(violations).toEqual([]);
  });

  it('after Enter and a tap elsewhere: the bar stays with the answer, its label whole, above the keyboard', async () => {
    const page = await open('?R=3&Rcr=1&machine=3axis&slope=30&h=0.05&unit=mm');
    await page.getByTestId('result-programmed-step').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
    const bar = page.getByTestId('result-bar');
    const h = page.getByTestId('input-h');
    await h.scrollIntoViewIfNeeded();
    await h.tap();
    const first = await text(page, 'result-programmed-step');
    await retype(page, '0.01');
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, 'result-programmed-step')).not.toBe(first);
    await expect.poll(() => page.locator('.results').getAttribute('aria-busy')).toBe('false');
    // A tap elsewhere (the page's heading, no control): no field has focus any more.
    await page.locator('.chrome h1').scrollIntoViewIfNeeded();
    await page.locator('.chrome h1').tap();
    await expect.poll(() => page.evaluate(() => document.activeElement === document.body)).toBe(true);
    // The headline itself lies below the fold: the bar is what keeps the answer in view.
    const headlineTop = await page.getByTestId('result-programmed-step').evaluate((e) => e.getBoundingClientRect().top);
    expect(headlineTop).toBeGreaterThan(844);
    await expect.poll(() => bar.isVisible()).toBe(true);
    expect(await inViewport(page, 'result-bar')).toBe(true);
    const step = await text(page, 'result-programmed-step');
    expect(await text(page, 'result-bar-value')).toBe(step);
    expect(await copyEnabled(page)).toBe(true);
    // The label is whole: its text is the headline's, and no line of it is cut or hidden.
    const label = page.locator('[data-testid="result-bar"] [data-role="bar-label"]');
    expect(await label.textContent()).toBe(await page.locator('[data-role="headline-label"]').textContent());
    expect(await label.textContent()).toMatch(/^Horizontal step Lxy \(as programmed\)$/);
    expect(await cut(page, '[data-testid="result-bar"] .bar-label')).toEqual([]);
    expect(await cut(page, '[data-testid="result-bar"] .bar-value')).toEqual([]);
    await keepShot(page, 'result-bar-phone-no-focus');

    // The on-screen keyboard: the visual viewport 300 px shorter than the window. The bar's bottom
    // edge moves onto its top edge, and back when it closes.
    const barBottom = () => bar.evaluate((e) => Math.round(e.getBoundingClientRect().bottom));
    expect(await barBottom()).toBe(844);
    await keyboard(page, 300);
    await expect.poll(barBottom).toBe(544);
    expect(await bar.isVisible()).toBe(true);
    await keepShot(page, 'result-bar-phone-keyboard');
    await keyboard(page, 0);
    await expect.poll(barBottom).toBe(844);
  });

  it('stays out of an embed and of print', async () => {
    for (const query of ['?R=3&Rcr=1&rho=5&h=0.05&unit=mm&embed=1', '?R=3&Rcr=1&rho=5&h=0.05&unit=mm']) {
      const page = await open(query);
      const h = page.getByTestId('input-h');
      await h.scrollIntoViewIfNeeded();
      await h.tap();
      await expect.poll(() => page.evaluate(() => document.activeElement?.getAttribute('data-testid'))).toBe('input-h');
      if (query.includes('embed')) expect(await page.getByTestId('result-bar').isVisible()).toBe(false);
      else {
        expect(await page.getByTestId('result-bar').isVisible()).toBe(true);
        await page.emulateMedia({ media: 'print' });
        expect(await page.getByTestId('result-bar').isVisible()).toBe(false);
        await page.emulateMedia({ media: 'screen' });
      }
    }
  });
});
