/**
 * Presentation mode (issue 21, the teacher at a projector) at 1920 x 1080 and 1440 x 900, light and
 * dark: entered by `?present=1` and by the Present button, the headline answer at least 24 px and
 * every other text at least 16 px (getComputedStyle; an SVG text's size times its scale on screen),
 * the 3D scene's canvas over half the window and its drawing buffer following its new size, no
 * header, no page scrolling; the Inputs button opens the inputs over the view; Escape closes them,
 * then leaves, the URL drops present=1 and the layout is as before; axe finds nothing.
 * Issue 28: a presenter's clicker (its key presses: ArrowRight/Left, PageDown/Up, Space, Home/End)
 * drives the step-through wherever focus is, a text field keeping its keys; the paper's tables are
 * whole at 1920 wide; the scrolled Inputs panel's text never lies under its buttons.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { axeViolations } from './axe';
import { animationFrames, keepShot, pageSettled, sceneIdle, useSite, viewAs } from './harness';

const site = useSite('docs/present');
const STATE = 'R=3&Rcr=1&rho=5&h=0.05&unit=mm';
const VIEWPORTS = [
  { width: 1920, height: 1080 },
  { width: 1440, height: 900 },
] as const;
const VIEWS = ['profile', 'chart', 'tables', 'stepper', 'formulas', 'surface'] as const;

/**
 * Visible texts smaller than the least size (24 px for the headline answer, 16 px for the rest):
 * each as "size text". An HTML or MathML text's size is its computed font-size; an SVG text's, its
 * computed font-size times the SVG's scale on screen. Script letters of a formula (sub- and
 * superscripts, drawn smaller by MathML's own rule) are judged by their formula's size. Not judged:
 * the machined surface's simulated trace (`.surface-trace`), whose labels fill a fixed margin of its
 * drawing (present.css; left as it is).
 */
function smallTexts(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const small: string[] = [];
    const app = document.querySelector('.app');
    if (!app) return ['no .app'];
    const walker = document.createTreeWalker(app, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n !== null; n = walker.nextNode()) {
      const text = n.textContent?.trim() ?? '';
      const el = n.parentElement;
      if (text === '' || el === null || !el.checkVisibility({ visibilityProperty: true })) continue;
      if (el.closest('.surface-trace')) continue;
      const r = el.getBoundingClientRect();
      if (r.width <= 1 || r.height <= 1) continue; // not drawn, or read to screen readers only (sr-only)
      const judged = el.closest('math') ?? el;
      let px = Number.parseFloat(getComputedStyle(judged).fontSize);
      if (judged instanceof SVGGraphicsElement) {
        const m = judged.getScreenCTM();
        px *= m ? Math.hypot(m.a, m.b) : 1;
      }
      const least = el.closest('[data-testid="result-exact-interval"]') ? 24 : 16;
      if (px < least - 0.05) small.push(`${px.toFixed(1)}px ${text.slice(0, 40)}`);
    }
    return small;
  });
}

/** The laid-out boxes of the page's parts (rounded px), to compare a layout before and after. */
function layout(page: Page): Promise<Record<string, number[]>> {
  return page.evaluate(() => {
    const out: Record<string, number[]> = {};
    for (const s of ['.chrome', '.controls', '.results', '.view', '.teaching', '[data-testid="scene-canvas"]']) {
      const r = document.querySelector(s)?.getBoundingClientRect();
      out[s] = r ? [r.x, r.y, r.width, r.height].map(Math.round) : [];
    }
    return out;
  });
}

/** The canvas's share of the window, and whether its drawing buffer has the canvas's shape (2 %). */
function canvasFit(page: Page): Promise<{ share: number; bufferFollows: boolean }> {
  return page.getByTestId('scene-canvas').evaluate((c: HTMLCanvasElement) => {
    const r = c.getBoundingClientRect();
    const visibleW = Math.min(r.right, window.innerWidth) - Math.max(r.left, 0);
    const visibleH = Math.min(r.bottom, window.innerHeight) - Math.max(r.top, 0);
    const share = (Math.max(0, visibleW) * Math.max(0, visibleH)) / (window.innerWidth * window.innerHeight);
    const bufferFollows = Math.abs(c.width / c.height / (c.clientWidth / c.clientHeight) - 1) < 0.02;
    return { share, bufferFollows };
  });
}

/** Everything presentation mode promises, on the page as it is now. */
async function expectPresenting(page: Page, label: string): Promise<void> {
  expect(await page.evaluate(() => document.documentElement.classList.contains('present')), label).toBe(true);
  await expect.poll(() => new URL(page.url()).searchParams.get('present'), { message: label }).toBe('1');
  expect(await page.locator('.chrome').isVisible(), `${label}: header`).toBe(false);
  expect(await page.locator('.controls').isVisible(), `${label}: inputs`).toBe(false);
  expect(await page.getByTestId('result-exact-interval').isVisible(), `${label}: headline`).toBe(true);
  expect(await page.getByTestId('present-toggle').locator('span:visible').textContent()).toBe(
    'Leave presentation (Esc)',
  );
  await expect.poll(async () => (await canvasFit(page)).bufferFollows, { message: label }).toBe(true);
  const { share } = await canvasFit(page);
  expect(share, `${label}: canvas share of the window`).toBeGreaterThan(0.5);
  // The page fills the window without scrolling.
  expect(await page.evaluate(() => document.documentElement.scrollHeight <= window.innerHeight + 1), label).toBe(true);
  const headlinePx = await page
    .getByTestId('result-exact-interval')
    .evaluate((e) => Number.parseFloat(getComputedStyle(e).fontSize));
  expect(headlinePx, `${label}: headline`).toBeGreaterThanOrEqual(24);
  expect(await smallTexts(page), `${label}: texts under 16 px`).toEqual([]);
}

describe('presentation mode', () => {
  it('by URL, at 1920x1080 and 1440x900, light and dark: large type, the scene over half the window, no header; axe finds nothing', async () => {
    for (const viewport of VIEWPORTS)
      for (const theme of ['light', 'dark'] as const) {
        const label = `${viewport.width}x${viewport.height} ${theme}`;
        const { page, errors } = await site.open(`?${STATE}&present=1`, viewport, theme);
        await page.locator('#panel-profile svg').first().waitFor();
        await sceneIdle(page);
        await pageSettled(page);
        await keepShot(page, `present-${viewport.width}-${theme}`);
        await expectPresenting(page, label);
        expect(await axeViolations(page), label).toEqual([]);
        expect(errors, label).toEqual([]);
      }
  }, 240_000);

  it('every teaching view keeps its texts at 16 px or more (1440x900)', async () => {
    const { page } = await site.open(`?${STATE}&present=1`, VIEWPORTS[1]);
    for (const view of VIEWS) {
      await page.locator(`[role="tab"][data-view="${view}"]`).click();
      await page.locator(`#panel-${view} > *`).first().waitFor();
      await pageSettled(page);
      expect(await smallTexts(page), view).toEqual([]);
      await keepShot(page, `present-view-${view}`);
    }
    expect(await axeViolations(page), 'formulas').toEqual([]);
  }, 120_000);

  it('by the button, at both sizes: the inputs open over the view and change the answer; Escape closes them, then leaves and restores the layout', async () => {
    for (const viewport of VIEWPORTS) {
      const label = `${viewport.width}x${viewport.height}`;
      const { page, errors } = await site.open(`?${STATE}`, viewport);
      await sceneIdle(page);
      await pageSettled(page);
      const before = await layout(page);
      const toggle = page.getByTestId('present-toggle');
      expect(await toggle.locator('span:visible').textContent()).toBe('Present');
      expect(await page.locator('.chrome').isVisible()).toBe(true);
      expect((await canvasFit(page)).share).toBeLessThan(0.5);

      await toggle.click();
      await sceneIdle(page);
      await pageSettled(page);
      await expectPresenting(page, `${label} button`);

      // Escape leaves: the URL drops present=1, the layout is the one before.
      await page.keyboard.press('Escape');
      await expect.poll(() => page.evaluate(() => document.documentElement.classList.contains('present'))).toBe(false);
      await expect.poll(() => new URL(page.url()).searchParams.has('present')).toBe(false);
      expect(await toggle.locator('span:visible').textContent()).toBe('Present');
      expect(await toggle.evaluate((e) => e === document.activeElement)).toBe(true);
      await sceneIdle(page);
      await pageSettled(page);
      expect(await layout(page), label).toEqual(before);
      await expect.poll(async () => (await canvasFit(page)).bufferFollows).toBe(true);
      await keepShot(page, `present-left-${viewport.width}`);

      // Again, by the keyboard: the inputs open over the teaching view and the answer follows a new h.
      await toggle.press('Enter');
      await expect.poll(() => page.evaluate(() => document.documentElement.classList.contains('present'))).toBe(true);
      const inputs = page.getByTestId('present-inputs');
      await inputs.click();
      expect(await inputs.getAttribute('aria-expanded')).toBe('true');
      await expect.poll(() => page.locator('.controls').isVisible()).toBe(true);
      const answer = await page.getByTestId('result-exact-interval').textContent();
      await page.getByTestId('input-h').fill('0.02');
      await page.getByTestId('input-h').press('Enter');
      await expect.poll(() => page.getByTestId('result-exact-interval').textContent()).not.toBe(answer);
      expect(await page.getByTestId('result-exact-interval').isVisible()).toBe(true);
      await pageSettled(page);
      expect(await smallTexts(page), `${label} inputs open`).toEqual([]);
      await keepShot(page, `present-inputs-${viewport.width}`);
      expect(await axeViolations(page), `${label} inputs open`).toEqual([]);

      // Escape: first the inputs close (focus back on their button), then presentation ends.
      await page.keyboard.press('Escape');
      await expect.poll(() => page.locator('.controls').isVisible()).toBe(false);
      expect(await inputs.evaluate((e) => e === document.activeElement)).toBe(true);
      expect(await page.evaluate(() => document.documentElement.classList.contains('present'))).toBe(true);
      await page.keyboard.press('Escape');
      await expect.poll(() => page.evaluate(() => document.documentElement.classList.contains('present'))).toBe(false);
      await expect.poll(() => new URL(page.url()).searchParams.has('present')).toBe(false);
      // The state changed in presentation stays in the URL.
      await expect.poll(() => new URL(page.url()).searchParams.get('h')).toBe('0.02');
      expect(await inputs.isVisible()).toBe(false);
      expect(errors, label).toEqual([]);
    }
  }, 180_000);

  it("a clicker's keys step the step-through wherever focus is; a text field keeps them", async () => {
    const { page, errors } = await site.open(`?${STATE}&present=1`, VIEWPORTS[0]);
    await page.locator('#panel-profile svg').first().waitFor();
    const counter = page.getByTestId('stepper-counter');
    const step = async () => Number(/step (\d+) of/.exec((await counter.textContent()) ?? '')?.[1] ?? Number.NaN);
    // No focus: the first press opens the step-through (at its first step), the next ones step.
    expect(await page.evaluate(() => document.activeElement === document.body)).toBe(true);
    await page.keyboard.press('ArrowRight');
    await expect
      .poll(() => page.locator('[role="tab"][data-view="stepper"]').getAttribute('aria-selected'))
      .toBe('true');
    await expect.poll(step).toBe(1);
    const total = Number(/of (\d+)/.exec((await counter.textContent()) ?? '')?.[1]);
    expect(total).toBeGreaterThan(5);
    for (const [key, expected] of [
      ['ArrowRight', 2],
      ['PageDown', 3],
      ['Space', 4],
      ['ArrowLeft', 3],
      ['PageUp', 2],
      ['End', total],
      ['Home', 1],
      ['Shift+Space', 1],
    ] as const) {
      await page.keyboard.press(key);
      await expect.poll(step, { message: key }).toBe(expected);
    }
    // Focus on a button (Space would press it: here, leave presentation mode) and on a tab (the
    // arrows would switch tabs): the clicker's keys still step.
    await page.getByTestId('present-toggle').focus();
    await page.keyboard.press('Space');
    await expect.poll(step).toBe(2);
    expect(await page.evaluate(() => document.documentElement.classList.contains('present'))).toBe(true);
    await page.locator('[role="tab"][data-view="stepper"]').focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(step).toBe(3);
    expect(await page.locator('[role="tab"][data-view="stepper"]').getAttribute('aria-selected')).toBe('true');
    // A text field keeps its keys: the caret moves, the step does not.
    await page.getByTestId('present-inputs').click();
    const h = page.getByTestId('input-h');
    await h.focus();
    await page.keyboard.press('End');
    const caret = () => h.evaluate((e: HTMLInputElement) => e.selectionStart);
    expect(await caret()).toBe((await h.inputValue()).length);
    await page.keyboard.press('Home');
    expect(await caret()).toBe(0);
    await page.keyboard.press('ArrowRight');
    expect(await caret()).toBe(1);
    expect(await step()).toBe(3);
    await page.keyboard.press('Escape');
    await expect.poll(() => page.locator('.controls').isVisible()).toBe(false);
    // Back on the Inputs button, outside the panel: the clicker steps again.
    await page.keyboard.press('PageDown');
    await expect.poll(step).toBe(4);
    expect(errors).toEqual([]);
  });

  it("the paper's tables whole at 1920 wide; the scrolled Inputs panel's text clear of its buttons", async () => {
    const { page } = await site.open(`?${STATE}&present=1&view=tables`, VIEWPORTS[0]);
    await page.locator('[data-testid="paper-table-half"] tr[data-condition]').first().waitFor();
    await pageSettled(page);
    const cut = () =>
      page.evaluate(() =>
        [...document.querySelectorAll<HTMLElement>('#panel-tables .table-scroll, #panel-tables table')].flatMap((e) => {
          const r = e.getBoundingClientRect();
          return e.scrollWidth > e.clientWidth + 1 || r.right > window.innerWidth
            ? [`${e.tagName} ${e.scrollWidth}/${e.clientWidth} right ${Math.round(r.right)}`]
            : [];
        }),
      );
    expect(await cut()).toEqual([]);
    await keepShot(page, 'present-tables-1920');

    // A 1280 x 720 projector: the opened Inputs panel scrolls; half way down no text lies under a button.
    await viewAs(page, { width: 1280, height: 720 });
    await page.getByTestId('present-inputs').click();
    const controls = page.locator('.controls');
    await expect.poll(() => controls.isVisible()).toBe(true);
    const scrolled = await controls.evaluate((e) => {
      e.scrollTop = (e.scrollHeight - e.clientHeight) / 2;
      return e.scrollTop;
    });
    expect(scrolled).toBeGreaterThan(100);
    await animationFrames(page);
    const covered = await page.evaluate(() => {
      const buttons = [...document.querySelectorAll('.present-tools button')].map((b) => b.getBoundingClientRect());
      const panel = document.querySelector('.controls') as HTMLElement;
      const box = panel.getBoundingClientRect();
      const out: string[] = [];
      const walker = document.createTreeWalker(panel, NodeFilter.SHOW_TEXT);
      for (let n = walker.nextNode(); n !== null; n = walker.nextNode()) {
        if ((n.textContent ?? '').trim() === '') continue;
        const range = document.createRange();
        range.selectNodeContents(n);
        for (const r of range.getClientRects()) {
          if (r.bottom <= box.top || r.top >= box.bottom) continue; // scrolled out of the panel's box
          for (const b of buttons)
            if (r.left < b.right && r.right > b.left && r.top < b.bottom && r.bottom > b.top)
              out.push(`${(n.textContent ?? '').trim().slice(0, 30)} at ${Math.round(r.top)}`);
        }
      }
      return out;
    });
    expect(covered).toEqual([]);
    await keepShot(page, 'present-inputs-scrolled-1280');

    // The chart view on that projector, in English and in German (its tabs the longest): the first
    // chart whole in the window (its lead axis's ticks and title without scrolling), and no chart
    // taller than the view's column (each can be scrolled into sight whole).
    await page.keyboard.press('Escape');
    await expect.poll(() => controls.isVisible()).toBe(false);
    await page.locator('#tab-chart').click();
    const charts = (view = '.chart-classic') =>
      page.evaluate((v) => {
        const svgs = [...document.querySelectorAll(`#panel-chart ${v} svg.chart-svg`)].map((s) =>
          s.getBoundingClientRect(),
        );
        const column = (document.querySelector('.teaching') as HTMLElement).clientHeight;
        const first = svgs[0]?.bottom ?? Number.POSITIVE_INFINITY;
        const tallest = Math.max(...svgs.map((r) => r.height));
        return {
          lang: document.documentElement.lang,
          charts: svgs.length,
          fits: first <= window.innerHeight && tallest <= column,
          first: Math.round(first),
          tallest: Math.round(tallest),
          column,
        };
      }, view);
    const choose = (lang: string) =>
      page.evaluate((l) => {
        (document.querySelector(`[data-testid="lang-switch"] input[value="${l}"]`) as HTMLInputElement).click();
      }, lang);
    for (const lang of ['en', 'de']) {
      await choose(lang);
      await expect.poll(() => charts(), { timeout: 15_000 }).toMatchObject({ lang, charts: 3, fits: true });
    }
    // Three-axis machining's chart view in German (its headline on two lines): its sentence below, the first chart whole.
    await page.getByTestId('present-inputs').click();
    await page.locator('[data-testid="machine-switch"] input[value="3axis"]').check();
    await page.getByTestId('input-slope').fill('20');
    await page.getByTestId('input-slope').press('Enter');
    await page.keyboard.press('Escape');
    await expect.poll(() => controls.isVisible()).toBe(false);
    await expect.poll(() => charts('.slope-chart'), { timeout: 15_000 }).toMatchObject({ charts: 2, fits: true });
    await choose('en');
    await expect.poll(() => charts(), { timeout: 15_000 }).toMatchObject({ lang: 'en' });
  });

  it('present= with another word: a notice naming it, and the normal page', async () => {
    const { page } = await site.open(`?${STATE}&present=yes`, VIEWPORTS[1]);
    await expect.poll(() => page.getByTestId('notice').textContent()).toContain('present="yes" is not 1');
    expect(await page.evaluate(() => document.documentElement.classList.contains('present'))).toBe(false);
    expect(await page.locator('.chrome').isVisible()).toBe(true);
  });
});
