/**
 * The CAM programmer's quick lookup (issue 10), driven as a user would at 390 x 844 (a phone:
 * touch, taps) and 1440 x 900 (a desktop: clicks): tool size as a diameter, typing with the
 * keyboard (decimal comma, half-typed values held back), the flat end without lead, Copy, the
 * lookup table download, touch targets and vertical swipes over the scene and the profile.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import type { BrowserContext, Page } from 'playwright-core';
import { afterEach, describe, expect, it } from 'vitest';
import { parseCsv } from '../../src/cli/csv';
import { forwardInput } from '../../src/core/input/validate';
import { LOOKUP_HEADER } from '../../src/core/output/lookupTable';
import { headerInUnit } from '../../src/core/output/lookupUnits';
import { exactForward } from '../../src/core/surfaces/solve';
import { scallopHeightLimits } from '../../src/core/surfaces/validate';
import { holdSceneAs, keepShot, ROOT, typeInto, useSite } from './harness';

const site = useSite('docs/quick-lookup');
/** The profile view's state: the touch test reads it, then the Copy test uses the same document. */
const PROFILE = '?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=profile';

const VIEWPORTS = [
  { name: 'phone', width: 390, height: 844, touch: true },
  { name: 'desktop', width: 1440, height: 900, touch: false },
] as const;
type Viewport = (typeof VIEWPORTS)[number];

/**
 * One context per viewport (touch on the phone; clipboard allowed) and its tab, shared by that
 * viewport's tests; `unchanged`: the query its document opened, while no test has changed its inputs.
 */
const contexts = new Map<
  string,
  { context: BrowserContext; page: Page; unchanged: string | null; sceneHeld: boolean }
>();
afterEach((context) => {
  // A failed test may have left its document anywhere.
  if (context.task.result?.state === 'fail') for (const entry of contexts.values()) entry.unchanged = null;
});

/**
 * Opens the page in the viewport's context (each open a fresh document in its tab) and waits for
 * the first result. With `reuse`, a document the test before opened with this query and left
 * unchanged (it called `keep`) serves as it is.
 */
async function open(vp: Viewport, query: string, reuse = false): Promise<{ page: Page; context: BrowserContext }> {
  let entry = contexts.get(vp.name);
  const held = site.holdsScene();
  if (reuse && entry !== undefined && !entry.page.isClosed() && entry.unchanged === query && entry.sceneHeld === held) {
    entry.unchanged = null;
    return entry;
  }
  if (entry === undefined || entry.page.isClosed()) {
    const context = await site.browser().newContext({
      viewport: { width: vp.width, height: vp.height },
      hasTouch: vp.touch,
      isMobile: vp.touch,
      acceptDownloads: true,
    });
    await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(site.url()).origin });
    entry = { context, page: await context.newPage(), unchanged: null, sceneHeld: false };
    contexts.set(vp.name, entry);
  } else await entry.page.goto('about:blank');
  entry.unchanged = null;
  // Without the scene's code for a test that looks at no part of it (site.noScene()).
  entry.sceneHeld = await holdSceneAs(entry.context, entry.sceneHeld, held);
  const { context, page } = entry;
  await page.goto(`${site.url()}${query}`);
  await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
  return { page, context };
}

/** Says, at the end of a test that changed no input, that the next test may reuse its document. */
function keep(vp: Viewport, query: string): void {
  const entry = contexts.get(vp.name);
  if (entry !== undefined) entry.unchanged = query;
}

/** Taps on the phone, clicks on the desktop. */
async function press(vp: Viewport, target: ReturnType<Page['getByTestId']>): Promise<void> {
  await target.scrollIntoViewIfNeeded();
  if (vp.touch) await target.tap();
  else await target.click();
}

const text = async (page: Page, id: string) => (await page.getByTestId(id).textContent())?.trim() ?? '';

/** Every number in the results: headline, details and table cells. */
const resultNumbers = (page: Page) =>
  page.evaluate(() =>
    [...document.querySelectorAll('.results output, .results .procedures td')]
      .map((e) => e.textContent ?? '')
      .filter((t) => /\d/.test(t)),
  );

/** The command line's JSON answer (asked once per question: both viewports compare to it). */
const cliAnswers = new Map<string, { exact: { interval: number; halfInterval: number } }>();
function cli(args: readonly string[]): { exact: { interval: number; halfInterval: number } } {
  const key = args.join(' ');
  let answer = cliAnswers.get(key);
  if (answer === undefined) {
    const r = spawnSync(process.execPath, [`${ROOT}src/cli/bin.mjs`, ...args, '--json'], { encoding: 'utf8' });
    answer = JSON.parse(r.stdout) as { exact: { interval: number; halfInterval: number } };
    cliAnswers.set(key, answer);
  }
  return answer;
}

/** What the page shows of the typing state of the h field, as read when a keystroke landed. */
interface TypedState {
  readonly value: string;
  readonly error: string;
  readonly status: string;
  readonly numbers: string[];
  readonly sceneClass: string;
  readonly typingBadge: boolean;
  readonly staleBadge: boolean;
  readonly labels: boolean;
}

/**
 * Records, from now on, what the page shows after each input event of the h field (read in a
 * microtask after the page's own handling of the event, before anything later can change it).
 */
async function recordTyping(page: Page): Promise<void> {
  await page.evaluate(() => {
    const w = window as unknown as { __typed: unknown[] };
    w.__typed = [];
    const field = document.querySelector('[data-testid="input-h"]') as HTMLInputElement;
    const shown = (selector: string) => {
      const e = document.querySelector(selector);
      if (!e) return false;
      const r = e.getBoundingClientRect();
      return e.checkVisibility({ visibilityProperty: true }) && r.width > 0 && r.height > 0;
    };
    const textOf = (id: string) => document.querySelector(`[data-testid="${id}"]`)?.textContent?.trim() ?? '';
    field.addEventListener('input', () =>
      queueMicrotask(() =>
        w.__typed.push({
          value: field.value,
          error: textOf('error-h'),
          status: textOf('results-status'),
          numbers: [...document.querySelectorAll('.results output, .results .procedures td')]
            .map((e) => e.textContent ?? '')
            .filter((t) => /\d/.test(t)),
          sceneClass: document.querySelector('[data-testid="scene"]')?.getAttribute('class') ?? '',
          typingBadge: shown('.typing-badge'),
          staleBadge: shown('.stale-badge:not(.typing-badge)'),
          labels: shown('.scene-labels'),
        }),
      ),
    );
  });
}

/** The recorded state when the h field last held `value` (see recordTyping). */
async function typedState(page: Page, value: string): Promise<TypedState> {
  const all = await page.evaluate(() => (window as unknown as { __typed: TypedState[] }).__typed);
  const found = all.filter((s) => s.value === value).at(-1);
  if (found === undefined) throw new Error(`the h field never held "${value}": ${JSON.stringify(all)}`);
  return found;
}

describe.each(VIEWPORTS)('quick lookup at $width x $height', (vp) => {
  it('a catalogue diameter: the switch makes the field D, D10 answers as R 5, errors name D, presets say custom', async () => {
    site.noScene(); // looks at no part of the 3D scene
    const { page } = await open(vp, '?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    expect(await page.getByTestId('preset').locator('option:checked').textContent()).toBe(
      'D6, corner R1 (paper Tool 1)',
    );
    await press(vp, page.getByTestId('size-switch').getByText('diameter D'));
    expect(await page.getByTestId('input-R').inputValue()).toBe('6');
    expect(await page.locator('label[for="field-R"]').textContent()).toBe('Tool diameter D');
    await expect.poll(() => new URL(page.url()).searchParams.get('D')).toBe('6');
    expect(new URL(page.url()).searchParams.has('R')).toBe(false);
    await typeInto(page, 'input-R', '10');
    const want = cli(['--R', '5', '--Rcr', '1', '--rho', '5', '--h', '0.05']);
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(`${want.exact.interval.toFixed(4)} mm`);
    expect(await page.getByTestId('preset').locator('option:checked').textContent()).toBe('D10, corner R1');
    await typeInto(page, 'input-Rcr', '1.2');
    await expect.poll(() => page.getByTestId('preset').locator('option:checked').textContent()).toBe('custom');
    await typeInto(page, 'input-Rcr', '6');
    await expect
      .poll(() => text(page, 'error-Rcr'))
      .toBe('Corner radius Rcr must be at most D/2 = 5 mm (got 6); Rcr = D/2 is a ball end mill.');
    await keepShot(page, `quick-lookup-diameter-${vp.name}`, { fullPage: true });
    // The link keeps the diameter: a reload opens the same state (once the address holds it: the
    // page writes it a moment after the inputs settle, urlState.ts).
    await expect.poll(() => new URL(page.url()).searchParams.get('Rcr')).toBe('6');
    expect(new URL(page.url()).searchParams.get('D')).toBe('10');
    await page.reload();
    await page
      .getByTestId('error-Rcr')
      .filter({ hasText: /D\/2 = 5 mm/ })
      .waitFor();
    expect(await page.getByTestId('input-R').inputValue()).toBe('10');
  });

  it('typing: a half-typed value shows no error and no old number, a decimal comma works, a pause or Enter commits', async () => {
    const { page } = await open(vp, '?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    const before = await text(page, 'result-exact-interval');
    // What the page shows while a text is held back is read as each keystroke lands (a later read
    // could come after the pause, when the text has committed).
    await recordTyping(page);
    await typeInto(page, 'input-h', '0');
    // Held back: no message, every number a dash, the status says why.
    const zero = await typedState(page, '0');
    expect(zero.error).toBe('');
    expect(zero.numbers).toEqual([]);
    expect(zero.status).toMatch(/^Typing/);
    expect(zero.sceneClass).toMatch(/typing/);
    expect(zero.typingBadge).toBe(true);
    expect(zero.staleBadge).toBe(false);
    expect(zero.labels).toBe(false);
    await page.keyboard.type(',', { delay: 30 });
    const comma = await typedState(page, '0,');
    expect(comma.error).toBe('');
    expect(comma.numbers).toEqual([]);
    await page.keyboard.type('05', { delay: 30 });
    // 0,05 is 0.05: the same answer as before, at once (a valid value commits while typing).
    await expect.poll(() => text(page, 'result-exact-interval')).toBe(before);
    expect(await page.getByTestId('scene').getAttribute('class')).not.toMatch(/typing/);
    await expect.poll(() => new URL(page.url()).searchParams.get('h')).toBe('0,05');
    // A pause on a wrong value: the message comes, still no number.
    await typeInto(page, 'input-h', '-');
    expect((await typedState(page, '-')).error).toBe('');
    await keepShot(page, `quick-lookup-typing-${vp.name}`);
    await expect.poll(() => text(page, 'error-h')).toMatch(/Scallop height h must be a number \(got "-"\)/);
    expect(await resultNumbers(page)).toEqual([]);
    expect(await text(page, 'results-status')).toBe('');
    expect(await page.locator('.typing-badge').isVisible()).toBe(false);
    expect(await page.locator('.stale-badge:not(.typing-badge)').isVisible()).toBe(true);
    // Enter commits at once (well before the pause).
    await typeInto(page, 'input-h', '0');
    await page.keyboard.press('Enter');
    await expect.poll(() => text(page, 'error-h')).toMatch(/must be greater than 0 mm \(got 0\)/);
  });

  it('a flat end without lead leaves no scallop: the page says so and gives L = 2R, as the command line', async () => {
    site.noScene(); // looks at no part of the 3D scene
    const { page } = await open(vp, '?R=3&Rcr=1&rho=5&h=0.05&unit=mm');
    await typeInto(page, 'input-Rcr', '0');
    await typeInto(page, 'input-rho', '0');
    const want = cli(['--R', '3', '--Rcr', '0', '--rho', '0', '--h', '0.05']);
    expect(want.exact.interval).toBe(6);
    await expect.poll(() => text(page, 'result-exact-interval')).toBe('6.0000 mm');
    expect(await text(page, 'error-h')).toBe('');
    expect(await text(page, 'no-scallop')).toMatch(
      /^No scallop: a flat end without lead or tilt .* leaves no scallop at any step-over up to its diameter, so L = 2R = 6\.0000 mm for any h\.$/,
    );
    await keepShot(page, `quick-lookup-flat-end-${vp.name}`);
    // With lead it leaves a scallop again and the statement goes.
    await typeInto(page, 'input-rho', '5');
    await expect.poll(() => page.getByTestId('no-scallop').isHidden()).toBe(true);
  });

  it('downloads the lookup table from the worker; its cells are the core exact step-over', async () => {
    site.noScene(); // looks at no part of the 3D scene
    const { page } = await open(vp, '?R=3&Rcr=1&rho=5&h=0.05&unit=mm&pattern=zigzag');
    const button = page.getByTestId('download-table');
    await expect.poll(() => button.isEnabled()).toBe(true);
    const downloaded = page.waitForEvent('download');
    await press(vp, button);
    const download = await downloaded;
    expect(download.suggestedFilename()).toBe('step-over-table_5-axis_R3_Rcr1_zigzag_plane_mm.csv');
    const csv = readFileSync(await download.path(), 'utf8');
    const [head, ...rows] = parseCsv(csv).filter((r) => !r.blank);
    // Every dimensioned column names its unit (issue 21).
    const header = headerInUnit(LOOKUP_HEADER, 'mm');
    expect(head?.fields.join(',')).toBe(header);
    expect(header).toMatch(/^R_mm,Rcr_mm,rho_deg,h_mm,tilt_deg,/);
    const col = (name: string) => header.split(',').indexOf(name);
    let checked = 0;
    for (const r of rows) {
      const [R, Rcr, rho, h, tilt] = r.fields.slice(0, 5).map(Number) as [number, number, number, number, number];
      const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt };
      if (h >= scallopHeightLimits(tool).limitMm) {
        expect(r.fields[col('interval_mm')]).toBe('');
        expect(r.fields[col('error')]).not.toBe('');
        continue;
      }
      // The browser's Math may differ from Node's in the last bit: compare to 1e-13 relative.
      const e = exactForward(forwardInput(tool, 'zigzag', h));
      const near = (got: string | undefined, want: number) =>
        expect(Math.abs(Number(got) - want)).toBeLessThanOrEqual(1e-13 * want);
      near(r.fields[col('interval_mm')], e.intervalMm);
      near(r.fields[col('exact_mm')], e.halfIntervalMm);
      checked++;
    }
    expect(checked).toBeGreaterThan(300);
    await expect
      .poll(() => text(page, 'download-table-status'))
      .toMatch(/^Saved step-over-table_5-axis_R3_Rcr1_zigzag_plane_mm\.csv: \d+ rows, h 0\.0002 to 2 mm /);
    // The table runs on its own worker.
    expect(await Promise.all(page.workers().map((w) => w.evaluate(() => self.name)))).toContain('path-interval-table');
    // Invalid input: nothing to tabulate.
    await typeInto(page, 'input-Rcr', '9');
    await page.keyboard.press('Enter');
    expect(await button.isDisabled()).toBe(true);
  });

  it('in inch mode the lookup table is in inches: _in in the file name and the header, the cells in inches', async () => {
    site.noScene(); // looks at no part of the 3D scene
    const { page } = await open(vp, '?R=0.25&Rcr=0.0625&rho=5&h=0.0005&unit=in');
    const button = page.getByTestId('download-table');
    await expect.poll(() => button.isEnabled()).toBe(true);
    const downloaded = page.waitForEvent('download');
    await press(vp, button);
    const download = await downloaded;
    expect(download.suggestedFilename()).toBe('step-over-table_5-axis_R0.25_Rcr0.0625_one-way_plane_in.csv');
    const [head, ...rows] = parseCsv(readFileSync(await download.path(), 'utf8')).filter((r) => !r.blank);
    const header = headerInUnit(LOOKUP_HEADER, 'in');
    expect(head?.fields.join(',')).toBe(header);
    const col = (name: string) => header.split(',').indexOf(name);
    // The page's own case, in inches: h 0.0005 in at lead 5, tilt 0 (the inch 1-2-5 series holds it).
    const at = rows.find(
      (r) => [col('rho_deg'), col('h_in'), col('tilt_deg')].map((c) => r.fields[c]).join() === '5,0.0005,0',
    );
    expect(at?.fields[col('R_in')]).toBe('0.25');
    const e = exactForward(
      forwardInput({ toolRadiusMm: 6.35, cornerRadiusMm: 1.5875, leadAngleDeg: 5, tiltAngleDeg: 0 }, 'one-way', 0.0127),
    );
    expect(Math.abs(Number(at?.fields[col('interval_in')]) - e.intervalMm / 25.4)).toBeLessThanOrEqual(
      1e-12 * e.intervalMm,
    );
    // A refused cell says its reason in inches.
    const refused = rows.find((r) => r.fields[col('error')] !== '');
    expect(refused?.fields[col('error')]).toMatch(/ in \(got [\d.]+\)/);
    await expect
      .poll(() => text(page, 'download-table-status'))
      .toMatch(
        /^Saved step-over-table_5-axis_R0\.25_Rcr0\.0625_one-way_plane_in\.csv: \d+ rows, h 0\.00002 to [\d.]+ in /,
      );
  });

  it('touch targets are at least 24 px; a vertical swipe over the scene or the profile scrolls the page', async () => {
    const { page, context } = await open(vp, PROFILE);
    const small = await page.evaluate(() => {
      const out: string[] = [];
      const targets = document.querySelectorAll<HTMLElement>(
        '.app button, .app select, .switch label, .field input[type="range"]',
      );
      for (const el of targets) {
        const r = el.getBoundingClientRect();
        if (r.width === 0 && r.height === 0) continue; // not shown
        if (r.width < 24 || r.height < 24)
          out.push(`${el.tagName} ${el.textContent?.trim() || el.getAttribute('aria-label')} ${r.width}x${r.height}`);
      }
      const thumb = getComputedStyle(
        document.querySelector('[data-testid="slider-R"]') as Element,
        '::-webkit-slider-thumb',
      );
      if (!(Number.parseFloat(thumb.width) >= 24 && Number.parseFloat(thumb.height) >= 24))
        out.push(`slider thumb ${thumb.width}x${thumb.height}`);
      return out;
    });
    expect(small).toEqual([]);
    if (vp.touch) {
      await page.getByTestId('profile-view').locator('polygon.scallop').waitFor();
      const cdp = await context.newCDPSession(page);
      for (const target of ['scene-canvas', 'profile-view'] as const) {
        const box = page.getByTestId(target);
        await box.scrollIntoViewIfNeeded();
        const r = await box.boundingBox();
        if (r === null) throw new Error(`${target} is not shown`);
        const y0 = await page.evaluate(() => window.scrollY);
        // Swipe up (the page scrolls down), or down when the page is already at its end.
        const atEnd = await page.evaluate(
          () => window.scrollY + window.innerHeight >= document.body.scrollHeight - 200,
        );
        // A finger swipe, as raw touch events: down, ten moves, up.
        const x = Math.round(r.x + r.width / 2);
        const y = Math.round(r.y + Math.min(r.height, 300) / 2);
        const dy = atEnd ? 150 : -150;
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x, y }] });
        for (let i = 1; i <= 10; i++)
          await cdp.send('Input.dispatchTouchEvent', {
            type: 'touchMove',
            touchPoints: [{ x, y: y + (dy * i) / 10 }],
          });
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
        const moved = () => page.evaluate((y) => Math.abs(window.scrollY - y), y0);
        const touchAction = await box.evaluate((e) => getComputedStyle(e).touchAction);
        await expect.poll(moved, { message: `${target} (touch-action ${touchAction})` }).toBeGreaterThan(50);
      }
      await cdp.detach();
      await keepShot(page, `quick-lookup-touch-${vp.name}`);
    }
    keep(vp, PROFILE);
  });

  it('Copy gives the plain number in the unit on screen, confirms it, and is disabled without a value', async () => {
    // The touch test's page (it changed no input; its view is no concern of Copy).
    const { page } = await open(vp, PROFILE, true);
    const headlineCopy = page.locator('.big button.copy');
    await expect.poll(() => headlineCopy.isEnabled()).toBe(true);
    await press(vp, page.getByRole('button', { name: 'Copy the headline value' }));
    await expect.poll(() => headlineCopy.textContent()).toBe('Copied');
    expect(await text(page, 'copy-status')).toBe('Copied 2.8872 (mm): 5-axis, lead 5°, tilt 0°, one-way, plane.');
    expect(await page.evaluate(() => navigator.clipboard.readText())).toBe('2.8872');
    await keepShot(page, `quick-lookup-copied-${vp.name}`);
    await expect.poll(() => headlineCopy.textContent()).toBe('Copy');
    await press(vp, page.getByRole('button', { name: 'Copy L/2' }));
    await expect.poll(() => page.evaluate(() => navigator.clipboard.readText())).toBe('1.4436');
    // Same format for a small value shown in um: copied in mm.
    await typeInto(page, 'input-h', '0.000001');
    await expect.poll(() => text(page, 'result-exact-interval')).toMatch(/ \u00b5m$/);
    await press(vp, page.getByRole('button', { name: 'Copy the headline value' }));
    const shown = await text(page, 'result-exact-interval');
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    expect(Number(copied) * 1000).toBeCloseTo(Number.parseFloat(shown), 3);
    // No value (invalid input): every Copy is disabled.
    await typeInto(page, 'input-h', 'x');
    await page.keyboard.press('Enter');
    for (const b of await page.locator('button.copy').all()) expect(await b.isDisabled()).toBe(true);
  });
});
