/**
 * Units everywhere (issue 21), at 1440 x 900, light, in mm and in inch: every length the page
 * shows carries its unit (the results panel and its tables, plane and cylinder, forward and
 * inverse; the profile's labels and scale bars; the formulas' values; the chart legends; the
 * paper's tables; the Machined surface view), no exponent notation, and roughness reads the same
 * in the results and in the Machined surface view (µm in mm, µin in inch).
 *
 * The scan reads the text of each region's value elements and finds every number in it; each must
 * be followed by a length unit, or be one of the dimensionless quantities listed in DIMENSIONLESS
 * (angles, percentages, counts), or sit in a table column whose header names its unit.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { axeViolations } from './axe';
import { keepShot, pageSettled, showView, typeInto, useSite } from './harness';

const site = useSite('docs/units', { scene: false });
const VIEWPORT = { width: 1440, height: 900 };

/** A length unit right after a number (with or without a space). */
const LENGTH_UNIT = /^\s?(mm|in|\u00b5m|thou|\u00b5in)(?![A-Za-z])/;

/**
 * The dimensionless quantities a number may be, by what follows it: an angle (`°`, MathML's
 * ring operator `∘`, `deg`), a percentage, or a count (the simulation's `512 x 512 cells, 5 passes`).
 */
const DIMENSIONLESS: readonly RegExp[] = [/^\s?(°|\u2218|deg\b)/, /^\s?%/, /^ x \d/, /^ cells\b/, /^ passes\b/];

/**
 * A number as text: not part of a name (`L/2`, `h/4`, `2R`, `x20`, `3D`, `P_hp`, `Eqs. 4-8`
 * keep their digits out: the digit touches a letter, a slash, or a hyphen between digits).
 */
const NUMBER = /(?<![A-Za-z_\d./-])[+\-\u2212]?\d+(?:\.\d+)?(?:e[+-]?\d+)?(?![A-Za-z_\d/]|-\d|\.\d)/g;

/** Table column headers whose numbers are dimensionless by what they count. */
const COUNT_COLUMNS = new Set(['Table']);

interface Shown {
  /** The element's text. */
  readonly text: string;
  /** Where it is (for the failure message). */
  readonly where: string;
  /** A table cell's column header and its table's caption, if any. */
  readonly header?: string;
}

/** Every number of `shown` that has no unit after it and is not dimensionless: `where: text`. */
function unitless(shown: readonly Shown[]): string[] {
  const bad: string[] = [];
  for (const s of shown) {
    const header = s.header ?? '';
    if (COUNT_COLUMNS.has(header.split('|')[0]?.trim() ?? '')) continue;
    for (const m of s.text.matchAll(NUMBER)) {
      const after = s.text.slice((m.index ?? 0) + m[0].length);
      if (/e[+-]?\d/.test(m[0])) bad.push(`${s.where}: exponent notation in "${s.text}"`);
      else if (LENGTH_UNIT.test(after) || DIMENSIONLESS.some((r) => r.test(after))) continue;
      // A cell under a header (or a caption) that names the unit: `[mm]`, `[%]`, `[°]`.
      else if (/\[(mm|in|%|\u00b0)\]/.test(header)) continue;
      else bad.push(`${s.where}: "${m[0]}" without a unit in "${s.text}"`);
    }
  }
  return bad;
}

/**
 * The visible value texts of the page's result regions: the results panel (outputs, table cells,
 * the roughness note), the open view's labels (profile SVG texts and scale bars, the formulas'
 * filled slots with what follows them, the chart legends and summary, the paper's table cells,
 * the Machined surface view's legend, trace and comparison line).
 */
function shownTexts(page: Page): Promise<Shown[]> {
  return page.evaluate(() => {
    const visible = (e: Element) => e.getClientRects().length > 0 && !e.closest('[hidden]');
    const out: Array<{ text: string; where: string; header?: string }> = [];
    const add = (selector: string, where: string) => {
      for (const e of document.querySelectorAll(selector))
        if (visible(e)) out.push({ text: (e.textContent ?? '').trim(), where: `${where} ${selector}` });
    };
    add('.results output', 'results');
    add('[data-testid="result-ra-rule"]', 'results');
    add('[data-testid="result-percent-diameter"]', 'results');
    add('[data-testid="surface-meaning"]', 'results');
    for (const td of document.querySelectorAll('table td')) {
      if (!visible(td)) continue;
      const tr = td.parentElement as HTMLTableRowElement;
      const table = td.closest('table') as HTMLTableElement;
      const index = [...tr.children].indexOf(td);
      const head = table.querySelector('thead tr')?.children[index]?.textContent ?? '';
      const caption = table.querySelector('caption')?.textContent ?? '';
      out.push({ text: (td.textContent ?? '').trim(), where: `table "${head}"`, header: `${head}|${caption}` });
    }
    add('[data-testid="profile-view"] svg text', 'profile');
    add('[data-testid="profile-scale"]', 'profile');
    // A formula's slot with what follows it (an angle's degree sign is the next MathML element).
    for (const slot of document.querySelectorAll('[data-testid="formulas"] [class^="slot-"]'))
      if (visible(slot))
        out.push({
          text: `${slot.textContent ?? ''}${slot.nextElementSibling?.textContent ?? ''}`.trim(),
          where: `formulas .${slot.className}`,
        });
    add('.legend-value', 'chart');
    add('[data-testid="chart-summary"]', 'chart');
    add('[data-testid="surface-legend"] text', 'surface');
    add('[data-testid="surface-trace"] text', 'surface');
    add('[data-testid="surface-comparison"]', 'surface');
    add('[data-testid="surface-exaggeration"]', 'surface');
    return out;
  });
}

const text = async (page: Page, id: string) => (await page.getByTestId(id).textContent())?.trim() ?? '';

/**
 * Shows a state with a view, waits until the page is quiet (every view and worker done). One load
 * per state (these tests change no input): its views by their tabs.
 */
async function openQuiet(query: string, view: string): Promise<Page> {
  const { page, errors } = await site.reuse(query, VIEWPORT, 'light');
  await showView(page, view);
  if (view === 'surface')
    await page
      .getByTestId('surface-comparison')
      .filter({ hasText: /Simulated cusp/ })
      .waitFor({ timeout: 30_000 });
  if (view === 'formulas') await page.getByTestId('formulas').locator('math').first().waitFor();
  await pageSettled(page);
  expect(errors).toEqual([]);
  return page;
}

/** The scan of the page as it is: no number without its unit. */
async function expectUnits(page: Page, label: string): Promise<void> {
  const shown = await shownTexts(page);
  // The scan read something of each region it was asked about (a broken selector would pass).
  expect(shown.length, label).toBeGreaterThan(10);
  expect(unitless(shown), label).toEqual([]);
}

const MM_PLANE = '?R=3&Rcr=1&rho=5&h=0.005&unit=mm';
const IN_PLANE = '?R=0.125&Rcr=0.04&rho=5&h=0.0002&unit=in';

describe('every shown length carries its unit (1440 x 900, light)', () => {
  it('the scan itself: a bare length fails it, units, angles, percentages, counts and headed columns pass', () => {
    expect(unitless([{ text: 'L/2 = 0.4861', where: 'x' }])).toHaveLength(1);
    expect(unitless([{ text: '+4.219e-7', where: 'x', header: 'Deviation [mm]|' }])).toHaveLength(1);
    expect(
      unitless([
        { text: 'L/2 = 0.4861 mm', where: 'a' },
        { text: 'h = 5.000 \u00b5m, Ra 51.19 \u00b5in, 0.2000 thou, 0.04 in', where: 'b' },
        { text: 'Rule of thumb Ra ~ h/4 = 1.250 \u00b5m: -2.31 % against the exact Ra.', where: 'c' },
        { text: '30 deg, 5.1\u00b0, 12\u2218, (512 x 512 cells, 5 passes), x20', where: 'd' },
        { text: '-29.31', where: 'e', header: 'Deviation [%]|' },
        { text: '2', where: 'f', header: 'Table|Tables 2-3: L/2 [mm] for h' },
        { text: 'Sekine et al. (Eqs. 4-8), Exact (3D), P_hp R', where: 'g' },
      ]),
    ).toEqual([]);
  });

  it('mm: plane with the profile, the formulas and the chart; cylinder; inverse with the paper tables', async () => {
    let page = await openQuiet(MM_PLANE, 'profile');
    expect(await text(page, 'result-exact-half')).toBe('0.4861 mm');
    expect(await page.getByTestId('profile-view').locator('svg text').allTextContents()).toEqual(
      expect.arrayContaining(['h = 5.000 \u00b5m', 'L/2 = 0.4861 mm', 'L = 0.9723 mm']),
    );
    await expectUnits(page, 'mm plane profile');
    await keepShot(page, 'units-mm');

    page = await openQuiet(MM_PLANE, 'formulas');
    await expectUnits(page, 'mm plane formulas');
    await keepShot(page.getByTestId('formulas'), 'units-formulas-mm');
    page = await openQuiet(MM_PLANE, 'chart');
    await expectUnits(page, 'mm plane chart');

    page = await openQuiet(`${MM_PLANE}&surfaceRadius=20&surfaceAxis=feed`, 'profile');
    await expectUnits(page, 'mm convex cylinder profile');
    page = await openQuiet(`${MM_PLANE}&feedRadius=80&crossRadius=40`, 'chart');
    await expectUnits(page, 'mm doubly curved point chart');
    page = await openQuiet('?R=3&Rcr=1&h=0.005&unit=mm&machine=3axis&slope=30', 'chart');
    await expectUnits(page, 'mm three-axis chart');

    // Inverse: tiny deviations in µm, never `+1.981e-7`.
    page = await openQuiet('?R=3&Rcr=1&rho=5&L=0.5&mode=inverse&unit=mm', 'tables');
    expect(await text(page, 'result-exact-height')).toBe('1.309 \u00b5m');
    const bedi = await page.locator('.procedures tr[data-procedure="bedi"] td').allTextContents();
    expect(bedi[1]).toBe('+0.0001981 \u00b5m');
    await expectUnits(page, 'mm inverse tables');
    // A number and its unit on one line in the results table, and still no horizontal scrolling.
    expect(await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth)).toBe(
      0,
    );
    await keepShot(page, 'units-mm-inverse');
  }, 240_000);

  it('inch: plane with the profile and the formulas; cylinder; inverse', async () => {
    let page = await openQuiet(IN_PLANE, 'profile');
    expect(await text(page, 'result-exact-half')).toBe('0.02003 in');
    expect(await text(page, 'result-rz')).toBe('200.0 \u00b5in');
    await expectUnits(page, 'inch plane profile');
    await keepShot(page, 'units-in');

    page = await openQuiet(IN_PLANE, 'formulas');
    await expectUnits(page, 'inch plane formulas');
    page = await openQuiet(`${IN_PLANE}&surfaceRadius=-2&surfaceAxis=cross`, 'chart');
    await expectUnits(page, 'inch concave cylinder chart');
    page = await openQuiet('?R=0.125&Rcr=0.04&rho=5&L=0.02&mode=inverse&unit=in', 'profile');
    await expectUnits(page, 'inch inverse');
  }, 240_000);
});

describe('the results and the Machined surface view agree on roughness', () => {
  for (const [unit, query, symbol] of [
    ['mm', MM_PLANE, '\u00b5m'],
    ['in', IN_PLANE, '\u00b5in'],
  ] as const)
    it(`${unit}: Rz, Ra, Rq the same value in the same unit (${symbol}) in both, every length with its unit`, async () => {
      const page = await openQuiet(query, 'surface');
      const results = {
        Rz: await text(page, 'result-rz'),
        Ra: await text(page, 'result-ra'),
        Rq: await text(page, 'result-rq'),
      };
      const caption = (await page.getByTestId('surface-trace').locator('text.trace-caption').textContent()) ?? '';
      for (const [name, value] of Object.entries(results)) {
        expect(value, name).toMatch(new RegExp(`^\\d+\\.\\d+ ${symbol}$`));
        // The trace's caption gives the exact roughness: the results' text, character for character.
        expect(caption, name).toContain(`${name} ${value}`);
      }
      // The simulated marks and the colour legend in the same unit.
      const marks = await page.getByTestId('surface-trace').locator('text').allTextContents();
      for (const name of ['Rz', 'Ra', 'Rq'])
        expect(marks.join(' | '), name).toMatch(new RegExp(`${name} \\d+\\.\\d+ ${symbol}`));
      expect(await text(page, 'surface-legend')).toMatch(new RegExp(`${symbol}.*${symbol}.*${symbol}`));
      expect(await text(page, 'surface-exaggeration')).toContain(`(${symbol})`);
      await expectUnits(page, `${unit} surface`);
      await keepShot(page, `units-surface-${unit}`, { fullPage: true });
      if (unit === 'in') {
        expect(await axeViolations(page)).toEqual([]);
      }
    }, 120_000);
});

/** Shown text that is not a number the page may show: NaN, Infinity, or a negative zero. */
const NOT_A_NUMBER = /NaN|Infinity|(?<![\d.])-0(?:\.0+)?(?![\d.])/;

describe('one rule for each kind of number, and the unit switch (issue 28 point 11; 1440 x 900, light)', () => {
  it('computed angles side by side with two decimals each (three-axis raster)', async () => {
    const { page, errors } = await site.open(
      '?D=6&Rcr=1&h=0.005&unit=mm&machine=3axis&slope=30&rasterAngle=30',
      VIEWPORT,
      'light',
    );
    const angle = /^\d{1,2}\.\d{2} deg$/;
    await expect.poll(() => text(page, 'result-equivalent-lead')).toMatch(angle);
    expect(await text(page, 'result-equivalent-tilt')).toMatch(angle);
    expect(await page.locator('.results').textContent()).not.toMatch(NOT_A_NUMBER);
    expect(errors).toEqual([]);
  }, 60_000);

  it('Rz reads as the scallop in the table; mm -> inch gives the round defaults, and an edited h comes back as typed', async () => {
    const { page, errors } = await site.open('', VIEWPORT, 'light');
    const field = (id: string) => page.getByTestId(`input-${id}`).inputValue();
    const unit = (u: 'mm' | 'in') => page.locator(`input[name="unit"][value="${u}"]`).check();
    await expect.poll(() => text(page, 'result-rz')).toBe('50.00 \u00b5m');
    expect(await text(page, 'table-exact-real-h')).toBe('50.00 \u00b5m');
    // Untouched defaults: the inch page's own, never 0.23622 / 0.0393701 / 0.0019685 / 3.14961.
    await unit('in');
    await expect.poll(() => field('R')).toBe('0.25');
    expect([await field('Rcr'), await field('h'), await field('feed-radius'), await field('cross-radius')]).toEqual([
      '0.03',
      '0.002',
      '3',
      '1.5',
    ]);
    await expect.poll(() => text(page, 'result-rz')).toBe('2000 \u00b5in');
    await expect.poll(() => text(page, 'table-exact-real-h')).toBe('2.000 thou');
    expect(await page.locator('.results').textContent()).not.toMatch(NOT_A_NUMBER);
    await keepShot(page, 'units-switch-inch-defaults');
    // And back: the mm defaults.
    await unit('mm');
    await expect.poll(() => field('R')).toBe('6');
    expect([await field('Rcr'), await field('h')]).toEqual(['1', '0.05']);
    // An edited h: converted without loss, back exactly as typed (to its last zero).
    await typeInto(page, 'input-h', '0.01230');
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, 'result-rz')).toBe('12.30 \u00b5m');
    await unit('in');
    await expect.poll(() => field('R')).toBe('0.25');
    const inch = Number(await field('h'));
    expect(Math.abs(inch * 25.4 - 0.0123)).toBeLessThan(1e-12 * 0.0123);
    await expect.poll(() => text(page, 'result-rz')).toBe('484.3 \u00b5in');
    await unit('mm');
    await expect.poll(() => field('h')).toBe('0.01230');
    await expect.poll(() => text(page, 'result-rz')).toBe('12.30 \u00b5m');
    expect(await page.locator('.results').textContent()).not.toMatch(NOT_A_NUMBER);
    expect(errors).toEqual([]);
    site.changed();
  }, 90_000);
});
