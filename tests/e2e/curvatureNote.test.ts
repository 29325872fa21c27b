/**
 * On a cylinder whose axis runs across the feed, each procedure's corrected row equals its plain row
 * (the correction 1/rho = 1/Reff + 1/Rs uses the surface's section across the feed, a straight line
 * there): the table's notes say why, in that case only (not along the feed, not on a plane).
 */
import { describe, expect, it } from 'vitest';
import { CORRECTED_KEYS } from '../../src/core/procedures/procedures';
import { CROSS_AXIS_NOTE } from '../../src/ui/resultsText';
import { useSite } from './harness';

const { open } = useSite('docs/curvature-note', { scene: false });

const BASE = '?R=3&Rcr=1&rho=5&tilt=3&h=0.05&unit=mm';

describe('the corrected rows across the axis', () => {
  it('equal the plain rows and the notes say why, across the feed only', async () => {
    for (const mode of ['', '&mode=inverse&L=1.5']) {
      const { page, errors } = await open(`${BASE}${mode}&surfaceRadius=40&surfaceAxis=cross`);
      const value = mode === '' ? 'half' : 'h';
      await page.getByTestId(`result-sekineCorrected-${value}`).filter({ hasText: /\d/ }).waitFor();
      for (const key of CORRECTED_KEYS) {
        const plain = await page.getByTestId(`result-${key}-${value}`).textContent();
        expect(plain).toMatch(/\d/);
        expect(await page.getByTestId(`result-${key}Corrected-${value}`).textContent(), key).toBe(plain);
      }
      await expect.poll(() => page.getByTestId('table-notes').textContent()).toContain(CROSS_AXIS_NOTE);
      expect(errors).toEqual([]);
    }
    for (const query of [`${BASE}&surfaceRadius=40&surfaceAxis=feed`, BASE]) {
      const { page } = await open(query);
      await page.getByTestId('result-sekine-half').filter({ hasText: /\d/ }).waitFor();
      expect(await page.getByTestId('table-notes').textContent(), query).not.toContain('straight line');
    }
    // Along the feed the correction changes the rows (the note would be false there).
    const { page } = await open(`${BASE}&surfaceRadius=40&surfaceAxis=feed`);
    await page.getByTestId('result-sekineCorrected-half').filter({ hasText: /\d/ }).waitFor();
    expect(await page.getByTestId('result-sekineCorrected-half').textContent()).not.toBe(
      await page.getByTestId('result-sekine-half').textContent(),
    );
  }, 90_000);
});
