/**
 * The calculator in real headless Chromium (Debian's), against the built site served from
 * a sub-path. Screenshots go to test-results/ as artifacts of the run.
 */
import { spawnSync } from 'node:child_process';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { compareForward, compareInverse, forwardInput, inverseInput } from '../../src/core/index';
import { formatLenUnit } from '../../src/ui/format';
import {
  animationFrames,
  frames,
  keepShot,
  namedWorker,
  paintedFraction,
  ROOT,
  SOLVER,
  useSite,
  VIEWS_WORKER,
  workerIdle,
} from './harness';

const site = useSite('docs/tools/path-interval');
const open = site.open;
/** The plain state, on one load for the tests that read it (the last of them changes it). */
const PLAIN = '?R=3&Rcr=1&rho=5&h=0.05&unit=mm';

const text = async (page: Page, id: string) => (await page.getByTestId(id).textContent())?.trim() ?? '';

describe('calculator page in headless Chromium', () => {
  it('loads from a sub-path, solves in a module worker, and shows the command line numbers', async () => {
    const { page, errors } = await site.reuse(PLAIN);
    const cli = spawnSync(
      process.execPath,
      [`${ROOT}src/cli/bin.mjs`, '--R', '3', '--Rcr', '1', '--rho', '5', '--h', '0.05', '--json'],
      {
        encoding: 'utf8',
      },
    );
    const out = JSON.parse(cli.stdout);
    expect(await text(page, 'result-exact-half')).toBe(`${out.exact.halfInterval.toFixed(4)} mm`);
    expect(await text(page, 'result-sekine-half')).toBe(`${out.sekine.halfInterval.toFixed(4)} mm`);
    expect(await text(page, 'result-redonnet-half')).toBe(`${out.redonnet.halfInterval.toFixed(4)} mm`);
    expect(await text(page, 'result-bedi-half')).toBe(`${out.bedi.halfInterval.toFixed(4)} mm`);
    expect(await text(page, 'result-exact-interval')).toBe(`${out.exact.interval.toFixed(4)} mm`);
    const workers = page.workers().map((w) => w.url());
    expect(workers.some((u) => u.startsWith(site.url()) && /solver\.worker/.test(u))).toBe(true);
    expect(errors).toEqual([]);
    await keepShot(page, 'calculator');
  });

  it('the mouse turns and zooms the scene (src/render/orbit.ts)', async () => {
    // The page of the test before (it changed nothing): the camera is no input.
    const { page } = await site.reuse(PLAIN);
    await expect.poll(() => frames(page)).toBeGreaterThan(0);
    const canvas = page.getByTestId('scene-canvas');
    const box = await canvas.boundingBox();
    if (box === null) throw new Error('no scene');
    const before = await canvas.screenshot();
    const framesBefore = await frames(page);
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 10, { steps: 4 });
    await page.mouse.up();
    await expect.poll(() => frames(page)).toBeGreaterThan(framesBefore);
    const turned = await canvas.screenshot();
    expect(turned.equals(before)).toBe(false);
    const framesTurned = await frames(page);
    await page.mouse.wheel(0, 300);
    await expect.poll(() => frames(page)).toBeGreaterThan(framesTurned);
    expect((await canvas.screenshot()).equals(turned)).toBe(false);
    // The page did not scroll under the wheel over the scene.
    expect(await page.evaluate(() => window.scrollY)).toBe(0);
  });

  it('moving a slider by keyboard updates the numbers, the URL and the scene', async () => {
    const { page } = await site.reuse(PLAIN);
    site.changed();
    const before = await text(page, 'result-exact-half');
    const framesBefore = await frames(page);
    await page.getByTestId('slider-rho').focus();
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('ArrowRight');
    await expect.poll(() => page.getByTestId('input-rho').inputValue()).toBe('5.2');
    const expected = compareForward(
      forwardInput({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5.2, tiltAngleDeg: 0 }, 'one-way', 0.05),
    );
    await expect.poll(() => text(page, 'result-exact-half')).toBe(`${expected.exact.halfIntervalMm.toFixed(4)} mm`);
    expect(await text(page, 'result-exact-half')).not.toBe(before);
    await expect.poll(() => new URL(page.url()).searchParams.get('rho')).toBe('5.2');
    await expect.poll(() => frames(page)).toBeGreaterThan(framesBefore);
  });

  it('draws the scene (the canvas is not blank) and renders only when something changed', async () => {
    const { page } = await open('');
    await page.waitForFunction(
      () => (window as unknown as { __pathInterval: { frames(): number } }).__pathInterval.frames() > 0,
    );
    expect(await paintedFraction(page)).toBeGreaterThan(0.05);
    // Headless Chromium rasterises WebGL with SwiftShader: the scene must see that and drop
    // multisampling, which on software tripled the input-to-frame time.
    expect(
      await page.evaluate(() =>
        (window as unknown as { __pathInterval: { softwareRendering(): boolean } }).__pathInterval.softwareRendering(),
      ),
    ).toBe(true);
    // Let the lazy teaching views load and draw their first data: nothing in the scene changes then.
    await page.getByTestId('profile-view').locator('polygon.scallop').waitFor();
    const before = await frames(page);
    // Both workers have answered everything, then 10 animation frames pass (a busy render loop
    // would draw in each) with nothing new to draw.
    await workerIdle(page, SOLVER);
    await workerIdle(page, VIEWS_WORKER);
    await animationFrames(page, 10);
    expect(await frames(page)).toBe(before); // no busy render loop
    // Switching between teaching views that do not touch the 3D scene draws no frame either.
    await page.getByRole('tab', { name: 'L against lead and tilt' }).click();
    await page.getByTestId('comparison-chart').locator('svg.chart-svg').first().waitFor();
    await page.getByRole('tab', { name: 'Formulas' }).click();
    await page.getByTestId('formulas').locator('math').first().waitFor();
    // Each view's data answered (the chart's and the formulas'), then frames enough to draw any change.
    await workerIdle(page, VIEWS_WORKER);
    await animationFrames(page, 5);
    expect(await frames(page)).toBe(before);
    await page.getByRole('button', { name: 'Along the feed' }).click();
    await page.waitForFunction(
      (n) => (window as unknown as { __pathInterval: { frames(): number } }).__pathInterval.frames() > n,
      before,
    );
    await keepShot(page, 'along-the-feed');
  });

  it('invalid input shows an alert naming the constraint, dashes instead of NaN, and keeps the other values', async () => {
    const { page, errors } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    await page.getByTestId('input-Rcr').fill('4');
    const alert = page.locator('[data-field="Rcr"] [role="alert"]');
    await expect.poll(() => alert.textContent()).toMatch(/must not exceed the tool radius R = 3 mm/);
    expect(await text(page, 'result-exact-half')).toBe('\u2014');
    expect(await page.locator('body').textContent()).not.toMatch(/NaN/);
    expect(await page.getByTestId('input-R').inputValue()).toBe('3');
    expect(await page.getByTestId('input-h').inputValue()).toBe('0.05');
    expect(await page.getByTestId('scene').getAttribute('class')).toMatch(/stale/);
    await keepShot(page, 'invalid-rcr');
    await page.getByTestId('input-Rcr').fill('1');
    await page.getByTestId('input-h').fill('5');
    await expect
      .poll(() => page.locator('[data-field="h"] [role="alert"]').textContent())
      .toMatch(/wall, not a scallop/);
    await page.getByTestId('input-Rcr').fill('abc');
    await expect
      .poll(() => page.locator('[data-field="Rcr"] [role="alert"]').textContent())
      .toMatch(/must be a number/);
    // Fixing the fields brings the results back.
    await page.getByTestId('input-Rcr').fill('1');
    await page.getByTestId('input-h').fill('0.05');
    await expect.poll(() => text(page, 'result-exact-half')).toBe('1.4436 mm'); // notes' exact column: 1.443592
    expect(await page.getByTestId('scene').getAttribute('class')).not.toMatch(/stale/);
    expect(errors).toEqual([]);
  });

  it('the URL holds the state: round trip, unit switch, and bad values fall back with a notice', async () => {
    site.noScene();
    const { page } = await open('?R=6&Rcr=2&rho=10&h=0.1&unit=mm');
    expect(await text(page, 'result-exact-half')).toBe('2.1690 mm'); // notes' exact column: 2.168977
    const historyAtLoad = await page.evaluate(() => window.history.length);
    await page.locator('input[name="unit"][value="in"]').check();
    await expect.poll(() => new URL(page.url()).searchParams.get('unit')).toBe('in');
    const url = page.url();
    // R = 6 mm from the link (not the default): converted without loss (issue 28 point 11).
    expect(new URL(url).searchParams.get('R')).toBe('0.236220472441');
    // 2.16898 mm = 0.08539 in, shown with 5 decimals.
    await expect.poll(() => text(page, 'result-exact-half')).toMatch(/^0\.0853\d in$/);
    const inches = await text(page, 'result-exact-half');
    expect(Math.abs(Number.parseFloat(inches) * 25.4 - 2.16898)).toBeLessThan(2e-4);
    const historyLength = await page.evaluate(() => window.history.length);
    const again = await site.browser().newPage();
    await again.goto(url);
    await again.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    expect(await text(again, 'result-exact-half')).toBe(inches);
    expect(await again.getByTestId('input-R').inputValue()).toBe('0.236220472441');
    expect(historyLength).toBe(historyAtLoad); // replaceState: no history entries added
    await again.goto(`${site.url()}?R=abc&Rcr=1&rho=5`);
    await again.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    const notice = again.getByTestId('notice');
    expect(await notice.isVisible()).toBe(true);
    expect(await notice.textContent()).toMatch(/R="abc".*not a number.*h is missing/);
    expect(await again.getByTestId('input-R').inputValue()).toBe('3');
    await again.close();
  });

  it('embed mode fits 480x360 without horizontal scrolling and links to the full calculator', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=20&h=0.3&unit=mm&embed=1', { width: 480, height: 360 });
    const size = await page.evaluate(() => [
      document.documentElement.scrollWidth,
      document.documentElement.clientWidth,
    ]);
    expect(size[0]).toBeLessThanOrEqual(size[1] as number);
    expect(await page.locator('.chrome').isVisible()).toBe(false);
    const link = page.getByTestId('open-full');
    expect(await link.isVisible()).toBe(true);
    const href = new URL((await link.getAttribute('href')) ?? '', page.url());
    expect(href.searchParams.get('embed')).toBeNull();
    expect(href.searchParams.get('rho')).toBe('20');
    await keepShot(page, 'embed-480x360');
  });

  it('solve for scallop height: the inverse mode takes L and shows each procedure h', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    await page.locator('input[name="mode"][value="inverse"]').check();
    await page.getByTestId('input-L').fill('3');
    const expected = compareInverse(
      inverseInput({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way', 3),
    );
    await expect
      .poll(() => text(page, 'table-exact-h'))
      .toBe(formatLenUnit(expected.exact.cuspHeightMm, 'mm', 'height'));
    const bedi = expected.approximations.bedi;
    expect(bedi.ok).toBe(true);
    if (bedi.ok) expect(await text(page, 'result-bedi-h')).toBe(formatLenUnit(bedi.scallopHeightMm, 'mm', 'height'));
    await expect.poll(() => new URL(page.url()).searchParams.get('L')).toBe('3');
    expect(new URL(page.url()).searchParams.get('mode')).toBe('inverse');
    // A step-over wider than the tool is named in terms of L, the field the user typed.
    await page.getByTestId('input-L').fill('7');
    await expect
      .poll(() => page.locator('[data-field="L"] [role="alert"]').textContent())
      .toMatch(/Step-over L must be below the tool diameter 2R = 6 mm \(got 7\)/);
  });

  it('a worker that dies is restarted, the request repeated, and the page says so', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    // The test kills the solver's worker itself (the page has no hook for it): close() from inside.
    const solver = await namedWorker(page, SOLVER);
    const closed = new Promise((resolve) => solver.once('close', resolve));
    void solver.evaluate(() => (globalThis as unknown as { close(): void }).close()).catch(() => undefined);
    await closed;
    await page.getByTestId('input-h').fill('0.1');
    await expect.poll(() => text(page, 'result-exact-half')).toBe('1.8921 mm'); // notes: 1.892088
    expect(await page.getByTestId('notice').textContent()).toMatch(/solver was restarted/);
    const starts = await page.evaluate(() =>
      (window as unknown as { __pathInterval: { workerStarts(): number } }).__pathInterval.workerStarts(),
    );
    expect(starts).toBe(2);
  });

  it('a burst of slider moves ends on the latest value (stale replies dropped)', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    const halfAt = (h: number) =>
      `${compareForward(
        forwardInput({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way', h),
      ).exact.halfIntervalMm.toFixed(4)} mm`;
    const final = halfAt(0.08);
    // Every number the page writes into L/2 from now on, in order, with the field's value and
    // whether the results were marked stale at that moment.
    await page.evaluate(() => {
      const out = document.querySelector('[data-testid="result-exact-half"]') as HTMLElement;
      const field = document.querySelector('[data-testid="input-h"]') as HTMLInputElement;
      const section = document.querySelector('section.results') as HTMLElement;
      const seen: { text: string; h: string; stale: boolean }[] = [];
      (window as unknown as { __seen: typeof seen }).__seen = seen;
      new MutationObserver(() =>
        seen.push({ text: out.textContent ?? '', h: field.value, stale: section.classList.contains('stale') }),
      ).observe(out, { childList: true, characterData: true, subtree: true });
    });
    // The solver is busy while the slider moves, so the replies lag behind the inputs: a page
    // that showed stale replies would show older values after the last move.
    const solver = await namedWorker(page, SOLVER);
    void solver.evaluate(() => {
      const end = Date.now() + 800;
      while (Date.now() < end);
    });
    await page.getByTestId('slider-h').focus();
    for (let i = 0; i < 30; i++) await page.keyboard.press('ArrowRight');
    await expect.poll(() => page.getByTestId('input-h').inputValue()).toBe('0.08');
    await expect.poll(() => text(page, 'result-exact-half')).toBe(final);
    // Every request of the burst answered: no late reply can come after this.
    await workerIdle(page, SOLVER);
    type Seen = { text: string; h: string; stale: boolean };
    const seen = await page.evaluate(() => (window as unknown as { __seen: Seen[] }).__seen);
    // From the moment the field holds the last value, the only number written is its answer.
    const afterLastMove = seen.findIndex((s) => s.h === '0.08');
    expect(afterLastMove).toBeGreaterThanOrEqual(0);
    expect(
      seen
        .slice(afterLastMove)
        .filter((s) => /\d/.test(s.text))
        .map((s) => s.text),
    ).toEqual([final]);
    // Throughout the burst, a number not marked stale is the answer to the value in the field.
    const current = seen.filter((s) => !s.stale && /\d/.test(s.text));
    expect(current.length).toBeGreaterThan(0);
    for (const s of current) expect(s.text, `h = ${s.h}`).toBe(halfAt(Number(s.h)));
  });

  it('the machine is the first choice, beside the unit, remembered for the next bare visit; a link keeps its meaning', async () => {
    // A context of its own: its storage is the user's, kept across its loads.
    const context = await site.browser().newContext({ viewport: { width: 1280, height: 800 } });
    try {
      const page = await context.newPage();
      const checked = (name: string) => page.locator(`input[name="${name}"]:checked`).getAttribute('value');
      const ready = () =>
        page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
      await page.goto(site.url());
      await ready();
      // First visit: the teacher's default, five-axis in mm.
      expect([await checked('machine'), await checked('unit')]).toEqual(['5axis', 'mm']);
      // The machine switch comes first in the form, in the same row as the unit.
      const [machineBox, unitBox] = await Promise.all(
        ['machine-switch', 'unit-switch'].map((id) => page.getByTestId(id).boundingBox()),
      );
      if (!machineBox || !unitBox) throw new Error('no switches');
      expect(Math.abs(machineBox.y - unitBox.y)).toBeLessThan(machineBox.height);
      expect(machineBox.x).toBeLessThan(unitBox.x);
      await page.getByTestId('machine-switch').getByText('3-axis').click();
      await page.getByTestId('unit-switch').getByText('inch').click();
      await expect.poll(() => page.evaluate(() => window.location.search)).toMatch(/machine=3axis.*unit=in/);
      // The next bare visit starts where the shop left.
      await page.goto(site.url());
      await ready();
      expect([await checked('machine'), await checked('unit')]).toEqual(['3axis', 'in']);
      // Every answer names its question: under the headline, and in the result bar that mirrors it.
      const question = () => page.getByTestId('headline-question').textContent();
      await expect.poll(question).toBe('3-axis, slope 30°, raster 0°');
      expect(await page.getByTestId('result-bar-question').textContent()).toBe('3-axis, slope 30°, raster 0°');
      // A shared five-axis link (no machine=, no unit=) still means five-axis in mm.
      await page.goto(`${site.url()}${PLAIN}`);
      await ready();
      expect([await checked('machine'), await checked('unit')]).toEqual(['5axis', 'mm']);
      await expect.poll(question).toBe('5-axis, lead 5°, tilt 0°, one-way, plane');
      // An invalid input: no answer, so no words (they never stand beside a dash or an old number).
      await page.getByTestId('input-h').fill('-1');
      await page.getByTestId('input-h').press('Enter');
      const hiddenAttr = (id: string) => page.getByTestId(id).evaluate((e) => (e as HTMLElement).hidden);
      await expect.poll(() => hiddenAttr('headline-question')).toBe(true);
      expect(await hiddenAttr('result-bar-question')).toBe(true);
    } finally {
      await context.close();
    }
  });
});
