/**
 * The procedures table never runs under the 3D scene. Since every length cell carries its unit
 * (issue 21) the table can be wider than the results column (1024-1920 px, the inch tool's cells
 * widest): it then scrolls sideways in its own box, whose edge with more beyond it is shaded
 * (`data-more-right` on the frame, scrollCue.ts), and the box is reachable by keyboard. Found on the
 * README's screenshot at 1280 x 800, where the "Scallop left" column sat under the scene.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { axeViolations } from './axe';
import { keepShot, pageSettled, useSite } from './harness';

const site = useSite('docs/results-table', { scene: false });

/** The table's box, the table and the scene's left edge (px), and the frame's cue. */
const measure = (page: Page) =>
  page.evaluate(() => {
    const box = document.querySelector('[data-testid="procedures-scroll"]') as HTMLElement;
    const table = document.querySelector('[data-testid="procedures-table"]') as HTMLElement;
    const scene = document.querySelector('[data-testid="scene"]') as HTMLElement;
    return {
      boxRight: box.getBoundingClientRect().right,
      tableRight: table.getBoundingClientRect().right,
      overflowX: getComputedStyle(box).overflowX,
      sceneLeft: scene.getBoundingClientRect().left,
      overflowPx: box.scrollWidth - box.clientWidth,
      tableWidth: table.getBoundingClientRect().width,
      cueRight: box.parentElement?.hasAttribute('data-more-right') ?? false,
      tabIndex: box.tabIndex,
    };
  });

const QUERIES = [
  '?D=6&Rcr=1&rho=5&h=0.05&unit=mm',
  '?D=6&Rcr=1&rho=5&L=2&mode=inverse&unit=mm',
  '?D=0.5&Rcr=0.03&rho=5&h=0.0004&unit=in',
];

describe('the procedures table beside the 3D scene', () => {
  for (const viewport of [
    { width: 1024, height: 768 },
    { width: 1280, height: 800 },
    { width: 1440, height: 900 },
    { width: 1920, height: 1080 },
  ]) {
    it(`stays in its column and shows that it scrolls when it is wider (${viewport.width}x${viewport.height})`, async () => {
      for (const query of QUERIES) {
        const { page } = await site.open(query, viewport);
        await pageSettled(page);
        const m = await measure(page);
        expect(m.boxRight, query).toBeLessThanOrEqual(m.sceneLeft);
        // The whole table is in sight: it fits beside the scene, or its box clips it and scrolls.
        if (m.tableRight > m.sceneLeft) expect(m.overflowX, query).toBe('auto');
        // Wider than its box: the cue says so; fitting: no cue.
        await expect.poll(async () => (await measure(page)).cueRight, { message: query }).toBe(m.overflowPx > 1);
        expect(m.tabIndex).toBe(0);
        if (viewport.width === 1280 && query.includes('unit=in')) {
          await keepShot(page, 'results-table-1280-inch');
          expect(await axeViolations(page)).toEqual([]);
        }
      }
    });
  }
});
