/**
 * The finish on the page (issue 29), one page load for the file: flutes and fz typed as a user
 * types them give hf, Sa and fz* equal to the core's finishReport to the digits shown; "use the
 * balanced feed" makes hf read as h; a bad fz is one line naming its limit in the unit, the
 * step-over kept; the profiles along and across the feed are drawn; a cylinder is refused in one line (no number); the x3p download is a zip of one
 * cell's 256 x 256 heights named by the question; feed rate and spindle speed give fz; a Fusion
 * 360 tool's NOF fills the flutes; a target Sa typed gives the best pair with its
 * Sa, L0 and the chart of pairs, "use this pair" solves at it, a cylinder and runout are refused in
 * one line and the earlier pair is never shown for them. Every status read is polled.
 */
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { feedMarks, finishReport, toothModel } from '../../src/core/finish/index';
import { forwardInput } from '../../src/core/input/validate';
import { forwardOfRaTarget, validateRaTarget } from '../../src/core/roughness/raTarget';
import { TARGET_SA_RUNOUT } from '../../src/core/roughness/targetSa';
import { exactForward } from '../../src/core/surfaces/solve';
import { feedLength } from '../../src/ui/finishLength';
import { formatLenUnit, formatRoughness } from '../../src/ui/format';
import { solve } from '../../src/worker/jobs/solve';
import { teethSurfaceGrid } from '../../src/worker/teethSurface';
import { typeInto, useSite } from './harness';

const site = useSite('finish', { scene: false });
const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const QUERY = '?R=3&Rcr=1&rho=5&h=0.05&unit=mm';

/** L0 of a target Sa (mm): the step-over whose passes leave Ra = Sa, where the curve of pairs meets fz = 0. */
function zeroFeedL(saMm: number): number {
  const v = validateRaTarget({ R: 3, Rcr: 1, rho: 5, tilt: 0, pattern: 'one-way', ra: saMm });
  if (!v.ok) throw new Error('invalid');
  return exactForward(forwardOfRaTarget(v.value)).intervalMm;
}

/** The core's answer at the page's question (one-way, h 0.05 mm, 4 teeth, fz 0.1 mm). */
function expected() {
  const reply = solve({ mode: 'forward', input: forwardInput(TOOL, 'one-way', 0.05) });
  if (!reply.ok) throw new Error('plane');
  const finish = { flutes: 4, feedPerToothMm: 0.1, runoutMm: 0, runoutPhaseDeg: 0, passPhase: 0 };
  const m = toothModel({ tool: TOOL, pattern: 'one-way', intervalMm: reply.exact.intervalMm, finish });
  const report = finishReport(TOOL, 'one-way', reply.exact.intervalMm, finish);
  const areal = report.areal;
  if (areal === null) throw new Error('areal');
  return {
    report: { ...report, areal },
    L: reply.exact.intervalMm,
    crestXMm: feedMarks(m).crestXMm,
  };
}

const text = async (page: Page, id: string) => (await page.getByTestId(id).textContent()) ?? '';

async function commit(page: Page, id: string, value: string): Promise<void> {
  await typeInto(page, id, value);
  await page.keyboard.press('Enter');
}

describe('the finish box', () => {
  let page: Page;
  let errors: string[];
  const core = expected();
  /** The best pair's step-over as the target-Sa box showed it. */
  let pairShown = '';

  it('typed flutes and fz give hf, Sa and fz* as the core computes them, to the digits shown', async () => {
    ({ page, errors } = await site.open(QUERY));
    await expect.poll(() => page.getByTestId('finish-results').isHidden()).toBe(true);
    // The optional box is closed while its fields are empty; its summary opens it.
    const box = page.getByTestId('finish-inputs');
    expect(await box.getAttribute('open')).toBeNull();
    await box.locator('summary').click();
    await commit(page, 'input-flutes', '4');
    await commit(page, 'input-fz', '0.1');
    const m = core.report.feedMarks;
    await expect.poll(() => text(page, 'finish-hf'), { timeout: 20_000 }).toBe(formatRoughness(m.height, 'mm'));
    // The areal parameters come from a worker of their own, after the feed marks.
    await expect
      .poll(() => text(page, 'finish-sa'), { timeout: 20_000 })
      .toBe(formatRoughness(core.report.areal.Sa, 'mm'));
    expect(await text(page, 'finish-balanced')).toBe(feedLength(m.balancedFz, 'mm'));
    // The cell's height map: painted (blue to orange), its scale in words.
    await expect
      .poll(() => text(page, 'finish-map-scale'))
      .toContain(`Sz = ${formatRoughness(core.report.areal.Sz, 'mm')} apart`);
    const colours = await page.getByTestId('finish-map-image').evaluate((c: HTMLCanvasElement) => {
      const d = c.getContext('2d')?.getImageData(0, 0, c.width, c.height).data ?? new Uint8ClampedArray();
      const seen = new Set<number>();
      for (let k = 0; k < d.length; k += 4) seen.add(((d[k] ?? 0) << 16) | ((d[k + 1] ?? 0) << 8) | (d[k + 2] ?? 0));
      return seen.size;
    });
    expect(colours).toBeGreaterThan(20);
    // The profiles along the CC path and across the feed: charts with axes in mm and µm, the across
    // one at the x of the highest feed mark (the core's).
    await expect.poll(() => page.getByTestId('finish-profiles').isVisible()).toBe(true);
    for (const id of ['finish-profile-along-chart', 'finish-profile-across-chart']) {
      const chart = page.getByTestId(id);
      expect(await chart.locator('.chart-axis-label').allTextContents()).toEqual([
        id.includes('along') ? 'x (mm)' : 'y (mm)',
        's (\u00b5m)',
      ]);
      expect(await chart.locator('path.chart-line').getAttribute('d')).toMatch(
        /^M[\d.]+ [\d.]+(L[\d.]+ [\d.]+){100,}$/,
      );
    }
    expect(await text(page, 'finish-profile-across-x')).toBe(feedLength(core.crestXMm, 'mm'));
    expect(await text(page, 'finish-areal-Sku')).toBe(core.report.areal.Sku.toFixed(4));
    // Sa once (beside Ra), not again in the areal list.
    expect(await page.getByTestId('finish-areal-Sa').count()).toBe(0);
    // One polite live region for the results (beside the x3p's own status): the answer once complete.
    const live = await page
      .getByTestId('finish-results')
      .evaluate((box) =>
        [...box.querySelectorAll('output, [role="status"], [aria-live]')]
          .filter((e) => e.getAttribute('aria-live') !== 'off')
          .map((e) => e.getAttribute('data-testid')),
      );
    expect(live).toEqual(['finish-live', 'x3p-status']);
    await expect
      .poll(() => text(page, 'finish-live'))
      .toBe(
        `Feed marks hf (along the CC path): ${formatRoughness(m.height, 'mm')}; Sa (areal): ${formatRoughness(core.report.areal.Sa, 'mm')}; ` +
          `Balanced feed fz* (hf = h): ${feedLength(m.balancedFz, 'mm')}`,
      );
    // The link carries the teeth and the feed.
    await expect.poll(() => new URL(page.url()).searchParams.get('fz')).toBe('0.1');
    expect(new URL(page.url()).searchParams.get('z')).toBe('4');
  });

  it("the Machined surface view shows the teeth's surface (legend 0 to Sz); without fz, the continuous passes", async () => {
    const before = await page.locator('[role="tab"][aria-selected="true"]').getAttribute('id');
    const cells = teethSurfaceGrid(0.1, core.L, false);
    await page.locator('#tab-surface').click();
    const view = page.getByTestId('surface-view');
    // Which surface, its question and cells, and how much longer the feed's lengths are drawn.
    const caption =
      "The teeth's surface (z teeth, fz per tooth, passes L apart; feed periods x pass periods shown): " +
      `z = 4, fz = ${feedLength(0.1, 'mm')}, L = ${feedLength(core.L, 'mm')}; ${cells.feedPeriods} x ${cells.crossPeriods}.`;
    await expect.poll(() => text(page, 'surface-shown'), { timeout: 20_000 }).toMatch(/^The teeth's surface/);
    const shown = await text(page, 'surface-shown');
    expect(shown.slice(0, caption.length)).toBe(caption);
    expect(shown.slice(caption.length)).toMatch(/^ Along the feed, lengths drawn longer by x\d+\.$/);
    // The scale bar spans the finish's Sz, as the finish box says it; the exaggeration is stated.
    const Sz = formatRoughness(core.report.areal.Sz, 'mm');
    await expect.poll(() => text(page, 'finish-areal-Sz')).toBe(Sz);
    expect(await view.locator('[data-testid="surface-legend"] text').last().textContent()).toBe(Sz);
    expect(await text(page, 'surface-exaggeration')).toMatch(/^Heights exaggerated x\d+ \(vertical exaggeration\)/);
    expect(await view.getByTestId('surface-trace').isVisible()).toBe(false);
    await expect.poll(() => view.getByTestId('surface-canvas').isVisible()).toBe(true);
    // fz cleared: the finish no longer answers, and the view shows the continuous passes again.
    await commit(page, 'input-fz', '');
    await expect.poll(() => text(page, 'surface-shown')).toBe('Continuous passes: the tool sweeps without teeth.');
    await expect.poll(() => text(page, 'surface-comparison'), { timeout: 20_000 }).toMatch(/^Simulated cusp/);
    expect(await view.getByTestId('surface-trace').isVisible()).toBe(true);
    await commit(page, 'input-fz', '0.1');
    await expect.poll(() => text(page, 'surface-shown'), { timeout: 20_000 }).toMatch(/^The teeth's surface/);
    if (before !== null) await page.locator(`#${before}`).click();
  });

  it('"use the balanced feed" sets fz to fz*: hf then reads as the scallop h', async () => {
    await page.getByTestId('use-balanced-feed').click();
    await expect.poll(() => page.getByTestId('input-fz').inputValue()).not.toBe('0.1');
    // fz* as a shop types it (rounded down to 0.1 µm), and the focus stays on the button.
    expect(await page.getByTestId('input-fz').inputValue()).toMatch(/^\d+\.\d{1,4}$/);
    expect(await page.evaluate(() => document.activeElement?.getAttribute('data-testid'))).toBe('use-balanced-feed');
    const h = formatRoughness(0.05, 'mm');
    await expect.poll(() => text(page, 'finish-h'), { timeout: 20_000 }).toBe(h);
    await expect.poll(() => text(page, 'finish-hf'), { timeout: 20_000 }).toBe(h);
  });

  it('a bad fz is one line naming its limit in the unit; the step-over and the other fields stay', async () => {
    await commit(page, 'input-fz', '5');
    await expect
      .poll(() => text(page, 'finish-message'), { timeout: 20_000 })
      .toBe('Feed per tooth fz must be at most the tool radius R = 3 mm (got 5).');
    // The same line on the field where it was typed, the field marked invalid.
    expect(await text(page, 'error-fz')).toBe('Feed per tooth fz must be at most the tool radius R = 3 mm (got 5).');
    expect(await page.getByTestId('input-fz').getAttribute('aria-invalid')).toBe('true');
    expect(await text(page, 'finish-hf')).toBe('\u2014');
    expect(await text(page, 'result-exact-interval')).toMatch(/\d/);
    expect(await page.getByTestId('input-flutes').inputValue()).toBe('4');
    // Text in an optional field (the tester's "abc" in the flutes): named on it, the step-over stays.
    const interval = await text(page, 'result-exact-interval');
    await commit(page, 'input-flutes', 'abc');
    await expect.poll(() => text(page, 'error-flutes')).toBe('Flutes z must be a number (got "abc").');
    expect(await text(page, 'result-exact-interval')).toBe(interval);
    await commit(page, 'input-flutes', '4');
    await expect.poll(() => text(page, 'error-flutes')).toBe('');
  });

  it('on a cylinder the finish is refused in one line, no number', async () => {
    await commit(page, 'input-fz', '0.1');
    // A good feed again: the field's message goes with the answer it belonged to.
    await expect.poll(() => text(page, 'error-fz'), { timeout: 20_000 }).toBe('');
    await page.locator('input[name="surface"][value="convex"]').check();
    await expect
      .poll(() => text(page, 'finish-message'), { timeout: 20_000 })
      .toMatch(/^Feed marks are not computed on cylinders yet: only on a plane/);
    // The one line stands alone: no grid of dashes, no x3p button.
    expect(await page.getByTestId('finish-areal').isHidden()).toBe(true);
    expect(await page.getByTestId('download-x3p').isHidden()).toBe(true);
    expect(await text(page, 'finish-hf')).toBe('\u2014');
    expect(await text(page, 'finish-sa')).toBe('\u2014');
    expect(await page.getByTestId('finish-profiles').isHidden()).toBe(true);
  });

  it('downloads the x3p of one cell: a zip, 256 x 256 float64 heights, named by the question', async () => {
    await page.locator('input[name="surface"][value="plane"]').check();
    await expect
      .poll(() => text(page, 'finish-hf'), { timeout: 20_000 })
      .toBe(formatRoughness(core.report.feedMarks.height, 'mm'));
    const button = page.getByTestId('download-x3p');
    await expect.poll(() => button.isEnabled()).toBe(true);
    const downloaded = page.waitForEvent('download');
    await button.click();
    const download = await downloaded;
    expect(download.suggestedFilename()).toMatch(/^finish_R3_Rcr1_rho5_tilt0_one-way_L[\d.]+_z4_fz0\.1_mm\.x3p$/);
    const bytes = readFileSync(await download.path());
    expect([...bytes.subarray(0, 4)]).toEqual([0x50, 0x4b, 0x03, 0x04]);
    expect(bytes.length).toBeGreaterThan(256 * 256 * 8);
    expect(bytes.length).toBeLessThan(256 * 256 * 8 + 20_000);
    await expect.poll(() => text(page, 'x3p-status')).toMatch(/^Saved finish_.*\.x3p: 256 x 256 heights/);
    expect(errors).toEqual([]);
  });

  it("a runout answers: hf of the teeth cutting unequally (the core's), the period z fz", async () => {
    // Written as a shop writes it (10 µm, still being typed), as every length field reads it; the
    // saved file's line goes with the question it answered.
    await typeInto(page, 'input-runout', '10 um');
    await expect.poll(() => text(page, 'x3p-status')).toBe('');
    const finish = { flutes: 4, feedPerToothMm: 0.1, runoutMm: 0.01, runoutPhaseDeg: 0, passPhase: 0 };
    const marks = feedMarks(toothModel({ tool: TOOL, pattern: 'one-way', intervalMm: core.L, finish }));
    await expect.poll(() => text(page, 'finish-hf'), { timeout: 30_000 }).toBe(formatRoughness(marks.heightMm, 'mm'));
    expect(await text(page, 'finish-period')).toBe(feedLength(0.4, 'mm'));
    expect(await text(page, 'finish-message')).not.toMatch(/runout/i);
    await commit(page, 'input-runout', '');
  });

  it('a flat end lying flat: the areal surface refused, so no x3p of it; hf still answers', async () => {
    await commit(page, 'input-Rcr', '0');
    await commit(page, 'input-rho', '0');
    await expect
      .poll(() => text(page, 'finish-message'), { timeout: 20_000 })
      .toMatch(/areal parameters are not defined here/);
    expect(await page.getByTestId('download-x3p').isDisabled()).toBe(true);
    expect(await text(page, 'finish-sa')).toBe('\u2014');
    expect(await text(page, 'finish-hf')).toMatch(/\d/);
    await commit(page, 'input-Rcr', '1');
    await commit(page, 'input-rho', '5');
    await expect
      .poll(() => text(page, 'finish-hf'), { timeout: 20_000 })
      .toBe(formatRoughness(core.report.feedMarks.height, 'mm'));
    await expect.poll(() => page.getByTestId('download-x3p').isEnabled(), { timeout: 20_000 }).toBe(true);
  });

  it('feed rate and spindle speed give fz (read-only, F / (n z)); they are off while fz is typed', async () => {
    expect(await page.getByTestId('input-feed-rate').isDisabled()).toBe(true);
    await commit(page, 'input-fz', '');
    await expect.poll(() => page.getByTestId('input-feed-rate').isDisabled()).toBe(false);
    await commit(page, 'input-feed-rate', '2400');
    await commit(page, 'input-spindle-speed', '6000');
    // 2400 mm/min at 6000 rpm with 4 teeth: 0.1 mm per tooth, the answer of the first test.
    await expect.poll(() => page.getByTestId('input-fz').inputValue()).toBe('0.1');
    expect(await page.getByTestId('input-fz').getAttribute('readonly')).toBe('');
    expect(await page.locator('[data-field="F"] .unit').textContent()).toBe('mm/min');
    await expect
      .poll(() => text(page, 'finish-hf'), { timeout: 20_000 })
      .toBe(formatRoughness(core.report.feedMarks.height, 'mm'));
    await expect.poll(() => new URL(page.url()).searchParams.get('rpm')).toBe('6000');
    expect(new URL(page.url()).searchParams.get('F')).toBe('2400');
    expect(new URL(page.url()).searchParams.get('fz')).toBeNull();
    // "use the balanced feed" keeps the spindle speed and sets the feed rate: fz* n z, down to 1 mm/min.
    const rate = Math.floor((core.report.feedMarks.balancedFz ?? 0) * 6000 * 4);
    await page.getByTestId('use-balanced-feed').click();
    await expect.poll(() => page.getByTestId('input-feed-rate').inputValue()).toBe(String(rate));
    expect(await page.getByTestId('input-spindle-speed').inputValue()).toBe('6000');
    await expect.poll(() => page.getByTestId('input-fz').inputValue()).toBe(String(rate / 24000));
    await commit(page, 'input-spindle-speed', '0');
    const message = 'Spindle speed n must be greater than 0 rpm (got 0).';
    await expect.poll(() => text(page, 'finish-message'), { timeout: 20_000 }).toBe(message);
    expect(await text(page, 'error-spindle-speed')).toBe(message);
    expect(await page.getByTestId('input-fz').inputValue()).toBe('');
    expect(await text(page, 'finish-hf')).toBe('\u2014');
  });

  it("a Fusion 360 tool's NOF gives the flutes", async () => {
    const library = {
      data: [
        {
          type: 'bull nose end mill',
          unit: 'millimeters',
          description: 'D6 R1 3FL',
          geometry: { DC: 6, RE: 1, NOF: 3 },
        },
      ],
      version: 16,
    };
    await page.locator('[data-testid="tool-shelf"] summary').click();
    await page.getByTestId('tool-library-import').setInputFiles({
      name: 'shop.json',
      mimeType: 'application/json',
      buffer: Buffer.from(JSON.stringify(library)),
    });
    const list = page.getByTestId('library-tools');
    await list.waitFor();
    await list.selectOption({ label: 'D6 R1 3FL: D 6 mm, corner R 1 mm, 3 flutes' });
    await expect.poll(() => page.getByTestId('input-flutes').inputValue()).toBe('3');
    await expect.poll(() => new URL(page.url()).searchParams.get('z')).toBe('3');
    expect(errors).toEqual([]);
  });

  it('a link that carries the teeth and the feed opens their box; the user may close it', async () => {
    await page.goto(new URL(`${QUERY}&z=4&fz=0.1`, page.url()).href);
    const box = page.getByTestId('finish-inputs');
    await expect.poll(() => box.getAttribute('open')).toBe('');
    await expect
      .poll(() => text(page, 'finish-hf'), { timeout: 20_000 })
      .toBe(formatRoughness(core.report.feedMarks.height, 'mm'));
    await box.locator('summary').click();
    await expect.poll(() => box.getAttribute('open')).toBeNull();
    // Closed by the user, it stays closed while the answers come (the results still show the finish).
    await page.locator('input[name="pattern"][value="zigzag"]').check();
    await expect.poll(() => page.getByTestId('finish-results').isHidden()).toBe(false);
    expect(await box.getAttribute('open')).toBeNull();
  });

  it('target Sa: chosen and typed, it gives the best pair, the Sa it leaves, L0 and the chart of pairs', async () => {
    await page.locator('input[name="pattern"][value="one-way"]').check();
    await page.locator('input[name="target"][value="sa"]').check();
    await commit(page, 'input-sa', '0.0008');
    const box = page.getByTestId('target-sa-results');
    await expect.poll(() => box.isVisible()).toBe(true);
    // Seconds of work in the worker: a waiting line saying what is computed, then the pair.
    await expect.poll(() => text(page, 'target-sa-message')).toMatch(/^Computing the pairs of step-over and feed/);
    await expect.poll(() => text(page, 'target-sa-sa'), { timeout: 90_000 }).toBe(formatRoughness(0.0008, 'mm'));
    expect(await text(page, 'target-sa-message')).toBe('');
    // L0: the curve's end at fz -> 0 (Ra = Sa), the step-over the results show.
    expect(await text(page, 'target-sa-l0')).toBe(feedLength(zeroFeedL(0.0008), 'mm'));
    expect(await text(page, 'result-exact-interval')).toBe(formatLenUnit(zeroFeedL(0.0008), 'mm'));
    // Named as what it is: not the pair's L.
    expect(await page.locator('[data-role="headline-label"]').textContent()).toBe('Step-over L0 (fz -> 0: Ra = Sa)');
    const L = parseFloat(await text(page, 'target-sa-interval'));
    const fz = parseFloat(await text(page, 'target-sa-fz'));
    expect(L).toBeGreaterThan(0);
    expect(L).toBeLessThan(zeroFeedL(0.0008));
    expect(fz).toBeGreaterThan(0);
    expect(parseFloat(await text(page, 'target-sa-area'))).toBeCloseTo(L * fz, 6);
    expect(await text(page, 'target-sa-h')).toMatch(/^\d+\.\d+ \u00b5m$/);
    // The chart: L across, fz up, in mm; the best pair a dot on a dashed line; the curve ends at fz = 0.
    const chart = page.getByTestId('target-sa-chart');
    expect(await chart.locator('.chart-axis-label').allTextContents()).toEqual(['L (mm)', 'fz (mm)']);
    expect(await chart.locator('circle.chart-point').count()).toBe(1);
    expect(await chart.locator('line.chart-marker').count()).toBe(1);
    expect(await chart.locator('path.chart-line').getAttribute('d')).toMatch(/^M[\d.]+ [\d.]+(L[\d.]+ [\d.]+){8,}$/);
    // The feed's fields are not used (fz is the answer), and say so; the finish box asks nothing.
    expect(await page.getByTestId('input-fz').isDisabled()).toBe(true);
    expect(await page.locator('[data-field="fz"] .hint').textContent()).toBe(
      'not used with a target Sa: fz is its answer',
    );
    expect(await page.getByTestId('finish-results').isHidden()).toBe(true);
    expect(await text(page, 'target-sa-live')).toMatch(
      /^Step-over L: [\d.]+ mm; Feed per tooth fz: [\d.]+ mm; Sa it leaves: /,
    );
    // The link: target=sa&sa=0.0008&z=4 (tests/fieldRegistry.test.ts reads it back).
    await expect.poll(() => new URL(page.url()).searchParams.get('target')).toBe('sa');
    expect(new URL(page.url()).searchParams.get('sa')).toBe('0.0008');
    expect(new URL(page.url()).searchParams.get('z')).toBe('4');
    // The worker's seconds (3-10 s of CPU, more on a loaded machine) within the test's own time.
  }, 120_000);

  it('target Sa: "use this pair" solves for the scallop height at its L with its fz; the finish then gives Sa', async () => {
    const L = await text(page, 'target-sa-interval');
    pairShown = L;
    await page.getByTestId('use-target-sa-pair').click();
    await expect.poll(() => page.locator('input[name="mode"][value="inverse"]').isChecked()).toBe(true);
    // L and fz as a shop types them: rounded down to 0.1 µm.
    expect(await page.getByTestId('input-L').inputValue()).toBe(String(Math.floor(parseFloat(L) * 1e4) / 1e4));
    expect(await page.getByTestId('target-sa-results').isHidden()).toBe(true);
    // The finish box at the pair: Sa at or just below the target (both rounded down).
    await expect.poll(() => text(page, 'finish-sa'), { timeout: 30_000 }).toMatch(/\d/);
    const sa = parseFloat(await text(page, 'finish-sa'));
    expect(sa).toBeLessThanOrEqual(0.8);
    expect(sa).toBeGreaterThan(0.79);
  });

  it('target Sa off a plane is refused on its field; a newer input never shows the earlier pair; runout refused', async () => {
    // From here on, every value the pair's output shows, sampled each frame.
    await page.evaluate(() => {
      const w = window as unknown as { seen: string[]; sampling: boolean };
      w.seen = [];
      w.sampling = true;
      const sample = () => {
        w.seen.push(document.querySelector('[data-testid="target-sa-interval"]')?.textContent ?? '');
        if (w.sampling) requestAnimationFrame(sample);
      };
      sample();
    });
    await page.locator('input[name="surface"][value="convex"]').check();
    await page.locator('input[name="mode"][value="forward"]').check();
    await expect.poll(() => text(page, 'error-sa')).toBe('Target Sa is computed on a plane only: give h or Ra here.');
    expect(await text(page, 'result-exact-interval')).toBe('\u2014');
    // The teeth-and-feed box was closed by the user above: opened again to reach the runout.
    const teeth = page.getByTestId('finish-inputs');
    if ((await teeth.getAttribute('open')) === null) await teeth.locator('summary').click();
    await commit(page, 'input-runout', '0.01');
    await page.locator('input[name="surface"][value="plane"]').check();
    await expect.poll(() => text(page, 'target-sa-message'), { timeout: 20_000 }).toBe(TARGET_SA_RUNOUT);
    expect(await text(page, 'error-runout')).toBe(TARGET_SA_RUNOUT);
    const seen = await page.evaluate(() => {
      const w = window as unknown as { seen: string[]; sampling: boolean };
      w.sampling = false;
      return w.seen;
    });
    // The earlier answer's pair is never shown for the newer inputs: dashes only.
    expect(seen.length).toBeGreaterThan(0);
    expect(seen).not.toContain(pairShown);
    expect(new Set(seen)).toEqual(new Set(['\u2014']));
    expect(errors).toEqual([]);
  });
});
