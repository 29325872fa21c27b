/**
 * The teaching views in real headless Chromium against the built site: each renders real
 * content, follows a slider change, and shows the solver's numbers. Screenshots are kept.
 */
import { describe, expect, it } from 'vitest';
import { compareForward, exactHalfIntervalMm, exactScallopHeightMm, traceProcedure } from '../../src/core/index';
import { autoExaggeration } from '../../src/core/output/drawingScale';
import { sekineModel } from '../../src/core/procedures/approximations';
import { PAPER_CONDITIONS } from '../../src/core/procedures/paper';
import { keepShot, showView, useSite } from './harness';

const site = useSite('docs/views');
const { open } = site;
/** The plain state, read on one load by the formulas and the highlighting tests (their views by tabs). */
const PLAIN = '?R=3&Rcr=1&rho=5&h=0.05&unit=mm';

const tool = (rho: number, h: number) => ({
  toolRadiusMm: 3,
  cornerRadiusMm: 1,
  leadAngleDeg: rho,
  tiltAngleDeg: 0,
  pattern: 'one-way' as const,
  surface: { kind: 'plane' as const },
  scallopHeightMm: h,
});

describe('teaching views in headless Chromium', () => {
  it('profile: three passes with the scallops shaded, the approximations overlaid, dimensions, zoom and reset', async () => {
    site.noScene();
    const { page, errors } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=profile');
    const view = page.getByTestId('profile-view');
    await view.locator('polygon.scallop').waitFor();
    // The exact profile once per pass; each approximation on both sides of each pass.
    expect(await view.locator('polyline.curve-exact').count()).toBe(3);
    for (const key of ['sekine', 'redonnet', 'bedi', 'osculating', 'cornerBall'])
      expect(await view.locator(`polyline.curve-${key}`).count()).toBe(6);
    const half = exactHalfIntervalMm(tool(5, 0.05)).toFixed(4);
    await expect.poll(() => view.locator('text.dim-text').allTextContents()).toContain(`L/2 = ${half} mm`);
    expect(await page.getByTestId('profile-scale').textContent()).toMatch(/vertical scale exaggerated x5/);
    const home = await view.locator('svg').getAttribute('viewBox');
    await page.getByTestId('profile-cusp').click();
    const zoomed = await view.locator('svg').getAttribute('viewBox');
    expect(zoomed).not.toBe(home);
    await keepShot(page, 'view-profile-cusp');
    await page.getByTestId('profile-reset').click();
    expect(await view.locator('svg').getAttribute('viewBox')).toBe(home);
    // Follows a slider change.
    const scallopBefore = await view.locator('polygon.scallop').getAttribute('points');
    await page.getByTestId('slider-h').focus();
    await page.keyboard.press('ArrowRight');
    const half2 = exactHalfIntervalMm(tool(5, 0.051)).toFixed(4);
    await expect.poll(() => view.locator('text.dim-text').allTextContents()).toContain(`L/2 = ${half2} mm`);
    expect(await view.locator('polygon.scallop').getAttribute('points')).not.toBe(scallopBefore);
    // A tiny scallop: "auto" exaggerates more, and says so; a fixed choice overrides it.
    await page.getByTestId('input-h').fill('0.005');
    const smallHalf = exactHalfIntervalMm(tool(5, 0.005));
    const k = autoExaggeration(2 * smallHalf + 0.4 * 3, 4 * 0.005);
    expect(k).toBeGreaterThan(5);
    await expect
      .poll(() => page.getByTestId('profile-scale').textContent())
      .toBe(`vertical scale exaggerated x${k} (auto)`);
    await page.getByTestId('profile-exaggeration').selectOption('1');
    await expect.poll(() => page.getByTestId('profile-scale').textContent()).toBe('true scale');
    expect(errors).toEqual([]);
  });

  it('chart: L against rho, the signed errors and L against tilt, with the values at the current posture from the solver', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=chart');
    const chart = page.getByTestId('comparison-chart');
    await chart.locator('svg.chart-svg').first().waitFor();
    expect(await chart.locator('svg.chart-svg').count()).toBe(3);
    const c = compareForward(tool(5, 0.05));
    const summary = page.getByTestId('chart-summary');
    await expect
      .poll(() => summary.textContent())
      .toMatch(new RegExp(`Exact \\(3D\\) ${c.exact.intervalMm.toFixed(4)} mm`));
    if (c.approximations.sekine.ok)
      expect(await summary.textContent()).toContain(
        `Sekine et al. ${c.approximations.sekine.intervalMm.toFixed(4)} mm`,
      );
    await page.getByTestId('slider-rho').focus();
    await page.keyboard.press('ArrowRight');
    const c2 = compareForward(tool(5.1, 0.05));
    await expect
      .poll(() => summary.textContent())
      .toMatch(new RegExp(`rho = 5\\.1 deg.*Exact \\(3D\\) ${c2.exact.intervalMm.toFixed(4)} mm`));
    expect(await chart.locator('.chart-title').first().textContent()).toMatch(/current rho = 5\.1/);
    // The dashed current-rho marker: on the default log axis 5.1 deg sits near the middle of
    // 0.5-89 deg (log ratio 0.45); on a linear axis near the left edge (0.05).
    const markerAt = () =>
      page.evaluate(() => {
        const marker = document.querySelector('[data-testid="chart-lead"] .chart-marker')?.getBoundingClientRect();
        const frame = document.querySelector('[data-testid="chart-lead"] .chart-frame')?.getBoundingClientRect();
        if (!marker || !frame) return -1;
        return (marker.left + marker.width / 2 - frame.left) / frame.width;
      });
    await expect.poll(markerAt).toBeGreaterThan(0.35);
    await page.getByTestId('chart-rho-axis').selectOption('linear');
    await expect.poll(markerAt).toBeLessThan(0.2);
    await keepShot(page, 'view-chart');
  });

  it('tables: printed and recomputed values of Tables 2-5, the 3D deviations highlighted, a click loads a condition', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=tables');
    const tables = page.getByTestId('paper-tables');
    await tables.locator('table').first().waitFor();
    const c = PAPER_CONDITIONS[1];
    if (!c) throw new Error('missing condition');
    const cell = page.getByTestId('paper-half-1-exact');
    expect(await cell.locator('.printed').textContent()).toBe(c.printedHalf.threeD.toFixed(3));
    expect(await cell.locator('.computed').textContent()).toBe(exactHalfIntervalMm(tool(5, 0.1)).toFixed(4));
    expect(await cell.getAttribute('class')).toMatch(/deviates/);
    expect(await page.getByTestId('paper-half-1-bedi').getAttribute('class')).not.toMatch(/deviates/);
    expect(await page.getByTestId('paper-height-1-sekine').locator('.printed').textContent()).toBe(
      c.printedHeight.sekine.toFixed(3),
    );
    await keepShot(page, 'view-tables');
    await tables.locator('tr[data-condition="6"]').first().click();
    await expect.poll(() => page.getByTestId('input-R').inputValue()).toBe('6');
    expect(await page.getByTestId('input-rho').inputValue()).toBe('10');
    expect(await page.getByTestId('input-h').inputValue()).toBe('0.05');
    await expect.poll(() => page.getByTestId('result-exact-half').textContent()).toBe('1.5580 mm'); // notes' exact column: 1.558019
  });

  it('stepper: steps through the trace in the scene and reaches the converged P_hp', async () => {
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.1&unit=mm&view=stepper');
    const caption = page.getByTestId('stepper-caption');
    await expect
      .poll(() => caption.textContent())
      .toMatch(/^Step 1 of \d+\. Right flank \(\+Y\)\. Fig\. 1, box 2 \(Eq\. 1\)/);
    const frames = () =>
      page.evaluate(() => (window as unknown as { __pathInterval: { frames(): number } }).__pathInterval.frames());
    const before = await frames();
    await page.getByTestId('stepper-forward').click();
    await expect.poll(() => page.getByTestId('stepper-counter').textContent()).toMatch(/^step 2 of \d+/);
    await expect.poll(frames).toBeGreaterThan(before);
    await page.getByTestId('stepper-back').click();
    await expect.poll(() => page.getByTestId('stepper-counter').textContent()).toMatch(/^step 1 of/);
    await page.getByTestId('stepper-last').click();
    const trace = traceProcedure(tool(5, 0.1));
    await expect.poll(() => caption.textContent()).toContain(`converged. L/2 = ${trace.right.widthMm.toFixed(6)} mm`);
    expect(await caption.textContent()).toContain(
      `exact solver gives ${exactHalfIntervalMm(tool(5, 0.1)).toFixed(6)} mm`,
    );
    await keepShot(page, 'view-stepper-converged');
    // Play runs through the steps by itself.
    await page.getByTestId('stepper-first').click();
    await page.getByTestId('stepper-play').click();
    await expect.poll(() => page.getByTestId('stepper-counter').textContent()).toMatch(/^step [3-9]/);
    await page.getByTestId('stepper-play').click();
  });

  it('formulas: typeset equations with the current numbers substituted', async () => {
    const { page } = await site.reuse(PLAIN);
    await showView(page, 'formulas');
    const formulas = page.getByTestId('formulas');
    await formulas.locator('math').first().waitFor();
    expect(await formulas.locator('math').count()).toBeGreaterThan(8);
    const reff = sekineModel(tool(5, 0.05));
    if (!reff.ok) throw new Error('applicable');
    expect(await formulas.locator('section[data-procedure="sekine"]').textContent()).toContain(
      String(Number(reff.effectiveRadiusMm.toPrecision(5))),
    );
    expect(await formulas.textContent()).toMatch(/osculating circle/i);
    expect(await formulas.textContent()).not.toMatch(/NaN|\{\{|\\/);
    await keepShot(page, 'view-formulas', { fullPage: true });
  });

  it('hovering or selecting a procedure highlights it in the profile and the results table', async () => {
    const { page } = await site.reuse(PLAIN);
    await showView(page, 'profile');
    await page.getByTestId('profile-view').locator('polyline.curve-bedi').first().waitFor();
    await page.locator('.procedures tr[data-procedure="bedi"]').hover();
    await expect.poll(() => page.locator('polyline.curve-sekine').first().getAttribute('class')).toMatch(/dimmed/);
    expect(await page.locator('polyline.curve-bedi').first().getAttribute('class')).not.toMatch(/dimmed/);
    expect(await page.locator('.procedures tr[data-procedure="bedi"]').getAttribute('class')).toMatch(/emph/);
    // Selecting (click) keeps the highlight when the pointer leaves.
    await page.locator('.procedures tr[data-procedure="redonnet"]').click();
    await page.getByTestId('input-R').hover();
    await expect.poll(() => page.locator('polyline.curve-bedi').first().getAttribute('class')).toMatch(/dimmed/);
    expect(await page.locator('polyline.curve-redonnet').first().getAttribute('class')).not.toMatch(/dimmed/);
    expect(await page.locator('.procedures tr[data-procedure="redonnet"]').getAttribute('class')).toMatch(/selected/);
  });

  it('formulas in inverse mode give each procedure its L/2 at the solved h, not the height', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&L=3&mode=inverse&unit=mm&view=formulas');
    const sekine = page.getByTestId('formulas').locator('section[data-procedure="sekine"]');
    await sekine.locator('math').first().waitFor();
    const h = exactScallopHeightMm({ ...tool(5, 0), intervalMm: 3 });
    const c = compareForward(tool(5, h));
    if (!c.approximations.sekine.ok) throw new Error('applicable');
    const last = sekine.locator('math').last();
    await expect
      .poll(() => last.textContent())
      .toMatch(new RegExp(`=${String(Number(c.approximations.sekine.halfIntervalMm.toPrecision(5)))} mm$`));
    expect(
      await page.getByTestId('formulas').locator('section[data-procedure="exact"] math').last().textContent(),
    ).toMatch(/=1\.5 mm$/);
  });

  it('?view=profile&embed=1 shows just that view, without horizontal scrolling at 480x360', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&embed=1&view=profile', { width: 480, height: 360 });
    await page.getByTestId('profile-view').locator('polygon.scallop').waitFor();
    expect(await page.getByTestId('profile-view').isVisible()).toBe(true);
    expect(await page.getByTestId('input-R').isVisible()).toBe(false);
    const [scroll, client] = await page.evaluate(() => [
      document.documentElement.scrollWidth,
      document.documentElement.clientWidth,
    ]);
    expect(scroll).toBeLessThanOrEqual(client as number);
    await keepShot(page, 'embed-profile');
  });
});
