/** Shared set-up of the browser tests: a built site on a loopback sub-path and one Chromium. */
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import type { Browser, BrowserContext, Locator, Page, Worker } from 'playwright-core';
import { afterAll, afterEach, beforeAll, beforeEach, expect } from 'vitest';
import { launchChromium } from '../../src/bench/browser';
import { type StaticSite, serveStatic } from '../../src/bench/staticServer';
import { PREFERENCES_KEY } from '../../src/ui/preferences';
import { E2E_OUT_DIR } from './globalSetup';
import { countLoads, reportLoads } from './loadCount';
import { colourShare } from './pixels';

export const ROOT = fileURLToPath(new URL('../..', import.meta.url));
export const SHOTS = `${ROOT}test-results/screenshots`;

/** The strict policy the page must run under with no violation (the README gives it to hosts). */
export const STRICT_CSP = "script-src 'self'; worker-src 'self'; style-src 'self'";

export interface SiteOptions {
  /** `e2e` (default): the instrumented build with the test probe; `production`: dist/ as shipped. */
  readonly build?: 'e2e' | 'production';
  /** Headers sent with every response. */
  readonly headers?: Readonly<Record<string, string>>;
  /**
   * false: the shared page never gets the 3D scene's code (its request held, as while it loads; the
   * page works without it, tests/e2e/lazyScene.test.ts), for files that look at no part of the scene:
   * a scene drawn on SwiftShader costs most of the CPU of a test that never reads it.
   */
  readonly scene?: boolean;
}

/**
 * The directory of a build. `E2E_SITE_DIR` replaces both (to run these tests against another
 * build, for instance the code before a change, and see which of them fail there).
 */
export function siteDir(build: 'e2e' | 'production'): string {
  const override = process.env.E2E_SITE_DIR;
  if (override) return override;
  return build === 'production' ? `${ROOT}dist` : `${ROOT}${E2E_OUT_DIR}`;
}

/** What {@link Harness.open} waits for. */
export interface OpenOptions {
  /**
   * The result whose digits mark the first answer (attached; it may be hidden): `result-exact-half`
   * by default; `result-exact-interval` for a question that shows L only (a three-axis one).
   */
  readonly readyTestId?: string;
}

export interface Harness {
  readonly browser: () => Browser;
  readonly url: () => string;
  /**
   * Opens the page with a query and waits for the first result (attached: it may be hidden). The
   * file's tests share one tab: each open is a fresh document in it (new workers, new state), at
   * the viewport and colour scheme asked (light by default), motion allowed, screen media; only the tab, its
   * context and the HTTP cache carry over. A test that routes requests, injects scripts or needs
   * two pages at once takes its own page from `browser()` instead. Closing the shared page is
   * allowed (the next open starts another).
   */
  open(
    query: string,
    viewport?: { width: number; height: number },
    colorScheme?: 'light' | 'dark',
    options?: OpenOptions,
  ): Promise<{ page: Page; errors: string[] }>;
  /**
   * As {@link open}, but keeps the shared page's document when it was opened with this query and
   * no test has changed its state since ({@link changed}; a failed test counts as a change): then
   * only the viewport and the colour scheme are set ({@link viewAs}). For tests that read a state
   * without changing its inputs, or that call `changed()` after they do.
   */
  reuse(
    query: string,
    viewport?: { width: number; height: number },
    colorScheme?: 'light' | 'dark',
    options?: OpenOptions,
  ): Promise<{ page: Page; errors: string[] }>;
  /** Says that the shared page's state is no longer the one its query opened: the next reuse loads it. */
  changed(): void;
  /**
   * Says that the running test looks at no part of the 3D scene: the documents it opens (or reuses)
   * do not get the scene's code, as with `useSite(path, { scene: false })` for a whole file.
   */
  noScene(): void;
  /** Whether documents opened now go without the scene's code (the file's or the running test's choice). */
  holdsScene(): boolean;
}

/**
 * Makes every load of a page (or of a context's pages) a first visit: no machine or unit remembered
 * from an earlier test's choice (src/ui/preferences.ts; its own test takes a context of its own).
 */
export async function forgetPreferences(target: Page | BrowserContext): Promise<void> {
  await target.addInitScript((key) => {
    try {
      localStorage.removeItem(key);
    } catch {
      // No storage: nothing remembered.
    }
  }, PREFERENCES_KEY);
}

/** The request of the 3D scene's code (its chunk, which brings three.js's). */
const SCENE_CODE = /\/assets\/scene-[^/]*\.js$/;

/** The 3D scene's code requested by a page (or a context's pages) is held: never answered. */
export async function holdScene(target: Page | BrowserContext): Promise<void> {
  await target.route(SCENE_CODE, () => {});
}

/**
 * Holds the scene's code for a page or a context's pages ({@link holdScene}) or serves it again,
 * as `hold` says; `held` is whether it holds it now. Returns whether it holds it then.
 */
export async function holdSceneAs(target: Page | BrowserContext, held: boolean, hold: boolean): Promise<boolean> {
  if (hold !== held) await (hold ? holdScene(target) : target.unroute(SCENE_CODE));
  return hold;
}

/** Registers beforeAll/afterAll hooks for a test file. */
export function useSite(subPath: string, options: SiteOptions = {}): Harness {
  let browser: Browser | null = null;
  let site: StaticSite | null = null;
  let shared: Page | null = null;
  /** Where the shared page's errors go: the latest open's list. */
  let errors: string[] = [];
  /** The query of the shared page's document while its state is still the one the query opened. */
  let intact: string | null = null;
  /** Whether the shared page holds the scene's code (holdScene). */
  let sceneHeld = false;
  /** The running test's choice ({@link Harness.noScene}), or null: the file's. */
  let sceneThisTest: boolean | null = null;
  beforeEach(() => {
    sceneThisTest = null;
  });
  /** Whether documents opened now go without the scene's code: the running test's choice, or the file's. */
  const sceneHeldNow = () => !(sceneThisTest ?? options.scene !== false);
  beforeAll(async () => {
    mkdirSync(SHOTS, { recursive: true });
    site = await serveStatic(siteDir(options.build ?? 'e2e'), subPath, options.headers);
    browser = await launchChromium();
    await countLoads(browser);
  });
  afterEach((context) => {
    if (context.task.result?.state === 'fail') intact = null;
  });
  afterAll(async () => {
    reportLoads();
    await browser?.close();
    await site?.close();
  });
  const need = <T>(v: T | null, what: string): T => {
    if (v === null) throw new Error(`${what} is not started`);
    return v;
  };
  const sharedPage = async (
    viewport: { width: number; height: number },
    colorScheme: 'light' | 'dark',
  ): Promise<Page> => {
    if (shared === null || shared.isClosed()) {
      const page = await need(browser, 'browser').newPage({ viewport, colorScheme });
      sceneHeld = false;
      await forgetPreferences(page);
      page.on('pageerror', (e) => errors.push(e.message));
      page.on('console', (m) => {
        if (m.type() === 'error') errors.push(m.text());
      });
      shared = page;
      return page;
    }
    const size = shared.viewportSize();
    if (size?.width !== viewport.width || size.height !== viewport.height) await shared.setViewportSize(viewport);
    await shared.emulateMedia({ media: 'screen', colorScheme, reducedMotion: 'no-preference' });
    return shared;
  };
  const open = async (
    query: string,
    viewport = { width: 1400, height: 900 },
    colorScheme: 'light' | 'dark' = 'light',
    { readyTestId = 'result-exact-half' }: OpenOptions = {},
  ) => {
    const page = await sharedPage(viewport, colorScheme);
    sceneHeld = await holdSceneAs(page, sceneHeld, sceneHeldNow());
    intact = null;
    // Leave the previous document first, so that nothing it logs while closing is counted here.
    if (page.url() !== 'about:blank') await page.goto('about:blank');
    errors = [];
    const mine = errors;
    await page.goto(`${need(site, 'site').url}${query}`);
    await page.getByTestId(readyTestId).filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
    intact = query;
    return { page, errors: mine };
  };
  return {
    browser: () => need(browser, 'browser'),
    url: () => need(site, 'site').url,
    open,
    async reuse(query, viewport = { width: 1400, height: 900 }, colorScheme = 'light', openOptions = {}) {
      if (intact !== query || sceneHeld !== sceneHeldNow() || shared === null || shared.isClosed())
        return open(query, viewport, colorScheme, openOptions);
      await viewAs(shared, viewport, colorScheme);
      return { page: shared, errors };
    },
    changed() {
      intact = null;
    },
    noScene() {
      sceneThisTest = false;
    },
    holdsScene: sceneHeldNow,
  };
}

/**
 * Fraction of the scene's on-screen pixels that differ from the background colour, read from
 * a screenshot (what the user sees; the WebGL buffer itself is not preserved between frames).
 */
export async function paintedFraction(page: Page): Promise<number> {
  return 1 - (await colourShare(page, page.getByTestId('scene-canvas'), '#f7f8fa', 24));
}

/** The page's worker of this name (path-interval-solver runs `solve`, path-interval-views `teach`). */
export async function namedWorker(page: Page, name: string): Promise<Worker> {
  const find = async (): Promise<Worker | null> => {
    for (const w of page.workers()) if ((await w.evaluate(() => self.name)) === name) return w;
    return null;
  };
  await expect.poll(async () => (await find()) !== null).toBe(true);
  const found = await find();
  if (found === null) throw new Error(`no worker ${name}`);
  return found;
}

type Probe = {
  __pathInterval: {
    frames(): number;
    replies(worker: string): number;
    pending(worker?: string): number;
    urlWrites(): number;
  };
};

/** The results' worker and the teaching views' (workers.ts), as the probe counts them. */
export const SOLVER = 'path-interval-solver';
export const VIEWS_WORKER = 'path-interval-views';

/** Frames the 3D scene has drawn (instrumented build). */
export const frames = (page: Page): Promise<number> =>
  page.evaluate(() => (window as unknown as Probe).__pathInterval.frames());

/** Replies received so far from the workers of this name (instrumented build). */
export const replies = (page: Page, worker: string): Promise<number> =>
  page.evaluate((w) => (window as unknown as Probe).__pathInterval.replies(w), worker);

/** URL writes so far (instrumented build; urlState.ts writes once the inputs settle). */
export const urlWrites = (page: Page): Promise<number> =>
  page.evaluate(() => (window as unknown as Probe).__pathInterval.urlWrites());

/**
 * Waits until every call sent to the live workers of this name has its reply: from then on no late
 * reply of theirs can arrive (instrumented build). Polled from the test, so the page's own handling
 * of the last reply (same task) is done.
 */
export async function workerIdle(page: Page, worker: string, timeout = 20_000): Promise<void> {
  await expect
    .poll(() => page.evaluate((w) => (window as unknown as Probe).__pathInterval.pending(w), worker), { timeout })
    .toBe(0);
}

/** Waits for `count` animation frames of the page (each a chance for the browser to render). */
export async function animationFrames(page: Page, count = 2): Promise<void> {
  await page.evaluate(async (n) => {
    for (let i = 0; i < n; i++) await new Promise((r) => requestAnimationFrame(r));
  }, count);
}

/**
 * Waits until the 3D scene has drawn and then let `quiet` animation frames pass without drawing
 * (instrumented build): whatever it was asked to draw is on screen, labels laid out.
 */
export async function sceneIdle(page: Page, quiet = 3): Promise<void> {
  await page.waitForFunction(() => (window as unknown as Probe).__pathInterval.frames() > 0);
  await page.evaluate(async (n) => {
    const probe = (window as unknown as Probe).__pathInterval;
    let last = probe.frames();
    for (let still = 0; still < n; ) {
      await new Promise((r) => requestAnimationFrame(r));
      const now = probe.frames();
      still = now === last ? still + 1 : 0;
      last = now;
    }
  }, quiet);
}

/**
 * Waits until the page has nothing left to do: every call to any of its workers answered, then
 * `quiet` animation frames in a row in which neither the DOM changed nor the 3D scene drew
 * (instrumented build). Layout read after this is the page's final one for its state.
 */
export async function pageSettled(page: Page, quiet = 3): Promise<void> {
  await expect
    .poll(() => page.evaluate(() => (window as unknown as Probe).__pathInterval.pending()), { timeout: 20_000 })
    .toBe(0);
  await page.evaluate(async (n) => {
    const probe = (window as unknown as Probe).__pathInterval;
    let changes = 0;
    const observer = new MutationObserver(() => changes++);
    observer.observe(document, { subtree: true, childList: true, attributes: true, characterData: true });
    let last = `${changes} ${probe.frames()}`;
    for (let still = 0; still < n; ) {
      await new Promise((r) => requestAnimationFrame(r));
      const now = `${changes} ${probe.frames()}`;
      still = now === last ? still + 1 : 0;
      last = now;
    }
    observer.disconnect();
  }, quiet);
}

/** The phone's viewport the phone tests use (CSS px). */
export const PHONE = { width: 390, height: 844 };

/**
 * A phone page shared by a file's tests (390x844, touch, clipboard allowed): `open(query)` loads
 * the query in it and waits for the first result (attached), without the scene's code where the
 * file or the test says so; the context closes after the file.
 */
export function usePhonePage(site: Harness): (query: string) => Promise<Page> {
  let context: BrowserContext | null = null;
  let shared: Page | null = null;
  let held = false;
  afterAll(async () => {
    await context?.close();
  });
  return async (query: string) => {
    if (context === null) {
      context = await site.browser().newContext({ viewport: PHONE, hasTouch: true, isMobile: true });
      await forgetPreferences(context);
      await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(site.url()).origin });
    }
    shared ??= await context.newPage();
    // Without the scene's code where the file or the test says so (useSite's scene: false, noScene()).
    held = await holdSceneAs(context, held, site.holdsScene());
    await shared.goto(`${site.url()}${query}`);
    await shared.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
    return shared;
  };
}

/**
 * True under `npm run shots` (E2E_SHOTS=1): the screenshots kept for a person to look at are
 * written to {@link SHOTS}. `npm test` writes none of them (a screenshot a test compares is taken
 * by that test itself, whatever this says).
 */
export const KEEP_SHOTS = Boolean(process.env.E2E_SHOTS);

/**
 * Keeps a screenshot of a page or an element for a person to look at, as `SHOTS/<name>.png`, under
 * `npm run shots` only (see {@link KEEP_SHOTS}); otherwise does nothing.
 */
export async function keepShot(
  target: Page | Locator,
  name: string,
  options: { fullPage?: boolean } = {},
): Promise<void> {
  if (!KEEP_SHOTS) return;
  await target.screenshot({ path: `${SHOTS}/${name}.png`, ...options });
}

/**
 * Shows the same document at another size and colour scheme, as a new load at them would (the
 * page follows the system's scheme when its link names no theme): the viewport and the scheme
 * set, the page's theme the scheme's, then the page settled (instrumented build).
 */
export async function viewAs(
  page: Page,
  viewport: { width: number; height: number },
  colorScheme: 'light' | 'dark' = 'light',
): Promise<void> {
  const size = page.viewportSize();
  if (size?.width !== viewport.width || size.height !== viewport.height) await page.setViewportSize(viewport);
  await page.emulateMedia({ colorScheme });
  await expect.poll(() => page.evaluate(() => document.documentElement.dataset.theme)).toBe(colorScheme);
  await pageSettled(page);
}

/** Opens a teaching view by its tab (as a click would) and waits until its panel has content. */
export async function showView(page: Page, view: string): Promise<void> {
  await page.locator(`[role="tab"][data-view="${view}"]`).click();
  await expect.poll(() => page.locator(`[role="tab"][data-view="${view}"]`).getAttribute('aria-selected')).toBe('true');
  await page.locator(`#panel-${view} > *`).first().waitFor();
}

/** Loses the WebGL context of a canvas (WEBGL_lose_context) and restores it once the loss has been reported. */
export async function loseAndRestore(page: Page, testId: string): Promise<void> {
  await page.evaluate(async (id) => {
    const canvas = document.querySelector(`[data-testid="${id}"]`) as HTMLCanvasElement;
    const lose = canvas.getContext('webgl2')?.getExtension('WEBGL_lose_context');
    if (!lose) throw new Error('no WEBGL_lose_context');
    const event = (type: string) => new Promise((resolve) => canvas.addEventListener(type, resolve, { once: true }));
    const lost = event('webglcontextlost');
    lose.loseContext();
    await lost;
    // Chromium allows the restore once the loss event's dispatch is over (the next task).
    await new Promise((resolve) => setTimeout(resolve, 0));
    const restored = event('webglcontextrestored');
    lose.restoreContext();
    await restored;
  }, testId);
}

/** Clears the focused field and types `text` with the keyboard, key by key (`delayMs` apart). */
export async function retype(page: Page, text: string, delayMs = 30): Promise<void> {
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.press('Backspace');
  await page.keyboard.type(text, { delay: delayMs });
}

/** Scrolls a field into view, focuses it (a click, or a tap on a touch page) and retypes it. */
export async function typeInto(
  page: Page,
  testId: string,
  text: string,
  { tap = false, delayMs = 30 }: { tap?: boolean; delayMs?: number } = {},
): Promise<void> {
  const input = page.getByTestId(testId);
  await input.scrollIntoViewIfNeeded();
  await (tap ? input.tap() : input.click());
  await retype(page, text, delayMs);
}
