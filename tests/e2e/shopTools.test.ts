/**
 * Tools as the shop has them (issue 21), driven on a phone (390 x 844, touch): lengths typed as
 * people write them (1/2", 12.7 mm), a Fusion 360 tool library imported through the file input and
 * a tool picked from it, a tool saved in the browser and picked after a reload, and Copy link.
 * Expected step-overs come from the command line (its own parsing of plain mm numbers).
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { keepShot, pageSettled, ROOT, typeInto, usePhonePage, useSite } from './harness';

const site = useSite('docs/shop-tools', { scene: false });

const open = usePhonePage(site);

/** A field on the phone: tapped, then typed key by key 20 ms apart. */
const PHONE_TYPING = { tap: true, delayMs: 20 } as const;

const text = async (page: Page, id: string) => (await page.getByTestId(id).textContent())?.trim() ?? '';

/** The command line's exact step-over L in mm for a tool and h given in mm. */
function cliInterval(R: number, Rcr: number, h: number): number {
  const args = ['--R', String(R), '--Rcr', String(Rcr), '--rho', '5', '--h', String(h), '--json'];
  const r = spawnSync(process.execPath, [`${ROOT}src/cli/bin.mjs`, ...args], { encoding: 'utf8' });
  return JSON.parse(r.stdout).exact.interval;
}

const AXE = readFileSync(`${ROOT}node_modules/axe-core/axe.min.js`, 'utf8');

/** axe-core's violations on the page as it is: rule ids and their first targets. */
async function violations(page: Page): Promise<string[]> {
  await pageSettled(page);
  await page.addScriptTag({ content: AXE });
  return page.evaluate(async () => {
    type Found = { id: string; nodes: { target: string[] }[] };
    const axe = (window as unknown as { axe: { run(): Promise<{ violations: Found[] }> } }).axe;
    return (await axe.run()).violations.map((v) => `${v.id}: ${v.nodes[0]?.target.join(' ')}`);
  });
}

/** The headline step-over's number, in the unit on screen. */
const headline = async (page: Page) => Number.parseFloat(await text(page, 'result-exact-interval'));

describe('numbers typed as people write them (phone)', () => {
  it('1/2" in inch mode is answered as D = 0.5 in; 12.7 mm and 1/2" in mm mode as D = 12.7 mm', async () => {
    const page = await open('?D=0.25&Rcr=0.03&rho=5&h=0.002&unit=in');
    const want = cliInterval(6.35, 0.762, 0.0508) / 25.4;
    await typeInto(page, 'input-R', '1/2"', PHONE_TYPING);
    // Answered while the text is still as typed (the field keeps it until it is committed).
    await expect.poll(() => headline(page)).toBeCloseTo(want, 4);
    expect(await page.getByTestId('input-R').inputValue()).toBe('1/2"');
    expect(await text(page, 'error-R')).toBe('');
    await page.keyboard.press('Enter');
    await expect.poll(() => page.getByTestId('input-R').inputValue()).toBe('0.5');
    await expect.poll(() => new URL(page.url()).searchParams.get('D')).toBe('0.5');
    await keepShot(page, 'shop-fraction-inch-phone');

    const mm = await open('?D=6&Rcr=1&rho=5&h=0.05&unit=mm');
    const wantMm = cliInterval(6.35, 1, 0.05);
    await typeInto(mm, 'input-R', '12.7 mm', PHONE_TYPING);
    await expect.poll(() => text(mm, 'result-exact-interval')).toBe(`${wantMm.toFixed(4)} mm`);
    await mm.keyboard.press('Enter');
    await expect.poll(() => mm.getByTestId('input-R').inputValue()).toBe('12.7');
    await typeInto(mm, 'input-R', '1/4"', PHONE_TYPING);
    await typeInto(mm, 'input-h', '50 um', PHONE_TYPING);
    await mm.keyboard.press('Enter');
    await expect.poll(() => mm.getByTestId('input-h').inputValue()).toBe('0.05');
    expect(await mm.getByTestId('input-R').inputValue()).toBe('6.35');
    await expect.poll(() => text(mm, 'result-exact-interval')).toBe(`${cliInterval(3.175, 1, 0.05).toFixed(4)} mm`);
    await expect.poll(() => new URL(mm.url()).searchParams.get('D')).toBe('6.35');
  });

  it('anything else gets the usual message, never NaN', async () => {
    const page = await open('?D=6&Rcr=1&rho=5&h=0.05&unit=mm');
    await typeInto(page, 'input-Rcr', '1/0', PHONE_TYPING);
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, 'error-Rcr')).toMatch(/must be a number/);
    expect(await page.getByTestId('input-Rcr').inputValue()).toBe('1/0');
    expect(await page.locator('body').textContent()).not.toMatch(/NaN|Infinity/);
  });

  it('a fresh page gives the size as a diameter, with the corner hint in D terms', async () => {
    const page = await open('');
    expect(await page.locator('label[for="field-R"]').textContent()).toBe('Tool diameter D');
    expect(await page.getByTestId('input-R').inputValue()).toBe('6');
    expect(await page.locator('#field-Rcr-hint').textContent()).toMatch(/Rcr = D\/2 is a ball end/);
    await page.getByTestId('preset').selectOption({ label: 'D3/8 in, corner R0.030 in' });
    await expect.poll(() => page.getByTestId('input-R').inputValue()).toBe('9.525');
    expect(await page.getByTestId('input-Rcr').inputValue()).toBe('0.762');
  });
});

/** A small Fusion 360 library: two end mills (mm and inches), a drill, one without DC, and a hostile name. */
const LIBRARY = JSON.stringify({
  data: [
    {
      type: 'bull nose end mill',
      unit: 'millimeters',
      description: 'D10 R1.5 4FL',
      geometry: { DC: 10, RE: 1.5, NOF: 4 },
    },
    { type: 'ball end mill', unit: 'inches', description: '1/4 ball', geometry: { DC: 0.25, RE: 0.125, NOF: 2 } },
    { type: 'drill', unit: 'millimeters', description: 'Drill 5', geometry: { DC: 5 } },
    { type: 'bull nose end mill', unit: 'millimeters', description: 'no size', geometry: { RE: 1 } },
    {
      type: 'flat end mill',
      unit: 'millimeters',
      description: '<img src=x onerror="window.__pwned=1">',
      geometry: { DC: 8 },
    },
  ],
  version: 16,
});

describe('tools of the shop (phone)', () => {
  it('imports a Fusion 360 library through the file input and fills D and the corner radius from a pick', async () => {
    const page = await open('?D=6&Rcr=1&rho=5&h=0.05&unit=mm');
    await page.locator('[data-testid="tool-shelf"] summary').tap();
    await page.getByTestId('tool-library-import').setInputFiles({
      name: 'shop.json',
      mimeType: 'application/json',
      buffer: Buffer.from(LIBRARY),
    });
    const list = page.getByTestId('library-tools');
    await list.waitFor();
    const status = page.getByTestId('tool-library-status');
    await expect.poll(() => status.textContent()).toMatch(/"shop\.json": 3 tools read/);
    expect(await status.textContent()).toMatch(/Tool 4 "no size": geometry\.DC \(the diameter\) is missing\./);
    expect(await status.textContent()).toMatch(
      /Tool 3 "Drill 5": type "drill" is not a flat, bull nose or ball end mill/,
    );
    // The hostile name is text: no element made of it, nothing run.
    expect(await page.locator('[data-testid="tool-shelf"] img').count()).toBe(0);
    expect(await list.locator('option').allTextContents()).toContain(
      '<img src=x onerror="window.__pwned=1">: D 8 mm, corner R 0 mm',
    );
    expect(await page.evaluate(() => (window as unknown as { __pwned?: number }).__pwned)).toBeUndefined();
    // An inch tool is listed in inches (its own unit), on a page in mm.
    await list.selectOption({ label: '1/4 ball: D 0.25 in, corner R 0.125 in, 2 flutes' });
    await expect.poll(() => page.getByTestId('input-R').inputValue()).toBe('6.35');
    expect(await page.getByTestId('input-Rcr').inputValue()).toBe('3.175');
    await expect
      .poll(() => text(page, 'result-exact-interval'))
      .toBe(`${cliInterval(3.175, 3.175, 0.05).toFixed(4)} mm`);
    // A file that is not a library leaves the list as it was.
    await page.getByTestId('tool-library-import').setInputFiles({
      name: 'notes.txt',
      mimeType: 'text/plain',
      buffer: Buffer.from('not json'),
    });
    await expect.poll(() => status.textContent()).toMatch(/"notes\.txt": 0 tools read\.The file is not JSON/);
    expect(await list.locator('option').count()).toBe(4);
    await keepShot(page, 'shop-library-phone', { fullPage: true });
    // The open shelf, its lists and its messages pass axe, light and dark.
    expect(await violations(page)).toEqual([]);
    await page.emulateMedia({ colorScheme: 'dark' });
    expect(await violations(page)).toEqual([]);
    await keepShot(page, 'shop-library-phone-dark');
    await page.emulateMedia({ colorScheme: 'light' });
    // Dropped on the shelf, as from a file manager: the same import.
    await page.evaluate((json) => {
      const data = new DataTransfer();
      data.items.add(new File([json], 'dropped.json', { type: 'application/json' }));
      const shelf = document.querySelector('[data-testid="tool-shelf"]');
      shelf?.dispatchEvent(new DragEvent('dragover', { dataTransfer: data, bubbles: true, cancelable: true }));
      shelf?.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
    }, LIBRARY);
    await expect.poll(() => status.textContent()).toMatch(/"dropped\.json": 3 tools read/);
    expect(await page.getByTestId('tool-shelf').getAttribute('class')).not.toMatch(/dragging/);
  });

  it('saves a tool in the browser, and after a reload picks it to fill the fields', async () => {
    const page = await open('?D=10&Rcr=1.5&rho=5&h=0.05&unit=mm');
    await page.locator('[data-testid="tool-shelf"] summary').tap();
    await page.getByTestId('tool-name').fill('Shop D10 R1.5');
    await page.getByTestId('tool-flutes').fill('4');
    await page.getByTestId('save-tool').tap();
    await expect.poll(() => text(page, 'tool-library-status')).toBe('Saved "Shop D10 R1.5" in this browser.');
    await page.goto(`${site.url()}?D=6&Rcr=1&rho=5&h=0.05&unit=in`);
    await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
    await page.locator('[data-testid="tool-shelf"] summary').tap();
    const saved = page.getByTestId('saved-tools');
    // Saved in mm, listed in mm on an inch page; chosen, it fills the inch fields without loss.
    const label = 'Shop D10 R1.5: D 10 mm, corner R 1.5 mm, 4 flutes';
    await expect.poll(() => saved.locator('option').allTextContents()).toContain(label);
    await saved.selectOption({ label });
    await expect.poll(() => page.getByTestId('input-R').inputValue()).toBe('0.3937007874016');
    expect(await page.getByTestId('input-Rcr').inputValue()).toBe('0.0590551181102');
    // Corrupt storage: the page still opens; the shelf (loaded when first opened) says so, and the list starts empty.
    await page.evaluate(() => localStorage.setItem('path-interval.saved-tools.v1', '{not json'));
    await page.reload();
    await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
    await page.locator('[data-testid="tool-shelf"] summary').tap();
    await expect.poll(() => text(page, 'tool-library-status')).toMatch(/could not be read \(not JSON\)/);
    expect(await saved.locator('option').allTextContents()).toEqual(['no saved tools yet']);
  });

  it('Copy link: the copied URL opens the same state (written lengths as plain numbers)', async () => {
    const page = await open('?D=6&Rcr=1&rho=5&h=0.05&unit=mm');
    // The fallback field for a refused clipboard is not shown while the clipboard works.
    expect(await page.getByTestId('link-text').isVisible()).toBe(false);
    const before = await text(page, 'result-exact-interval');
    await typeInto(page, 'input-Rcr', '1/32"', PHONE_TYPING);
    await page.keyboard.press('Enter');
    await expect.poll(() => page.getByTestId('input-Rcr').inputValue()).toBe('0.79375');
    // The answer to the new corner radius (not the one shown before the worker replied).
    await expect.poll(() => text(page, 'result-exact-interval')).not.toBe(before);
    await expect.poll(() => page.locator('.results').getAttribute('aria-busy')).toBe('false');
    const answer = await text(page, 'result-exact-interval');
    await page.getByTestId('copy-link').tap();
    await expect.poll(() => text(page, 'copy-link-status')).toMatch(/Link copied/);
    const link = await page.evaluate(() => navigator.clipboard.readText());
    expect(new URL(link).searchParams.get('Rcr')).toBe('0.79375');
    expect(link.startsWith(site.url())).toBe(true);
    expect(await page.getByTestId('link-text').isVisible()).toBe(false);
    const again = await open(new URL(link).search);
    await expect.poll(() => text(again, 'result-exact-interval')).toBe(answer);
    expect(await again.getByTestId('input-R').inputValue()).toBe('6');
    expect(await again.getByTestId('input-Rcr').inputValue()).toBe('0.79375');
  });
});

/** A library of one inch tool with a realistic name (Fusion 360's export). */
const INCH_TOOL = 'Harvey 33531-C3 1/2 3FL corner radius .030 AlTiN';
const INCH_LIBRARY = JSON.stringify({
  data: [
    { type: 'bull nose end mill', unit: 'inches', description: INCH_TOOL, geometry: { DC: 0.5, RE: 0.03, NOF: 3 } },
  ],
});

describe('an inch tool from a library, on a page in mm (phone; issue 28 point 3)', () => {
  it('is listed in inch, offers inch in one tap, and its name goes with the answer and the link', async () => {
    // A fresh page: the paper's tool and h, in mm.
    const page = await open('');
    await page.locator('[data-testid="tool-shelf"] summary').tap();
    await page.getByTestId('tool-library-import').setInputFiles({
      name: 'harvey.json',
      mimeType: 'application/json',
      buffer: Buffer.from(INCH_LIBRARY),
    });
    const list = page.getByTestId('library-tools');
    const label = `${INCH_TOOL}: D 0.5 in, corner R 0.03 in, 3 flutes`;
    await expect.poll(() => list.locator('option').allTextContents()).toContain(label);
    await list.selectOption({ label });
    // Chosen: the exact lengths in mm, the tool named with the answer, inch offered.
    await expect.poll(() => page.getByTestId('input-R').inputValue()).toBe('12.7');
    expect(await page.getByTestId('input-Rcr').inputValue()).toBe('0.762');
    await expect.poll(() => text(page, 'result-tool-name')).toBe(`Tool: ${INCH_TOOL}`);
    const offer = page.getByTestId('tool-unit-offer');
    expect(await offer.textContent()).toBe('Work in inch');
    await keepShot(page, 'shop-inch-tool-offer-phone', { fullPage: true });
    // One tap: the page in inch, the tool's own numbers, h the inch default, the answer in inch.
    await offer.tap();
    await expect.poll(() => page.getByTestId('input-R').inputValue()).toBe('0.5');
    expect(await page.locator('input[name="unit"][value="in"]').isChecked()).toBe(true);
    expect(await page.getByTestId('input-Rcr').inputValue()).toBe('0.03');
    expect(await page.getByTestId('input-h').inputValue()).toBe('0.002');
    const want = cliInterval(6.35, 0.762, 0.0508) / 25.4;
    await expect.poll(() => headline(page)).toBeCloseTo(want, 5);
    expect(await text(page, 'result-exact-interval')).toMatch(/ in$/);
    expect(await text(page, 'result-tool-name')).toBe(`Tool: ${INCH_TOOL}`);
    expect(await offer.count()).toBe(0);
    // Copy link carries the name; the link opens with it.
    await page.getByTestId('copy-link').tap();
    await expect.poll(() => text(page, 'copy-link-status')).toMatch(/Link copied/);
    const link = await page.evaluate(() => navigator.clipboard.readText());
    expect(new URL(link).searchParams.get('tool')).toBe(INCH_TOOL);
    const again = await open(new URL(link).search);
    await expect.poll(() => text(again, 'result-tool-name')).toBe(`Tool: ${INCH_TOOL}`);
    expect(await again.getByTestId('input-R').inputValue()).toBe('0.5');
    await expect.poll(() => headline(again)).toBeCloseTo(want, 5);
    // Another D: not that tool any more, its name goes.
    await typeInto(again, 'input-R', '0.375', PHONE_TYPING);
    await again.keyboard.press('Enter');
    await expect.poll(() => again.getByTestId('result-tool-name').isVisible()).toBe(false);
    await expect.poll(() => new URL(again.url()).searchParams.has('tool')).toBe(false);
  });

  it('a hostile name in a link is shown as text, cut to 80 characters', async () => {
    const hostile = `<img src=x onerror="window.__pwned=1">\u202e${'W'.repeat(200)}`;
    const page = await open(`?D=0.5&Rcr=0.03&rho=5&h=0.002&unit=in&tool=${encodeURIComponent(hostile)}`);
    const shown = await text(page, 'result-tool-name');
    expect(shown.startsWith('Tool: <img src=x onerror="window.__pwned=1"> WWW')).toBe(true);
    expect(shown).toHaveLength('Tool: '.length + 80);
    expect(await page.locator('.results img').count()).toBe(0);
    expect(await page.evaluate(() => (window as unknown as { __pwned?: number }).__pwned)).toBeUndefined();
    // No horizontal overflow from the long name on the phone.
    expect(await page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth)).toBe(
      0,
    );
  });
});
