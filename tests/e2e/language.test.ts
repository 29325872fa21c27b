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

/** The shop sheet's Latin words a translation keeps: the paper's symbols, the unit, the marks' letters, file kinds. */
const SHEET_KEPT = new Set('L h R D Rcr rho Rs Rf Rc Lxy dz mm in W G X Z CSV CAM sin'.split(' '));

/** The scene legend's Latin words a translation keeps: the sheet's, and the paper's P_hp, P_base, CC, O, y0, N, i. */
const LEGEND_KEPT = new Set([...SHEET_KEPT, 'P', 'hp', 'base', 'CC', 'O', 'y0', 'N', 'i', 'X', 'Y', 'Z']);

/** The tick labels of the chart `id`. */
const ticksOf = (page: Page, id: string): Promise<string[]> =>
  page.getByTestId(id).evaluate((e) => [...e.querySelectorAll('text.chart-tick')].map((t) => t.textContent ?? ''));

/**
 * Waits for the chart `id`'s ticks to be written with a decimal comma (some tick has a fraction: the
 * chart spans less than its number of ticks), then checks that none has a point.
 */
async function expectCommaTicks(page: Page, id: string): Promise<void> {
  await expect.poll(() => ticksOf(page, id), POLL).toEqual(expect.arrayContaining([expect.stringMatching(/\d,\d/)]));
  expect((await ticksOf(page, id)).filter((t) => /\d\.\d/.test(t))).toEqual([]);
}

/** The Latin words of a text. */
const latinWords = (t: string): string[] => t.match(/[A-Za-z][A-Za-z0-9]*/g) ?? [];

/** The row heads of the open sheet's table (the screen reader's "your h" left out). */
const rowHeads = (page: Page): Promise<string[]> =>
  page
    .getByTestId('shop-sheet-table')
    .evaluate((t) => [...t.querySelectorAll('tbody th')].map((th) => th.firstChild?.textContent ?? ''));

/**
 * Opens the shop sheet on the inputs on screen, types a bad list of heights (its message returned),
 * then three heights, the last past the tool's limit at lead 0 (a W mark: the legend and its hints
 * are drawn), once the table shows them.
 */
async function openSheet(page: Page, sign: '.' | ','): Promise<string> {
  await expect.poll(() => page.getByTestId('shop-sheet').isEnabled(), POLL).toBe(true);
  await page.getByTestId('shop-sheet').click();
  await page.getByTestId('shop-sheet-dialog').waitFor({ state: 'visible', timeout: POLL.timeout });
  const field = page.getByTestId('shop-sheet-heights');
  await field.fill('0.01 -1');
  await field.press('Enter');
  await expect.poll(() => text(page, '[data-testid="shop-sheet-heights-error"]')).not.toBe('');
  const message = await text(page, '[data-testid="shop-sheet-heights-error"]');
  await field.fill('0.01 0.05 1.5');
  await field.press('Enter');
  await expect.poll(async () => (await rowHeads(page)).at(-1), POLL).toBe(`1${sign}5`);
  // A mark's full reason, tapped (its words read with the rest).
  await page.getByTestId('shop-sheet-table').locator('td.refused .mark').first().click();
  await expect.poll(() => text(page, '[data-testid="shop-sheet-reason"]'), POLL).toMatch(/\S/);
  return message;
}

/**
 * Every word of the open sheet a person reads or hears: its text (the legend's hints for a pointer
 * and for touch, the caption, the heights' label, the buttons, a mark's reason) and its elements'
 * accessible names and titles (a refused cell's reason on hover).
 */
const sheetWords = (page: Page): Promise<string> =>
  page.getByTestId('shop-sheet-dialog').evaluate((d) => {
    const texts: string[] = [];
    const walker = document.createTreeWalker(d, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node !== null; node = walker.nextNode()) texts.push(node.nodeValue ?? '');
    const names = [...d.querySelectorAll('[aria-label], [title]')].map(
      (e) => `${e.getAttribute('aria-label') ?? ''} ${e.getAttribute('title') ?? ''}`,
    );
    return [...texts, ...names].join(' ');
  });

/** The Machined surface view's English words (views/surfaceWords.ts, the teeth's caption), to find any left over. */
const SURFACE_ENGLISH =
  /\b(teeth|tooth|passes|apart|shown|continuous|sweeps|along|drawn|longer|heights?|true|scale|exaggerated|vertical|colour|above|lowest|point|simulated|cusp|against|exact|differ|within|beyond|stated|resolution|bound|cells|trace|mean|line|profilometer|marked|view|machined|coloured|simulating|the|of|by|and)\b/gi;

/** The surface view's Latin words a Japanese translation keeps: the symbols, the units, the roughness' names. */
const SURFACE_KEPT = new Set([...SHEET_KEPT, 'z', 'fz', 'x', 'Rz', 'Ra', 'Rq', '3D']);

/** Every word the open Machined surface view shows or names (its texts, its elements' names), its lang and its legend's numbers. */
const surfaceWords = (page: Page): Promise<{ lang: string; words: string; legend: string[] }> =>
  page.getByTestId('surface-view').evaluate((v) => {
    const texts: string[] = [];
    const walker = document.createTreeWalker(v, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node !== null; node = walker.nextNode()) texts.push(node.nodeValue ?? '');
    const names = [...v.querySelectorAll('[aria-label]')].map((e) => e.getAttribute('aria-label') ?? '');
    const legend = [...v.querySelectorAll('[data-testid="surface-legend"] text')].map((t) => t.textContent ?? '');
    return { lang: (v as HTMLElement).lang, words: [...texts, ...names].join(' '), legend };
  });

/** The 3D scene's own English words (render/drawables/parts.ts SCENE_WORDS, the arc, its name). */
const SCENE_ENGLISH =
  /\b(design|pseudo|plane|surface|cusp|converged|best|single|contact|arc|feed|view|tool|posture|neighbouring|passes|sections)\b/gi;

/** The 3D scene's label texts and its canvas's accessible name. */
const sceneWords = (page: Page): Promise<string> =>
  page
    .getByTestId('scene')
    .evaluate((scene) =>
      [
        ...[...scene.querySelectorAll('.scene-labels .scene-label')].map((l) => l.textContent ?? ''),
        scene.querySelector('canvas')?.getAttribute('aria-label') ?? '',
      ].join(' '),
    );

/** The procedures' table: its head, its procedures' names, and whether a part of it is marked English. */
const procedureNames = (page: Page): Promise<{ head: string[]; rows: string[]; english: boolean }> =>
  page.getByTestId('procedures-table').evaluate((t) => ({
    head: [...t.querySelectorAll('thead th')].map((th) => th.textContent ?? ''),
    rows: [...t.querySelectorAll('tr[data-procedure] > th')].map((th) => th.textContent ?? ''),
    english: t.querySelector('[lang="en"]') !== null || t.closest('[lang]')?.getAttribute('lang') === 'en',
  }));

/** The cross-feed profile's English words (views/profileWords.ts), to find any left over. */
const PROFILE_ENGLISH =
  /\b(cross|feed|adjacent|passes|vertical|scale|true|auto|zoom|reset|view|cusp|approximations|drawn|exact|compare|shapes|results|table|ring|ellipse|next|pass|cylinder|ignored|heights|exaggerated|high|arc|along|across|doubly|curved|point|section|circle|flanks|marks|radially|surface|the|of|at|on)\b/gi;

/**
 * Every word of the profile view but a part marked English: its texts, its
 * elements' names, its options; its lang; and its dimension labels.
 */
const profileWords = (page: Page): Promise<{ lang: string; words: string; dims: string[] }> =>
  page.getByTestId('profile-view').evaluate((v) => {
    const texts: string[] = [];
    const walker = document.createTreeWalker(v, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node !== null; node = walker.nextNode())
      if (node.parentElement?.closest('[lang]')?.getAttribute('lang') !== 'en') texts.push(node.nodeValue ?? '');
    const names = [...v.querySelectorAll('[aria-label]')].map((e) => e.getAttribute('aria-label') ?? '');
    const dims = [...v.querySelectorAll('text.dim-text')].map((t) => t.textContent ?? '');
    return { lang: (v as HTMLElement).lang, words: [...texts, ...names].join(' '), dims };
  });

/**
 * Every word a teaching view (by its test id) shows or names, but its equations (MathML, the paper's
 * symbols): its texts, its elements' accessible names and hover titles.
 */
const viewWords = (page: Page, testId: string): Promise<string> =>
  page.getByTestId(testId).evaluate((v) => {
    const texts: string[] = [];
    const walker = document.createTreeWalker(v, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node !== null; node = walker.nextNode())
      if (node.parentElement?.closest('math') === null) texts.push(node.nodeValue ?? '');
    const names = [...v.querySelectorAll('[aria-label], [title]')].map(
      (e) => `${e.getAttribute('aria-label') ?? ''} ${e.getAttribute('title') ?? ''}`,
    );
    return [...texts, ...names].join(' ');
  });

/** The catalogue tools' names: the preset box's first option, the first chip's title, the chips' legend. */
const toolNames = (page: Page): Promise<{ option: string; title: string; legend: string }> =>
  page.evaluate(() => ({
    option: document.querySelector('[data-testid="preset"] option[value="0"]')?.textContent ?? '',
    title: document.querySelector('.tool-chip')?.getAttribute('title') ?? '',
    legend: document.querySelector('[data-testid="tool-chips"] legend')?.textContent ?? '',
  }));

/** The Latin words the step-through, the formulas and the paper's tables keep in Japanese: the paper's symbols, authors, units. */
const TEACH_KEPT = new Set([
  ...LEGEND_KEPT,
  ...'Rb Reff Rlong Rshort Ztc b d s gamma scp wR wL eta sin sqrt thou Sekine Redonnet Bedi 3D'.split(' '),
]);

/** English words of the procedures table's notes and titles and of the surface box's presets, none of which German keeps. */
const TABLE_ENGLISH =
  /\b(the|exact|answer|point|plane|cylinder|along|across|feed|dome|bowl|saddle|sphere|boss|custom|radii|correction|usual)\b/i;

/** The step-through's, the formulas' and the tables' English words (views/stepperWords.ts, formulaWords.ts, tableWords.ts). */
const TEACH_ENGLISH =
  /(?<!\p{L})(step|of|flank|box|boxes|section|sections|towards|touches|pseudo|single|search|contact|farthest|crossings|best|converged|exact|solver|scene|play|back|forward|first|last|reduced|motion|procedure|torus|shown|true|tool|moves|surface|projection|offset|tilt|posture|ball|approximation|ignores|curvature|lead|osculates|treats|equations|scrolls|sideways|lengths|angles|degrees|table|tables|printed|recomputed|condition|load|why|column|calculator|the|and|at|on|is)(?!\p{L})/giu;

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
    // The scene's dimensions with a decimal comma, its own words and its name in German.
    await expect
      .poll(() => page.locator('.scene-labels .label-dim').first().textContent(), POLL)
      .toBe(`L = ${stepOver(0.05).replace('.', ',')} mm`);
    await expect.poll(() => sceneWords(page), POLL).toContain('Sollebene');
    expect((await sceneWords(page)).match(SCENE_ENGLISH)).toBeNull();
    // The result bar mirrors the headline, in German too; the question named in German; Copy in German.
    expect(await text(page, '[data-role="bar-label"]')).toBe('Bahnabstand L');
    await expect
      .poll(() => text(page, '[data-testid="headline-question"]'))
      .toBe('5-Achs, Anstellung 5°, Kippung 0°, in einer Richtung, Ebene');
    expect(await text(page, '.headline .big button.copy')).toBe('Kopieren');
    await expect.poll(() => text(page, '#tab-profile'), POLL).toBe('Profil quer zum Vorschub');
    expect(await text(page, '#tab-chart')).toBe('L über Anstell- und Kippwinkel');
    // The tabs' list named in German; the presentation mode's button says its word (index.html holds both of its words).
    expect(await page.locator('[role="tablist"]').getAttribute('aria-label')).toBe('Lehransichten');
    expect(await page.getByTestId('present-toggle').locator('span:visible').textContent()).toBe('Präsentation');
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
    // The procedures' table in German: its head and each procedure's name (equations kept), no part marked English.
    await expect
      .poll(() => procedureNames(page), POLL)
      .toEqual({
        head: ['Verfahren', 'L/2', 'Abweichung', 'Abweichung [%]', 'Verbleibende Rautiefe'],
        rows: [
          'Exakt (3D-Geometrie)',
          'Sekine et al. (Gl. 4-8)',
          'Redonnet et al. (Gl. 9, 8)',
          'Bedi et al. (Gl. 10-11)',
          'Schmiegkreis am Kontaktpunkt',
          'Kugel mit dem Eckenradius',
        ],
        english: false,
      });
    expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(PHONE.width);
    // The teeth and feed in German: fz typed with a decimal comma, the finish box in German.
    await page.getByTestId('finish-inputs').locator('summary').click();
    await typeInto(page, 'input-flutes', '4');
    await typeInto(page, 'input-fz', '0,1');
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, '.finish-title'), POLL).toBe('Oberfläche: die Vorschubmarken der Schneiden');
    await expect.poll(() => text(page, '[data-testid="finish-hf"]'), POLL).toMatch(/^\d+,\d+ µm$/);
    expect(await text(page, '[data-testid="use-balanced-feed"]')).toBe('ausgewogenen Vorschub übernehmen');
    // The finish profiles' charts: their ticks with a decimal comma, as the teaching charts' (views/lineChart.ts).
    // (The across profile's ticks are whole numbers here: none with a point.)
    await expectCommaTicks(page, 'finish-profile-along-chart');
    expect((await ticksOf(page, 'finish-profile-across-chart')).filter((t) => /\d\.\d/.test(t))).toEqual([]);
    // The cell map's caption and name, and the areal rows' titles, in German with decimal commas.
    await expect
      .poll(() => text(page, '[data-testid="finish-map-scale"]'), POLL)
      .toMatch(/^Eine Periodenzelle, 0,10* mm in Vorschubrichtung .* Sz = \d+,\d+ µm dazwischen\./);
    expect(await page.getByTestId('finish-map-image').getAttribute('aria-label')).toMatch(/^Höhen einer Periodenzelle/);
    expect(await page.getByTestId('finish-areal').locator('div[title]').first().getAttribute('title')).toBe(
      'quadratischer Mittelwert der Höhe',
    );
    // A refusal of the finish worker, worded on the page from its data: the bound in mm, what was typed.
    await typeInto(page, 'input-fz', '5');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => text(page, '[data-testid="finish-message"]'), POLL)
      .toBe('Vorschub pro Zahn fz darf höchstens den Werkzeugradius R = 3 mm betragen (eingegeben: 5).');
    expect(await page.getByTestId('finish-message').evaluate((e) => e.closest('[lang]')?.getAttribute('lang'))).toBe(
      'de',
    );
    await typeInto(page, 'input-fz', '0,1');
    await page.keyboard.press('Enter');
    // The target-Sa box's refusal in German (the worker names it, the page words it): runout refused,
    // in the box and on its field, no longer marked English.
    await typeInto(page, 'input-runout', '0,01');
    await page.locator('input[name="target"][value="sa"]').check();
    await typeInto(page, 'input-sa', '0,0008');
    await page.keyboard.press('Enter');
    const runout =
      'Ziel-Sa wird ohne Rundlauffehler berechnet: für das beste Paar den Rundlauffehler e auf 0 setzen (oder leer lassen).';
    await expect.poll(() => text(page, '[data-testid="target-sa-message"]'), { timeout: 30_000 }).toBe(runout);
    expect(await text(page, '[data-testid="error-runout"]')).toBe(runout);
    // A switch words it anew, in the page's language (not marked English).
    await tap(page, 'ja');
    await expect
      .poll(() => text(page, '[data-testid="target-sa-message"]'), POLL)
      .toMatch(/^目標 Sa は振れなしで計算します/);
    const saLang = () =>
      page.getByTestId('target-sa-message').evaluate((e) => e.closest('[lang]')?.getAttribute('lang'));
    expect(await saLang()).toBe('ja');
    await tap(page, 'de');
    await expect.poll(() => text(page, '[data-testid="target-sa-message"]'), POLL).toBe(runout);
    expect(await saLang()).toBe('de');
    await typeInto(page, 'input-runout', '');
    await page.locator('input[name="target"][value="h"]').check();
    await page.keyboard.press('Enter');
    // The machined surface (the teeth's): its caption, scale line, legend and names in German, numbers with a comma.
    await page.locator('#tab-surface').click();
    await expect
      .poll(() => text(page, '[data-testid="surface-shown"]'), POLL)
      .toMatch(/^Die Oberfläche der Schneiden .* z = 4, fz = 0,10* mm, L = \d+,\d+ mm; /);
    await expect
      .poll(() => text(page, '[data-testid="surface-exaggeration"]'), POLL)
      .toMatch(/über dem tiefsten Punkt \(µm\)\.$/);
    const surface = await surfaceWords(page);
    expect(surface.lang).toBe('de');
    expect(surface.words.match(SURFACE_ENGLISH), surface.words).toBeNull();
    expect(surface.legend.some((t) => /\d,\d/.test(t)) && !surface.legend.some((t) => /\d\.\d/.test(t))).toBe(true);
    await page.locator('#tab-profile').click();
    // The cross-feed profile in German: its dimensions with a decimal comma, its words, names and lang.
    await expect
      .poll(async () => (await profileWords(page)).dims, POLL)
      .toContain(`L = ${stepOver(0.08).replace('.', ',')} mm`);
    const profile = await profileWords(page);
    expect(profile.lang).toBe('de');
    // The legend's procedures in German too (no longer marked English).
    expect(profile.words).toContain('Exakt (3D)');
    expect(profile.words).toContain('Schmiegkreis');
    expect(profile.words.match(PROFILE_ENGLISH), profile.words).toBeNull();
    expect(profile.dims.filter((t) => /\d\.\d/.test(t))).toEqual([]);
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
    expect(await page.getByTestId('present-toggle').locator('span:visible').textContent()).toBe('発表モード');
    expect(await page.locator('[role="tablist"]').getAttribute('aria-label')).toBe('解説ビュー');
    // The 3D scene's legend in Japanese: no Latin word but the paper's symbols (and its lang the page's).
    const legend = await text(page, '[data-testid="scene-legend"]');
    expect(
      latinWords(legend).filter((w) => !LEGEND_KEPT.has(w)),
      legend,
    ).toEqual([]);
    expect(await page.getByTestId('scene-legend').getAttribute('lang')).toBeNull();
    // The scene's own labels and its name in Japanese: the surfaces' names, the symbols kept.
    await expect.poll(() => sceneWords(page), POLL).toContain('設計平面');
    const scene = await sceneWords(page);
    expect(
      latinWords(scene).filter((w) => !LEGEND_KEPT.has(w)),
      scene,
    ).toEqual([]);
    expect(await page.getByTestId('scene').getAttribute('lang')).toBeNull();
    expect(await text(page, '[data-testid="result-exact-interval"]')).toMatch(/^\d+\.\d{4} mm$/);
    // The procedures' table in Japanese: the authors and the equation numbers kept, the words around them translated.
    await expect
      .poll(async () => (await procedureNames(page)).rows.slice(0, 2), POLL)
      .toEqual(['厳密解（3次元形状）', 'Sekine らの式 (4)-(8)']);
    expect((await procedureNames(page)).head[0]).toBe('手法');
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
    expect(await page.getByTestId('present-toggle').locator('span:visible').textContent()).toBe('Present');
    expect(await page.locator('[role="tablist"]').getAttribute('aria-label')).toBe('Teaching views');
    expect((await procedureNames(page)).rows[0]).toBe('Exact (3D geometry)');
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

  it('the shop sheet in Japanese and German: no English word left on screen or printed, German decimal commas', async () => {
    // English first (the page is in English by now): the sheet's own words, to find any left over.
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('en');
    const englishMessage = await openSheet(page, '.');
    expect(await text(page, '[data-testid="shop-sheet-title"]')).toBe('Shop sheet: L (mm)');
    const english = new Set(latinWords(`${englishMessage} ${await sheetWords(page)}`));
    // The English sheet's words include its legend, its hints, its buttons and its table's names.
    for (const w of ['Bold', 'posture', 'Tap', 'Hover', 'Print', 'Close', 'Download', 'table', 'separated'])
      expect(english.has(w), `${w} in ${[...english].join(' ')}`).toBe(true);
    await page.getByTestId('shop-sheet-close').click();
    for (const [lang, title, sign] of [
      ['ja', '現場用シート：L（mm）', '.'],
      ['de', 'Werkstattblatt: L (mm)', ','],
    ] as const) {
      await tap(page, lang);
      await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe(lang);
      const message = await openSheet(page, sign);
      expect(await text(page, '[data-testid="shop-sheet-title"]')).toBe(title);
      // Japanese: no Latin word but the symbols and the unit; German: none of the English sheet's words.
      const leftOver = (t: string) =>
        latinWords(t).filter((w) => !SHEET_KEPT.has(w) && (lang === 'ja' || english.has(w)));
      const words = `${message} ${await sheetWords(page)}`;
      expect(leftOver(words), `${lang}: ${words}`).toEqual([]);
      // axe on the open sheet in the language (its reason tapped).
      if (lang === 'ja') expect(await axeViolations(page)).toEqual([]);
      // Printed (print media): the sheet alone, in the language.
      await page.emulateMedia({ media: 'print' });
      expect(await page.locator('#app').isVisible()).toBe(false);
      // biome-ignore lint/performance/useDomNodeTextContent: the text as rendered in print is the point
      const printed = await page.getByTestId('shop-sheet-dialog').evaluate((d) => (d as HTMLElement).innerText);
      expect(printed).toContain(title);
      // The marks print as their letters (a mark is a button on screen; the page's buttons do not print).
      expect(await page.getByTestId('shop-sheet-table').locator('td.refused .mark').first().isVisible()).toBe(true);
      expect(leftOver(printed), `${lang} printed: ${printed}`).toEqual([]);
      await keepShot(page, `shop-sheet-print-${lang}-phone`, { fullPage: true });
      await page.emulateMedia({ media: 'screen' });
      // The numbers with the locale's decimal sign, every digit kept; past the limit, a W.
      expect(await rowHeads(page)).toEqual(expect.arrayContaining(['0.01', '0.05'].map((h) => h.replace('.', sign))));
      const cells = await page
        .getByTestId('shop-sheet-table')
        .locator('tbody tr')
        .first()
        .locator('td')
        .allTextContents();
      for (const c of cells) expect(c).toMatch(sign === ',' ? /^\d+,\d{4}$/ : /^\d+\.\d{4}$/);
      expect(
        await page.getByTestId('shop-sheet-table').locator('tbody tr').last().locator('td').first().textContent(),
      ).toBe('W');
      await page.getByTestId('shop-sheet-close').click();
    }
    await tap(page, 'en');
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('en');
  });

  it('German words the page writes itself: the three-axis step, its question with a decimal comma, Copy said, an empty slider, a flat end lying flat', async () => {
    // A link value replaced: the notice in the language, its details too (the parameter and its value kept, nothing marked English).
    await page.goto(new URL('?R=3&Rcr=abc&rho=5&h=0.05&unit=mm&lang=de', page.url()).href);
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('de');
    const notice = page.getByTestId('notice');
    await expect
      .poll(() => notice.textContent(), POLL)
      .toMatch(
        /^Einige Werte des Links wurden ersetzt: Rcr="abc" im Link ist keine Zahl; der Standardwert \S+ wird verwendet\.$/,
      );
    expect(await notice.locator('[lang="en"]').count()).toBe(0);
    expect(await notice.getAttribute('lang')).toBe('de');
    await tap(page, 'ja');
    await expect
      .poll(() => notice.textContent(), POLL)
      .toMatch(/^リンクの値の一部を置き換えました：リンクの Rcr="abc" は数値ではありません。既定値 \S+ を使います。$/);
    await tap(page, 'en');
    await expect.poll(() => notice.textContent(), POLL).toMatch(/^Some link values were replaced: \S*Rcr\S*="abc"/);
    expect(await notice.getAttribute('lang')).toBeNull();
    await page
      .context()
      .grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(page.url()).origin });
    await tap(page, 'de');
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('de');
    // An optional field left empty: its slider says so in German.
    await expect.poll(() => page.getByTestId('slider-runout').getAttribute('aria-valuetext'), POLL).toBe('leer');
    // The comparison charts in German: captions, axis titles, choices, the legend's head, the summary,
    // the ticks' decimal commas; no English word of theirs left but the procedures' names.
    await page.locator('#tab-chart').click();
    const caption = page.getByTestId('chart-lead').locator('figcaption');
    await expect
      .poll(() => caption.textContent(), POLL)
      .toBe('L [mm] über dem Anstellwinkel rho [°] (R, Rcr, beta, h fest; gestrichelt: aktueller rho = 5)');
    expect(await page.getByTestId('chart-summary').textContent()).toMatch(/^Bei rho = 5°, beta = 0°, L: .*\d,\d{4} mm/);
    const charts = await page.getByTestId('comparison-chart').evaluate((e) => {
      const classic = e.querySelector('.chart-classic') as HTMLElement;
      const parts = [...classic.querySelectorAll('figcaption, text, option, .chart-legend-head, [aria-label]')];
      return {
        lang: classic.lang,
        words: [...parts.map((p) => p.textContent ?? ''), ...parts.map((p) => p.getAttribute('aria-label') ?? '')].join(
          ' ',
        ),
        ticks: [...classic.querySelectorAll('text')]
          .map((t) => t.textContent ?? '')
          .filter((t) => /^[\d.,−-]+$/.test(t)),
        names: [...classic.querySelectorAll('[data-testid="chart-lead"] .legend-name')].map((n) => n.textContent ?? ''),
      };
    });
    expect(charts.lang).toBe('de');
    expect(charts.names).toEqual([
      'Exakt (3D)',
      'Sekine et al.',
      'Redonnet et al.',
      'Bedi et al.',
      'Schmiegkreis',
      'Eckenradius-Kugel',
    ]);
    expect(
      charts.words.match(
        /\b(against|lead|tilt|fixed|dashed|current|error|axis|angle|signed|approximation|along|length|at|deg)\b/gi,
      ),
      charts.words,
    ).toBeNull();
    expect(charts.ticks.some((t) => /\d,\d/.test(t)) && !charts.ticks.some((t) => /\d\.\d/.test(t))).toBe(true);
    // The gaps' notes in German, their reasons too (the solver's, read back: nothing marked English).
    const gaps = await page.getByTestId('comparison-chart').evaluate((e) =>
      [...e.querySelectorAll('.chart-classic .chart-gaps li')].map((li) => ({
        text: li.textContent ?? '',
        english: li.querySelector('[lang="en"]') !== null,
      })),
    );
    expect(gaps.length).toBeGreaterThan(0);
    expect(gaps.filter((g) => g.english)).toEqual([]);
    const gapText = gaps.map((g) => g.text).join(' ');
    expect(
      gapText.match(
        /\b(is|the|at|no|from|above|widest|infinite|degenerates|flat|divides|overflows|sharp|edge|corner|ball)\b/gi,
      ),
      gapText,
    ).toBeNull();
    // A switch while the charts are on screen draws them anew in its words.
    await tap(page, 'ja');
    await expect.poll(() => caption.textContent(), POLL).toMatch(/^前傾角 rho \[°\] に対する L \[mm\]/);
    await tap(page, 'de');
    await expect.poll(() => caption.textContent(), POLL).toMatch(/^L \[mm\] über dem Anstellwinkel/);
    // The machined surface simulated (no teeth given): the comparison, the trace, the scale line in German.
    await page.locator('#tab-surface').click();
    await expect
      .poll(() => text(page, '[data-testid="surface-comparison"]'), { timeout: 30_000 })
      .toMatch(/^Simulierte Kammhöhe \d+,\d+ µm gegenüber exakt \d+,\d+ µm: /);
    const simulated = await surfaceWords(page);
    expect(simulated.lang).toBe('de');
    expect(simulated.words).toMatch(/Simulierter Tastschnitt, \d+ Bahnen\. Exakt: Rz \d+,\d+ µm/);
    expect(simulated.words.match(SURFACE_ENGLISH), simulated.words).toBeNull();
    // A switch while it is on screen words it anew.
    await tap(page, 'ja');
    await expect
      .poll(() => text(page, '[data-testid="surface-comparison"]'), POLL)
      .toMatch(/^シミュレーションのカスプ高さ /);
    const japanese = await surfaceWords(page);
    expect(
      latinWords(japanese.words.replace(/µ(m|in)\b/g, '')).filter((w) => !SURFACE_KEPT.has(w)),
      japanese.words,
    ).toEqual([]);
    await tap(page, 'de');
    await expect.poll(() => text(page, '[data-testid="surface-comparison"]'), POLL).toMatch(/^Simulierte Kammhöhe /);
    await page.locator('#tab-profile').click();
    await page.locator('[data-testid="machine-switch"] input[value="3axis"]').check();
    await typeInto(page, 'input-slope', '20,5');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => text(page, '[data-role="headline-label"]'), POLL)
      .toBe('Waagerechter Bahnabstand Lxy (wie programmiert)');
    expect(await text(page, '[data-i18n="alongSurface"]')).toBe('L entlang der Fläche');
    await expect.poll(() => text(page, '[data-testid="headline-question"]'), POLL).toMatch(/^3-Achs, Neigung 20,5°, /);
    await expect
      .poll(() => text(page, '[data-testid="result-bar-question"]'), POLL)
      .toMatch(/^3-Achs, Neigung 20,5°, /);
    // A three-axis refusal in German, its bound in mm with a decimal comma: h past the flank's or shank's limit.
    const h = await page.getByTestId('input-h').inputValue();
    await typeInto(page, 'input-h', '5');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => text(page, '[data-testid="error-h"]'), POLL)
      .toMatch(/^Rautiefe h muss bei dieser Neigung unter \d+,\d+ mm liegen \(eingegeben: 5\)[;:] /);
    await typeInto(page, 'input-h', h);
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, '[data-testid="error-h"]'), POLL).toBe('');
    // The three-axis chart in German: captions, axis titles, legends, the crossing sentence, notes,
    // the ticks' decimal commas; no English word of its own left.
    await page.locator('#tab-chart').click();
    const slopeCaption = page.getByTestId('chart-slope').locator('figcaption');
    await expect
      .poll(() => slopeCaption.textContent(), POLL)
      .toMatch(/^Programmierter Abstand \[mm\] über der Neigung/);
    const slopeView = await page.getByTestId('chart-slope-view').evaluate((e) => ({
      lang: (e as HTMLElement).lang,
      words: [
        ...[...e.querySelectorAll('figcaption, text, li, p')].map((p) => p.textContent ?? ''),
        ...[...e.querySelectorAll('[aria-label]')].map((p) => p.getAttribute('aria-label') ?? ''),
      ].join(' '),
      ticks: [...e.querySelectorAll('text')].map((t) => t.textContent ?? '').filter((t) => /^[\d.,−-]+$/.test(t)),
    }));
    expect(slopeView.lang).toBe('de');
    expect(
      slopeView.words.match(
        /\b(against|slope|step|scallop|programmed|fixed|dashed|dotted|current|constant|leaves|raster|waterline|flat|floor|above|below|cross|larger|at|of|the|no)\b/gi,
      ),
      slopeView.words,
    ).toBeNull();
    expect(slopeView.ticks.some((t) => /\d,\d/.test(t)) && !slopeView.ticks.some((t) => /\d\.\d/.test(t))).toBe(true);
    await page.locator('#tab-profile').click();
    // The profile's line over the three-axis question in German, its numbers with a decimal comma.
    await expect
      .poll(() => page.getByTestId('views-page-note').textContent(), POLL)
      .toMatch(
        /^Das senkrechte Werkzeug bei Neigung 20,5°, Zeilenwinkel 0° ist das Werkzeug mit Anstellwinkel \d+(,\d+)?°/,
      );
    expect(await page.getByTestId('views-page-note').getAttribute('lang')).toBe('de');
    // Copy says what it copied in German (the value with a point, as pasted into CAM), the question too.
    await page.evaluate(() => {
      const live = document.querySelector('[data-testid="copy-status"]') as HTMLElement;
      const said: string[] = [];
      (window as unknown as { said: string[] }).said = said;
      new MutationObserver(() => said.push(live.textContent ?? '')).observe(live, { childList: true });
    });
    await page.locator('.headline .big button.copy').click();
    await expect
      .poll(() => page.evaluate(() => (window as unknown as { said: string[] }).said.filter((t) => t !== '')), POLL)
      .toEqual([expect.stringMatching(/^\d+\.\d+ \(mm\) kopiert: 3-Achs, Neigung 20,5°, .*\.$/)]);
    // Copy link says so in German too.
    await page.getByTestId('copy-link').click();
    await expect
      .poll(() => text(page, '[data-testid="copy-link-status"]'), POLL)
      .toBe('Link kopiert: Er öffnet diesen Rechner mit diesen Eingaben.');
    // A doubly curved point's charts in German: caption, axis titles, legends, summary, ticks.
    await page.locator('[data-testid="machine-switch"] input[value="5axis"]').check();
    await page.locator('input[name="surface"][value="curved"]').check();
    await typeInto(page, 'input-feed-radius', '80');
    await typeInto(page, 'input-cross-radius', '40');
    await page.keyboard.press('Enter');
    await page.locator('#tab-chart').click();
    await expect
      .poll(() => page.getByTestId('chart-radius-feed').locator('figcaption').textContent(), POLL)
      .toMatch(/^L \[mm\] über \|Rf\| \[mm\], logarithmische Achse \(Rc fest konvex 40 mm; /);
    const radiusView = await page.getByTestId('chart-radius-view').evaluate((e) => ({
      lang: (e as HTMLElement).lang,
      words: [...e.querySelectorAll('figcaption, text, li, p')].map((p) => p.textContent ?? '').join(' '),
    }));
    expect(radiusView.lang).toBe('de');
    expect(
      radiusView.words.match(
        /\b(against|log|axis|held|fixed|dashed|current|convex|concave|straight|at|with|no|the)\b/gi,
      ),
      radiusView.words,
    ).toBeNull();
    expect(await page.getByTestId('chart-radius-summary').textContent()).toMatch(
      /^Bei Rf konvex 80 mm, Rc konvex 40 mm: L = \d+,\d{4} mm/,
    );
    // The scene on a doubly curved point: the step-over measured along an arc, said in German.
    await expect
      .poll(() => page.locator('.scene-labels .label-dim').first().textContent(), POLL)
      .toMatch(/^L = \d+,\d{4} mm \(Bogenlänge\)$/);
    expect((await sceneWords(page)).match(SCENE_ENGLISH), await sceneWords(page)).toBeNull();
    await page.locator('#tab-profile').click();
    // The profile at that point in German: its note, the arc, its words.
    await expect
      .poll(() => text(page, '[data-testid="profile-cylinder-note"]'), POLL)
      .toMatch(/^An einem doppelt gekrümmten Punkt \(Rf konvex 80 mm in Vorschubrichtung/);
    const curvedProfile = await profileWords(page);
    expect(
      curvedProfile.dims.some((t) => /^L = \d+,\d{4} mm \(Bogenlänge\)$/.test(t)),
      curvedProfile.dims.join(' | '),
    ).toBe(true);
    expect(curvedProfile.words.match(PROFILE_ENGLISH), curvedProfile.words).toBeNull();
    // The comparison rows at that point in German: the exact answers' names, a corrected procedure's.
    const curvedRows = () =>
      page
        .getByTestId('procedures-table')
        .evaluate((t) => [...t.querySelectorAll('tr[data-curved] > th')].map((th) => th.textContent ?? ''));
    await expect.poll(curvedRows, POLL).toContain('Exakt (dieser doppelt gekrümmte Punkt)');
    expect(await curvedRows()).toContain('Sekine et al., korrigiert (1/rho = 1/Reff + 1/Rc)');
    expect(await curvedRows()).toContain('Zylinder quer zum Vorschub, exakt (Rc ignoriert)');
    // Their hover titles, the table's notes (nothing marked English) and the surface box's presets in German.
    await expect
      .poll(() => text(page, '[data-testid="table-notes"]'), POLL)
      .toMatch(/^Jede Zeile neben der exakten Lösung: /);
    const curvedTable = await page.evaluate(() => ({
      titles: [...document.querySelectorAll<HTMLElement>('.procedures tr[data-curved]')].map((tr) => tr.title),
      english: document.querySelectorAll('[data-testid="table-notes"] [lang="en"]').length,
      presets: [...document.querySelectorAll('[data-testid="surface-preset"] option')].map((o) => o.textContent ?? ''),
      presetLabel: document.querySelector('[data-i18n="surfacePreset"]')?.textContent ?? '',
    }));
    expect(curvedTable.titles).toContain('Der exakte Bahnabstand in diesem Punkt.');
    expect(curvedTable.english).toBe(0);
    expect(curvedTable.presets).toContain('Kuppel (in beiden Richtungen konvex)');
    expect(curvedTable.presetLabel).toBe('Flächenvorgabe');
    const curvedWords = [...curvedTable.titles, ...curvedTable.presets].join(' ');
    expect(curvedWords.match(TABLE_ENGLISH), curvedWords).toBeNull();
    expect(await text(page, '[data-testid="surface-meaning"]')).toMatch(/^An diesem doppelt gekrümmten Punkt \(Rf /);
    // A radius field's own error in German (the page's, before any worker): not a number, what was typed quoted.
    await typeInto(page, 'input-cross-radius', 'abc');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => text(page, '[data-testid="error-cross-radius"]'), POLL)
      .toBe('Radius quer Rc muss eine Zahl sein (eingegeben: "abc").');
    await typeInto(page, 'input-cross-radius', '40');
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, '[data-testid="error-cross-radius"]'), POLL).toBe('');
    // The radius side boxes' names and choices, and the link's text box's name, in German.
    const named = () =>
      page.evaluate(() =>
        ['side-feed-radius', 'side-cross-radius', 'link-text'].map((id) => {
          const e = document.querySelector(`[data-testid="${id}"]`) as HTMLElement;
          return [e.getAttribute('aria-label'), ...[...e.querySelectorAll('option')].map((o) => o.textContent)].join(
            ' | ',
          );
        }),
      );
    expect(await named()).toEqual([
      'Radius längs Rf: konvex, konkav oder gerade | konvex | konkav | gerade',
      'Radius quer Rc: konvex, konkav oder gerade | konvex | konkav | gerade',
      'Link zu diesem Zustand',
    ]);
    // A refusal at that point worded on the page from the worker's data, in German: h above a flank's or the shank's limit.
    const curvedH = await page.getByTestId('input-h').inputValue();
    await typeInto(page, 'input-h', '5');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => text(page, '[data-testid="error-h"]'), POLL)
      .toMatch(/^Rautiefe h muss an diesem Punkt unter \d+,\d+ mm liegen \(eingegeben: 5\): darüber /);
    await typeInto(page, 'input-h', curvedH);
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, '[data-testid="error-h"]'), POLL).toBe('');
    // A convex cylinder: the corrected rows' hover titles (what each assumes) and the table's notes in German.
    await page.locator('input[name="surface"][value="convex"]').check();
    await typeInto(page, 'input-surface-radius', '20');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => page.locator('.procedures tr[data-curvature="sekineCorrected"]').getAttribute('title'), POLL)
      .toMatch(/^Der Kreis mit Radius Reff von Sekine et al\. mit der üblichen Krümmungskorrektur /);
    expect(await text(page, '[data-testid="table-notes"]')).toMatch(/^Auf einem Zylinder werden die Verfahren oben /);
    expect(await text(page, '.procedures tr.curvature-head th')).toBe(
      'Auf dem Zylinder: Krümmung ignoriert oder wie üblich korrigiert',
    );
    expect(await page.locator('[data-testid="table-notes"] [lang="en"]').count()).toBe(0);
    // What L and the heights mean on it, and what the step-over means, in German (no part marked English).
    expect(await text(page, '[data-testid="surface-meaning"]')).toMatch(
      /^Auf diesem konvexen Zylinder \(Radius 20,\d+ mm, Achse in Vorschubrichtung: /,
    );
    expect(await text(page, '[data-testid="step-over-meaning"]')).toMatch(
      /^Der Bahnabstand L ist .* quer zum Vorschub verschieben um −y0 = -?\d+,\d+ mm Kopieren\.$/,
    );
    expect(await page.locator('.meaning[lang="en"], .meaning [lang="en"]').count()).toBe(0);
    await page.locator('input[name="surface"][value="plane"]').check();
    // Back to five axes: a flat end without lead or tilt lies flat, said in German with its L = 2R.
    await page.locator('[data-testid="machine-switch"] input[value="5axis"]').check();
    await typeInto(page, 'input-Rcr', '0');
    await typeInto(page, 'input-rho', '0');
    await page.keyboard.press('Enter');
    await expect
      .poll(() => text(page, '[data-testid="no-scallop"]'), POLL)
      .toMatch(/^Kein Kamm: ein Schaftfräser ohne Anstell- und Kippwinkel .* also L = 2R = 6,0000 mm für jedes h\.$/);
    // The table's notes say it too, and why the models without lead give no value (their cells' n/a), in German.
    expect(await text(page, '[data-testid="table-notes"]')).toMatch(/^Kein Kamm: ein flach aufliegender Schaftfräser /);
    expect(await text(page, '[data-testid="table-notes"]')).toContain('Sekine et al.: bei rho = 0 ');
    expect(await page.locator('[data-testid="table-notes"] [lang="en"]').count()).toBe(0);
    expect(await text(page, '[data-testid="result-sekine-half"]')).toBe('nicht berechenbar');
    await typeInto(page, 'input-Rcr', '1');
    await typeInto(page, 'input-rho', '5');
    await page.keyboard.press('Enter');
    // Given Ra: the roughness rows' scallop height for it, named in German.
    const raHeight = page
      .getByTestId('roughness')
      .locator('div', { has: page.getByTestId('result-ra-height') })
      .locator('dt');
    await page.locator('input[name="target"][value="ra"]').check();
    await expect.poll(() => raHeight.textContent(), POLL).toBe('Rautiefe h für dieses Ra');
    await page.locator('input[name="target"][value="h"]').check();
    await tap(page, 'en');
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('en');
    await expect.poll(() => text(page, '[data-role="headline-label"]'), POLL).toBe('Step-over L');
    // Their English back.
    expect(await raHeight.textContent()).toBe('h for this Ra');
    expect(await named()).toEqual([
      'Feed radius Rf: convex, concave or straight | convex | concave | straight',
      'Cross radius Rc: convex, concave or straight | convex | concave | straight',
      'Link to this state',
    ]);
  });

  it("the step-through's steps, the formulas and the paper's tables in Japanese and German: no English left, German decimal commas", async () => {
    // The page is in English by now (R = 3, Rcr = 1, rho = 5, h = 0.05 on a plane, five axes).
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('en');
    for (const lang of ['ja', 'de'] as const) {
      await tap(page, lang);
      await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe(lang);
      // Every step of the step-through, walked with its Forward button: captions, counter, gauge.
      await page.locator('#tab-stepper').click();
      await expect.poll(() => page.getByTestId('stepper').getAttribute('lang'), POLL).toBe(lang);
      await page.getByTestId('stepper-first').click();
      await expect.poll(() => text(page, '[data-testid="stepper-counter"]'), POLL).toMatch(/\d/);
      const steps = await page.getByTestId('stepper').evaluate((v) => {
        const read = (id: string) => v.querySelector(`[data-testid="${id}"]`)?.textContent ?? '';
        const forward = v.querySelector('[data-testid="stepper-forward"]') as HTMLButtonElement;
        const seen: string[] = [];
        // A step's counter names the total: the walk stops at the last step (each click draws at once).
        for (let i = 0; i < 100; i++) {
          seen.push(`${read('stepper-counter')} ${read('stepper-caption')} ${read('stepper-ds-text')}`);
          const counter = read('stepper-counter');
          forward.click();
          if (read('stepper-counter') === counter) break;
        }
        return seen;
      });
      expect(steps.length, steps.join('\n')).toBeGreaterThanOrEqual(20);
      const stepper = [...steps, await viewWords(page, 'stepper')].join(' ');
      // Formulas: their words (the equations' own symbols left out), their names, the decimal sign in the slots.
      await page.locator('#tab-formulas').click();
      await expect.poll(() => page.getByTestId('formulas').getAttribute('lang'), POLL).toBe(lang);
      const formulas = await viewWords(page, 'formulas');
      const slots = await page
        .getByTestId('formulas')
        .evaluate((v) => [...v.querySelectorAll('math [class^="slot-"]')].map((e) => e.textContent ?? '').join(' '));
      // The paper's tables: notes, captions, head, names, rows' titles, the cells' decimal sign.
      await page.locator('#tab-tables').click();
      await expect.poll(() => page.getByTestId('paper-tables').getAttribute('lang'), POLL).toBe(lang);
      const tables = await viewWords(page, 'paper-tables');
      // The procedures' table's name, its box's and its rows' hover title.
      const procedures = await page
        .getByTestId('procedures-scroll')
        .evaluate((box) =>
          [
            box.getAttribute('aria-label') ?? '',
            box.querySelector('table')?.getAttribute('aria-label') ?? '',
            ...[...box.querySelectorAll('tr[title]')].map((tr) => tr.getAttribute('title') ?? ''),
          ].join(' '),
        );
      // The roughness's rule of thumb and L's share of the tool diameter, with the locale's decimal sign.
      expect(await text(page, '[data-testid="result-ra-rule"]')).toMatch(
        lang === 'ja'
          ? /^経験則 Ra ~ h\/4 = \d+\.\d+ µm：厳密な Ra に対して [+-]?\d+\.\d+ %。$/
          : /^Faustregel Ra ~ h\/4 = \d+,\d+ µm: [+-]?\d+,\d+ % gegenüber dem exakten Ra\.$/,
      );
      expect(await text(page, '[data-testid="result-percent-diameter"]')).toMatch(
        lang === 'ja' ? /^L = 工具直径の \d+\.\d %$/ : /^L = \d+,\d % des Werkzeugdurchmessers$/,
      );
      // The catalogue tools' names: the preset box's first option, a chip's title, the chips' legend.
      await expect
        .poll(() => toolNames(page), POLL)
        .toEqual(
          lang === 'ja'
            ? {
                option: 'D6、コーナ R1（論文の工具 1）',
                title: 'D6、コーナ R1（論文の工具 1）',
                legend: 'カタログの工具（mm）',
              }
            : {
                option: 'D6, Eckenradius R1 (Werkzeug 1 der Studie)',
                title: 'D6, Eckenradius R1 (Werkzeug 1 der Studie)',
                legend: 'Katalogwerkzeuge (mm)',
              },
        );
      // The 3D scene's heights' scale badge and its title (the scene's own words).
      await expect
        .poll(
          () => page.getByTestId('scene-exaggeration').evaluate((e) => `${e.textContent} | ${e.getAttribute('title')}`),
          POLL,
        )
        .toMatch(
          lang === 'ja'
            ? /^高さを \d+ 倍で表示（平面から 2h まで） \| カスプが見えるように、/
            : /^Höhen \d+-fach überhöht \(bis 2h über der Ebene\) \| Damit der Kamm sichtbar wird, /,
        );
      // The landmarks' names (index.html's data-i18n-label).
      expect(await page.locator('section.controls').getAttribute('aria-label')).toBe(
        lang === 'ja' ? '入力' : 'Eingaben',
      );
      expect(await page.locator('section.notices').getAttribute('aria-label')).toBe(
        lang === 'ja' ? 'お知らせ' : 'Hinweise',
      );
      const teachingName = lang === 'ja' ? '解説ビュー' : 'Lehransichten';
      expect(await page.locator('section.teaching').getAttribute('aria-label')).toBe(teachingName);
      expect(await page.locator('section.teaching > h2.sr-only').textContent()).toBe(teachingName);
      const all = `${stepper} ${formulas} ${tables} ${procedures}`;
      if (lang === 'ja') {
        const left = latinWords(all.replace(/µ(m|in)\b/g, '')).filter((w) => !TEACH_KEPT.has(w));
        expect([...new Set(left)], all).toEqual([]);
        expect(all).not.toMatch(/\d,\d/);
      } else {
        expect([...new Set(all.match(TEACH_ENGLISH) ?? [])], all).toEqual([]);
        // German numbers with a decimal comma: the captions, the slots, the tables' cells; no point left.
        expect(stepper).toMatch(/\d,\d/);
        expect(slots).toMatch(/\d,\d/);
        expect(tables).toMatch(/\d,\d{3}\s+\/\s+\d,\d{4}/);
        expect(`${stepper} ${slots} ${tables}`).not.toMatch(/\d\.\d/);
      }
    }
    expect(await page.evaluate(() => document.documentElement.scrollWidth)).toBeLessThanOrEqual(PHONE.width);
    await pageSettled(page);
    expect(await axeViolations(page)).toEqual([]);
    // English comes back whole: the step-through's, the tables' words as written.
    await tap(page, 'en');
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('en');
    await expect
      .poll(() => page.getByTestId('paper-table-half').locator('caption').textContent(), POLL)
      .toBe('Tables 2-3: L/2 [mm] for h');
    expect(await page.getByTestId('paper-tables').getAttribute('lang')).toBeNull();
    expect(await page.getByTestId('procedures-scroll').getAttribute('aria-label')).toBe(
      'Procedures table (scrolls sideways when wider than its column)',
    );
    expect(await page.locator('section.controls').getAttribute('aria-label')).toBe('Inputs');
    await expect
      .poll(() => toolNames(page), POLL)
      .toEqual({
        option: 'D6, corner R1 (paper Tool 1)',
        title: 'D6, corner R1 (paper Tool 1)',
        legend: 'Catalogue tools (mm)',
      });
    expect(await text(page, '[data-testid="result-percent-diameter"]')).toMatch(/^L = \d+\.\d % of the tool diameter$/);
    expect(await page.getByTestId('procedures-table').getAttribute('aria-label')).toBe(
      'Procedures (select a row to highlight it in every view)',
    );
    await page.locator('#tab-stepper').click();
    await expect.poll(() => text(page, '[data-testid="stepper-counter"]'), POLL).toMatch(/^step \d+ of \d+$/);
    await page.locator('#tab-profile').click();
  });

  it("an embed takes its language from the link (the element's lang attribute), not the one remembered (English by now)", async () => {
    await page.goto(new URL(`${QUERY}&embed=1&lang=ja`, page.url()).href);
    await expect.poll(() => page.evaluate(() => document.documentElement.lang), POLL).toBe('ja');
    await expect.poll(() => text(page, '[data-role="headline-label"]'), POLL).toBe('ピックフィード L');
    await page.goto(new URL(`${QUERY}&embed=1`, page.url()).href);
    await expect.poll(() => text(page, '[data-role="headline-label"]'), POLL).toBe('Step-over L');
  });
});
