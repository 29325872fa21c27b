/**
 * Screenshots of the 3D scene in each preset view (isometric, along the feed, top) at the projector's
 * sizes (1920 x 1080 and 1440 x 900), on a plane at no, middle and extreme lead and tilt, on a
 * cylinder and at a doubly curved point, light and dark: kept in test-results/screenshots/ to be
 * looked at (issue 21: the teacher's scene). The camera's fit is checked in sceneCamera.test.ts.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { frames, SHOTS, sceneIdle, useSite } from './harness';

const { open } = useSite('docs/scene-gallery');

const CASES = [
  ['plane-0', 'R=3&Rcr=1&rho=0&tilt=0&h=0.05'],
  ['plane-mid', 'R=3&Rcr=1&rho=40&tilt=30&h=0.05'],
  ['plane-limit', 'R=3&Rcr=1&rho=80&tilt=60&h=0.005'],
  ['cylinder', 'R=3&Rcr=1&rho=5&h=0.05&surface=convex&surfaceRadius=12'],
  ['dome', 'R=3&Rcr=1&rho=5&h=0.05&feedRadius=8&crossRadius=12'],
] as const;

const VIEWS = ['Isometric', 'Along the feed', 'Top'] as const;

async function view(page: Page, name: string): Promise<void> {
  const before = await frames(page);
  await page.getByRole('button', { name, exact: true }).click();
  await expect.poll(() => frames(page)).toBeGreaterThan(before);
  await sceneIdle(page);
}

describe('the scene at the projector sizes (screenshots to look at)', () => {
  for (const vp of [
    { name: '1920', width: 1920, height: 1080 },
    { name: '1440', width: 1440, height: 900 },
  ]) {
    for (const [i, [name, query]] of CASES.entries()) {
      const theme = i % 2 === 0 ? 'light' : 'dark';
      it(`${vp.name} ${name} ${theme}`, async () => {
        const { page, errors } = await open(`?${query}&unit=mm&theme=${theme}`, vp);
        await page.getByTestId('scene').scrollIntoViewIfNeeded();
        await sceneIdle(page);
        for (const v of VIEWS) {
          await view(page, v);
          const tag = v === 'Isometric' ? 'iso' : v === 'Top' ? 'top' : 'feed';
          await page
            .getByTestId('scene')
            .screenshot({ path: `${SHOTS}/gallery-${vp.name}-${name}-${tag}-${theme}.png` });
        }
        expect(errors).toEqual([]);
      });
    }
  }
});
