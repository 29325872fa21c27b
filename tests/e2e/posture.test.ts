/**
 * Any tool posture on the page (issue 9): the tilt slider and field, the pass pattern switch,
 * both in the URL; the flank widths, the contact offset and both cusp heights; the new rows; the
 * views following the posture. Numbers are checked against the solver core.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import {
  compareForward,
  exactForward,
  forwardInput,
  osculatingModel,
  type PassPattern,
  shapeOfTool,
  type ToolInput,
  traceProcedure,
} from '../../src/core/index';
import { formatLenUnit } from '../../src/ui/format';
import { frames, keepShot, sceneIdle, showView, urlWrites, useSite } from './harness';

const site = useSite('docs/posture');
const { open } = site;

const text = async (page: Page, id: string) => (await page.getByTestId(id).textContent())?.trim() ?? '';
const tool = (tilt: number, rho = 5): ToolInput => ({
  toolRadiusMm: 3,
  cornerRadiusMm: 1,
  leadAngleDeg: rho,
  tiltAngleDeg: tilt,
});
const exact = (tilt: number, pattern: PassPattern, h = 0.05) => exactForward(forwardInput(tool(tilt), pattern, h));
const mm = (v: number) => `${v.toFixed(4)} mm`;
const signed = (v: number) => `${v > 0 ? '+' : ''}${v.toFixed(4)} mm`;

/** The states several tests read, each on one load (the views by their tabs). */
const TILT5 = '?R=3&Rcr=1&rho=5&tilt=5&h=0.05&unit=mm';
const ZIGZAG10 = '?R=3&Rcr=1&rho=5&tilt=10&pattern=zigzag&h=0.05&unit=mm';

describe('tool posture on the page', () => {
  it('defaults give the paper case: no tilt, one-way, nothing new in the URL, the same numbers', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    expect(await page.getByTestId('input-tilt').inputValue()).toBe('0');
    expect(await page.locator('[data-testid="pattern-switch"] input[value="one-way"]').isChecked()).toBe(true);
    expect(await text(page, 'result-exact-half')).toBe('1.4436 mm');
    expect(await text(page, 'result-width-right')).toBe('1.4436 mm');
    expect(await text(page, 'result-width-left')).toBe('1.4436 mm');
    expect(await text(page, 'result-contact-offset')).toBe('0.0000 mm');
    expect(await page.getByTestId('result-cusp-height').isVisible()).toBe(false);
    // The URL is written once the inputs settle (urlState.ts): wait for that write.
    await expect.poll(() => urlWrites(page)).toBeGreaterThan(0);
    const url = new URL(page.url());
    expect(url.searchParams.has('tilt')).toBe(false);
    expect(url.searchParams.has('pattern')).toBe(false);
  });

  it('the tilt field and slider: L, wR, wL and y0 of the exact solver; in the URL; arrow keys step 0.1 deg', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    await page.getByTestId('input-tilt').fill('5');
    const e = exact(5, 'one-way');
    // Issue 9's figure: L = 1.8789 mm at lead 5, tilt 5 (2.8872 without tilt).
    await expect.poll(() => text(page, 'result-exact-interval')).toBe('1.8789 mm');
    expect(await text(page, 'result-width-right')).toBe(mm(e.halfWidthRightMm));
    expect(await text(page, 'result-width-left')).toBe(mm(e.halfWidthLeftMm));
    expect(await text(page, 'result-contact-offset')).toBe(signed(e.contactOffsetMm));
    expect(await text(page, 'result-centre-offset')).toBe(signed(-e.contactOffsetMm));
    expect(e.halfWidthRightMm).not.toBeCloseTo(e.halfWidthLeftMm, 3);
    await expect.poll(() => new URL(page.url()).searchParams.get('tilt')).toBe('5');
    expect(await page.getByTestId('slider-tilt').inputValue()).toBe('5');
    await page.getByTestId('slider-tilt').focus();
    await page.keyboard.press('ArrowRight');
    await expect.poll(() => page.getByTestId('input-tilt').inputValue()).toBe('5.1');
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(mm(exact(5.1, 'one-way').intervalMm));
    // A tilt out of range names its limits.
    await page.getByTestId('input-tilt').fill('95');
    await expect
      .poll(() => page.getByTestId('error-tilt').textContent())
      .toMatch(/Tilt angle beta must be above -90 and below 90 degrees \(got 95\)/);
    expect(await text(page, 'result-exact-interval')).toBe('\u2014');
  });

  it('the pattern switch: zigzag gives L = 2 min(wR, wL) and both cusp heights; in the URL', async () => {
    const { page } = await open('?R=3&Rcr=1&rho=5&tilt=10&h=0.05&unit=mm');
    await page.locator('[data-testid="pattern-switch"] input[value="zigzag"]').check();
    const e = exact(10, 'zigzag');
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(mm(e.intervalMm));
    expect(e.intervalMm).toBeCloseTo(2 * Math.min(e.halfWidthRightMm, e.halfWidthLeftMm), 12);
    expect(await page.getByTestId('result-cusp-height').isVisible()).toBe(true);
    // Heights below 0.1 mm read in um (format.ts), at the same 0.01 um resolution.
    expect(await text(page, 'result-cusp-height')).toBe('50.00 \u00b5m');
    expect(await text(page, 'result-other-cusp-height')).toBe(
      `${(1000 * (e.otherCuspHeightMm ?? 0)).toFixed(2)} \u00b5m`,
    );
    await expect.poll(() => new URL(page.url()).searchParams.get('pattern')).toBe('zigzag');
    // The URL opens the same state.
    const again = await site.browser().newPage();
    await again.goto(page.url());
    await again.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    expect(await text(again, 'result-exact-interval')).toBe(mm(e.intervalMm));
    expect(await again.locator('[data-testid="pattern-switch"] input[value="zigzag"]').isChecked()).toBe(true);
    await again.close();
    await keepShot(page, 'posture-zigzag');
  });

  it('the 3D scene: tilted tool, its axis and centre O off the contact, cusp sections on both sides, L and y0', async () => {
    const { page } = await site.reuse(ZIGZAG10);
    const labels = () =>
      page
        .locator('.scene-labels .scene-label')
        .evaluateAll((els) =>
          els.filter((e) => (e.parentElement as HTMLElement).style.display !== 'none').map((e) => e.textContent),
        );
    const e = exact(10, 'zigzag');
    await expect.poll(labels).toEqual(expect.arrayContaining(['P_hp R', 'P_hp L', 'O', 'CC (P_base)']));
    expect(await labels()).toContain(`L = ${mm(e.intervalMm)}`);
    expect(await labels(), JSON.stringify(await labels())).toContain(`y0 = ${signed(e.contactOffsetMm)}`);
    await sceneIdle(page);
    const before = await frames(page);
    await page.getByRole('button', { name: 'Along the feed' }).click();
    await expect.poll(() => frames(page)).toBeGreaterThan(before);
    await sceneIdle(page);
    await keepShot(page.getByTestId('scene'), 'posture-scene-feed');
  });

  it('the formulas follow the posture: projected ellipse, rotation phi, D0, y0, osculating radius, corner ball', async () => {
    const { page } = await site.reuse(ZIGZAG10);
    await showView(page, 'formulas');
    const formulas = page.getByTestId('formulas');
    await formulas.locator('math').first().waitFor();
    const s = shapeOfTool(tool(10));
    const five = (v: number) => String(Number(v.toPrecision(5)));
    const exactText = (await formulas.locator('section[data-procedure="exact"]').textContent()) ?? '';
    expect(exactText).toContain(`=${five(s.b)} mm`); // b = Rb cos(beta) sin(rho)
    expect(exactText).toContain(`=${five((s.phi * 180) / Math.PI)}`);
    expect(exactText).toContain(`=${five(s.d0)} mm`);
    expect(exactText).toMatch(/2min/); // the zigzag rule, not the one-way one
    expect(exactText).not.toMatch(/wR\+wL=/);
    const osc = osculatingModel(tool(10));
    if (!osc.ok) throw new Error('applies');
    expect(await formulas.locator('section[data-procedure="osculating"]').textContent()).toContain(
      five(osc.effectiveRadiusMm),
    );
    expect(await formulas.locator('section[data-procedure="cornerBall"]').textContent()).toMatch(/Rcr=1 mm/);
    expect(await formulas.locator('section[data-procedure="sekine"]').textContent()).toMatch(/tilt ignored/);
    await keepShot(page, 'posture-formulas', { fullPage: true });
  });

  it('says what the step-over means (between cutter-contact paths) and gives the tool-centre offset', async () => {
    const { page } = await site.reuse(TILT5);
    const meaning = (await page.getByTestId('step-over-meaning').textContent()) ?? '';
    expect(meaning).toMatch(/distance between adjacent cutter-contact \(CC\) paths/);
    expect(meaning).toMatch(/tool centre point O instead, offset each CC path across the feed by −y0 = [-+]?\d/);
  });

  it('the chart of L against tilt at the current lead, beside L against lead', async () => {
    const { page } = await site.reuse(TILT5);
    await showView(page, 'chart');
    const chart = page.getByTestId('comparison-chart');
    await page.getByTestId('chart-tilt').locator('svg.chart-svg').waitFor();
    expect(await page.getByTestId('chart-tilt').locator('.chart-title').textContent()).toMatch(
      /L \[mm\] against tilt beta \[deg\] .*current beta = 5\)/,
    );
    expect(await page.getByTestId('chart-lead').locator('.chart-title').textContent()).toMatch(/current rho = 5\)/);
    await expect
      .poll(() => page.getByTestId('chart-summary').textContent())
      .toMatch(new RegExp(`beta = 5 deg, L: Exact \\(3D\\) ${exact(5, 'one-way').intervalMm.toFixed(4)} mm`));
    await keepShot(chart, 'posture-chart');
  });

  it('the profile: three passes, both cusps, wR and wL labelled, O at -y0; zigzag: both cusp heights', async () => {
    const { page } = await site.reuse(TILT5);
    await showView(page, 'profile');
    const view = page.getByTestId('profile-view');
    await view.locator('polygon.scallop').waitFor();
    const e = exact(5, 'one-way');
    const dims = () => view.locator('text.dim-text').allTextContents();
    await expect
      .poll(dims)
      .toEqual(
        expect.arrayContaining([
          `wR = ${e.halfWidthRightMm.toFixed(4)} mm`,
          `wL = ${e.halfWidthLeftMm.toFixed(4)} mm`,
          `L = ${e.intervalMm.toFixed(4)} mm`,
          `O (y0 = ${e.contactOffsetMm.toFixed(4)} mm)`,
        ]),
      );
    expect(await view.locator('polyline.curve-exact').count()).toBe(3);
    await keepShot(page, 'posture-profile');
    site.changed();
    await page.locator('[data-testid="pattern-switch"] input[value="zigzag"]').check();
    const z = exact(5, 'zigzag');
    await expect
      .poll(dims)
      .toEqual(
        expect.arrayContaining([
          'h = 50.00 \u00b5m',
          `h' = ${formatLenUnit(z.otherCuspHeightMm ?? 0, 'mm', 'height')}`,
          `L = ${z.intervalMm.toFixed(4)} mm`,
        ]),
      );
  });

  it('the table: osculating circle and corner ball rows; the paper three labelled lead-only with tilt', async () => {
    const { page } = await site.reuse(TILT5);
    const c = compareForward(forwardInput(tool(5), 'one-way', 0.05));
    const osc = c.approximations.osculating;
    const ball = c.approximations.cornerBall;
    if (!osc.ok || !ball.ok) throw new Error('both apply here');
    expect(await text(page, 'result-osculating-half')).toBe(`${osc.halfIntervalMm.toFixed(4)} mm`);
    expect(await text(page, 'result-cornerBall-half')).toBe(`${ball.halfIntervalMm.toFixed(4)} mm`);
    const label = (key: string) => page.locator(`.procedures tr[data-procedure="${key}"] th`).textContent();
    for (const key of ['sekine', 'redonnet', 'bedi']) expect(await label(key)).toMatch(/lead only$/);
    for (const key of ['exact', 'osculating', 'cornerBall']) expect(await label(key)).not.toMatch(/lead only/);
    expect(await page.getByTestId('table-notes').textContent()).toMatch(/lead-only models/);
    site.changed();
    await page.getByTestId('input-tilt').fill('0');
    await expect.poll(() => label('sekine')).toBe('Sekine et al. (Eqs. 4-8)');
  });

  it('the stepper runs the procedure on both flanks and ends on both widths', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&tilt=8&h=0.05&unit=mm&view=stepper');
    const caption = page.getByTestId('stepper-caption');
    await expect
      .poll(() => caption.textContent())
      .toMatch(/^Step 1 of \d+\. Right flank \(\+Y\)\. Fig\. 1, box 2 \(Eq\. 1\)/);
    const trace = traceProcedure(forwardInput(tool(8), 'one-way', 0.05));
    const e = exact(8, 'one-way');
    await page.getByTestId('stepper-last').click();
    await expect
      .poll(() => caption.textContent())
      .toContain(
        `Fig. 1, box 26: converged on both flanks. wR = ${trace.right.widthMm.toFixed(6)} mm, wL = ${trace.left.widthMm.toFixed(6)} mm; ` +
          `the exact solver gives wR = ${e.halfWidthRightMm.toFixed(6)} mm, wL = ${e.halfWidthLeftMm.toFixed(6)} mm.`,
      );
    // Somewhere along the way: the left flank's own steps.
    await page.getByTestId('stepper-back').click();
    await expect.poll(() => caption.textContent()).toMatch(/^Step \d+ of \d+\. Left flank \(-Y\) converged: wL = /);
  });
});
