/**
 * The three-axis scene framed as the five-axis one is, and its labels legible on a phone (issue 28,
 * point 7's leftovers): on a desktop and on a phone (390 x 844) what the scene paints (the tool, the
 * sloped surface, the passes, its labels hidden) fills at least FILL_MIN of the view's limiting
 * dimension, as the five-axis scene's does (no wide empty band above and below the tool); and every label
 * shown is at least 12 CSS px, inside the canvas, and at least LEAST_GAP_PX clear of every other
 * label (X, Lxy and L/2 no longer crowd each other). One page, resized.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { PHONE, sceneIdle, useSite } from './harness';
import { countPixels } from './pixels';

const site = useSite('docs/scene-three-axis');

const DESKTOP = { width: 1400, height: 900 };
/**
 * The least share of the view's limiting dimension the painted scene fills (1: edge to edge): the
 * camera keeps 0.14 of the view's half-size free (scene.ts), and the tool's box about its axis stands
 * a little out of the tool in perspective; the three-axis scene framed to the box of the tool along
 * the surface's axes filled 0.68 (desktop and phone).
 */
const FILL_MIN = 0.75;
/** The least space between two labels (px). */
const LEAST_GAP_PX = 4;
/** The least label size (CSS px). */
const LEAST_FONT_PX = 12;
/** Sampling step over the canvas (px). */
const STEP_PX = 3;
/** The canvas's edge band left out of the sampling (px). */
const EDGE_PX = 4;

const THREE_AXIS = '?machine=3axis&R=3&Rcr=1&slope=30&rasterAngle=30&h=0.01&unit=mm';
const FIVE_AXIS = '?R=3&Rcr=1&rho=5&h=0.01&unit=mm';

/**
 * The painted extent of the scene's canvas with its labels and badges hidden: the bounding box of
 * the pixels that differ from the background (read in the top right corner's neighbourhood), as
 * shares of the canvas's width and height.
 */
async function paintedFill(page: Page): Promise<{ across: number; up: number; fill: number }> {
  const canvas = page.getByTestId('scene-canvas');
  await page.evaluate(() => {
    for (const e of document.querySelectorAll<HTMLElement>('[data-testid="scene"] .scene-labels, .scene-scale'))
      e.style.visibility = 'hidden';
  });
  const png = await canvas.screenshot();
  await page.evaluate(() => {
    for (const e of document.querySelectorAll<HTMLElement>('[data-testid="scene"] .scene-labels, .scene-scale'))
      e.style.visibility = '';
  });
  const box = await canvas.boundingBox();
  if (box === null) throw new Error('no scene canvas');
  const points: Array<[number, number]> = [[box.width - 3, 3]];
  // Inside the canvas's edges (the scene box's border and rounded corners lie on them).
  for (let y = EDGE_PX; y < box.height - EDGE_PX; y += STEP_PX)
    for (let x = EDGE_PX; x < box.width - EDGE_PX; x += STEP_PX) points.push([x, y]);
  const { counts } = await countPixels(page, [png], { kind: 'at', points });
  const background = [counts[0], counts[1], counts[2]] as number[];
  let [left, right, top, bottom] = [Number.POSITIVE_INFINITY, Number.NEGATIVE_INFINITY, Number.POSITIVE_INFINITY, 0];
  for (let i = 1; i < points.length; i++) {
    let d = 0;
    for (let c = 0; c < 3; c++) d += Math.abs((counts[3 * i + c] as number) - (background[c] as number));
    if (d <= 24) continue;
    const [x, y] = points[i] as [number, number];
    left = Math.min(left, x);
    right = Math.max(right, x);
    top = Math.min(top, y);
    bottom = Math.max(bottom, y);
  }
  const across = (right - left) / (box.width - 2 * EDGE_PX);
  const up = (bottom - top) / (box.height - 2 * EDGE_PX);
  return { across, up, fill: Math.max(across, up) };
}

/** The labels shown in the scene: text, box (px, page) and font size. */
function shownLabels(page: Page) {
  return page.evaluate(() =>
    [...document.querySelectorAll<HTMLElement>('[data-testid="scene"] .scene-label')]
      .filter((e) => e.checkVisibility({ visibilityProperty: true }) && e.getBoundingClientRect().width > 0)
      .map((e) => {
        const r = e.getBoundingClientRect();
        return {
          text: e.textContent ?? '',
          left: r.left,
          top: r.top,
          right: r.right,
          bottom: r.bottom,
          fontPx: Number.parseFloat(getComputedStyle(e).fontSize),
        };
      }),
  );
}

async function settledScene(page: Page): Promise<void> {
  await page.getByTestId('scene').scrollIntoViewIfNeeded();
  await expect.poll(() => page.locator('.scene.stale').count()).toBe(0);
  await sceneIdle(page);
}

describe('the three-axis scene, framed and labelled', { timeout: 60_000 }, () => {
  for (const [name, viewport] of [
    ['desktop 1400x900', DESKTOP],
    ['phone 390x844', PHONE],
  ] as const) {
    it(`${name}: the scene fills the view as the five-axis one does; labels 12 px or more, inside, apart`, async () => {
      const { page: five } = await site.open(FIVE_AXIS, viewport);
      await settledScene(five);
      const fiveFill = await paintedFill(five);
      const { page, errors } = await site.open(THREE_AXIS, viewport);
      await settledScene(page);
      const threeFill = await paintedFill(page);
      console.log(
        `${name}: painted fill five-axis ${fiveFill.across.toFixed(2)} x ${fiveFill.up.toFixed(2)}, three-axis ${threeFill.across.toFixed(2)} x ${threeFill.up.toFixed(2)}`,
      );
      expect(fiveFill.fill, 'the five-axis scene').toBeGreaterThanOrEqual(FILL_MIN);
      expect(threeFill.fill, 'the three-axis scene').toBeGreaterThanOrEqual(FILL_MIN);

      const canvas = await page.getByTestId('scene-canvas').boundingBox();
      if (canvas === null) throw new Error('no scene canvas');
      const labels = await shownLabels(page);
      const texts = labels.map((l) => l.text);
      for (const want of ['X (feed)', 'Z']) expect(texts, `${name}: ${want} shown`).toContain(want);
      expect(texts.some((t) => t.startsWith('Lxy = ')) && texts.some((t) => t.startsWith('L/2 = '))).toBe(true);
      for (const l of labels) {
        expect(l.fontPx, `${l.text}: its size`).toBeGreaterThanOrEqual(LEAST_FONT_PX);
        expect(
          l.left >= canvas.x - 0.5 &&
            l.top >= canvas.y - 0.5 &&
            l.right <= canvas.x + canvas.width + 0.5 &&
            l.bottom <= canvas.y + canvas.height + 0.5,
          `${l.text} inside the canvas`,
        ).toBe(true);
      }
      const crowded: string[] = [];
      for (const [i, a] of labels.entries())
        for (const b of labels.slice(i + 1)) {
          const apart = Math.max(b.left - a.right, a.left - b.right, b.top - a.bottom, a.top - b.bottom);
          if (apart < LEAST_GAP_PX) crowded.push(`${a.text} / ${b.text}: ${apart.toFixed(1)} px`);
        }
      expect(crowded, `${name}: labels closer than ${LEAST_GAP_PX} px`).toEqual([]);
      expect(errors).toEqual([]);
    });
  }
});
