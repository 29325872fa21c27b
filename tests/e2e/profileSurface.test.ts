/**
 * The cross-feed profile is one drawing over the design surface (issue 18): a plane and the
 * cylinders are drawn by the same code, so what the plane's drawing did the curved ones now do too.
 * The height scale bar says the exaggeration drawn as soon as one is chosen (on a cylinder it said
 * the previous one until the next zoom), and a strong exaggeration grows the plot so the scallops
 * span it (on a cylinder the drawing shrank to a narrow strip).
 */
import { describe, expect, it } from 'vitest';
import { keepShot, useSite } from './harness';

const { open } = useSite('docs/profile-surface');

const SURFACES = [
  ['plane', ''],
  ['convex cylinder, axis along the feed', '&surfaceRadius=12&surfaceAxis=feed'],
  ['concave cylinder, axis along the feed', '&surfaceRadius=-40&surfaceAxis=feed'],
  ['concave cylinder, axis across the feed', '&surfaceRadius=-60&surfaceAxis=cross'],
] as const;

describe('the profile over any surface', () => {
  for (const [name, query] of SURFACES) {
    it(`${name}: the height scale bar follows the chosen exaggeration; x100 fills the plot`, async () => {
      const { page, errors } = await open(`?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=profile${query}`, {
        width: 1440,
        height: 900,
      });
      const view = page.getByTestId('profile-view');
      await view.locator('polyline.curve-exact').first().waitFor({ state: 'attached' });
      await view.scrollIntoViewIfNeeded();
      const bar = page.getByTestId('profile-scale-bar-z');
      for (const k of ['20', '5']) {
        await page.getByTestId('profile-exaggeration').selectOption(k);
        await expect.poll(() => page.getByTestId('profile-scale').textContent()).toMatch(new RegExp(`x${k}\\b`));
        expect(await bar.textContent()).toMatch(new RegExp(`\\(drawn x${k}\\)$`));
      }
      await page.getByTestId('profile-exaggeration').selectOption('100');
      await expect.poll(() => bar.textContent()).toMatch(/\(drawn x100\)$/);
      const plot = await view.locator('svg.profile-svg').boundingBox();
      const scallop = await page.getByTestId('profile-scallop').boundingBox();
      if (!plot || !scallop) throw new Error('no profile');
      await keepShot(view, `profile-surface-x100-${name.replaceAll(/[ ,]+/g, '-')}`);
      // A third of the width at least: on a convex cylinder the exaggerated heights, drawn radially,
      // fan out over the passes (a plane's reach half of it, teachScene.test.ts).
      expect(scallop.width / plot.width, 'the scallops span the plot').toBeGreaterThan(0.3);
      expect(scallop.height / plot.height, 'the scallops are tall enough to read').toBeGreaterThan(0.2);
      expect(errors).toEqual([]);
      await page.close();
    });
  }
});
