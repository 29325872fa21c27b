/**
 * The page in Japanese and German (issue 30, first step), one phone page as a user holds it: one
 * tap on the language switch changes the page's words (the chrome, the fields' labels and hints,
 * the headline), its `lang`, and the numbers' decimal sign (German 2,8872 mm, every digit kept);
 * German inputs take a decimal comma; Copy keeps the point; the choice is written into the link
 * and remembered on the next visit; English comes back whole; axe finds nothing in either language.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { forwardInput } from '../../src/core/input/validate';
import { solve } from '../../src/worker/jobs/solve';
import { axeViolations } from './axe';
import { keepShot, pageSettled, typeInto, useSite } from './harness';

const site = useSite('language');
const QUERY = '?R=3&Rcr=1&rho=5&h=0.05&unit=mm';
const PHONE = { width: 390, height: 844 };
/** A language's code and catalogue load on first use: on a loaded machine that takes seconds. */
const POLL = { timeout: 15_000 };

/** The core's step-over at scallop height h (mm), to the page's four decimals. */
function stepOver(h: number): string {
  const reply = solve({
    mode: 'forward',
    input: forwardInput({ toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way', h),
  });
  if (!reply.ok) throw new Error('plane');
  return reply.exact.intervalMm.toFixed(4);
}

const text = async (page: Page, selector: string) => (await page.locator(selector).first().textContent()) ?? '';
const tap = (page: Page, lang: string) => page.locator(`[data-testid="lang-switch"] input[value="${lang}"]`).check();

describe('the language switch (phone)', { timeout: 90_000 }, () => {
  let page: Page;

  it('German in one tap: words, lang, a decimal comma in the answer, the link; 0,08 typed', async () => {
    ({ page } = await site.open(QUERY, PHONE));
    expect(await page.evaluate(() => document.documentElement.lang)).toBe('en');
    await tap(page, 'de');
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('de');
    expect(await text(page, '[data-testid="machine-switch"] legend')).toBe('Maschine');
    expect(await text(page, 'label[for="field-Rcr"]')).toBe('Eckenradius Rcr');
    expect(await text(page, '#field-rho-hint')).toBe('Neigung des Werkzeugs in Vorschubrichtung');
    expect(await text(page, '[data-role="headline-label"]')).toBe('Bahnabstand L');
    await expect
      .poll(() => text(page, '[data-testid="result-exact-interval"]'))
      .toBe(`${stepOver(0.05).replace('.', ',')} mm`);
    // The result bar mirrors the headline, in German too; the question named in German; Copy in German.
    expect(await text(page, '[data-role="bar-label"]')).toBe('Bahnabstand L');
    await expect
      .poll(() => text(page, '[data-testid="headline-question"]'))
      .toBe('5-Achs, Anstellung 5°, Kippung 0°, in einer Richtung, Ebene');
    expect(await text(page, '.headline .big button.copy')).toBe('Kopieren');
    await expect.poll(() => text(page, '#tab-profile'), POLL).toBe('Profil quer zum Vorschub');
    expect(await text(page, '#tab-chart')).toBe('L über Anstell- und Kippwinkel');
    // Copy keeps the point (a CAM field's reader).
    expect(await page.getByTestId('result-exact-interval').getAttribute('data-copy')).toBe(stepOver(0.05));
    await expect.poll(() => new URL(page.url()).searchParams.get('lang'), POLL).toBe('de');
    await typeInto(page, 'input-h', '0,08');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => text(page, '[data-testid="result-exact-interval"]'))
      .toBe(`${stepOver(0.08).replace('.', ',')} mm`);
    // A bad corner radius: one line in German on its field, the bound in mm; the answer a dash.
    await typeInto(page, 'input-Rcr', '5');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => text(page, '[data-testid="error-Rcr"]'))
      .toBe(
        'Eckenradius Rcr darf den Werkzeugradius R = 3 mm nicht überschreiten (eingegeben: 5); Rcr = R ist ein Kugelfräser.',
      );
    expect(await text(page, '[data-testid="result-exact-interval"]')).toBe('\u2014');
    await typeInto(page, 'input-Rcr', '1');
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, '[data-testid="error-Rcr"]'), POLL).toBe('');
    expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(PHONE.width);
    // The teeth and feed in German: fz typed with a decimal comma, the finish box in German.
    await page.getByTestId('finish-inputs').locator('summary').click();
    await typeInto(page, 'input-flutes', '4');
    await typeInto(page, 'input-fz', '0,1');
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, '.finish-title'), POLL).toBe('Oberfläche: die Vorschubmarken der Schneiden');
    await expect.poll(() => text(page, '[data-testid="finish-hf"]'), POLL).toMatch(/^\d+,\d+ µm$/);
    expect(await text(page, '[data-testid="use-balanced-feed"]')).toBe('ausgewogenen Vorschub übernehmen');
    // axe on the page at rest (a view marked out of date while it redraws is greyed on purpose).
    await expect.poll(() => page.locator('.teaching').getAttribute('class'), POLL).not.toMatch(/\bstale\b/);
    await pageSettled(page);
    await keepShot(page, 'language-de-phone', { fullPage: true });
    expect(await axeViolations(page)).toEqual([]);
  });

  it('remembered: a bare visit later opens in German', async () => {
    await page.goto(new URL('./', page.url()).href);
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('de');
    await expect.poll(() => text(page, '[data-role="headline-label"]'), POLL).toBe('Bahnabstand L');
  });

  it('Japanese: its words and a decimal point; English comes back whole, lang= leaves the link', async () => {
    await tap(page, 'ja');
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('ja');
    expect(await text(page, '[data-testid="machine-switch"] legend')).toBe('機械');
    expect(await text(page, 'label[for="field-Rcr"]')).toBe('コーナ半径 Rcr');
    await expect.poll(() => text(page, '[data-role="headline-label"]'), POLL).toBe('ピックフィード L');
    await expect
      .poll(() => text(page, '[data-testid="headline-question"]'))
      .toMatch(/^5軸、前傾 5°、傾斜 0°、片方向、平面$/);
    expect(await text(page, '.headline .big button.copy')).toBe('コピー');
    expect(await text(page, '[data-testid="result-exact-interval"]')).toMatch(/^\d+\.\d{4} mm$/);
    expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(PHONE.width);
    await pageSettled(page);
    await keepShot(page, 'language-ja-phone', { fullPage: true });
    expect(await axeViolations(page)).toEqual([]);
    // An error shown while the language changes is worded anew: Rcr 5 in Japanese, then in English
    // (this bare visit gives the tool size as the diameter D, as a first visit does).
    await typeInto(page, 'input-Rcr', '5');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => text(page, '[data-testid="error-Rcr"]'))
      .toBe('コーナ半径 Rcrは D/2 = 3 mm 以下にしてください（入力：5）。Rcr = D/2 はボールエンドミルです。');
    await tap(page, 'en');
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('en');
    await expect
      .poll(() => text(page, '[data-testid="error-Rcr"]'))
      .toBe('Corner radius Rcr must be at most D/2 = 3 mm (got 5); Rcr = D/2 is a ball end mill.');
    await typeInto(page, 'input-Rcr', '1');
    await page.keyboard.press('Enter');
    expect(await text(page, '[data-testid="machine-switch"] legend')).toBe('Machine');
    expect(await text(page, 'label[for="field-Rcr"]')).toBe('Corner radius Rcr');
    await expect.poll(() => text(page, '[data-role="headline-label"]'), POLL).toBe('Step-over L');
    expect(await text(page, '.headline .big button.copy')).toBe('Copy');
    expect(await text(page, '#tab-profile')).toBe('Cross-feed profile');
    expect(await text(page, '[data-testid="result-exact-interval"]')).toMatch(/^\d+\.\d{4} mm$/);
    await expect.poll(() => new URL(page.url()).searchParams.get('lang'), POLL).toBeNull();
    // German then English again, with a valid answer: the table's decimal sign follows both ways.
    await expect.poll(() => text(page, '[data-testid="error-Rcr"]'), POLL).toBe('');
    await tap(page, 'de');
    // In German the table's numbers take a comma, its cells keep their outputs (test ids).
    await expect.poll(() => text(page, '[data-testid="result-sekine-half"]'), POLL).toMatch(/^\d+,\d{4} mm$/);
    // The parts still in English say so (screen readers read them as English).
    expect(await page.locator('.teaching').getAttribute('lang')).toBe('en');
    await tap(page, 'en');
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('en');
    // Back in English: the table drawn anew with points (no comma left to read as a thousands separator).
    await expect.poll(() => text(page, '[data-testid="result-sekine-half"]'), POLL).toMatch(/^\d+\.\d{4} mm$/);
    expect(await page.locator('.teaching').getAttribute('lang')).toBeNull();
  });

  it("an embed takes its language from the link (the element's lang attribute), not the one remembered (English by now)", async () => {
    await page.goto(new URL(`${QUERY}&embed=1&lang=ja`, page.url()).href);
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('ja');
    await expect.poll(() => text(page, '[data-role="headline-label"]'), POLL).toBe('ピックフィード L');
    await page.goto(new URL(`${QUERY}&embed=1`, page.url()).href);
    await expect.poll(() => text(page, '[data-role="headline-label"]'), POLL).toBe('Step-over L');
  });
});
