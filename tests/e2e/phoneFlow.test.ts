/**
 * The CAM programmer at the machine (issue 21): from a fresh page on a phone (390 x 844, touch,
 * no query), a catalogue tool's step-over for the shop's scallop height h, copied to the clipboard,
 * in at most 3 user actions, in mm and in inch (a first visit offers the catalogue tools of both
 * units, each in its own, and an inch tool's tap sets the inch unit); a three-axis shop's inch job
 * (issue 28) in at most 5 on its first visit and 4 on its next (the machine and unit remembered). The phone's first screen shows the machine, the unit, the tool
 * (catalogue buttons, preset box, saved tools, D, Rcr), the posture (lead, tilt) and h before the
 * other switches; screenshots of it, light and dark, are kept.
 *
 * Counting rule: a tap on a control (the unit switch, a catalogue tool button, Copy) is one action;
 * entering a value in a field is one action: the tap that focuses the field and the typing of the
 * value (on a touch screen that tap selects the field's text, so the value typed replaces the old
 * one: nothing to clear). Waiting for the answer to show is not an action; no scroll is needed (each
 * control tapped is on screen when it is tapped, checked below; a scroll would count as one). The
 * step-over copied is checked against the core solver called here, at the shown resolution.
 *
 * The wall-clock time of each flow, from the loaded page to the value on the clipboard, is printed
 * (`phone flow mm: N actions, S s`); Playwright's taps and typing are faster than a hand, so the
 * seconds measure the page's own delays (answers, copy), not a user's.
 */
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { exactForward, forwardInput } from '../../src/core/index';
import { PRESETS } from '../../src/ui/toolPresets';
import { keepShot, PHONE, pageSettled, ROOT, usePhonePage, useSite } from './harness';

const site = useSite('docs/phone-flow');
const open = usePhonePage(site);
const AXE = readFileSync(`${ROOT}node_modules/axe-core/axe.min.js`, 'utf8');

/** Default posture of a fresh page (state.ts DEFAULT_FIELDS_MM): lead 5 deg, no tilt; one-way, plane. */
const LEAD_DEG = 5;

/** The exact step-over (mm) of a preset at h (mm), on a plane, one-way, at the default posture. */
function exactStepOverMm(label: string, hMm: number): number {
  const preset = PRESETS.find((p) => p.label === label);
  if (!preset) throw new Error(`no preset ${label}`);
  const tool = { toolRadiusMm: preset.R, cornerRadiusMm: preset.Rcr, leadAngleDeg: LEAD_DEG, tiltAngleDeg: 0 };
  return exactForward(forwardInput(tool, 'one-way', hMm)).intervalMm;
}

/** True when the whole of the element lies inside the viewport (it can be tapped without a scroll). */
const onScreen = (page: Page, selector: string) =>
  page.locator(selector).evaluate((e) => {
    const r = e.getBoundingClientRect();
    return r.height > 0 && r.top >= 0 && r.bottom <= window.innerHeight && r.left >= 0 && r.right <= window.innerWidth;
  });

/** Counts and performs the user's actions, each checked on screen first. */
function actions(page: Page) {
  let count = 0;
  return {
    get count() {
      return count;
    },
    async tap(selector: string): Promise<void> {
      expect(await onScreen(page, selector), `${selector} on screen`).toBe(true);
      await page.locator(selector).tap();
      count++;
    },
    /** One entry: the tap that focuses the field (selecting its text) and the value typed. */
    async enter(selector: string, value: string): Promise<void> {
      expect(await onScreen(page, selector), `${selector} on screen`).toBe(true);
      await page.locator(selector).tap();
      // The tap selects the field's text (touchSelect.ts) once its click lands: what is typed replaces it.
      await expect
        .poll(() =>
          page.locator(selector).evaluate((e) => {
            const input = e as HTMLInputElement;
            return input.selectionStart === 0 && input.selectionEnd === input.value.length && input.value !== '';
          }),
        )
        .toBe(true);
      await page.keyboard.type(value);
      count++;
    },
  };
}

/** Runs one flow from a fresh page and returns the number copied. */
async function flow(
  unit: 'mm' | 'in',
  chip: string,
  h: string,
  expectedText: (copied: string) => void,
): Promise<{ count: number; seconds: number }> {
  const page = await open('');
  await pageSettled(page);
  const start = performance.now();
  const user = actions(page);
  // A first visit offers the tools of both units: an inch tool's tap also sets the inch unit.
  await user.tap(`[data-testid="tool-chips"] button:text-is("${chip}")`);
  expect(await page.locator('[data-testid="unit-switch"] input:checked').inputValue()).toBe(unit);
  // A tool chosen is a unit chosen: the catalogue of its unit only from then on.
  expect(await page.locator('[data-testid="tool-chips"] button:visible').allTextContents()).toEqual(
    PRESETS.filter((p) => p.sizedIn === unit).map((p) => p.chip),
  );
  await user.enter('[data-testid="input-h"]', h);
  // The user reads the answer in the result bar before copying it.
  const bar = page.getByTestId('result-bar-value');
  const headline = page.getByTestId('result-exact-interval');
  await expect
    .poll(
      async () =>
        (await bar.textContent()) === (await headline.textContent()) && /\d/.test((await bar.textContent()) ?? ''),
    )
    .toBe(true);
  await expect.poll(() => page.locator('.results').getAttribute('aria-busy')).toBe('false');
  await user.tap('[data-testid="result-bar"] button.copy');
  await expect.poll(() => page.locator('[data-testid="result-bar"] button.copy').textContent()).toBe('Copied');
  const copied = await page.evaluate(() => navigator.clipboard.readText());
  const seconds = (performance.now() - start) / 1000;
  expect(await page.getByTestId('input-h').inputValue()).toBe(h);
  expectedText(copied);
  return { count: user.count, seconds };
}

/** Checks the copied text is `exact` (in the page's unit) to the resolution the text shows, 4 digits at least. */
function matches(copied: string, exact: number): void {
  expect(copied).toMatch(/^\d+\.\d+$/);
  const decimals = copied.split('.')[1]?.length ?? 0;
  expect(copied.replace('.', '').replace(/^0+/, '').length).toBeGreaterThanOrEqual(4);
  expect(Math.abs(Number(copied) - exact)).toBeLessThanOrEqual(0.5 * 10 ** -decimals + 1e-12);
}

describe('a step-over at the machine, on a phone', () => {
  it('the first screen: unit, tool, posture and h come before the switches (light and dark)', async () => {
    const page = await open('');
    await pageSettled(page);
    for (const id of [
      'machine-switch',
      'unit-switch',
      'tool-chips',
      'input-R',
      'input-Rcr',
      'input-rho',
      'input-tilt',
      'input-h',
    ])
      expect(await onScreen(page, `[data-testid="${id}"]`), id).toBe(true);
    // DOM order (tab order) = visual order: the tool, then the posture, then h, then the switches.
    const order = await page.evaluate(() => {
      const at = (s: string) => document.querySelector(s);
      const list = [
        at('[data-testid="machine-switch"]'),
        at('[data-testid="unit-switch"]'),
        at('[data-testid="tool-chips"]'),
        at('[data-testid="preset"]'),
        at('[data-field="R"]'),
        at('[data-field="rho"]'),
        at('[data-field="h"]'),
        at('[data-testid="mode-switch"]'),
        at('[data-testid="surface-kind"]'),
      ];
      return list.every(
        (e, i) =>
          e !== null &&
          (i === 0 || (list[i - 1] as Element).compareDocumentPosition(e) & Node.DOCUMENT_POSITION_FOLLOWING),
      );
    });
    expect(order).toBe(true);
    const tops = await page.evaluate(() =>
      [
        '[data-testid="machine-switch"]',
        '[data-testid="unit-switch"]',
        '[data-testid="tool-chips"]',
        '[data-field="R"]',
        '[data-field="rho"]',
        '[data-field="h"]',
        '[data-testid="mode-switch"]',
      ].map((s) => document.querySelector(s)?.getBoundingClientRect().top ?? Number.NaN),
    );
    expect(tops).toEqual([...tops].sort((a, b) => a - b));
    // A first visit: the metric catalogue in mm, then the inch one in inch (a tap on an inch tool
    // sets the inch unit); the one the fields hold pressed (the default is the paper's Tool 1).
    expect(await page.locator('[data-testid="tool-chips"] button:visible').allTextContents()).toEqual([
      ...PRESETS.filter((p) => p.sizedIn === 'mm').map((p) => p.chip),
      ...PRESETS.filter((p) => p.sizedIn === 'in').map((p) => p.chip),
    ]);
    expect(await page.locator('[data-testid="tool-chips"] button[aria-pressed="true"]').textContent()).toBe('D6 R1');
    await keepShot(page, 'phone-first-screen-light');
    await page.emulateMedia({ colorScheme: 'dark' });
    await pageSettled(page);
    await keepShot(page, 'phone-first-screen-dark');
    await page.emulateMedia({ colorScheme: 'light' });
  });

  it('mm: a D10 R1 end mill, h = 0.01 mm, copied in at most 3 actions', async () => {
    const label = 'D10, corner R1';
    const { count, seconds } = await flow('mm', 'D10 R1', '0.01', (copied) =>
      matches(copied, exactStepOverMm(label, 0.01)),
    );
    console.log(`phone flow mm: ${count} actions, ${seconds.toFixed(2)} s`);
    expect(count).toBeLessThanOrEqual(3);
  });

  it('inch: a 1/2 in bull nose with a 0.030 in corner, h = 0.0004 in, copied in at most 3 actions (the tool sets the unit)', async () => {
    const label = 'D1/2 in, corner R0.030 in';
    const { count, seconds } = await flow('in', '1/2 R.030', '0.0004', (copied) =>
      matches(copied, exactStepOverMm(label, 0.0004 * 25.4) / 25.4),
    );
    console.log(`phone flow inch: ${count} actions, ${seconds.toFixed(2)} s`);
    expect(count).toBeLessThanOrEqual(3);
  });

  it('the catalogue buttons follow the unit and the fields; axe finds nothing on them', async () => {
    const page = await open('?unit=in&D=0.5&Rcr=0.06&rho=5&h=0.0005');
    expect(await page.locator('[data-testid="tool-chips"] button:visible').allTextContents()).toEqual(
      PRESETS.filter((p) => p.sizedIn === 'in').map((p) => p.chip),
    );
    expect(await page.locator('[data-testid="tool-chips"] legend').textContent()).toBe('Catalogue tools (inch)');
    expect(await page.locator('[data-testid="tool-chips"] button[aria-pressed="true"]').textContent()).toBe(
      '1/2 R.060',
    );
    // Edited away from every preset: none pressed, the preset box says custom.
    await page.locator('[data-field="Rcr"] input[type="text"]').fill('0.07');
    await expect.poll(() => page.locator('[data-testid="tool-chips"] button[aria-pressed="true"]').count()).toBe(0);
    expect(await page.getByTestId('preset').inputValue()).toBe('custom');
    await pageSettled(page);
    await page.addScriptTag({ content: AXE });
    const violations = await page.evaluate(async () => {
      const axe = (
        window as unknown as {
          axe: { run(ctx: unknown): Promise<{ violations: Array<{ id: string; nodes: unknown[] }> }> };
        }
      ).axe;
      return (await axe.run({ include: [['.controls']] })).violations.map((v) => `${v.id} x${v.nodes.length}`);
    });
    expect(violations).toEqual([]);
  });

  it('three-axis inch: 1/2 R.030, raster, slope 30, raster angle 30, h = 0.0004 in; a first visit in at most 5 actions, the next in 4', async () => {
    // A context of its own: the shop's storage carries its machine and unit to the next visit.
    const context = await site.browser().newContext({ viewport: PHONE, hasTouch: true, isMobile: true });
    try {
      await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(site.url()).origin });
      const page = await context.newPage();
      const label = 'D1/2 in, corner R0.030 in';
      const preset = PRESETS.find((p) => p.label === label);
      if (!preset) throw new Error(`no preset ${label}`);
      // The upright tool on a 30 deg slope, raster passes 30 deg from the fall line: the horizontal step
      // Lxy the machine is programmed with, as the command line answers it (a process of its own).
      const cli = spawnSync(
        process.execPath,
        [
          `${ROOT}src/cli/bin.mjs`,
          '--R',
          `${preset.R}`,
          '--Rcr',
          `${preset.Rcr}`,
          '--slope',
          '30',
          '--raster-angle',
          '30',
          '--h',
          `${0.0004 * 25.4}`,
          '--json',
        ],
        { encoding: 'utf8' },
      );
      const exactIn = (JSON.parse(cli.stdout) as { exact: { horizontalStep: number } }).exact.horizontalStep / 25.4;
      const job = async (first: boolean): Promise<{ count: number; seconds: number }> => {
        await page.goto(site.url());
        await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
        await pageSettled(page);
        const start = performance.now();
        const user = actions(page);
        // The first visit chooses the machine; its inch tool sets the unit in the same tap.
        if (first) await user.tap('[data-testid="machine-switch"] label:has(input[value="3axis"])');
        await user.tap('[data-testid="tool-chips"] button:text-is("1/2 R.030")');
        expect(await page.locator('[data-testid="unit-switch"] input:checked').inputValue()).toBe('in');
        // The unit chosen: the inch catalogue only from then on (the fields below stay where they were).
        expect(await page.locator('[data-testid="tool-chips"] button:visible').allTextContents()).toEqual(
          PRESETS.filter((p) => p.sizedIn === 'in').map((p) => p.chip),
        );
        expect(await page.getByTestId('input-slope').inputValue()).toBe('30');
        await user.enter('[data-testid="input-raster-angle"]', '30');
        await user.enter('[data-testid="input-h"]', '0.0004');
        const bar = page.getByTestId('result-bar-value');
        await expect.poll(async () => /\d/.test((await bar.textContent()) ?? '')).toBe(true);
        await expect.poll(() => page.locator('.results').getAttribute('aria-busy')).toBe('false');
        await user.tap('[data-testid="result-bar"] button.copy');
        await expect.poll(() => page.locator('[data-testid="result-bar"] button.copy').textContent()).toBe('Copied');
        matches(await page.evaluate(() => navigator.clipboard.readText()), exactIn);
        expect(await page.getByTestId('copy-status').textContent()).toContain('3-axis, slope 30°, raster 30°');
        return { count: user.count, seconds: (performance.now() - start) / 1000 };
      };
      const first = await job(true);
      const next = await job(false);
      console.log(
        `phone flow three-axis inch: first visit ${first.count} actions, ${first.seconds.toFixed(2)} s; next visit ${next.count} actions, ${next.seconds.toFixed(2)} s`,
      );
      expect(first.count).toBeLessThanOrEqual(5);
      expect(next.count).toBeLessThanOrEqual(4);
    } finally {
      await context.close();
    }
  });
});
