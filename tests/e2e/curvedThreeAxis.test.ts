/**
 * Issues 19 and 20 on the page, driven as a user would in headless Chromium, at a desktop and a
 * phone viewport: a doubly curved point chosen by its preset (the exact L and the comparison rows
 * of the core), gouging said on the radius that must grow; the machine switched to three-axis, the
 * slope typed (the programmed step of the core, copyable), a waterline link that loads and answers.
 * Expected values come from the solver core itself.
 */
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { formatInputNumber } from '../../src/core/input/units';
import { compareDoublyCurved } from '../../src/core/procedures/compareDoublyCurved';
import { doublyCurvedHeightForRaMm, doublyCurvedRoughness } from '../../src/core/roughness/doublyCurved';
import { slopedPlaneRoughness } from '../../src/core/roughness/slopedPlane';
import { doublyCurvedForward, doublyCurvedRadiusLimit } from '../../src/core/surfaces/doublyCurved';
import { curvedPoint } from '../../src/core/surfaces/doublyCurvedPoint';
import { slopedPlaneForward } from '../../src/core/threeAxis/slopedPlane';
import { slopePosture } from '../../src/core/threeAxis/slopePosture';
import { waterlineForward } from '../../src/core/threeAxis/waterlineRevolution';
import { formatAngle, formatLen, formatLenUnit, formatRoughness } from '../../src/ui/format';
import { REVOLUTION_NOTE } from '../../src/ui/roughness';
import { parseUrl } from '../../src/ui/state';
import { run } from '../cli/helpers';
import { answeredRanges } from '../support/pageAnswer';
import { keepShot, pageSettled, ROOT, urlWrites, useSite } from './harness';

const site = useSite('docs/curved-three-axis', { scene: false });

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const DESKTOP = { width: 1400, height: 900 };
const PHONE = { width: 390, height: 844 };
const DASH = '\u2014';

const text = async (page: Page, id: string) => (await page.getByTestId(id).textContent())?.trim() ?? '';
const radio = (page: Page, group: string, value: string) =>
  page.locator(`[data-testid="${group}"] input[value="${value}"]`);

/** The core's exact L at the default radii (Rf 80 mm, Rc 40 mm) with the given sides. */
function curvedL(feedRadiusMm: number, crossRadiusMm: number): number {
  return doublyCurvedForward({ ...TOOL, pattern: 'one-way', feedRadiusMm, crossRadiusMm, scallopHeightMm: 0.05 })
    .intervalMm;
}

/** The core's Lxy of raster passes up and down a plane of this slope. */
function rasterStep(slopeDeg: number, h = 0.05): number {
  const r = slopedPlaneForward(
    { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg, passes: 'raster', rasterAngleDeg: 0 },
    h,
  );
  if (!r.ok) throw new Error('core refused');
  return r.value.horizontalStepMm;
}

/** No horizontal scrolling: the page fits its viewport's width. */
async function fitsWidth(page: Page): Promise<boolean> {
  return page.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth);
}

/** The three-axis job (raster at 30 degrees over a 30 degree slope, h 0.01 mm) opened, and the core's answer. */
async function openRaster30() {
  const { page, errors } = await site.open('?machine=3axis&R=3&Rcr=1&slope=30&rasterAngle=30&h=0.01&unit=mm', DESKTOP);
  const step = slopedPlaneForward(
    { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 30 },
    0.01,
  );
  if (!step.ok) throw new Error('core refused');
  return { page, errors, step };
}

describe.each([
  ['desktop', DESKTOP],
  ['phone', PHONE],
] as const)('doubly curved points and three-axis machining (%s)', (name, viewport) => {
  it('a dome chosen by its preset: L and the comparison rows are the core values; in the URL', async () => {
    const { page, errors } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm', viewport);
    await radio(page, 'surface-kind', 'curved').check();
    // A bowl first, then the dome: each preset's L is the core's.
    await page.getByTestId('surface-preset').selectOption('bowl');
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(curvedL(-80, -40), 'mm'));
    await page.getByTestId('surface-preset').selectOption('dome');
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(curvedL(80, 40), 'mm'));
    expect(await page.getByTestId('side-feed-radius').inputValue()).toBe('convex');
    expect(await page.getByTestId('side-cross-radius').inputValue()).toBe('convex');
    // The lookup table of this point can be downloaded (its columns: tests/worker/curvedTable.test.ts).
    expect(await page.getByTestId('download-table').isEnabled()).toBe(true);
    // The three-axis results are not shown at a five-axis point.
    expect(await page.getByTestId('result-equivalent-lead').isVisible()).toBe(false);
    const c = compareDoublyCurved({
      ...TOOL,
      pattern: 'one-way',
      feedRadiusMm: 80,
      crossRadiusMm: 40,
      scallopHeightMm: 0.05,
    });
    if (!c.plane.ok || !c.cylinderAlong.ok) throw new Error('rows');
    expect(await text(page, 'result-curved-plane-L')).toBe(formatLenUnit(c.plane.intervalMm, 'mm'));
    expect(await text(page, 'result-curved-cylinderAlong-L')).toBe(formatLenUnit(c.cylinderAlong.intervalMm, 'mm'));
    expect(await text(page, 'result-curved-cylinderAlong-real-h')).toBe(
      formatLenUnit(c.cylinderAlong.realScallopMm, 'mm', 'height'),
    );
    await expect.poll(() => urlWrites(page)).toBeGreaterThan(0);
    await expect.poll(() => new URL(page.url()).searchParams.get('crossRadius')).toBe('40');
    expect(new URL(page.url()).searchParams.get('feedRadius')).toBe('80');
    expect(await fitsWidth(page)).toBe(true);
    await keepShot(page, `curved-dome-${name}`, { fullPage: true });
    expect(errors).toEqual([]);
  });

  it('a gouging concave radius: its message on that field with the limit, dashes in the results', async () => {
    const { page } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&feedRadius=80&crossRadius=-30&unit=mm', viewport);
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(curvedL(80, -30), 'mm'));
    await page.getByTestId('input-cross-radius').fill('2');
    const limit = doublyCurvedRadiusLimit(TOOL, { feedRadiusMm: 80, crossRadiusMm: -2 }, 'cross');
    await expect
      .poll(() => text(page, 'error-cross-radius'))
      .toContain(`at least ${formatInputNumber(limit.radiusMm ?? 0)} mm while concave`);
    expect(await text(page, 'error-feed-radius')).toBe('');
    expect(await text(page, 'result-exact-interval')).toBe(DASH);
    expect(await page.getByTestId('error-cross-radius').isVisible()).toBe(true);
    // Widening the radius past the limit answers again.
    await page.getByTestId('input-cross-radius').fill('25');
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(curvedL(80, -25), 'mm'));
    expect(await text(page, 'error-cross-radius')).toBe('');
  });

  it('three-axis: the slope sets the posture; the programmed step Lxy is the core value, copyable', async () => {
    const { page, errors } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm', viewport);
    await radio(page, 'machine-switch', '3axis').check();
    expect(await page.getByTestId('input-rho').isVisible()).toBe(false);
    expect(await page.getByTestId('input-tilt').isVisible()).toBe(false);
    const slope = page.getByTestId('input-slope');
    expect(await slope.isVisible()).toBe(true);
    await slope.fill('50');
    await expect.poll(() => text(page, 'result-programmed-step')).toBe(formatLenUnit(rasterStep(50), 'mm'));
    await slope.fill('30');
    const step = rasterStep(30);
    await expect.poll(() => text(page, 'result-programmed-step')).toBe(formatLenUnit(step, 'mm'));
    expect(await page.getByTestId('result-programmed-step').getAttribute('data-copy')).toBe(formatLen(step, 'mm'));
    // L along the surface and the equivalent posture follow it.
    expect(await text(page, 'result-exact-interval')).toMatch(/\d/);
    // Computed angles with two decimals each (format.ts formatAngle, issue 28 point 11).
    expect(await text(page, 'result-equivalent-lead')).toBe('30.00 deg');
    expect(await text(page, 'result-equivalent-tilt')).toBe('0.00 deg');
    // Nor are the five-axis ones (flank widths, the surface kind) in three-axis machining.
    expect(await page.getByTestId('result-width-right').isVisible()).toBe(false);
    expect(await page.getByTestId('surface-kind').isVisible()).toBe(false);
    await expect.poll(() => new URL(page.url()).searchParams.get('slope')).toBe('30');
    expect(new URL(page.url()).searchParams.get('machine')).toBe('3axis');
    expect(new URL(page.url()).searchParams.has('rho')).toBe(false);
    expect(await fitsWidth(page)).toBe(true);
    await keepShot(page, `three-axis-raster-${name}`, { fullPage: true });
    expect(errors).toEqual([]);
  });

  it('a waterline link on a dome loads and answers: dz of the core; a bad slope is said on its field', async () => {
    const { page, errors } = await site.open(
      '?R=3&Rcr=1&machine=3axis&slope=40&passes=waterline&feedRadius=50&crossRadius=50&h=0.02&unit=mm',
      viewport,
    );
    const core = waterlineForward(
      { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: 40, feedRadiusMm: 50, crossRadiusMm: 50 },
      0.02,
    );
    if (!core.ok) throw new Error('core refused');
    await expect.poll(() => text(page, 'result-programmed-step')).toBe(formatLenUnit(core.value.stepDownMm, 'mm'));
    expect(await text(page, 'result-exact-interval')).toBe(formatLenUnit(core.value.intervalMm, 'mm'));
    expect(await radio(page, 'passes-switch', 'waterline').isChecked()).toBe(true);
    expect(await page.getByTestId('surface-preset').inputValue()).toBe('dome');
    await page.getByTestId('input-slope').fill('0');
    await expect.poll(() => text(page, 'error-slope')).toMatch(/^Slope alpha must be above 0 degrees for waterline/);
    expect(await text(page, 'result-programmed-step')).toBe(DASH);
    expect(errors).toEqual([]);
  });
});

describe('roughness, a target Ra and the sliders at a doubly curved point; three-axis roughness and table', () => {
  it('a saddle: Rz, Ra, Rq of the core; a target Ra typed answers the core h and L; the h slider stops at this point', async () => {
    const { page, errors } = await site.open('?R=3&Rcr=1&rho=5&h=0.05&feedRadius=80&crossRadius=-40&unit=mm', DESKTOP);
    const radii = { feedRadiusMm: 80, crossRadiusMm: -40 };
    const e = curvedL(80, -40);
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(e, 'mm'));
    const c = compareDoublyCurved({ ...TOOL, pattern: 'one-way', ...radii, scallopHeightMm: 0.05 });
    const r = doublyCurvedRoughness(curvedPoint(TOOL, radii, 'one-way'), c.exact);
    await expect.poll(() => text(page, 'result-ra')).toBe(formatRoughness(r.raMm, 'mm'));
    expect(await text(page, 'result-rz')).toBe(formatRoughness(r.rzMm, 'mm'));
    expect(await text(page, 'result-rq')).toBe(formatRoughness(r.rqMm, 'mm'));
    // The h slider's top is this point's limit (not the plane's), as the field's message states it.
    const state = parseUrl('?R=3&Rcr=1&rho=5&h=0.05&feedRadius=80&crossRadius=-40&unit=mm').state;
    const max = answeredRanges(state).h.max;
    await expect.poll(() => page.getByTestId('slider-h').getAttribute('max')).toBe(max);
    expect(max).not.toBe(answeredRanges(parseUrl('?R=3&Rcr=1&rho=5&h=0.05&unit=mm').state).h.max);
    // A target Ra: the h that leaves it and its step-over, as the core gives them.
    await radio(page, 'target-switch', 'ra').check();
    await page.getByTestId('input-ra').fill('0.004');
    const h = doublyCurvedHeightForRaMm(curvedPoint(TOOL, radii, 'one-way'), 0.004);
    const L = compareDoublyCurved({ ...TOOL, pattern: 'one-way', ...radii, scallopHeightMm: h }).exact.intervalMm;
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(L, 'mm'));
    expect(await text(page, 'result-ra-height')).toBe(formatLenUnit(h, 'mm', 'height'));
    expect(await text(page, 'error-ra')).toBe('');
    // Above the largest Ra at this point: said on the field, no answer.
    await page.getByTestId('input-ra').fill('5');
    await expect.poll(() => text(page, 'error-ra')).toMatch(/^Roughness Ra must be below [\d.]+ mm \(got 5\)/);
    expect(await text(page, 'result-exact-interval')).toBe(DASH);
    expect(errors).toEqual([]);
  });

  it('three-axis: Rz, Ra, Rq on the sloped plane are the plane roughness at its posture; a surface of revolution says why none', async () => {
    const { page, errors } = await site.open(
      '?machine=3axis&R=3&Rcr=1&slope=30&rasterAngle=30&h=0.01&unit=mm',
      DESKTOP,
    );
    const rough = (passes: 'raster' | 'waterline') =>
      slopedPlaneRoughness({ toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: 30, passes, rasterAngleDeg: 30 }, 0.01);
    const raster = rough('raster');
    await expect.poll(() => text(page, 'result-ra')).toBe(formatRoughness(raster.raMm, 'mm'));
    expect(await text(page, 'result-rz')).toBe(formatRoughness(raster.rzMm, 'mm'));
    expect(await text(page, 'result-rq')).toBe(formatRoughness(raster.rqMm, 'mm'));
    expect(await text(page, 'result-ra-rule')).toMatch(
      /^Rule of thumb Ra ~ h\/4 = 2\.500 µm: -?[\d.]+ % against the exact Ra\.$/,
    );
    // Waterline on the plane: the posture of raster angle 90, its own roughness.
    await radio(page, 'passes-switch', 'waterline').check();
    const waterline = rough('waterline');
    expect(waterline.raMm).not.toBeCloseTo(raster.raMm, 7);
    await expect.poll(() => text(page, 'result-ra')).toBe(formatRoughness(waterline.raMm, 'mm'));
    expect(await text(page, 'result-rz')).toBe(formatRoughness(waterline.rzMm, 'mm'));
    // A surface of revolution: dashes, and the one line that says why.
    await page.getByTestId('surface-preset').selectOption('dome');
    await expect.poll(() => text(page, 'result-ra-rule')).toBe(REVOLUTION_NOTE);
    expect(await text(page, 'result-ra')).toBe(DASH);
    expect(await text(page, 'result-rz')).toBe(DASH);
    expect(await text(page, 'result-programmed-step')).toMatch(/\d/);
    expect(errors).toEqual([]);
  });

  it('three-axis views: the plane at the equivalent posture (profile, formulas, machined surface), the tab named for its chart, neutral notes only', async () => {
    const { page, errors, step } = await openRaster30();
    const posture = slopePosture(30, 30);
    const lead = formatAngle(posture.leadDeg);
    const tilt = formatAngle(posture.tiltDeg);
    await expect
      .poll(() => text(page, 'result-programmed-step'))
      .toBe(formatLenUnit(step.value.horizontalStepMm, 'mm'));
    const views = page.locator('.teaching');
    await views.scrollIntoViewIfNeeded();
    // The Profile (the default tab): the plane's cross-pass profile at the posture, its L the answer's L.
    const profile = page.getByTestId('profile-view');
    await expect.poll(() => profile.textContent()).toContain(`L = ${formatLenUnit(step.value.intervalMm, 'mm')}`);
    expect(await profile.isVisible()).toBe(true);
    const note = page.getByTestId('views-page-note');
    expect(await note.textContent()).toBe(
      `The upright tool over slope 30°, raster 30° is the tool at lead ${lead}, tilt ${tilt} on a plane, one-way: drawn in the plane's own frame (lengths along it, h along its normal).`,
    );
    expect(await page.getByTestId('views-stale').isVisible()).toBe(false);
    // A neutral line, not an error's colours: the note's colour is the page's muted text, not --bad.
    const colours = await note.evaluate((e) => {
      const bad = getComputedStyle(document.documentElement).getPropertyValue('--bad').trim();
      const probe = document.createElement('span');
      probe.style.color = bad;
      document.body.append(probe);
      const badRgb = getComputedStyle(probe).color;
      probe.remove();
      return { note: getComputedStyle(e).color, bad: badRgb, border: getComputedStyle(e).borderTopStyle };
    });
    expect(colours.note).not.toBe(colours.bad);
    expect(colours.border).toBe('none');
    await keepShot(views, 'three-axis-profile-desktop');
    // The chart's tab is named for what it draws.
    const chartTab = page.locator('#tab-chart');
    expect(await chartTab.textContent()).toBe('Step against slope');
    // Formulas: the posture from slope and raster angle first, then the plane's.
    await page.locator('#tab-formulas').click();
    const posed = page.getByTestId('formulas-posture');
    await expect.poll(() => posed.textContent()).toContain(`rho = ${lead}`);
    expect(await posed.textContent()).toContain(`beta = ${tilt}`);
    expect(await posed.textContent()).toContain(`Lxy / L = ${posture.horizontalStepPerInterval.toFixed(6)}`);
    expect(await page.locator('[data-testid="formulas"] section.formula[data-procedure="exact"]').count()).toBe(1);
    await keepShot(views, 'three-axis-formulas-desktop');
    // Machined surface: the plane at the posture simulated, its cusp against the exact one.
    await page.locator('#tab-surface').click();
    await expect
      .poll(() => text(page, 'surface-comparison'), { timeout: 30_000 })
      .toMatch(/^Simulated cusp [\d.]+ µm against exact 10\.000 µm/);
    await keepShot(views, 'three-axis-surface-desktop');
    // Waterline on a dome: the chart draws it; the profile says neutrally why it draws nothing.
    await radio(page, 'passes-switch', 'waterline').check();
    await page.getByTestId('surface-preset').selectOption('dome');
    await page.locator('#tab-profile').click();
    await expect
      .poll(() => note.textContent())
      .toMatch(/^Waterline passes on a surface of revolution \(slope 30°, waterline\)/);
    expect(await profile.isVisible()).toBe(false);
    expect(await page.getByTestId('views-stale').isVisible()).toBe(false);
    expect(await chartTab.textContent()).toBe('Step against slope');
    await keepShot(views, 'three-axis-revolution-profile-desktop');
    // Back to five-axis: the chart's own name again, no note.
    await radio(page, 'machine-switch', '5axis').check();
    await expect.poll(() => chartTab.textContent()).toBe('L against lead and tilt');
    expect(await note.isVisible()).toBe(false);
    expect(errors).toEqual([]);
  });

  it('three-axis: the lookup table (slope x h, the programmed step) downloads and reads back through --batch', async () => {
    const { page, errors, step: core } = await openRaster30();
    await expect
      .poll(() => text(page, 'result-programmed-step'))
      .toBe(formatLenUnit(core.value.horizontalStepMm, 'mm'));
    const button = page.getByTestId('download-table');
    await expect.poll(() => button.isEnabled()).toBe(true);
    const downloaded = page.waitForEvent('download');
    await button.click();
    const name = 'step-over-table_3-axis_R3_Rcr1_raster30_plane_mm.csv';
    await expect
      .poll(() => text(page, 'download-table-status'), { timeout: 15_000 })
      .toMatch(
        new RegExp(
          `^Saved ${name.replaceAll('.', '\\.')}: \\d+ rows, h [\\d.]+ to [\\d.]+ mm x slope 0 to 85 deg, the programmed step \\(Lxy\\)`,
        ),
      );
    const download = await downloaded;
    expect(download.suggestedFilename()).toBe(name);
    const csv = readFileSync(await download.path(), 'utf8');
    const [head, ...rows] = parseCsv(csv).filter((r) => !r.blank);
    const col = (c: string) => head?.fields.indexOf(c) ?? -1;
    // The question on screen is a row of the table: its Lxy is the answer's.
    const at = rows.find((r) => r.fields[col('slope_deg')] === '30' && r.fields[col('h_mm')] === '0.01');
    const lxy = Number(at?.fields[col('horizontalStep_mm')]);
    expect(Math.abs(lxy - core.value.horizontalStepMm)).toBeLessThanOrEqual(1e-12 * lxy);
    // Read back by the command line (in process): the same rows, the same numbers (to the last
    // digits: the browser's sine may round apart from Node's by an ulp).
    const back = await run(['--batch'], csv);
    expect(back.code).toBe(0);
    const again = parseCsv(back.stdout)
      .filter((r) => !r.blank)
      .slice(1);
    expect(again.length).toBe(rows.length);
    rows.forEach((r, k) => {
      r.fields.forEach((field, c) => {
        const other = again[k]?.fields[c] ?? '';
        if (field === '' || Number.isNaN(Number(field))) expect(other, `${k} ${c}`).toBe(field);
        else
          expect(Math.abs(Number(other) - Number(field)), `${k} ${c}`).toBeLessThanOrEqual(
            1e-13 * Math.abs(Number(field)),
          );
      });
    });
    expect(errors).toEqual([]);
  });
});

describe('accessibility of the new inputs and results', () => {
  const AXE = readFileSync(`${ROOT}node_modules/axe-core/axe.min.js`, 'utf8');
  it('axe-core finds no violation at a doubly curved point, in three-axis raster and waterline', async () => {
    for (const query of [
      '?R=3&Rcr=1&rho=5&h=0.05&feedRadius=80&crossRadius=-40&unit=mm',
      '?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=20&h=0.05&unit=mm',
      '?R=3&Rcr=1&machine=3axis&slope=40&passes=waterline&feedRadius=-50&crossRadius=-6&mode=inverse&dz=0.2&unit=mm',
    ]) {
      const { page } = await site.open(query, DESKTOP);
      await pageSettled(page);
      await page.addScriptTag({ content: AXE });
      const found = await page.evaluate(async () => {
        type Run = { violations: Array<{ id: string; nodes: Array<{ target: string[] }> }> };
        const axe = (window as unknown as { axe: { run(): Promise<Run> } }).axe;
        return (await axe.run()).violations.map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
      });
      expect(found, query).toEqual([]);
    }
  });
});
