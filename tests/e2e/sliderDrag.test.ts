/**
 * The page's own mouse drag of its sliders (src/ui/sliderDrag.ts), driven with the mouse: the
 * value lands where the browser's own slider puts it (compared with a touch tap, which the page
 * leaves to the browser), and each dragged value is set by the page inside the pointer's event
 * (so its answer can reach the same frame; how often it does is `npm run bench:web`'s figure).
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { animationFrames, useSite } from './harness';

const site = useSite('docs/slider-drag');

async function open(query: string): Promise<Page> {
  const context = await site.browser().newContext({ viewport: { width: 1440, height: 900 }, hasTouch: true });
  const page = await context.newPage();
  await page.goto(`${site.url()}${query}`);
  await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
  return page;
}

/** The slider's box in the viewport, scrolled into view first (the inputs' column is taller than a screen). */
async function sliderBox(page: Page, testId: string) {
  await page.getByTestId(testId).scrollIntoViewIfNeeded();
  const box = await page.getByTestId(testId).boundingBox();
  if (box === null) throw new Error(`${testId} is not visible`);
  return box;
}

describe('slider drag with the mouse', () => {
  it('puts the value where the browser puts it for a tap, over the whole track and past its ends', async () => {
    const page = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    try {
      for (const testId of ['slider-h', 'slider-rho', 'slider-tilt']) {
        const box = await sliderBox(page, testId);
        const y = box.y + box.height / 2;
        const slider = page.getByTestId(testId);
        const step = Number(await slider.getAttribute('step'));
        const xs = [-5, 0, 3, 12, 13, 50, 97.5, box.width / 2, box.width - 12.5, box.width - 3, box.width + 5];
        for (const dx of [...xs, ...Array.from({ length: 12 }, (_, i) => ((i + 0.37) * box.width) / 12)]) {
          const x = box.x + dx;
          await page.touchscreen.tap(x, y); // the browser's own slider
          const native = Number(await slider.inputValue());
          await page.mouse.click(x, y); // the page's drag
          const own = Number(await slider.inputValue());
          expect(
            Math.abs(own - native),
            `${testId} at ${dx.toFixed(1)} px: page ${own}, browser ${native}`,
          ).toBeLessThanOrEqual(step * 1.0001);
        }
      }
    } finally {
      await page.context().close();
    }
  });

  it('sets each dragged value from the pointer event itself, and the results answer it', async () => {
    const page = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    try {
      const box = await sliderBox(page, 'slider-h');
      const y = box.y + box.height / 2;
      const x0 = box.x + box.width * 0.3;
      // Every value the drag sets, and who set it: the page's own drag dispatches an untrusted
      // `input` event from the pointer's raw update (before the frame), the browser's a trusted one
      // with the frame. That the answer then reaches the same frame is a timing figure, measured by
      // `npm run bench:web` (input -> results + next frame), not asserted here.
      await page.evaluate(() => {
        const w = window as unknown as { __dragInputs: { trusted: boolean; inPointerEvent: boolean }[] };
        w.__dragInputs = [];
        const slider = document.querySelector('[data-testid="slider-h"]') as HTMLInputElement;
        let inPointerEvent = false;
        // Set while a pointer event travels from the window down to the slider and back up.
        for (const type of ['pointerrawupdate', 'pointermove', 'pointerdown']) {
          window.addEventListener(type, () => (inPointerEvent = true), true);
          window.addEventListener(type, () => (inPointerEvent = false));
        }
        slider.addEventListener('input', (e) => w.__dragInputs.push({ trusted: e.isTrusted, inPointerEvent }));
      });
      await page.mouse.move(x0, y);
      await page.mouse.down();
      const values = new Set<string>();
      const steps = 24;
      /** The field shows the slider's value and the results answer it (neither stale nor awaited). */
      const answered = () =>
        page.evaluate(() => {
          const results = document.querySelector('.results') as HTMLElement;
          const slider = document.querySelector('[data-testid="slider-h"]') as HTMLInputElement;
          const field = document.querySelector('[data-testid="input-h"]') as HTMLInputElement;
          const current = !results.classList.contains('stale') && results.getAttribute('aria-busy') !== 'true';
          return current && Number(field.value) === Number(slider.value) ? slider.value : null;
        });
      for (let i = 1; i <= steps; i++) {
        const previous = await page.getByTestId('slider-h').inputValue();
        await page.mouse.move(x0 + 3 * i, y);
        // A slow drag: the next move comes once this value's answer is drawn, two frames later.
        await expect.poll(answered).toSatisfy((v: string | null) => v !== null && v !== previous);
        await animationFrames(page, 2);
        values.add(await page.getByTestId('slider-h').inputValue());
      }
      const inputs = await page.evaluate(
        () => (window as unknown as { __dragInputs: { trusted: boolean; inPointerEvent: boolean }[] }).__dragInputs,
      );
      await page.mouse.up();
      // The URL follows once the drag settles (tests/ui/urlState.test.ts: not at every step).
      const last = await page.getByTestId('slider-h').inputValue();
      await expect.poll(() => new URL(page.url()).searchParams.get('h')).toBe(String(Number(last)));
      // Every step changed the value (else the test would assert nothing).
      expect(values.size).toBe(steps);
      // Each step's value came from the page's drag, inside the pointer's event (not with a frame).
      expect(inputs.length, 'input events during the drag').toBeGreaterThanOrEqual(steps);
      expect(
        inputs.filter((e) => e.trusted || !e.inPointerEvent),
        "input events not dispatched by the page's drag inside a pointer event",
      ).toEqual([]);
      // The value shown answers the slider.
      await expect
        .poll(() => page.getByTestId('input-h').inputValue())
        .toBe(String(Number(await page.getByTestId('slider-h').inputValue())));
    } finally {
      await page.context().close();
    }
  });
});
