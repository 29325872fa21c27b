/**
 * The 3D scene's camera (issue 21, the teacher's projector), in headless Chromium at 1920 x 1080
 * and 1440 x 900: in every preset view and in postures at the limits of lead and tilt, on a plane,
 * a cylinder and a doubly curved point, the tool's bounding box (shank included) projects inside
 * the view and what the camera frames fills at least FILL_MIN of its limiting dimension; "Top"
 * puts P_hp R (+Y) above the path with the Y axis named; the step-through's camera moves to what
 * each step shows. The camera is read through the e2e probe and projected here with three.js.
 */
import type { Page } from 'playwright-core';
import { Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import type { SceneFraming } from '../../src/render/scene';
import { frames, keepShot, sceneIdle, showView, useSite, viewAs } from './harness';
import { hueShares } from './pixels';
import { cameraOf, expectLegible, framing } from './sceneContrast';

const site = useSite('docs/scene-camera');
const { open } = site;

/** The least share of the view's limiting dimension that what the camera frames must fill. */
const FILL_MIN = 0.6;

const POSTURES = [
  ['plane, no lead or tilt', 'R=3&Rcr=1&rho=0&tilt=0&h=0.05'],
  ['plane, lead near its limit', 'R=3&Rcr=1&rho=89&tilt=0&h=0.05'],
  ['plane, tilt near its limit', 'R=3&Rcr=1&rho=0&tilt=85&h=0.0001'],
  ['plane, tilt near its other limit', 'R=3&Rcr=1&rho=0&tilt=-85&h=0.0001'],
  ['plane, lead and tilt', 'R=3&Rcr=1&rho=80&tilt=60&h=0.005'],
  ['cylinder', 'R=3&Rcr=1&rho=5&h=0.05&surface=convex&surfaceRadius=12'],
  ['doubly curved (dome)', 'R=3&Rcr=1&rho=5&h=0.05&feedRadius=8&crossRadius=12'],
] as const;

const VIEWS = [
  ['iso', 'Isometric'],
  ['feed', 'Along the feed'],
  ['top', 'Top'],
] as const;

/** Projects flat xyz points through the probe's camera: normalised device coordinates (-1 to 1 across). */
function project(f: SceneFraming, xyz: readonly number[]): Array<[number, number]> {
  const camera = cameraOf(f);
  const out: Array<[number, number]> = [];
  for (let i = 0; i < xyz.length; i += 3) {
    const p = new Vector3(xyz[i], xyz[i + 1], xyz[i + 2]).project(camera);
    out.push([p.x, p.y]);
  }
  return out;
}

/** The share of the view's limiting dimension the points fill (1: edge to edge). */
function fill(points: Array<[number, number]>): number {
  const xs = points.map((p) => p[0]);
  const ys = points.map((p) => p[1]);
  return Math.max((Math.max(...xs) - Math.min(...xs)) / 2, (Math.max(...ys) - Math.min(...ys)) / 2);
}

async function clickView(page: Page, name: string): Promise<void> {
  const before = await frames(page);
  await page.getByRole('button', { name, exact: true }).click();
  await expect.poll(() => frames(page)).toBeGreaterThan(before);
  await sceneIdle(page);
}

/** Waits until the scene has drawn and its camera rests. */
async function settled(page: Page): Promise<SceneFraming> {
  await page.getByTestId('scene').scrollIntoViewIfNeeded();
  await expect.poll(async () => (await framing(page))?.framed.length ?? 0).toBeGreaterThan(0);
  await sceneIdle(page);
  return (await framing(page)) as SceneFraming;
}

/** The projector's sizes; the second in the dark theme (the page's errors then checked in both, as the gallery's were). */
const SIZES = [
  { name: '1920x1080', width: 1920, height: 1080, theme: 'light' },
  { name: '1440x900', width: 1440, height: 900, theme: 'dark' },
] as const;

describe('the camera frames the whole tool and fills the view', { timeout: 90_000 }, () => {
  for (const [k, [posture, query]] of POSTURES.entries()) {
    it(`${posture}, at ${SIZES.map((s) => s.name).join(' and ')}: in every preset view the tool's box is inside and the view is filled`, async () => {
      // One load; the second size by setViewportSize (the scene refits to its new box).
      const { page, errors } = await open(`?${query}&unit=mm`, SIZES[0], SIZES[0].theme);
      for (const vp of SIZES) {
        await viewAs(page, vp, vp.theme);
        await settled(page);
        for (const [tag, name] of VIEWS) {
          await clickView(page, name);
          const f = await settled(page);
          const where = `${vp.name} ${posture} ${name}`;
          const box = project(f, f.toolBox);
          // The tool's box and its holder's.
          expect(box.length, where).toBe(16);
          for (const [x, y] of box) {
            expect(Math.abs(x), `${where}: a corner of the tool's box is outside the view`).toBeLessThanOrEqual(1);
            expect(Math.abs(y), `${where}: a corner of the tool's box is outside the view`).toBeLessThanOrEqual(1);
          }
          const all = project(f, f.framed);
          for (const [x, y] of all) expect(Math.max(Math.abs(x), Math.abs(y)), where).toBeLessThanOrEqual(1.0001);
          expect(fill(all), `${where}: the view is not filled`).toBeGreaterThanOrEqual(FILL_MIN);
          if (k === 0 || k === 4 || k === 6)
            await keepShot(page.getByTestId('scene'), `scene-camera-${vp.name}-${k}-${tag}`);
          // Legible on a projector (issue 28, point 7): measured on the plane and the dome, light and dark.
          if ((k === 0 || k === 6) && tag === 'iso') await expectLegible(page, where);
        }
      }
      expect(errors).toEqual([]);
    });
  }

  it('Top: +Y up the screen (P_hp R above the path, P_hp L below), X to the right, the Y axis named', async () => {
    const { page } = await open('?R=3&Rcr=1&rho=5&tilt=5&h=0.05&unit=mm', { width: 1440, height: 900 });
    await settled(page);
    await clickView(page, 'Top');
    await settled(page);
    const at = async (text: string) => {
      const label = page.locator('.scene-label', { hasText: new RegExp(`^${text.replace(/[()]/g, '\\$&')}$`) });
      await expect.poll(() => label.evaluate((e) => e.checkVisibility({ visibilityProperty: true }))).toBe(true);
      const r = await label.boundingBox();
      if (r === null) throw new Error(`no ${text}`);
      return { x: r.x + r.width / 2, y: r.y + r.height / 2 };
    };
    const cc = await at('CC (P_base)');
    expect((await at('P_hp R')).y).toBeLessThan(cc.y);
    expect((await at('P_hp L')).y).toBeGreaterThan(cc.y);
    expect((await at('Y')).y).toBeLessThan(cc.y);
    expect((await at('X (feed)')).x).toBeGreaterThan(cc.x);
    await keepShot(page.getByTestId('scene'), 'scene-camera-top-labels');
  });

  it('a zoom is kept (the camera stops following) until a preset view is chosen again', async () => {
    const { page } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm', { width: 1440, height: 900 });
    const before = await settled(page);
    const canvas = page.getByTestId('scene-canvas');
    await canvas.hover();
    await page.mouse.wheel(0, 300);
    await expect.poll(async () => (await framing(page))?.autoFit).toBe(false);
    const zoomed = (await framing(page)) as SceneFraming;
    const distance = (f: SceneFraming) => new Vector3(...f.position).distanceTo(new Vector3(...f.target));
    expect(distance(zoomed)).toBeGreaterThan(distance(before) * 1.2);
    // A new posture keeps the user's zoom.
    const field = page.getByTestId('input-rho');
    await field.fill('30');
    await field.press('Enter');
    await expect.poll(async () => (await framing(page))?.framed.join()).not.toBe(zoomed.framed.join());
    expect(distance((await framing(page)) as SceneFraming)).toBeCloseTo(distance(zoomed), 6);
    await clickView(page, 'Isometric');
    expect((await framing(page))?.autoFit).toBe(true);
  });
});

describe("the step-through's camera moves to what each step shows", { timeout: 180_000 }, () => {
  for (const reducedMotion of ['no-preference', 'reduce'] as const) {
    it(`each step's section and points are framed, the target moving with them (motion: ${reducedMotion})`, async () => {
      // Both motions on one load: the step-through from its first step again, the motion emulated.
      const { page, errors } = await site.reuse('?R=3&Rcr=1&rho=5&tilt=5&h=0.05&unit=mm&view=stepper', {
        width: 1440,
        height: 900,
      });
      await page.emulateMedia({ reducedMotion });
      await showView(page, 'stepper');
      await page.getByTestId('stepper-first').click();
      const counter = page.getByTestId('stepper-counter');
      await expect.poll(() => counter.textContent()).toMatch(/step 1 of \d+/);
      const total = Number(/of (\d+)/.exec((await counter.textContent()) ?? '')?.[1]);
      const targets: string[] = [];
      // The first steps one by one (the sections moving along the ring), then the last (the answer).
      const visit = [1, 2, 3, 4, total];
      for (const k of visit) {
        if (k > 1) {
          await page.getByTestId(k === total ? 'stepper-last' : 'stepper-forward').click();
          await expect.poll(() => counter.textContent()).toMatch(new RegExp(`step ${k} of`));
        }
        const f = await settled(page);
        expect(f.focus, `step ${k}: the scene knows what the step shows`).not.toBeNull();
        const focus = project(f, f.focus ?? []);
        for (const [x, y] of focus) expect(Math.max(Math.abs(x), Math.abs(y)), `step ${k}`).toBeLessThanOrEqual(1);
        // A close-up: what the step shows fills the view.
        expect(fill(focus), `step ${k}: a close-up`).toBeGreaterThan(0.4);
        // The camera looks at the middle of what the step shows.
        const xs = focus.map((p) => p[0]);
        const ys = focus.map((p) => p[1]);
        expect(Math.abs(Math.max(...xs) + Math.min(...xs)) / 2, `step ${k}: centred across`).toBeLessThan(0.05);
        expect(Math.abs(Math.max(...ys) + Math.min(...ys)) / 2, `step ${k}: centred up`).toBeLessThan(0.05);
        targets.push(f.target.map((v) => v.toFixed(4)).join());
        // The close-up's labels inside the canvas, its lines legible over the tool (issue 28, point 7).
        if (k === 1) await expectLegible(page, `step 1 (${reducedMotion})`, { tool: false });
        if (k === 1 || k === total)
          await keepShot(page.getByTestId('scene'), `scene-camera-step-${k === 1 ? 'first' : 'last'}-${reducedMotion}`);
      }
      // The target follows the steps (the sections move along the ring, then to the other flank).
      expect(new Set(targets).size).toBeGreaterThanOrEqual(3);
      // Leaving the step-through: the whole scene again.
      await page.getByRole('tab', { name: /Cross-feed profile/ }).click();
      await expect.poll(async () => (await framing(page))?.focus).toBeNull();
      const back = await settled(page);
      expect(back.target.map((v) => v.toFixed(4)).join()).not.toBe(targets.at(-1));
      expect(fill(project(back, back.framed))).toBeGreaterThanOrEqual(FILL_MIN);
      expect(errors).toEqual([]);
    });
  }
});

describe('the surfaces read as what they are', { timeout: 90_000 }, () => {
  it('a cylinder is shaded by its height above the tangent plane: a concave one rises (orange), a convex one falls (blue)', async () => {
    for (const [side, hue] of [
      ['concave', 'orange'],
      ['convex', 'blue'],
    ] as const) {
      const { page } = await open(`?R=3&Rcr=1&rho=5&h=0.05&surfaceRadius=${side === 'concave' ? -60 : 12}&unit=mm`, {
        width: 1440,
        height: 900,
      });
      await settled(page);
      await keepShot(page.getByTestId('scene'), `scene-camera-cylinder-${side}`);
      const shares = await hueShares(page);
      console.log(`${side} cylinder: ${JSON.stringify(shares)}`);
      expect(shares[hue], `${side}: ${JSON.stringify(shares)}`).toBeGreaterThan(0.01);
    }
  });
});
