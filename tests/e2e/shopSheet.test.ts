/**
 * The shop sheet (issue 21), driven as a user would in headless Chromium at 1440 x 900 (clicks)
 * and 390 x 844 (a phone: taps), light and dark: the button opens the matrix of the tool, posture,
 * pattern and surface on screen in the user's unit (mm and inch; five-axis by lead, three-axis by
 * slope), its cells the core's values, refused cells marked with a legend; the CSV downloads with
 * the unit in its header and file name; printed, the sheet alone fits one A4 and one Letter page;
 * axe-core finds no violation on the open sheet. Expected values come from the solver core.
 */
import { readFileSync } from 'node:fs';
import type { BrowserContext, Page } from 'playwright-core';
import { afterAll, describe, expect, it } from 'vitest';
import { forwardInput } from '../../src/core/input/validate';
import { PLANE, type Surface } from '../../src/core/surfaces/cylinder';
import { exactForward } from '../../src/core/surfaces/solve';
import { slopedPlaneForward } from '../../src/core/threeAxis/slopedPlane';
import { formatLen } from '../../src/ui/format';
import { cellText } from '../../src/ui/shopSheetText';
import { axeViolations } from './axe';
import { forgetPreferences, holdScene, keepShot, useSite, viewAs } from './harness';

const site = useSite('shop/sheet', { scene: false });

const PLAIN = '?R=3&Rcr=1&rho=5&h=0.05&unit=mm';
const DESKTOP = { name: 'desktop', width: 1440, height: 900, touch: false } as const;
const PHONE = { name: 'phone', width: 390, height: 844, touch: true } as const;
type Viewport = typeof DESKTOP | typeof PHONE;

/** Per viewport, one context (downloads accepted; touch on the phone) and its one tab, with the query it holds intact (null: changed or none). */
const tabs = new Map<string, { context: BrowserContext; page: Page; errors: string[]; intact: string | null }>();
afterAll(async () => {
  for (const { context } of tabs.values()) await context.close();
});

/** The viewport's tab, opened on first use; a first visit every load (nothing remembered). */
async function tab(
  vp: Viewport,
): Promise<{ context: BrowserContext; page: Page; errors: string[]; intact: string | null }> {
  const found = tabs.get(vp.name);
  if (found !== undefined && !found.page.isClosed()) return found;
  const context = await site.browser().newContext({
    viewport: { width: vp.width, height: vp.height },
    hasTouch: vp.touch,
    isMobile: vp.touch,
    acceptDownloads: true,
  });
  await forgetPreferences(context);
  await holdScene(context);
  const page = await context.newPage();
  const made = { context, page, errors: [] as string[], intact: null as string | null };
  page.on('pageerror', (e) => made.errors.push(e.message));
  page.on('console', (m) => {
    if (m.type() === 'error') made.errors.push(m.text());
  });
  tabs.set(vp.name, made);
  return made;
}

/** A fresh document of `query` in the viewport's tab, in `theme`, the first result shown; its console's errors. */
async function open(vp: Viewport, theme: 'light' | 'dark', query: string): Promise<{ page: Page; errors: string[] }> {
  const t = await tab(vp);
  t.intact = null;
  if (t.page.url() !== 'about:blank') await t.page.goto('about:blank');
  await t.page.emulateMedia({ media: 'screen', colorScheme: theme });
  t.errors = [];
  const errors = t.errors;
  await t.page.goto(`${site.url()}${query}`);
  await t.page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
  return { page: t.page, errors };
}

/**
 * The plain mm state in `vp`'s tab, in `theme`: loaded once for the light and dark tests that share
 * it (they change no input; the sheet closed after each), the second theme by the system's colour
 * scheme on the same document.
 */
async function openPlain(vp: Viewport, theme: 'light' | 'dark'): Promise<{ page: Page; errors: string[] }> {
  const t = await tab(vp);
  if (t.intact !== PLAIN) {
    await open(vp, theme, PLAIN);
    t.intact = PLAIN;
  }
  await viewAs(t.page, vp, theme);
  return { page: t.page, errors: t.errors };
}

/** Taps on the phone, clicks on the desktop. */
async function press(vp: Viewport, page: Page, testId: string): Promise<void> {
  const target = page.getByTestId(testId);
  await target.scrollIntoViewIfNeeded();
  if (vp.touch) await target.tap();
  else await target.click();
}

/** Opens the sheet with its button once the inputs make a valid question. */
async function openSheet(vp: Viewport, page: Page): Promise<void> {
  await expect.poll(() => page.getByTestId('shop-sheet').isEnabled()).toBe(true);
  await press(vp, page, 'shop-sheet');
  await page.getByTestId('shop-sheet-dialog').waitFor({ state: 'visible' });
}

/** The table as the eye reads it: the header row, then each row (its h first); screen-reader-only words left out. */
const tableText = (page: Page) =>
  page.getByTestId('shop-sheet-table').evaluate((t) =>
    [...(t as HTMLTableElement).rows].map((r) =>
      [...r.cells].map((c) => {
        const seen = c.cloneNode(true) as HTMLElement;
        for (const hidden of seen.querySelectorAll('.sr-only')) hidden.remove();
        return (seen.textContent ?? '').trim();
      }),
    ),
  );

/** Downloads the sheet's CSV: its suggested file name and text. */
async function downloadCsv(vp: Viewport, page: Page): Promise<{ name: string; csv: string }> {
  const downloaded = page.waitForEvent('download');
  await press(vp, page, 'shop-sheet-csv');
  const download = await downloaded;
  return { name: download.suggestedFilename(), csv: readFileSync(await download.path(), 'utf8') };
}

/** Pages in a PDF (its /Type /Page objects, not the /Pages tree). */
function pdfPages(pdf: Buffer): number {
  return pdf.toString('latin1').match(/\/Type\s*\/Page(?![s\w])/g)?.length ?? 0;
}

/** The core's L (mm) of the R 3, Rcr 1 tool at a lead, h (mm) and surface, tilt 0, one-way. */
function coreL(leadDeg: number, hMm: number, surface: Surface = PLANE, R = 3, Rcr = 1): number {
  const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: leadDeg, tiltAngleDeg: 0 };
  return exactForward(forwardInput(tool, 'one-way', hMm, surface)).intervalMm;
}

const LEADS = ['0', '2', '5', '10', '15', '20', '30'];

describe('shop sheet', () => {
  for (const vp of [DESKTOP, PHONE])
    for (const theme of ['light', 'dark'] as const)
      it(`mm, a plane (${vp.name}, ${theme}): the core's L by h x lead, the title lines, the CSV, axe`, async () => {
        const { page, errors } = await openPlain(vp, theme);
        await openSheet(vp, page);
        expect(await page.getByTestId('shop-sheet-title').textContent()).toBe('Shop sheet: L (mm)');
        const lines = await page.getByTestId('shop-sheet-lines').locator('p').allTextContents();
        expect(lines.slice(0, 3)).toEqual([
          'Tool: D 6 mm (R 3 mm), corner radius Rcr 1 mm',
          'Five-axis, tilt 0 deg; one-way passes; on a plane',
          'Rows: scallop height h (mm). Columns: lead angle rho (deg). Cells: step-over L between adjacent passes, along the surface (mm).',
        ]);
        expect(lines[3]).toMatch(/^Exact solution, path-interval calculator, \d{4}-\d\d-\d\d\.$/);
        const rows = await tableText(page);
        expect(rows[0]?.slice(1)).toEqual(LEADS);
        const heights = [0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1];
        expect(rows.slice(1).map((r) => r[0])).toEqual(heights.map(String));
        heights.forEach((h, i) => {
          expect(rows[i + 1]?.slice(1), `h ${h}`).toEqual(LEADS.map((lead) => formatLen(coreL(Number(lead), h), 'mm')));
        });
        // The sheet fits the viewport's width (the table scrolls inside it on a phone).
        const box = await page.getByTestId('shop-sheet-dialog').boundingBox();
        expect((box?.x ?? -1) >= 0 && (box?.x ?? 0) + (box?.width ?? 0) <= vp.width).toBe(true);
        await keepShot(page, `shop-sheet-mm-${vp.name}-${theme}`);
        // Seven lead columns without scrolling sideways, on the phone too.
        expect(await page.locator('.sheet-scroll').evaluate((e) => [e.scrollWidth, e.clientWidth])).toSatisfy(
          ([scroll, client]: number[]) => (scroll ?? 1) <= (client ?? 0),
        );
        expect(await axeViolations(page), `${vp.name} ${theme}`).toEqual([]);
        const { name, csv } = await downloadCsv(vp, page);
        expect(name).toBe('shop-sheet_R3_Rcr1_one-way_plane_tilt0_mm.csv');
        const lines2 = csv.trim().split('\n');
        expect(lines2[0]).toBe(`h_mm,${LEADS.map((l) => `L_mm_lead_${l}_deg`).join(',')}`);
        const at = lines2.find((l) => l.startsWith('0.05,'))?.split(',');
        expect(Math.abs(Number(at?.[3]) - coreL(5, 0.05))).toBeLessThanOrEqual(1e-13 * coreL(5, 0.05));
        expect(await page.getByTestId('shop-sheet-status').textContent()).toBe(
          'Saved shop-sheet_R3_Rcr1_one-way_plane_tilt0_mm.csv.',
        );
        // Closed with its button: the page is back, the sheet's class gone.
        await press(vp, page, 'shop-sheet-close');
        await page.getByTestId('shop-sheet-dialog').waitFor({ state: 'hidden' });
        await expect
          .poll(() => page.evaluate(() => document.documentElement.classList.contains('shop-sheet-open')))
          .toBe(false);
        expect(errors).toEqual([]);
      }, 90_000);

  it('mm: the user lists heights; one at or above the limit is a W mark with its legend and reason, a bad list is named', async () => {
    const { page } = await open(DESKTOP, 'light', '?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    await openSheet(DESKTOP, page);
    const field = page.getByTestId('shop-sheet-heights');
    expect(await field.inputValue()).toBe('0.001 0.002 0.005 0.01 0.02 0.05 0.1');
    await field.fill('0,05 1.5 0.01');
    await field.press('Enter');
    await expect.poll(async () => (await tableText(page)).slice(1).map((r) => r[0])).toEqual(['0.01', '0.05', '1.5']);
    const rows = await tableText(page);
    // Lead 0: the limit is Rcr = 1 mm; at lead 30 it is (R - Rcr) sin 30 + Rcr = 2 mm.
    expect(rows[3]?.[1]).toBe('W');
    expect(rows[3]?.[7]).toBe(formatLen(coreL(30, 1.5), 'mm'));
    expect(await page.getByTestId('shop-sheet-table').locator('td.refused').first().getAttribute('title')).toMatch(
      /^Scallop height h must be below .* = 1 mm \(got 1\.5\)/,
    );
    expect(await page.getByTestId('shop-sheet-legend').textContent()).toMatch(/W: h at or above this posture's limit/);
    await field.fill('0.01 abc');
    await field.press('Enter');
    expect(await page.getByTestId('shop-sheet-heights-error').textContent()).toBe(
      'Scallop heights: give 1 to 12 scallop heights above 0 mm, separated by spaces (got "abc").',
    );
    expect(await field.getAttribute('aria-invalid')).toBe('true');
    // The last good sheet stays; no NaN anywhere.
    expect((await tableText(page)).length).toBe(4);
    expect(await page.getByTestId('shop-sheet-dialog').textContent()).not.toMatch(/NaN|Infinity/);
    await keepShot(page, 'shop-sheet-heights-desktop');
  }, 90_000);

  for (const vp of [DESKTOP, PHONE])
    it(`inch, a concave cylinder (${vp.name}, dark): inches everywhere, gouging marked G; the CSV names inches`, async () => {
      const { page, errors } = await open(
        vp,
        'dark',
        '?R=0.125&Rcr=0.03125&rho=5&h=0.0005&unit=in&surfaceRadius=-1.25&surfaceAxis=cross',
      );
      await openSheet(vp, page);
      expect(await page.getByTestId('shop-sheet-title').textContent()).toBe('Shop sheet: L (in)');
      const lines = await page.getByTestId('shop-sheet-lines').locator('p').allTextContents();
      expect(lines[0]).toBe('Tool: D 0.25 in (R 0.125 in), corner radius Rcr 0.03125 in');
      expect(lines[1]).toBe(
        'Five-axis, tilt 0 deg; one-way passes; on a concave cylinder, Rs 1.25 in, axis across the feed',
      );
      const rows = await tableText(page);
      expect(rows.slice(1).map((r) => r[0])).toEqual(['0.0001', '0.0002', '0.0005', '0.001', '0.002', '0.005']);
      // A flat bottom lying flat (lead 0) gouges a concave cylinder: G; the others on the cylinder, in inches.
      expect(rows.slice(1).map((r) => r[1])).toEqual(Array(6).fill('G'));
      const cyl: Surface = { kind: 'cylinder', radiusMm: -31.75, axis: 'cross' };
      expect(rows[3]?.[3]).toBe(
        cellText({ ok: true, stepMm: coreL(5, 0.0005 * 25.4, cyl, 3.175, 0.79375), noScallop: false }, 'in'),
      );
      expect(await page.getByTestId('shop-sheet-legend').textContent()).toMatch(/G: the tool gouges the surface/);
      await keepShot(page, `shop-sheet-inch-${vp.name}-dark`);
      expect(await axeViolations(page)).toEqual([]);
      const { name, csv } = await downloadCsv(vp, page);
      expect(name).toBe('shop-sheet_R0.125_Rcr0.03125_one-way_Rs-1.25_cross_tilt0_in.csv');
      const [head, ...body] = csv.trim().split('\n');
      expect(head).toBe(`h_in,${LEADS.map((l) => `L_in_lead_${l}_deg`).join(',')}`);
      expect(body[2]?.split(',').slice(0, 2)).toEqual(['0.0005', 'gouges']);
      const L = coreL(5, 0.0005 * 25.4, cyl, 3.175, 0.79375) / 25.4;
      expect(Math.abs(Number(body[2]?.split(',')[3]) - L)).toBeLessThanOrEqual(1e-12 * L);
      expect(errors).toEqual([]);
    }, 90_000);

  for (const vp of [DESKTOP, PHONE])
    it(`three-axis raster (${vp.name}): columns are slopes, cells Lxy as programmed`, async () => {
      const { page, errors } = await open(
        vp,
        'light',
        '?R=3&Rcr=1&machine=3axis&slope=20&rasterAngle=0&h=0.05&unit=mm',
      );
      await openSheet(vp, page);
      expect(await page.getByTestId('shop-sheet-title').textContent()).toBe('Shop sheet: Lxy (mm)');
      const lines = await page.getByTestId('shop-sheet-lines').locator('p').allTextContents();
      expect(lines[1]).toBe(
        'Three-axis, the tool upright; raster passes at 0 deg from the fall line; on a sloped plane',
      );
      const rows = await tableText(page);
      const slopes = ['0', '10', '20', '30', '45', '60', '75'];
      expect(rows[0]?.slice(1)).toEqual(slopes);
      const r = slopedPlaneForward(
        { toolRadiusMm: 3, cornerRadiusMm: 1, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 0 },
        0.01,
      );
      if (!r.ok) throw new Error('core');
      expect(rows[4]?.[4]).toBe(formatLen(r.value.horizontalStepMm, 'mm'));
      await keepShot(page, `shop-sheet-3axis-${vp.name}`);
      expect(await axeViolations(page)).toEqual([]);
      const { name, csv } = await downloadCsv(vp, page);
      expect(name).toBe('shop-sheet_R3_Rcr1_raster_psi0_plane_mm.csv');
      expect(csv.split('\n')[0]).toBe(`h_mm,${slopes.map((s) => `Lxy_mm_slope_${s}_deg`).join(',')}`);
      expect(errors).toEqual([]);
    }, 90_000);

  for (const format of ['A4', 'Letter'] as const)
    it(`printed: the sheet alone on one ${format} page (dark screen theme)`, async () => {
      const { page } = await open(DESKTOP, 'dark', '?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
      await openSheet(DESKTOP, page);
      // Twelve rows, the most the list takes.
      const field = page.getByTestId('shop-sheet-heights');
      await field.fill('0.001 0.002 0.003 0.005 0.01 0.02 0.03 0.05 0.1 0.2 0.5 1');
      await field.press('Enter');
      await expect.poll(async () => (await tableText(page)).length).toBe(13);
      await page.emulateMedia({ media: 'print', colorScheme: 'dark' });
      // The printable area: the page less print.css's 12 mm margins, at 96 px per inch.
      const px = (mm: number) => Math.floor((mm / 25.4) * 96);
      const size =
        format === 'A4'
          ? { width: px(210 - 24), height: px(297 - 24) }
          : { width: px(215.9 - 24), height: px(279.4 - 24) };
      await page.setViewportSize(size);
      // Only the sheet prints: the calculator, the field and the buttons are hidden.
      expect(await page.locator('#app').isVisible()).toBe(false);
      expect(await page.getByTestId('shop-sheet-print').isVisible()).toBe(false);
      expect(await page.getByTestId('shop-sheet-heights').isVisible()).toBe(false);
      expect(await page.getByTestId('shop-sheet-table').isVisible()).toBe(true);
      // Dark ink on white paper whatever the screen's theme.
      expect(await page.getByTestId('shop-sheet-dialog').evaluate((d) => getComputedStyle(d).color)).toBe(
        'rgb(0, 0, 0)',
      );
      // The sheet within the printable area: nothing wider, nothing below it.
      const box = await page.getByTestId('shop-sheet-table').boundingBox();
      expect(box?.width ?? 1e9).toBeLessThanOrEqual(size.width);
      const bottom = await page.getByTestId('shop-sheet-legend').evaluate((e) => e.getBoundingClientRect().bottom);
      expect(bottom).toBeLessThanOrEqual(size.height);
      expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(size.width);
      await keepShot(page, `shop-sheet-print-${format}`, { fullPage: true });
      const pdf = await page.pdf({ format, printBackground: false });
      expect(pdfPages(pdf)).toBe(1);
      await page.emulateMedia({ media: 'screen' });
    }, 90_000);

  it("phone, the three-axis inch job: the heights fixed while 60 and 75 scroll into view, the user's h a row, one digit count, a tap shows a mark's reason", async () => {
    const { page, errors } = await open(
      PHONE,
      'light',
      '?R=0.25&Rcr=0.03&machine=3axis&slope=30&rasterAngle=30&h=0.0004&unit=in',
    );
    await openSheet(PHONE, page);
    // A height past the tool's limits, so that the sheet has marks.
    const field = page.getByTestId('shop-sheet-heights');
    await field.fill('0.0001 0.0002 0.0005 0.001 0.002 0.005 0.3');
    await field.press('Enter');
    await expect.poll(async () => (await tableText(page)).length).toBe(9);
    const rows = await tableText(page);
    const slopes = ['0', '10', '20', '30', '45', '60', '75'];
    expect(rows[0]?.slice(1)).toEqual(slopes);
    // The user's own h (0.0004 in, not in the list) is a row, bold, named for a screen reader.
    expect(rows.slice(1).map((r) => r[0])).toEqual([
      '0.0001',
      '0.0002',
      '0.0004',
      '0.0005',
      '0.001',
      '0.002',
      '0.005',
      '0.3',
    ]);
    const own = page.getByTestId('shop-sheet-own-row');
    expect(await own.locator('th').textContent()).toBe('0.0004 (your h)');
    expect(
      await own
        .locator('td')
        .first()
        .evaluate((td) => getComputedStyle(td).fontWeight),
    ).toBe('700');
    const r = slopedPlaneForward(
      { toolRadiusMm: 6.35, cornerRadiusMm: 0.762, slopeDeg: 30, passes: 'raster', rasterAngleDeg: 30 },
      0.0004 * 25.4,
    );
    if (!r.ok) throw new Error('core');
    const ownL = r.value.horizontalStepMm / 25.4;
    expect(Number(rows[3]?.[4])).toBeCloseTo(ownL, 5);
    expect(rows[3]?.[4]).toBe(cellText({ ok: true, stepMm: r.value.horizontalStepMm, noScallop: false }, 'in'));
    // Every inch cell to one count of significant digits (4): 0.01245 beside 0.4449, not 0.44489.
    const numbers = rows.slice(1).flatMap((row) => row.slice(1).filter((c) => /\d/.test(c)));
    expect(numbers.length).toBeGreaterThan(40);
    for (const c of numbers) expect(c.replace('.', '').replace(/^0+/, '').length, c).toBe(4);
    // At 390 and 320 wide: the box scrolls; 60 and 75 scrolled into view (a swipe) are whole, in the
    // box and the window, right of the heights' column, which stays at the box's left.
    for (const width of [390, 320]) {
      await page.setViewportSize({ width, height: 844 });
      const box = page.locator('.sheet-scroll');
      for (const slope of ['60', '75']) {
        const th = page
          .getByTestId('shop-sheet-table')
          .locator('thead th')
          .nth(slopes.indexOf(slope) + 1);
        await th.scrollIntoViewIfNeeded();
        const problems = await box.evaluate((b, column) => {
          const out: string[] = [];
          const frame = b.getBoundingClientRect();
          const inner = { left: frame.left + b.clientLeft, right: frame.left + b.clientLeft + b.clientWidth };
          for (const tr of b.querySelectorAll('tr')) {
            const head = (tr as HTMLTableRowElement).cells[0]?.getBoundingClientRect();
            const cell = (tr as HTMLTableRowElement).cells[column]?.getBoundingClientRect();
            if (!head || !cell) {
              out.push('missing cell');
              continue;
            }
            const name = (tr as HTMLTableRowElement).cells[0]?.textContent;
            if (Math.abs(head.left - inner.left) > 1)
              out.push(`${name}: first column at ${head.left}, box at ${inner.left}`);
            if (cell.left < head.right - 0.5) out.push(`${name}: under the first column`);
            if (cell.right > inner.right + 0.5 || cell.right > window.innerWidth)
              out.push(`${name}: cut at ${cell.right}`);
          }
          return out;
        }, slopes.indexOf(slope) + 1);
        expect(problems, `${width} px, slope ${slope}`).toEqual([]);
      }
      expect(await box.evaluate((b) => b.scrollLeft), `${width} px scrolled`).toBeGreaterThan(0);
      await keepShot(page, `shop-sheet-3axis-inch-phone-${width}`);
    }
    // A touch screen cannot hover: the legend says tap; a tap on a mark writes its full reason.
    const legend = page.getByTestId('shop-sheet-legend');
    expect(await legend.locator('.hint-hover').isVisible()).toBe(false);
    expect(await legend.locator('.hint-touch').isVisible()).toBe(true);
    const reason = page.getByTestId('shop-sheet-reason');
    expect(await reason.isVisible()).toBe(false);
    const mark = page.getByTestId('shop-sheet-table').locator('td.refused button').last();
    const title = await mark.evaluate((b) => (b.parentElement as HTMLElement).title);
    expect(title).toMatch(/\S/);
    await mark.scrollIntoViewIfNeeded();
    await mark.tap();
    await expect.poll(() => reason.textContent()).toMatch(/^[WGX] at h 0\.3 in, slope \d+ deg: /);
    expect((await reason.textContent())?.endsWith(title)).toBe(true);
    expect(await reason.isVisible()).toBe(true);
    expect(await axeViolations(page)).toEqual([]);
    // Printed: neither hint nor the tapped reason; the heights' column is a plain column.
    await page.emulateMedia({ media: 'print' });
    expect(await legend.locator('.hint-hover').isVisible()).toBe(false);
    expect(await legend.locator('.hint-touch').isVisible()).toBe(false);
    expect(await reason.isVisible()).toBe(false);
    expect(await own.locator('th').evaluate((th) => getComputedStyle(th).position)).toBe('static');
    await page.emulateMedia({ media: 'screen' });
    expect(errors).toEqual([]);
  }, 90_000);
});
