/**
 * The example documentation site (tests/docs-site/, MkDocs, installed by the project's own
 * tests/support/ensure-mkdocs.mjs) is built, served at /docs/ beside the calculator's production
 * build at /calculator/ on one server, and opened as a reader would: the embeds (the custom
 * element following the page, light and dark, the result card, a plain iframe with the README's
 * listener) render; each element keeps the height it reserved before it loaded (height="auto" and
 * the plain iframe take the height of their content) and ignores a resize message from another
 * origin or another window; the site loads nothing from outside its server (MkDocs' theme would
 * fetch highlight.js from a CDN: off in mkdocs.yml); the page follows the reader's colour scheme (color_mode: auto), and its theme="auto"
 * embed with it, in place: a light embed on a light page, a dark one on a dark page.
 */
import { execFileSync } from 'node:child_process';
import type { Browser, Frame, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { launchChromium } from '../../src/bench/browser';
import { type StaticMounts, serveStaticMounts } from '../../src/bench/staticServer';
import { animationFrames, keepShot, ROOT, siteDir } from './harness';

const DOCS_OUT = `${ROOT}test-results/docs-site`;
let browser: Browser | null = null;
let server: StaticMounts | null = null;

beforeAll(async () => {
  execFileSync(
    'node',
    [`${ROOT}tests/support/ensure-mkdocs.mjs`, 'build', `${ROOT}tests/docs-site/mkdocs.yml`, DOCS_OUT],
    { stdio: 'inherit' },
  );
  server = await serveStaticMounts([
    { root: DOCS_OUT, subPath: 'docs' },
    { root: siteDir('production'), subPath: 'calculator' },
  ]);
  browser = await launchChromium();
}, 180_000);

afterAll(async () => {
  await browser?.close();
  await server?.close();
});

/** Every address the last opened docs page (and its frames) asked for. */
let requested: string[] = [];

async function openDocs(colorScheme: 'light' | 'dark' = 'light'): Promise<Page> {
  if (!browser || !server) throw new Error('not started');
  const page = await browser.newPage({ viewport: { width: 1100, height: 900 }, colorScheme });
  requested = [];
  page.on('request', (r) => requested.push(r.url()));
  await page.goto(`${server.urls[0]}index.html`);
  return page;
}

/** The embedded calculator inside the iframe `selector`, once its view has drawn. */
async function embedded(page: Page, selector: string, drawn: string): Promise<Frame> {
  const handle = await page.locator(selector).elementHandle();
  const frame = await handle?.contentFrame();
  if (!frame) throw new Error(`no frame ${selector}`);
  await frame.locator(drawn).first().waitFor({ timeout: 20_000 });
  return frame;
}

const frameHeight = (page: Page, selector: string) =>
  page.locator(selector).evaluate((f) => Math.round(f.getBoundingClientRect().height));
const contentHeight = (frame: Frame) =>
  frame.locator('#app').evaluate((e) => Math.ceil(e.getBoundingClientRect().height));

describe('example documentation site (MkDocs)', () => {
  it('embeds render in light and dark, keep their reserved heights (height="auto" and the plain iframe: their content\'s), nothing loads from outside', async () => {
    const page = await openDocs();
    expect(await page.locator('h1').first().textContent()).toMatch(/Step-over of a bull-nose end mill/);
    const cases: Array<[string, string, 'light' | 'dark']> = [
      ['#embed-card iframe', '[data-testid="card-summary"]', 'light'],
      ['#embed-auto iframe', '[data-testid="profile-view"] polygon.scallop', 'light'],
      ['#embed-light iframe', '[data-testid="profile-view"] polygon.scallop', 'light'],
      ['#embed-dark iframe', '.formula', 'dark'],
      ['#plain-frame', '[data-testid="paper-table-half"] tr[data-condition]', 'dark'],
    ];
    // The elements' heights before they load (reserved), to compare with after.
    const reserved = new Map<string, number>();
    for (const [selector] of cases) reserved.set(selector, await frameHeight(page, selector));
    for (const [selector, drawn, theme] of cases) {
      await page.locator(selector).scrollIntoViewIfNeeded();
      const frame = await embedded(page, selector, drawn);
      expect(await frame.evaluate(() => document.documentElement.dataset.theme), selector).toBe(theme);
      expect(await frame.getByTestId('result-exact-half').textContent()).toMatch(/^1\.44\d+ mm$/);
      expect(await frame.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth), selector).toBe(
        true,
      );
      if (selector === '#plain-frame' || selector === '#embed-light iframe') {
        // The plain iframe (the README's listener) and height="auto": the height of the content, no inner scrollbar.
        await expect
          .poll(async () => (await frameHeight(page, selector)) - (await contentHeight(frame)), { timeout: 15_000 })
          .toBe(0);
        expect(await frame.evaluate(() => document.documentElement.scrollHeight <= window.innerHeight)).toBe(true);
      } else {
        // The element keeps the height it reserved before loading (the page did not move).
        await animationFrames(page);
        expect(await frameHeight(page, selector), selector).toBe(reserved.get(selector));
      }
    }
    // The plain iframe started at 360 px and the tables are taller: it grew.
    expect(await frameHeight(page, '#plain-frame')).toBeGreaterThan(360);
    // Nothing came from outside the server (no CDN highlighter, no font).
    const origin = new URL(server?.urls[0] ?? '').origin;
    expect(requested.filter((u) => !u.startsWith(`${origin}/`) && !/^(data|blob|about):/.test(u))).toEqual([]);
    expect(requested.length).toBeGreaterThan(10);
    await keepShot(page, 'docs-site', { fullPage: true });
    await page.close();
  }, 90_000);

  it('a resize message from another origin or another window is ignored', async () => {
    const page = await openDocs();
    const selector = '#embed-light iframe';
    const frame = await embedded(page, selector, '[data-testid="profile-view"] polygon.scallop');
    await expect
      .poll(async () => (await frameHeight(page, selector)) - (await contentHeight(frame)), { timeout: 15_000 })
      .toBe(0);
    const before = await frameHeight(page, selector);
    // From the iframe's own window but another origin, then from the right origin but another window.
    await page.locator(selector).evaluate((f) => {
      const source = (f as HTMLIFrameElement).contentWindow;
      const data = { type: 'path-interval:resize', height: 2345 };
      window.dispatchEvent(new MessageEvent('message', { data, origin: 'http://evil.example', source }));
      window.dispatchEvent(
        new MessageEvent('message', { data, origin: new URL(document.baseURI).origin, source: window }),
      );
    });
    // The listeners run while the messages are dispatched; two animation frames later any height
    // they set is laid out.
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    expect(await frameHeight(page, selector)).toBe(before);
    // The same message from the iframe's window and origin is taken (the check is not blind): the
    // listener sets the height while the message is dispatched (read at once: the frame's own
    // content posts its real height again as soon as it lays out at the new size).
    const taken = await page.locator(selector).evaluate((f) => {
      const source = (f as HTMLIFrameElement).contentWindow;
      const data = { type: 'path-interval:resize', height: 2345 };
      window.dispatchEvent(
        new MessageEvent('message', {
          data,
          origin: new URL(f.getAttribute('src') ?? '', document.baseURI).origin,
          source,
        }),
      );
      return (f as HTMLIFrameElement).style.height;
    });
    expect(taken).toBe('2345px');
    await page.close();
  }, 60_000);
});

/** The page's own colours: MkDocs' colour mode (data-bs-theme) and the body's background. */
const pageLook = (page: Page) =>
  page.evaluate(() => ({
    mode: document.documentElement.dataset.bsTheme,
    background: getComputedStyle(document.body).backgroundColor,
  }));
/** The embedded page's theme, its background, and the marker the test left on its window. */
const frameLook = (frame: Frame) =>
  frame.evaluate(() => ({
    theme: document.documentElement.dataset.theme,
    background: getComputedStyle(document.documentElement).backgroundColor,
    marker: (window as unknown as { marker?: string }).marker ?? null,
  }));

describe('the page and its theme="auto" embed follow the reader\'s colour scheme together', () => {
  it('a light page shows a light embed; turned dark, both are dark, the embed restyled without reloading', async () => {
    const page = await openDocs('light');
    const selector = '#embed-auto iframe';
    const frame = await embedded(page, selector, '[data-testid="profile-view"] polygon.scallop');
    expect(await pageLook(page)).toEqual({ mode: 'light', background: 'rgb(255, 255, 255)' });
    await frame.evaluate(() => {
      (window as unknown as { marker: string }).marker = 'same document';
    });
    expect(await frameLook(frame)).toEqual({
      theme: 'light',
      background: 'rgb(255, 255, 255)',
      marker: 'same document',
    });
    const src = await page.locator(selector).getAttribute('src');
    await page.locator('#embed-auto').scrollIntoViewIfNeeded();
    await keepShot(page, 'docs-site-light-page-light-embed');

    await page.emulateMedia({ colorScheme: 'dark' });
    await expect.poll(async () => (await pageLook(page)).mode).toBe('dark');
    expect((await pageLook(page)).background).not.toBe('rgb(255, 255, 255)');
    await expect
      .poll(() => frameLook(frame))
      .toEqual({ theme: 'dark', background: 'rgb(18, 22, 31)', marker: 'same document' });
    expect(await page.locator(selector).getAttribute('src')).toBe(src);
    // The pinned embeds keep their themes on the dark page.
    const pinned = await embedded(page, '#embed-light iframe', '[data-testid="profile-view"] polygon.scallop');
    expect((await frameLook(pinned)).theme).toBe('light');
    await keepShot(page, 'docs-site-dark-page-dark-embed');
    await page.close();
  }, 60_000);
});
