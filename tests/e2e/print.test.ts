/**
 * The printed sheet: with print media the page is one A4 page holding the inputs as text, the
 * results table and the profile, without sliders, buttons or the 3D canvas.
 */
import { describe, expect, it } from 'vitest';
import { keepShot, useSite } from './harness';

const site = useSite('shop/print');

/** Pages in a PDF (its /Type /Page objects, not the /Pages tree). */
function pdfPages(pdf: Buffer): number {
  return pdf.toString('latin1').match(/\/Type\s*\/Page(?![s\w])/g)?.length ?? 0;
}

describe('print', () => {
  for (const theme of ['light', 'dark'] as const) {
    it(`one page with inputs, results and profile; no sliders, buttons or 3D (${theme} screen theme)`, async () => {
      const page = await site.browser().newPage({ viewport: { width: 1400, height: 900 }, colorScheme: theme });
      await page.goto(`${site.url()}?R=3&Rcr=1&rho=5&tilt=5&pattern=zigzag&h=0.05&unit=mm`);
      await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
      await page.getByTestId('profile-view').locator('polygon.scallop').first().waitFor();
      await page.emulateMedia({ media: 'print' });
      await page.setViewportSize({ width: 794, height: 1123 }); // A4 at 96 dpi
      const visible = async (selector: string) => page.locator(selector).first().isVisible();
      expect(await visible('input[type="range"]')).toBe(false);
      expect(await visible('button')).toBe(false);
      expect(await visible('[data-testid="scene-canvas"]')).toBe(false);
      expect(await visible('[role="tablist"]')).toBe(false);
      expect(await visible('[data-testid="preset"]')).toBe(false);
      expect(await page.locator('button:visible, input[type="range"]:visible').count()).toBe(0);
      expect(await visible('[data-testid="procedures-table"]')).toBe(true);
      expect(await visible('[data-testid="profile-view"] svg')).toBe(true);
      expect(await page.getByTestId('input-tilt').inputValue()).toBe('5');
      expect(await visible('[data-testid="input-tilt"]')).toBe(true);
      // A switch prints only its chosen value.
      expect(await page.locator('[data-testid="pattern-switch"] label:visible').allTextContents()).toEqual([' zigzag']);
      // Printed on white: the text is dark whatever the screen's theme.
      expect(await page.evaluate(() => getComputedStyle(document.documentElement).color)).toBe('rgb(29, 35, 48)');
      await keepShot(page, `print-${theme}`, { fullPage: true });
      const pdf = await page.pdf({ format: 'A4', printBackground: false });
      expect(pdfPages(pdf)).toBe(1);
      await page.close();
    });
  }
});
