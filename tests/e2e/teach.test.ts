/**
 * The teacher's page (issue 10): the comparison charts and the step-through, driven as a teacher
 * would at 1440 x 900 (projector) and 390 x 844 (phone), in the light and the dark theme (one load
 * for the four: the sizes by setViewportSize, the theme by the system's scheme). Screenshots are kept
 * in test-results/screenshots/ under `npm run shots`.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { compareForward } from '../../src/core/index';
import { formatPercent, formatSignificant } from '../../src/core/input/units';
import { forwardInput } from '../../src/core/input/validate';
import { stepOverSweep } from '../../src/core/procedures/teaching';
import { groupSteps, sceneToleranceMm } from '../../src/ui/views/stepGroups';
import { traceFrames } from '../../src/worker/api';
import { holdScene, keepShot, useSite } from './harness';

const site = useSite('docs/teach', { scene: false });
const { open } = site;

const TOOL1 = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const VIEWPORTS = [
  { name: 'wide', width: 1440, height: 900 },
  { name: 'phone', width: 390, height: 844 },
] as const;
const THEMES = ['light', 'dark'] as const;
/** The exact curve's colour in each theme (procedures.ts). */
const EXACT_STROKE = { light: 'rgb(17, 24, 39)', dark: 'rgb(243, 244, 246)' };

/** The chart's and the step-through's pages, each shared by the tests that only read them. */
const CHART = '?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=chart';
const STEPPER = '?R=3&Rcr=1&rho=5&h=0.1&unit=mm&view=stepper';

async function noHorizontalScroll(page: Page): Promise<void> {
  const { scroll, client } = await page.evaluate(() => ({
    scroll: document.documentElement.scrollWidth,
    client: document.documentElement.clientWidth,
  }));
  expect(scroll, 'page scrolls sideways').toBeLessThanOrEqual(client);
}

describe('teacher: the comparison charts', () => {
  for (const vp of VIEWPORTS) {
    for (const theme of THEMES) {
      it(`${vp.name} ${theme}: tall plots, units in the titles, legend values at the current lead and tilt, the reason where Bedi has no answer`, async () => {
        const { page, errors } = await site.reuse(CHART, vp, theme);
        const chart = page.getByTestId('comparison-chart');
        const c = compareForward(forwardInput(TOOL1, 'one-way', 0.05));
        const lead = page.getByTestId('chart-lead');
        // Legend: each procedure's value at the current lead, without hovering (the solver's numbers).
        await expect
          .poll(() => page.getByTestId('chart-lead-value-exact').textContent())
          .toBe(`${c.exact.intervalMm.toFixed(4)} mm`);
        for (const key of ['sekine', 'redonnet', 'bedi', 'osculating', 'cornerBall'] as const) {
          const a = c.approximations[key];
          if (!a.ok) throw new Error(key);
          expect(await page.getByTestId(`chart-lead-value-${key}`).textContent(), key).toBe(
            `${a.intervalMm.toFixed(4)} mm`,
          );
          // The error chart's legend: the signed % against exact.
          expect(await page.getByTestId(`chart-error-value-${key}`).textContent(), key).toBe(
            `${formatPercent(a.deviationPercent)} %`,
          );
        }
        expect(await page.getByTestId('chart-tilt-value-exact').textContent()).toBe(
          `${c.exact.intervalMm.toFixed(4)} mm`,
        );
        expect(await page.getByTestId('chart-tilt-legend').textContent()).toMatch(/^at beta = 0 deg:/);
        // Units in every title.
        expect(await lead.locator('.chart-title').textContent()).toMatch(/^L \[mm\] against lead rho \[deg\]/);
        expect(await page.getByTestId('chart-error').locator('.chart-title').textContent()).toMatch(/\[%\]$/);
        expect(await page.getByTestId('chart-tilt').locator('.chart-title').textContent()).toMatch(
          /^L \[mm\] against tilt beta \[deg\]/,
        );
        // Tall enough to read: the plot area is 280 px high on screen at either width.
        const plot = await lead.locator('.chart-frame').boundingBox();
        expect(plot?.height).toBeGreaterThan(260);
        expect(plot?.height).toBeLessThan(300);
        // Bedi has no answer at small lead: its line stops, and the chart says why.
        const sweep = stepOverSweep(TOOL1, 'one-way', 0.05, 'lead', 0.5, 89, 120, 5);
        const gap = sweep.gaps.bedi[0];
        if (!gap) throw new Error('Bedi should have a gap for Tool 1 at h = 0.05');
        expect(gap.toDeg).toBeGreaterThan(1.3);
        expect(gap.toDeg).toBeLessThan(1.5);
        const edge = formatSignificant(gap.toDeg, { digits: 3, trimZeros: true });
        expect(await page.getByTestId('chart-lead-gaps').textContent()).toBe(
          `No answer from Bedi et al. for rho from about 0.5 to ${edge} deg: h is above the widest point of its ellipse (its height Rlong sin(rho) is below h).`,
        );
        expect(await page.getByTestId('chart-error-gaps').textContent()).toContain('No answer from Bedi et al.');
        expect(await lead.locator('.chart-gap[data-procedure="bedi"] title').textContent()).toMatch(/ellipse/);
        // Follows the theme through the stylesheet (no colours read at draw time).
        expect(
          await lead.locator('.chart-line[data-procedure="exact"]').evaluate((e) => getComputedStyle(e).stroke),
        ).toBe(EXACT_STROKE[theme]);
        await noHorizontalScroll(page);
        await keepShot(chart, `teach-chart-${vp.name}-${theme}`);
        expect(errors).toEqual([]);
      });
    }
  }

  it('highlighting a procedure in the results emphasises its line and dims the others', async () => {
    const { page } = await site.reuse(CHART, { width: 1440, height: 900 });
    const lead = page.getByTestId('chart-lead');
    await lead.locator('.chart-line[data-procedure="bedi"]').waitFor();
    await page.locator('.procedures tr[data-procedure="bedi"]').hover();
    await expect
      .poll(() => lead.locator('.chart-line[data-procedure="bedi"]').getAttribute('class'))
      .toMatch(/chart-focus/);
    expect(await lead.locator('.chart-line[data-procedure="exact"]').getAttribute('class')).toMatch(/chart-dim/);
    const width = (key: string) =>
      lead
        .locator(`.chart-line[data-procedure="${key}"]`)
        .evaluate((e) => Number.parseFloat(getComputedStyle(e).strokeWidth));
    expect(await width('bedi')).toBeGreaterThan(await width('sekine'));
    await keepShot(page.getByTestId('comparison-chart'), 'teach-chart-highlight-bedi');
  });

  it('inside the gap the legend says n/a and points to the reason; the error unit switch changes the title', async () => {
    const { page } = await open('?R=3&Rcr=1&rho=1&h=0.05&unit=mm&view=chart', { width: 1440, height: 900 });
    await expect.poll(() => page.getByTestId('chart-lead-value-bedi').textContent()).toBe('n/a (see below)');
    expect(await page.getByTestId('chart-lead-value-exact').textContent()).toMatch(/^\d+\.\d{4} mm$/);
    await page.getByTestId('chart-error-unit').selectOption('mm');
    await expect.poll(() => page.getByTestId('chart-error').locator('.chart-title').textContent()).toMatch(/\[mm\]$/);
    expect(await page.getByTestId('chart-error-value-sekine').textContent()).toMatch(/^[+-]\d\.\d{4} mm$/);
    await keepShot(page.getByTestId('comparison-chart'), 'teach-chart-rho1-gap');
  });

  it('an error that rounds to zero reads 0.00 in the legend, never -0.00 or +0.00 (mm and inch; issue 17)', async () => {
    // Bedi's error here is -1.1e-14 %, Redonnet's and the osculating circle's +0.0029 %.
    const input = forwardInput(
      { toolRadiusMm: 0.001, cornerRadiusMm: 0, leadAngleDeg: 0.5, tiltAngleDeg: 0 },
      'one-way',
      1e-9,
    );
    const c = compareForward(input);
    for (const unit of ['mm', 'in']) {
      const { page, errors } = await open(`?R=0.001&Rcr=0&rho=0.5&h=1e-9&unit=${unit}&view=chart`, {
        width: 1440,
        height: 900,
      });
      await expect
        .poll(() => page.getByTestId('chart-error-value-bedi').textContent(), { message: unit })
        .toBe('0.00 %');
      expect(await page.getByTestId('chart-error-value-redonnet').textContent(), unit).toBe('0.00 %');
      expect(await page.getByTestId('chart-error-value-osculating').textContent(), unit).toBe('0.00 %');
      const sekine = c.approximations.sekine;
      if (sekine.ok) {
        expect(await page.getByTestId('chart-error-value-sekine').textContent(), unit).toBe(
          `${formatPercent(sekine.deviationPercent)} %`,
        );
      }
      // No text of the page (its legends, ticks, results, SVG labels) reads as a negative zero.
      const texts = await page.evaluate(() => {
        const out: string[] = [];
        const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
        for (let n = walker.nextNode(); n !== null; n = walker.nextNode()) out.push(n.nodeValue ?? '');
        return out;
      });
      expect(texts.length).toBeGreaterThan(100);
      expect(
        texts.filter((t) => /(^|[^\w.])-0(\.0+)?(e[+-]?\d+)?(?![\d.]*[1-9])/.test(t)),
        unit,
      ).toEqual([]);
      expect(errors).toEqual([]);
    }
  });
});

describe('teacher: the step-through', () => {
  const input = forwardInput(TOOL1, 'one-way', 0.1);
  const frames = traceFrames(input).frames;
  const steps = groupSteps(frames, sceneToleranceMm(3), 1);
  const total = steps.length;

  for (const vp of VIEWPORTS) {
    for (const theme of THEMES) {
      it(`${vp.name} ${theme}: one numbering, alike frames merged or explained, an honest d_s / Rcr gauge`, async () => {
        const { page, errors } = await site.reuse(STEPPER, vp, theme);
        const caption = page.getByTestId('stepper-caption');
        const counter = page.getByTestId('stepper-counter');
        // From the first step (a test before on this page may have stepped on).
        await page.getByTestId('stepper-first').click();
        await expect.poll(() => caption.textContent()).toMatch(/^Step 1 of \d+\. Right flank/);
        // One numbering: the caption's step is the counter's, and the paper's are boxes of its Figure 1.
        expect(total).toBeLessThan(frames.length);
        expect(await counter.textContent()).toBe(`step 1 of ${total}`);
        expect(((await caption.textContent()) ?? '').match(/step \d/gi)).toHaveLength(1);
        expect(await caption.textContent()).toContain('Fig. 1, box 2 (Eq. 1)');
        // The gauge: linear from 0, its scale shown, the bar as long as d_s / Rcr says.
        const first = frames[0];
        if (!first || first.dsMm === null) throw new Error('first frame has d_s');
        const gauge = page.getByTestId('stepper-ds');
        expect(await gauge.locator('svg').getAttribute('data-max')).toBe('1.25');
        expect(await gauge.locator('.ds-tick').allTextContents()).toEqual([
          '0',
          '0.25',
          '0.5',
          '0.75',
          '1 = Rcr',
          '1.25',
        ]);
        const bar = await gauge.locator('.ds-bar').boundingBox();
        const track = await gauge.locator('.ds-track').boundingBox();
        if (!bar || !track) throw new Error('gauge not drawn');
        expect(bar.width / track.width).toBeCloseTo(first.dsMm / 1 / 1.25, 2);
        expect(await page.getByTestId('stepper-ds-text').textContent()).toMatch(/^ 0\.95178: d_s = 0\.951778 mm/);
        // Forward through the trace: a merged search step says so, with the counter in step.
        let merged = '';
        for (let k = 2; k <= total && merged === ''; k++) {
          await page.getByTestId('stepper-forward').click();
          await expect.poll(() => counter.textContent()).toBe(`step ${k} of ${total}`);
          const text = (await caption.textContent()) ?? '';
          expect(text.startsWith(`Step ${k} of ${total}. `), text).toBe(true);
          if (/Search passes .* shown as one/.test(text)) merged = text;
        }
        expect(merged).toMatch(/Search passes \d+ to \d+ shown as one \(\d+ passes: each narrows the range further/);
        // The search has no d_s: the gauge says so instead of showing a bar.
        expect(await page.getByTestId('stepper-ds-text').textContent()).toMatch(/no d_s here/);
        expect(await gauge.locator('.ds-bar').getAttribute('width')).toBe('0.00');
        await keepShot(page, `teach-stepper-merged-${vp.name}-${theme}`);
        // The flank's convergence looks like its last search pass: explained.
        await page.getByTestId('stepper-last').click();
        await expect
          .poll(() => caption.textContent())
          .toMatch(new RegExp(`^Step ${total} of ${total}\\. Fig\\. 1, box 26: converged\\.`));
        await page.getByTestId('stepper-back').click();
        await expect
          .poll(() => caption.textContent())
          .toMatch(/Left flank \(-Y\) converged: .*the search has stopped moving/);
        await noHorizontalScroll(page);
        await keepShot(page, `teach-stepper-${vp.name}-${theme}`);
        expect(errors).toEqual([]);
      });
    }
  }

  it('prefers-reduced-motion: Play shows one step per press, says so, and never animates', async () => {
    // A page of its own, on Playwright's clock: time flows as usual, and `runFor` fires at once
    // every timer due within a stretch of time instead of the test waiting it out.
    const page = await site.browser().newPage({ viewport: { width: 1440, height: 900 } });
    await holdScene(page); // the file looks at no part of the scene
    await page.clock.install();
    await page.goto(`${site.url()}${STEPPER}`);
    const counter = page.getByTestId('stepper-counter');
    const note = page.getByTestId('stepper-motion-note');
    await expect.poll(() => counter.textContent()).toBe(`step 1 of ${total}`);
    expect(await note.isVisible()).toBe(false);
    await page.emulateMedia({ reducedMotion: 'reduce' });
    await expect.poll(() => note.isVisible()).toBe(true);
    expect(await page.getByTestId('stepper-play').textContent()).toBe('Play (one step)');
    await page.getByTestId('stepper-play').click();
    await expect.poll(() => counter.textContent()).toBe(`step 2 of ${total}`);
    // Every timer of the next 2.1 s fires: an animation (700 ms a step) would move on 3 steps.
    await page.clock.runFor(2100);
    expect(await counter.textContent()).toBe(`step 2 of ${total}`);
    await keepShot(page, 'teach-stepper-reduced-motion');
    // Back to full motion: Play animates again.
    await page.emulateMedia({ reducedMotion: 'no-preference' });
    await expect.poll(() => note.isVisible()).toBe(false);
    await page.getByTestId('stepper-play').click();
    await page.clock.runFor(2100);
    await expect.poll(() => counter.textContent()).toMatch(/^step [4-9]/);
    await page.close();
  });
});
