/**
 * The teaching views on a narrow screen (issue 21): the paper's tables keep their condition columns
 * (Table, R, Rcr, rho, h or L/2) readable at 390 x 844 and at 640 wide, and every formula box on a
 * phone either fits or shades the edge with more of it, the shade going once scrolled to the end;
 * axe finds nothing. Saved tools with long names (issue 28 point 5) never widen the page, swept over
 * every width from 320 to 1920 on one page.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { axeViolations } from './axe';
import { animationFrames, keepShot, PHONE, pageSettled, usePhonePage, useSite } from './harness';

const site = useSite('docs/narrow-views', { scene: false });
const openPhone = usePhonePage(site);
const STATE = 'R=3&Rcr=1&rho=5&h=0.05&unit=mm';

/**
 * Each condition cell of both paper tables, scrolled into view: its box, its text's box, its font
 * size; a problem per cell that is empty, clipped, smaller than 11 px or outside the window.
 */
async function conditionCellProblems(page: Page): Promise<{ cells: number; problems: string[] }> {
  const cells = page.locator('[data-testid^="paper-table-"] tbody td:not([data-procedure])');
  const count = await cells.count();
  const problems: string[] = [];
  for (let i = 0; i < count; i++) {
    const cell = cells.nth(i);
    await cell.scrollIntoViewIfNeeded();
    const problem = await cell.evaluate((td) => {
      const box = td.getBoundingClientRect();
      const range = document.createRange();
      range.selectNodeContents(td);
      const text = range.getBoundingClientRect();
      const px = Number.parseFloat(getComputedStyle(td).fontSize);
      const label = `${td.closest('table')?.dataset.testid} row ${td.closest('tr')?.dataset.condition} col ${(td as HTMLTableCellElement).cellIndex} "${td.textContent}"`;
      if ((td.textContent ?? '').trim() === '') return `${label}: empty`;
      if (box.width <= 0 || box.height <= 0) return `${label}: cell ${box.width}x${box.height}`;
      if (text.width <= 0 || text.height <= 0) return `${label}: text ${text.width}x${text.height}`;
      if (px < 11) return `${label}: ${px}px`;
      if (text.left < box.left - 0.5 || text.right > box.right + 0.5) return `${label}: text outside its cell`;
      if (text.left < 0 || text.right > window.innerWidth || text.top < 0 || text.bottom > window.innerHeight)
        return `${label}: not in the window after scrolling`;
      return null;
    });
    if (problem !== null) problems.push(problem);
  }
  return { cells: count, problems };
}

describe("the paper's tables on a narrow screen", () => {
  it('at 360, 390x844 and 640 wide every condition cell has a size and readable text in view', async () => {
    const pages: Array<[string, () => Promise<Page>]> = [
      ['360', async () => (await site.open(`?${STATE}&view=tables`, { width: 360, height: 780 })).page],
      ['390', () => openPhone(`?${STATE}&view=tables`)],
      ['640', async () => (await site.open(`?${STATE}&view=tables`, { width: 640, height: 900 })).page],
    ];
    for (const [width, open] of pages) {
      const page = await open();
      await page.getByTestId('paper-table-height').waitFor();
      await pageSettled(page);
      const { cells, problems } = await conditionCellProblems(page);
      // 8 conditions x 5 columns, in each of the two tables.
      expect(cells, width).toBe(80);
      expect(problems, width).toEqual([]);
      // The page itself does not scroll sideways.
      expect(await page.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth), width).toBe(true);
      await page.getByTestId('paper-table-half').scrollIntoViewIfNeeded();
      await keepShot(page, `narrow-tables-${width}`);
      expect(await axeViolations(page), width).toEqual([]);
    }
  }, 120_000);
});

describe('formulas on a phone', () => {
  it('every formula box fits or shades the edge with more; the shade goes once scrolled to the end', async () => {
    const page = await openPhone(`?${STATE}&view=formulas`);
    await page.locator('.maths').first().waitFor();
    await pageSettled(page);
    await animationFrames(page);
    const boxes = page.locator('.maths');
    const count = await boxes.count();
    expect(count).toBeGreaterThan(3);
    let wide = 0;
    // A box's overflow, its frame's marks, and whether the frame draws its left and right shades.
    const state = (i: number) =>
      boxes.nth(i).evaluate((b) => {
        const frame = b.parentElement as HTMLElement;
        return {
          overflows: b.scrollWidth > b.clientWidth + 1,
          left: frame.hasAttribute('data-more-left'),
          right: frame.hasAttribute('data-more-right'),
          leftShade: getComputedStyle(frame, '::before').content !== 'none',
          rightShade: getComputedStyle(frame, '::after').content !== 'none',
        };
      });
    for (let i = 0; i < count; i++) {
      const box = boxes.nth(i);
      const s = await state(i);
      // A keyboard can reach each box, which a screen reader names.
      expect(await box.getAttribute('tabindex')).toBe('0');
      expect(await box.getAttribute('aria-label')).toMatch(/equations/);
      if (!s.overflows) {
        expect(s, `box ${i} fits`).toMatchObject({ left: false, right: false, leftShade: false, rightShade: false });
        continue;
      }
      wide++;
      expect(s, `box ${i} overflows`).toMatchObject({ left: false, right: true, leftShade: false, rightShade: true });
      // The frame's own picture (a page screenshot on this emulated phone showed a stale raster).
      if (wide <= 2) await keepShot(box.locator('..'), `narrow-formula-cue-${wide}`);
      // The keyboard scrolls it (focus, arrow right); then scrolled to its end, the right shade
      // goes and the left one comes.
      await box.focus();
      await page.keyboard.press('ArrowRight');
      await expect.poll(() => box.evaluate((b) => b.scrollLeft)).toBeGreaterThan(0);
      await expect.poll(() => state(i)).toMatchObject({ left: true });
      await box.evaluate((b) => {
        b.scrollLeft = b.scrollWidth;
      });
      await expect.poll(() => state(i)).toMatchObject({ left: true, right: false, leftShade: true, rightShade: false });
      if (wide <= 2) await keepShot(box.locator('..'), `narrow-formula-end-${wide}`);
    }
    // At 390 px the exact procedure's formulas are wider than the screen: the cue is tested.
    expect(wide).toBeGreaterThan(0);
    expect(page.viewportSize()).toEqual(PHONE);
    expect(await axeViolations(page)).toEqual([]);
  }, 120_000);
});

/** A saved tool's name as a shop writes it (issue 28 point 5), and the longest a name may be, unbroken. */
const SHOP_NAME = 'Harvey 33531-C3 1/2 3FL corner radius .030 AlTiN';
const LONGEST_NAME = `HARVEY-33531-C3-${'X'.repeat(80 - 16)}`;

/**
 * The widths swept: 320 to 1920 every 80 px, the tablet's 820 and the phone's 390, and both sides of
 * each of the stylesheet's width breakpoints (where the columns change).
 */
const SWEPT_WIDTHS = [
  ...new Set([
    ...Array.from({ length: 21 }, (_, i) => 320 + 80 * i),
    390,
    820,
    ...[420, 480, 640, 700, 1000].flatMap((w) => [w, w + 1]),
  ]),
].sort((a, b) => a - b);

/**
 * At the page's present width: the page's scroll width beyond the window, and for each named element a
 * problem when, scrolled into view (its own scroll box too, as a finger would), it is not wholly inside
 * the window and inside every box that clips it.
 */
async function overflowProblems(page: Page, width: number): Promise<string[]> {
  return page.evaluate((w) => {
    const problems: string[] = [];
    const doc = document.documentElement;
    if (doc.scrollWidth > window.innerWidth) problems.push(`${w}: the page is ${doc.scrollWidth} px wide`);
    const headline = document.querySelector('[data-testid="result-exact-interval"]');
    const named: Array<[string, Element | null | undefined]> = [
      ['headline', headline],
      ['headline Copy', headline?.parentElement?.querySelector('button.copy')],
      [
        '"Scallop it leaves"',
        [...document.querySelectorAll('[data-testid="procedures-table"] th')].find(
          (th) => th.textContent === 'Scallop it leaves',
        ),
      ],
      ['saved tools', document.querySelector('[data-testid="saved-tools"]')],
      ['tool name', document.querySelector('[data-testid="tool-name"]')],
    ];
    for (const [name, e] of named) {
      if (!e) {
        problems.push(`${w}: no ${name}`);
        continue;
      }
      e.scrollIntoView({ block: 'nearest', inline: 'nearest' });
      // A control's box; a text's own box (a table cell's borders may overhang its scroll box by a pixel).
      const range = document.createRange();
      range.selectNodeContents(e);
      const r = /^(BUTTON|SELECT|INPUT)$/.test(e.tagName) ? e.getBoundingClientRect() : range.getBoundingClientRect();
      if (r.width <= 0) problems.push(`${w}: ${name} has no width`);
      if (r.left < -0.5 || r.right > window.innerWidth + 0.5)
        problems.push(`${w}: ${name} spans ${r.left.toFixed(0)}..${r.right.toFixed(0)} of ${window.innerWidth}`);
      for (let p = e.parentElement; p !== null && p !== doc; p = p.parentElement) {
        if (getComputedStyle(p).overflowX === 'visible') continue;
        const c = p.getBoundingClientRect();
        if (r.left < c.left - 0.5 || r.right > c.right + 0.5)
          problems.push(
            `${w}: ${name} cut by ${p.className || p.tagName} (${r.left.toFixed(0)}..${r.right.toFixed(0)} in ${c.left.toFixed(0)}..${c.right.toFixed(0)})`,
          );
      }
    }
    window.scrollTo(0, 0);
    return problems;
  }, width);
}

describe('saved tools with long names (issue 28 point 5)', () => {
  it('names up to 80 characters never widen the page: every width from 320 to 1920, the headline, its Copy and the table inside', async () => {
    const { page, errors } = await site.open(`?${STATE}`, { width: 820, height: 1180 });
    // As the shop does: open My tools, name the tool, save it; the longest name too; then pick the longest.
    await page.locator('[data-testid="tool-shelf"] summary').click();
    for (const name of [LONGEST_NAME, SHOP_NAME]) {
      await page.getByTestId('tool-name').fill(name);
      await page.getByTestId('save-tool').click();
      await expect
        .poll(() => page.getByTestId('tool-library-status').textContent())
        .toBe(`Saved "${name}" in this browser.`);
    }
    // Newest first: the longest name is the second.
    await page.getByTestId('saved-tools').selectOption('1');
    await expect.poll(() => page.getByTestId('tool-library-status').textContent()).toContain(LONGEST_NAME);
    await pageSettled(page);
    await keepShot(page, 'long-tool-name-820');
    const problems: string[] = [];
    for (const width of SWEPT_WIDTHS) {
      await page.setViewportSize({ width, height: 900 });
      await animationFrames(page);
      problems.push(...(await overflowProblems(page, width)));
    }
    expect(problems).toEqual([]);
    expect(errors).toEqual([]);
    site.changed();
  }, 120_000);
});
