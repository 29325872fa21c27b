/** Shared set-up of the browser tests: a built site on a loopback sub-path and one Chromium. */
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import type { Browser, Page, Worker } from 'playwright-core';
import { afterAll, beforeAll, expect } from 'vitest';
import { launchChromium } from '../../src/bench/browser';
import { type StaticSite, serveStatic } from '../../src/bench/staticServer';
import { E2E_OUT_DIR } from './globalSetup';
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

export interface Harness {
  readonly browser: () => Browser;
  readonly url: () => string;
  /** Opens the page with a query and waits for the first result (attached: it may be hidden). */
  open(query: string, viewport?: { width: number; height: number }): Promise<{ page: Page; errors: string[] }>;
}

/** Registers beforeAll/afterAll hooks for a test file. */
export function useSite(subPath: string, options: SiteOptions = {}): Harness {
  let browser: Browser | null = null;
  let site: StaticSite | null = null;
  beforeAll(async () => {
    mkdirSync(SHOTS, { recursive: true });
    site = await serveStatic(siteDir(options.build ?? 'e2e'), subPath, options.headers);
    browser = await launchChromium();
  });
  afterAll(async () => {
    await browser?.close();
    await site?.close();
  });
  const need = <T>(v: T | null, what: string): T => {
    if (v === null) throw new Error(`${what} is not started`);
    return v;
  };
  return {
    browser: () => need(browser, 'browser'),
    url: () => need(site, 'site').url,
    async open(query, viewport = { width: 1400, height: 900 }) {
      const page = await need(browser, 'browser').newPage({ viewport });
      const errors: string[] = [];
      page.on('pageerror', (e) => errors.push(e.message));
      page.on('console', (m) => {
        if (m.type() === 'error') errors.push(m.text());
      });
      await page.goto(`${need(site, 'site').url}${query}`);
      await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
      return { page, errors };
    },
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
