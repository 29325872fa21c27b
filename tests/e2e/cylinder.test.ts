/**
 * Curved surfaces on the page (issue 12): the surface choice, the radius field and slider, the axis
 * switch, all in the URL; the exact L on the cylinder and the comparison rows of the core; gouging
 * on the radius field with dashes everywhere else; the 3D scene and the cross-feed profile on the
 * cylinder; inch mode. Expected values come from the solver core itself. Runs the production site
 * under the strict Content-Security-Policy and records every violation.
 */
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import {
  type CylinderSurface,
  compareForward,
  exactForward,
  exactInverse,
  forwardInput,
  inverseInput,
  minConcaveRadiusMm,
  type ToolInput,
} from '../../src/core/index';
import { formatInputNumber, fromMm } from '../../src/core/input/units';
import { LOOKUP_HEADER } from '../../src/core/output/lookupTable';
import { headerInUnit } from '../../src/core/output/lookupUnits';
import { scallopHeightForRaMm } from '../../src/core/roughness/roughness';
import { formatLenUnit, formatSignedLenUnit } from '../../src/ui/format';
import { keepShot, paintedFraction, STRICT_CSP, useSite } from './harness';

const site = useSite('docs/cylinder', { build: 'production', headers: { 'Content-Security-Policy': STRICT_CSP } });

const TOOL: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
const cyl = (radiusMm: number, axis: 'feed' | 'cross'): CylinderSurface => ({ kind: 'cylinder', radiusMm, axis });
const text = async (page: Page, id: string) => (await page.getByTestId(id).textContent())?.trim() ?? '';
const DASH = '\u2014';

/** The file's tab, shared by its tests (each open is a fresh document in it), and where its errors go. */
let shared: Page | null = null;
let pageErrors: string[] = [];

/**
 * Opens a page that records every CSP violation and counts the URL writes (both recorders are
 * injected by the test, not shipped), in the file's shared tab.
 */
async function open(query: string): Promise<{ page: Page; violations: () => Promise<string[]>; errors: string[] }> {
  if (shared === null || shared.isClosed()) {
    const created = await site.browser().newPage({ viewport: { width: 1400, height: 1000 } });
    created.on('pageerror', (e) => pageErrors.push(e.message));
    created.on('console', (m) => {
      if (m.type() === 'error' || /Content Security Policy|Refused to/i.test(m.text())) pageErrors.push(m.text());
    });
    await created.addInitScript(() => {
      const seen: string[] = [];
      (window as unknown as { __violations: string[] }).__violations = seen;
      document.addEventListener('securitypolicyviolation', (e) => seen.push(`${e.violatedDirective}: ${e.blockedURI}`));
      const w = window as unknown as { __urlWrites: number };
      w.__urlWrites = 0;
      const replace = history.replaceState.bind(history);
      history.replaceState = (...args: Parameters<History['replaceState']>) => {
        w.__urlWrites++;
        replace(...args);
      };
    });
    shared = created;
  } else if (shared.url() !== 'about:blank') await shared.goto('about:blank');
  const page = shared;
  const errors: string[] = [];
  pageErrors = errors;
  await page.goto(`${site.url()}${query}`);
  await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
  const violations = () => page.evaluate(() => (window as unknown as { __violations: string[] }).__violations);
  return { page, violations, errors };
}

const radio = (page: Page, group: string, value: string) =>
  page.locator(`[data-testid="${group}"] input[value="${value}"]`);

describe('curved surfaces on the page', () => {
  it('a user picks convex, types a radius, switches the axis: L and the comparison rows are the core values', async () => {
    site.noScene();
    const { page, violations, errors } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    // A plane: no radius, no axis, none in the URL.
    expect(await page.getByTestId('input-surface-radius').isVisible()).toBe(false);
    expect(await page.getByTestId('surface-axis').isVisible()).toBe(false);
    await radio(page, 'surface-kind', 'convex').check();
    expect(await page.getByTestId('input-surface-radius').isVisible()).toBe(true);
    expect(await page.getByTestId('slider-surface-radius').isVisible()).toBe(true);
    await page.getByTestId('input-surface-radius').fill('20');
    const feed = forwardInput(TOOL, 'one-way', 0.05, cyl(20, 'feed'));
    const e = exactForward(feed);
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(e.intervalMm, 'mm'));
    expect(await text(page, 'result-width-right')).toBe(formatLenUnit(e.halfWidthRightMm, 'mm'));
    // The comparison rows: the plane's answer (curvature ignored) and the corrected procedures.
    const k = compareForward(feed).curvature;
    if (k === null || !k.plane.ok || !k.corrected.redonnet.ok) throw new Error('rows apply');
    expect(await text(page, 'result-plane-half')).toBe(formatLenUnit(k.plane.halfIntervalMm, 'mm'));
    expect(await text(page, 'result-redonnetCorrected-half')).toBe(
      formatLenUnit(k.corrected.redonnet.halfIntervalMm, 'mm'),
    );
    expect(await page.locator('tr[data-curvature="plane"] th').textContent()).toBe('Plane, exact (curvature ignored)');
    const planeRow = await page.locator('tr[data-curvature="plane"] td').allTextContents();
    expect(planeRow[1]).toBe(formatSignedLenUnit(k.plane.deviationMm / 2, 'mm'));
    expect(await text(page, 'surface-meaning')).toMatch(/convex cylinder .* arc lengths on the surface/);
    await expect.poll(() => new URL(page.url()).searchParams.get('surfaceRadius')).toBe('20');
    expect(new URL(page.url()).searchParams.get('surfaceAxis')).toBe('feed');
    // Across the feed.
    await radio(page, 'surface-axis', 'cross').check();
    const cross = exactForward(forwardInput(TOOL, 'one-way', 0.05, cyl(20, 'cross')));
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(cross.intervalMm, 'mm'));
    await expect.poll(() => new URL(page.url()).searchParams.get('surfaceAxis')).toBe('cross');
    // Back to a plane: the paper's answer, and nothing about a surface in the URL.
    await radio(page, 'surface-kind', 'plane').check();
    const plane = exactForward(forwardInput(TOOL, 'one-way', 0.05));
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(plane.intervalMm, 'mm'));
    await expect.poll(() => new URL(page.url()).search).not.toMatch(/surface/);
    expect(await page.locator('tr[data-curvature]').count()).toBe(0);
    expect(await violations()).toEqual([]);
    expect(errors).toEqual([]);
  });

  it('a concave cylinder too tight: the gouging message with the limit on the radius field, dashes elsewhere', async () => {
    site.noScene();
    const { page, violations } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&surfaceRadius=-30&surfaceAxis=feed');
    await expect.poll(() => text(page, 'result-exact-interval')).toMatch(/\d/);
    expect(await radio(page, 'surface-kind', 'concave').isChecked()).toBe(true);
    expect(await page.getByTestId('input-surface-radius').inputValue()).toBe('30');
    await page.getByTestId('input-surface-radius').fill('20');
    const limit = minConcaveRadiusMm(TOOL, 'feed');
    await expect
      .poll(() => text(page, 'error-surface-radius'))
      .toBe(
        `Surface radius Rs: a concave cylinder must have a radius of at least ${formatInputNumber(limit)} mm for this tool and posture (got 20); a tighter one is gouged (the tool reaches below the surface away from the contact).`,
      );
    for (const id of [
      'result-exact-interval',
      'result-exact-half',
      'result-width-right',
      'result-width-left',
      'result-contact-offset',
      'result-rz',
      'result-ra',
      'table-exact-half',
      'result-sekine-half',
    ])
      expect(await text(page, id), id).toBe(DASH);
    expect(await page.getByTestId('input-surface-radius').getAttribute('aria-invalid')).toBe('true');
    // The slider starts at the limit, rounded up to its step.
    expect(Number(await page.getByTestId('slider-surface-radius').getAttribute('min'))).toBe(
      Math.ceil(limit / 0.1) * 0.1,
    );
    await keepShot(page, 'cylinder-gouging');
    // Wide enough again: an answer.
    await page.getByTestId('input-surface-radius').fill('25');
    const e = exactForward(forwardInput(TOOL, 'one-way', 0.05, cyl(-25, 'feed')));
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(e.intervalMm, 'mm'));
    expect(await text(page, 'error-surface-radius')).toBe('');
    expect(await violations()).toEqual([]);
  });

  it('the lookup table of a concave cylinder that a flat bottom lying flat gouges: saved, named by its surface, cells on the cylinder', async () => {
    site.noScene();
    const { page, violations, errors } = await open(
      '?R=3&Rcr=1&rho=5&h=0.05&unit=mm&surfaceRadius=-30&surfaceAxis=cross',
    );
    await expect.poll(() => text(page, 'result-exact-interval')).toBe('3.0381 mm');
    const button = page.getByTestId('download-table');
    await expect.poll(() => button.isEnabled()).toBe(true);
    const downloaded = page.waitForEvent('download');
    await button.click();
    // The status says what was saved (before the fix: "No table: This tool gouges ...").
    await expect
      .poll(() => text(page, 'download-table-status'), { timeout: 15_000 })
      .toMatch(/^Saved step-over-table_5-axis_R3_Rcr1_one-way_Rs-30_cross_mm\.csv: 780 rows/);
    const download = await downloaded;
    expect(download.suggestedFilename()).toBe('step-over-table_5-axis_R3_Rcr1_one-way_Rs-30_cross_mm.csv');
    const [head, ...rows] = parseCsv(readFileSync(await download.path(), 'utf8')).filter((r) => !r.blank);
    const header = headerInUnit(LOOKUP_HEADER, 'mm');
    expect(head?.fields.join(',')).toBe(header);
    const col = (name: string) => header.split(',').indexOf(name);
    const at = rows.find((r) => r.fields.slice(2, 5).join(',') === '5,0.05,0');
    const e = exactForward(forwardInput(TOOL, 'one-way', 0.05, cyl(-30, 'cross')));
    expect(Math.abs(Number(at?.fields[col('interval_mm')]) - e.intervalMm)).toBeLessThanOrEqual(1e-13 * e.intervalMm);
    expect(
      rows.every((r) => r.fields[col('surfaceRadius_mm')] === '-30' && r.fields[col('surfaceAxis')] === 'cross'),
    ).toBe(true);
    expect(await violations()).toEqual([]);
    expect(errors).toEqual([]);
  });

  it('the URL round-trips (and the embedded page links the full calculator with the same surface)', async () => {
    site.noScene();
    const query = '?R=3&Rcr=1&rho=5&tilt=4&pattern=zigzag&surfaceRadius=-80&surfaceAxis=cross&h=0.03&unit=mm';
    const { page } = await open(query);
    const e = exactForward(forwardInput({ ...TOOL, tiltAngleDeg: 4 }, 'zigzag', 0.03, cyl(-80, 'cross')));
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(e.intervalMm, 'mm'));
    expect(await radio(page, 'surface-kind', 'concave').isChecked()).toBe(true);
    expect(await radio(page, 'surface-axis', 'cross').isChecked()).toBe(true);
    // The URL is written once the inputs settle (urlState.ts): wait for that write.
    await expect.poll(() => page.evaluate(() => (window as unknown as { __urlWrites: number }).__urlWrites)).toBe(1);
    expect(new URL(page.url()).search).toBe(query);
    const embedded = await open(`${query}&embed=1`);
    const href = (await embedded.page.getByTestId('open-full').getAttribute('href')) ?? '';
    expect(href).toBe(query);
    // Inverse mode on the cylinder: the cusp height of the core.
    const inv = await open('?R=3&Rcr=1&rho=5&surfaceRadius=50&surfaceAxis=feed&mode=inverse&L=2.5&unit=mm');
    const h = exactInverse(inverseInput(TOOL, 'one-way', 2.5, cyl(50, 'feed'))).cuspHeightMm;
    await expect.poll(() => text(inv.page, 'result-exact-height')).toBe(formatLenUnit(h, 'mm', 'height'));
    expect(await text(inv.page, 'result-plane-h')).toMatch(/\d/);
  });

  it('inch mode: the radius in inches like the other lengths, and L in inches', async () => {
    site.noScene();
    const { page, violations } = await open(
      '?R=0.11811&Rcr=0.03937&rho=5&h=0.002&unit=in&surfaceRadius=-2&surfaceAxis=feed',
    );
    const tool = { ...TOOL, toolRadiusMm: 0.11811 * 25.4, cornerRadiusMm: 0.03937 * 25.4 };
    const e = exactForward(forwardInput(tool, 'one-way', 0.002 * 25.4, cyl(-2 * 25.4, 'feed')));
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(e.intervalMm, 'in'));
    expect(await text(page, 'surface-meaning')).toMatch(/radius 2\.00000 in/);
    // A too-tight trough: the limit in inches.
    await page.getByTestId('input-surface-radius').fill('0.5');
    const limit = minConcaveRadiusMm(tool, 'feed');
    await expect
      .poll(() => text(page, 'error-surface-radius'))
      .toMatch(`at least ${formatInputNumber(fromMm(limit, 'in'))} in for this tool`);
    await page.getByTestId('input-surface-radius').fill('2');
    await expect.poll(() => text(page, 'result-exact-interval')).toMatch(/ in$/);
    // To mm: converted, and the URL follows.
    await page.locator('input[name="unit"][value="mm"]').check();
    await expect.poll(() => page.getByTestId('input-surface-radius').inputValue()).toBe('50.8');
    await expect.poll(() => new URL(page.url()).searchParams.get('surfaceRadius')).toBe('-50.8');
    expect(await violations()).toEqual([]);
  });

  it('the 3D scene and the cross-feed profile show the cylinder, convex along the feed and concave across', async () => {
    for (const [query, axis] of [
      ['?R=3&Rcr=1&rho=5&tilt=5&h=0.05&unit=mm&surfaceRadius=12&surfaceAxis=feed&view=profile', 'feed'],
      ['?R=3&Rcr=1&rho=5&h=0.05&unit=mm&surfaceRadius=-60&surfaceAxis=cross&view=profile', 'cross'],
    ] as const) {
      const { page, violations, errors } = await open(query);
      const view = page.getByTestId('profile-view');
      await view.locator('[data-testid="profile-surface"]').waitFor({ state: 'attached' });
      expect(await text(page, 'profile-cylinder-note')).toMatch(
        axis === 'feed' ? /axis along the feed: each pass leaves the plane profile/ : /revolved about the axis/,
      );
      // The design surface is curved in the section with the axis along the feed, straight across it.
      const ys = (await view.locator('[data-testid="profile-surface"]').getAttribute('points'))
        ?.trim()
        .split(/\s+/)
        .map((p) => Number(p.split(',')[1]));
      const spread = Math.max(...(ys ?? [0])) - Math.min(...(ys ?? [0]));
      if (axis === 'feed') expect(spread).toBeGreaterThan(0.05);
      else expect(spread).toBeLessThan(1e-9);
      expect(await view.locator('polyline.curve-exact').count()).toBe(3);
      expect(await view.locator('[data-testid="profile-h-surface"]').count()).toBe(1);
      expect(await view.locator('polyline[data-curvature]').count()).toBeGreaterThan(1);
      const e = exactForward(
        forwardInput(
          { ...TOOL, tiltAngleDeg: axis === 'feed' ? 5 : 0 },
          'one-way',
          0.05,
          cyl(axis === 'feed' ? 12 : -60, axis),
        ),
      );
      await expect
        .poll(() => view.locator('text.dim-text').allTextContents())
        .toEqual(
          expect.arrayContaining([`L = ${formatLenUnit(e.intervalMm, 'mm')}${axis === 'feed' ? ' (arc)' : ''}`]),
        );
      await keepShot(view, `cylinder-profile-${axis}`);
      // The scene: the cusps on the h pseudo surface, the legend for a cylinder, something drawn.
      const labels = () =>
        page
          .locator('.scene-labels .scene-label')
          .evaluateAll((els) =>
            els.filter((x) => (x.parentElement as HTMLElement).style.display !== 'none').map((x) => x.textContent),
          );
      await expect.poll(labels).toEqual(expect.arrayContaining(['cusp R', 'cusp L', 'CC (P_base)']));
      expect(await labels()).not.toContain('P_hp R');
      expect(await page.locator('.legend .cylinder-only').isVisible()).toBe(true);
      expect(await page.locator('.legend .plane-only').isVisible()).toBe(false);
      expect(await paintedFraction(page)).toBeGreaterThan(0.05);
      await keepShot(page.getByTestId('scene'), `cylinder-scene-${axis}`);
      // The views that cannot show a cylinder say so.
      await page.getByRole('tab', { name: '3D procedure, step by step' }).click();
      await expect.poll(() => text(page, 'stepper-caption')).toMatch(/shown for a plane only/);
      await page.getByRole('tab', { name: 'Machined surface' }).click();
      await expect.poll(() => page.getByTestId('surface-view').textContent()).toMatch(/planes only/);
      await page.getByRole('tab', { name: 'Formulas' }).click();
      await expect.poll(() => text(page, 'formulas-cylinder-note')).toMatch(/solved on the cylinder itself/);
      await page.getByRole('tab', { name: 'L against lead and tilt' }).click();
      await expect
        .poll(() => text(page, 'chart-summary'))
        .toMatch(new RegExp(`Exact \\(3D\\) ${formatLenUnit(e.intervalMm, 'mm').replace('.', '\\.')}.*cylinder's`));
      expect(await violations()).toEqual([]);
      expect(errors).toEqual([]);
    }
  }, 120_000);

  it('a target Ra: solved on a cylinder along the feed and across it, the step-over of the core, within the watchdog', async () => {
    site.noScene();
    const { page } = await open('?R=3&Rcr=1&rho=5&target=ra&ra=0.01&unit=mm&surfaceRadius=50&surfaceAxis=feed');
    await expect.poll(() => text(page, 'result-exact-interval')).toMatch(/\d mm$/);
    await radio(page, 'surface-axis', 'cross').check();
    // The core's answer (it once took about 3 s, beyond the worker's 3 s watchdog, and was refused).
    const surface = cyl(50, 'cross');
    const h = scallopHeightForRaMm(TOOL, 'one-way', 0.01, surface);
    const e = exactForward(forwardInput(TOOL, 'one-way', h, surface));
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(formatLenUnit(e.intervalMm, 'mm'));
    expect(await text(page, 'result-ra-height')).toBe(formatLenUnit(h, 'mm', 'height'));
    expect(await text(page, 'error-ra')).toBe('');
    // No worker was restarted on the way (a restart says so in the notice).
    expect(await text(page, 'notice')).toBe('');
  });
});
