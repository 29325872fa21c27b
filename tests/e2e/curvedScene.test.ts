/**
 * The 3D scene of the new surfaces (issues 19 and 20), in headless Chromium on a phone and a desktop:
 * a doubly curved point (a dome reads blue, falling away from its tangent plane; a saddle both blue
 * and orange) and three-axis machining (a raster on a sloped plane with its Lxy dimension, a
 * waterline on a dome with its dz dimension). Each is drawn (not stale, painted), labelled, and
 * raises no console error.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { keepShot, loseAndRestore, paintedFraction, sceneIdle, useSite } from './harness';
import { hueShares } from './pixels';
import { expectLegible } from './sceneContrast';

const site = useSite('docs/curved-scene');

type Probe = { __pathInterval: { frames(): number } };

/**
 * Opens the query in the file's shared tab (a fresh document at this size, light) and waits for the
 * step-over L (a three-axis answer shows no L/2); the page's console errors come with it.
 */
const open = (query: string, viewport: { width: number; height: number }) =>
  site.open(`?${query}`, viewport, 'light', { readyTestId: 'result-exact-interval' });

/** The scene's labels on screen overlap none other and lie inside the scene (as teachScene.test.ts checks). */
async function expectLabelsClear(page: Page, where: string): Promise<void> {
  const { labels, scene } = await page.evaluate(() => {
    const box = (e: Element) => {
      const r = e.getBoundingClientRect();
      return { text: e.textContent ?? '', left: r.left, top: r.top, right: r.right, bottom: r.bottom };
    };
    const sceneEl = document.querySelector('[data-testid="scene"]') as HTMLElement;
    const shown = [...sceneEl.querySelectorAll<HTMLElement>('.scene-label, .scene-scale')].filter((e) => {
      const r = e.getBoundingClientRect();
      return e.checkVisibility({ visibilityProperty: true }) && r.width > 0 && r.height > 0;
    });
    return { labels: shown.map(box), scene: box(sceneEl) };
  });
  for (const l of labels)
    expect(
      l.left >= scene.left && l.right <= scene.right && l.top >= scene.top && l.bottom <= scene.bottom,
      `${where}: "${l.text}" runs out of the scene`,
    ).toBe(true);
  labels.forEach((a, i) => {
    for (const b of labels.slice(i + 1))
      expect(
        a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom,
        `${where}: "${a.text}" covers "${b.text}"`,
      ).toBe(false);
  });
  // Every kind of element drawn has a visible legend entry.
  const drawn = ((await page.getByTestId('scene').getAttribute('data-drawn')) ?? '').split(' ').filter(Boolean);
  expect(drawn.length).toBeGreaterThan(5);
  for (const key of drawn) {
    const visible = await page
      .locator(`[data-testid="scene-legend"] [data-legend="${key}"]`)
      .evaluateAll((els) => els.some((e) => (e as HTMLElement).checkVisibility()));
    expect(visible, `${where}: no legend entry for "${key}"`).toBe(true);
  }
}

const VIEWPORTS = [
  ['phone', { width: 390, height: 844 }],
  ['desktop', { width: 1400, height: 900 }],
] as const;

const CASES = [
  ['dome', 'R=3&Rcr=1&rho=5&h=0.05&unit=mm&feedRadius=8&crossRadius=12', null],
  ['saddle', 'R=3&Rcr=1&rho=5&h=0.05&unit=mm&feedRadius=20&crossRadius=-30', null],
  ['raster on a sloped plane', 'R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=20&h=0.05&unit=mm', /^Lxy = \d/],
  [
    'waterline on a dome',
    'R=3&Rcr=1&machine=3axis&slope=40&passes=waterline&feedRadius=20&crossRadius=20&h=0.05&unit=mm',
    /^dz = \d/,
  ],
] as const;

describe('the 3D scene of a doubly curved point at the limits of the tool radius', () => {
  for (const [name, query] of [
    ['R = 500 mm', 'R=500&Rcr=100&rho=5&h=0.05&unit=mm&feedRadius=1500&crossRadius=2500'],
    ['R = 0.001 mm', 'R=0.001&Rcr=0.0005&rho=5&h=0.00005&unit=mm&feedRadius=0.003&crossRadius=0.005'],
    ['R = 500 mm, raster on a sloped plane', 'R=500&Rcr=100&machine=3axis&slope=30&h=0.05&unit=mm'],
  ] as const)
    it(`a dome or a sloped plane, ${name}: drawn and fitted`, async () => {
      const { page, errors } = await open(query, { width: 1400, height: 900 });
      expect(await page.locator('[data-testid^="error-"]:not(:empty)').count()).toBe(0);
      await sceneIdle(page);
      const painted = await paintedFraction(page);
      console.log(`${name}: painted ${painted.toFixed(3)}`);
      expect(painted).toBeGreaterThan(0.1);
      // The axes' labels are placed (none behind the camera or beyond the far plane).
      expect(await page.locator('.scene-label.label-axis:visible').count()).toBe(3);
      expect(errors).toEqual([]);
    });
});

describe('the 3D scene of doubly curved points and three-axis machining', () => {
  for (const [device, viewport] of VIEWPORTS)
    for (const [name, query, step] of CASES)
      it(`${device}: ${name}`, async () => {
        const { page, errors } = await open(query, viewport);
        expect(await page.locator('[data-testid^="error-"]:not(:empty)').count()).toBe(0);
        await page.getByTestId('scene-canvas').scrollIntoViewIfNeeded();
        await sceneIdle(page);
        // Drawn for these inputs: not marked stale, most of the view painted.
        await expect.poll(() => page.locator('.scene.stale').count()).toBe(0);
        const painted = await paintedFraction(page);
        const hues = await hueShares(page);
        console.log(
          `${device} ${name}: painted ${painted.toFixed(3)}, blue ${hues.blue.toFixed(3)}, orange ${hues.orange.toFixed(3)}`,
        );
        await keepShot(page.getByTestId('scene-canvas'), `curved-scene-${device}-${name.replace(/ /g, '-')}`);
        expect(painted).toBeGreaterThan(0.1);
        if (name === 'dome') {
          // Falling away from the tangent plane in every direction: blue, and no rising (orange) part.
          expect(hues.blue).toBeGreaterThan(0.05);
          expect(hues.orange).toBeLessThan(0.2 * hues.blue);
        }
        if (name === 'saddle') {
          // Falling along the feed (blue), rising across it (orange).
          expect(hues.blue).toBeGreaterThan(0.03);
          expect(hues.orange).toBeGreaterThan(0.004);
        }
        const stepLabel = page.locator('.scene-label.label-step');
        if (step === null) expect(await stepLabel.isVisible()).toBe(false);
        else await expect.poll(async () => (await stepLabel.textContent()) ?? '').toMatch(step);
        await expectLabelsClear(page, `${device} ${name}`);
        // Legible on a projector, light and dark (issue 28, point 7): the same page in the dark theme.
        if (name === 'dome' || name === 'raster on a sloped plane') {
          await expectLegible(page, `${device} ${name} light`);
          const before = await page.evaluate(() => (window as unknown as Probe).__pathInterval.frames());
          await page.emulateMedia({ colorScheme: 'dark' });
          await expect
            .poll(() => page.evaluate(() => (window as unknown as Probe).__pathInterval.frames()))
            .toBeGreaterThan(before);
          await sceneIdle(page);
          await keepShot(page.getByTestId('scene-canvas'), `curved-scene-${device}-${name.replace(/ /g, '-')}-dark`);
          await expectLegible(page, `${device} ${name} dark`);
        }
        expect(errors).toEqual([]);
      });
});

describe('the 3D scene switched between machines and after a lost WebGL context', () => {
  it('waterline on a dome, then five-axis: updated in place; the context lost and restored: drawn again, no input', async () => {
    const { page, errors } = await open(
      'R=3&Rcr=1&machine=3axis&slope=40&passes=waterline&feedRadius=20&crossRadius=20&h=0.05&unit=mm',
      { width: 1400, height: 900 },
    );
    await sceneIdle(page);
    const stepLabel = page.locator('.scene-label.label-step');
    await expect.poll(async () => (await stepLabel.textContent()) ?? '').toMatch(/^dz = \d/);
    // Its anchor is laid out while its line is drawn, and taken off the layout when it is not.
    const anchorDisplay = () =>
      page.evaluate(
        () => document.querySelector<HTMLElement>('.scene-label.label-step')?.parentElement?.style.display ?? 'absent',
      );
    expect(await anchorDisplay()).toBe('');
    await page.locator('input[name="machine"][value="5axis"]').check();
    await expect.poll(() => new URL(page.url()).searchParams.get('machine')).toBeNull();
    await expect.poll(() => page.locator('.scene.stale').count()).toBe(0);
    await sceneIdle(page);
    // The machine's step is gone with the machine; the scene still draws the surface and the tool.
    expect(await anchorDisplay()).toBe('none');
    expect(await paintedFraction(page)).toBeGreaterThan(0.1);
    const frames = () => page.evaluate(() => (window as unknown as Probe).__pathInterval.frames());
    const before = await frames();
    await loseAndRestore(page, 'scene-canvas');
    await expect.poll(frames).toBeGreaterThan(before);
    await sceneIdle(page);
    expect(await paintedFraction(page)).toBeGreaterThan(0.1);
    expect(errors).toEqual([]);
  });
});
