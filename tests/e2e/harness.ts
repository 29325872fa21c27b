/** Shared set-up of the browser tests: the built site on a loopback sub-path and one Chromium. */
import { mkdirSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import type { Browser, Page } from 'playwright-core';
import { afterAll, beforeAll } from 'vitest';
import { launchChromium } from '../../src/bench/browser';
import { type StaticSite, serveStatic } from '../../src/bench/staticServer';

export const ROOT = fileURLToPath(new URL('../..', import.meta.url));
export const SHOTS = `${ROOT}test-results/screenshots`;

export interface Harness {
  readonly browser: () => Browser;
  readonly url: () => string;
  /** Opens the page with a query and waits for the first result (attached: it may be hidden). */
  open(query: string, viewport?: { width: number; height: number }): Promise<{ page: Page; errors: string[] }>;
}

/** Registers beforeAll/afterAll hooks for a test file. */
export function useSite(subPath: string): Harness {
  let browser: Browser | null = null;
  let site: StaticSite | null = null;
  beforeAll(async () => {
    mkdirSync(SHOTS, { recursive: true });
    site = await serveStatic(`${ROOT}dist`, subPath);
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
