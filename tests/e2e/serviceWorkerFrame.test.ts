/**
 * The production page registers its offline service worker (src/main.ts) when it is the top-level
 * page, and not inside a frame of another site (an embed): there the worker would be the host's
 * third-party storage, and the embed must not log errors into the host's console. The host page
 * is served from `localhost`, the calculator from `127.0.0.1` (two origins, both secure contexts).
 * `navigator.serviceWorker.register` is counted by an init script in every frame, read once the
 * page's load handlers have run.
 */
import type { Frame, Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { isGlDriverNote } from '../../src/bench/browser';
import { useSite } from './harness';

const site = useSite('docs/sw-frame', { build: 'production' });

interface Counted {
  __registerCalls: number;
  __afterLoad: boolean;
}

/** Counts register() calls and marks the end of the load event's handlers (ours runs first, its timeout after all). */
function countRegistrations(): void {
  const w = window as unknown as Counted;
  w.__registerCalls = 0;
  w.__afterLoad = false;
  const container = navigator.serviceWorker;
  if (container !== undefined) {
    const register = container.register.bind(container);
    container.register = (...args: Parameters<ServiceWorkerContainer['register']>) => {
      w.__registerCalls++;
      return register(...args);
    };
  }
  window.addEventListener('load', () => setTimeout(() => (w.__afterLoad = true)));
}

/** register() calls in `frame`, once its load handlers have run. */
async function registrationsAfterLoad(frame: Frame | Page): Promise<number> {
  await frame.waitForFunction(() => (window as unknown as Counted).__afterLoad, null, { timeout: 20_000 });
  return frame.evaluate(() => (window as unknown as Counted).__registerCalls);
}

describe('the service worker and embeds', () => {
  it('an embed in another origin registers none and logs no error; the page itself registers one', async () => {
    const context = await site.browser().newContext({ viewport: { width: 900, height: 900 } });
    await context.addInitScript(countRegistrations);
    const errors: string[] = [];
    const host = await context.newPage();
    host.on('pageerror', (e) => errors.push(e.message));
    const calculator = new URL(site.url());
    const hostOrigin = `http://localhost:${calculator.port}`;
    // Every error or warning but the host's own missing favicon (the host here is a bare test page)
    // and the GL driver's notes on the tests' software compositing (src/bench/browser.ts).
    host.on('console', (m) => {
      const at = m.location().url;
      if (
        (m.type() === 'error' || m.type() === 'warning') &&
        at !== `${hostOrigin}/favicon.ico` &&
        !isGlDriverNote(m.text())
      )
        errors.push(`${m.text()} (${at})`);
    });
    expect(hostOrigin).not.toBe(calculator.origin);
    // A page of the host's origin (a file the server has), its content replaced by the embed's frame.
    await host.goto(`${hostOrigin}${calculator.pathname}embed.js`);
    await host.setContent(`<iframe title="calculator" src="${site.url()}?embed=1" width="800" height="800"></iframe>`);
    const frame = host.frameLocator('iframe');
    await frame.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
    const embedded = host.frames().find((f) => f.url().startsWith(calculator.origin));
    if (embedded === undefined) throw new Error('no frame of the calculator');
    expect(await embedded.evaluate(() => window.top !== window && 'serviceWorker' in navigator)).toBe(true);
    expect(await registrationsAfterLoad(embedded)).toBe(0);

    // The same build as a page of its own registers it (the count above is not zero for want of a worker).
    const own = await context.newPage();
    await own.goto(`${site.url()}?R=3&Rcr=1&rho=5&h=0.05&unit=mm`);
    expect(await registrationsAfterLoad(own)).toBe(1);
    await expect
      .poll(() => own.evaluate(async () => (await navigator.serviceWorker.ready).active?.state))
      .toBe('activated');
    expect(errors).toEqual([]);
    await context.close();
  }, 60_000);
});
