/**
 * The technical writer's embedding, driven as a documentation page would: light and dark (system
 * and `theme=`), the height posted to the host, the "Copy embed code" button, and every view
 * fitting its 480 px embed and the full page fitting phones and tablets (no sideways scrolling,
 * nothing cut off). Issue 28: the element reserves its height before its frame loads (lazily, when
 * scrolled to) and keeps it, the height recorded before and after each scrolls into view; the whole
 * calculator in an 860 px column stands in one column with a scene at least 300 px tall; the
 * compact `view=result` card.
 */

import { mkdirSync, writeFileSync } from 'node:fs';
import type { Frame, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { isGlDriverNote } from '../../src/bench/browser';
import { type StaticSite, serveStatic } from '../../src/bench/staticServer';
import { EMBED_ATTRIBUTES } from '../../src/core/input/fields';
import { axeViolations } from './axe';
import { animationFrames, keepShot, pageSettled, ROOT, showView, useSite, viewAs } from './harness';
import { clippedElements, colourShare } from './pixels';

const site = useSite('docs/embed');
const STATE = 'R=3&Rcr=1&rho=5&h=0.05&unit=mm';
const VIEWS = ['profile', 'chart', 'tables', 'stepper', 'formulas', 'surface'] as const;
/** The scene's background per theme (--scene-bg in src/ui/theme.css). */
const SCENE_BG = { light: '#f7f8fa', dark: '#12161f' };

async function sceneShows(page: Page, hex: string): Promise<number> {
  return colourShare(page, page.getByTestId('scene-canvas'), hex, 12);
}

describe('dark mode', () => {
  it('follows prefers-color-scheme, live, in the page, the 3D scene and the chart', async () => {
    const { page } = await site.open(`?${STATE}&view=chart`, { width: 1400, height: 900 }, 'dark');
    await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    expect(await page.evaluate(() => document.documentElement.dataset.theme)).toBe('dark');
    expect(await page.evaluate(() => getComputedStyle(document.documentElement).backgroundColor)).toBe(
      'rgb(18, 22, 31)',
    );
    await expect.poll(() => sceneShows(page, SCENE_BG.dark)).toBeGreaterThan(0.3);
    // The chart's curves take the dark palette: Sekine's amber #fbbf24, not the light #b45309.
    const lead = page.getByTestId('chart-lead');
    await lead.locator('svg.chart-svg').waitFor();
    await expect.poll(() => colourShare(page, lead, '#fbbf24', 40)).toBeGreaterThan(0.0005);
    expect(await colourShare(page, lead, '#b45309', 30)).toBe(0);
    await keepShot(page, 'theme-dark-system-1400');
    await page.emulateMedia({ colorScheme: 'light' });
    await expect.poll(() => page.evaluate(() => document.documentElement.dataset.theme)).toBe('light');
    await expect.poll(() => sceneShows(page, SCENE_BG.light)).toBeGreaterThan(0.3);
    await expect.poll(() => colourShare(page, lead, '#b45309', 40)).toBeGreaterThan(0.0005);
  });

  it('theme=dark|light in the link overrides the system; an invalid value gets a notice', async () => {
    const dark = (await site.open(`?${STATE}&view=profile&embed=1&theme=dark`, { width: 480, height: 700 }, 'light'))
      .page;
    await dark.getByTestId('profile-view').locator('polygon.scallop').waitFor();
    expect(await dark.evaluate(() => document.documentElement.dataset.theme)).toBe('dark');
    // The profile's exact curve is drawn in the dark palette's exact colour.
    const stroke = await dark
      .locator('.profile-svg .curve-exact')
      .first()
      .evaluate((e) => getComputedStyle(e).stroke);
    expect(stroke).toBe('rgb(243, 244, 246)');
    expect(new URL(dark.url()).searchParams.get('theme')).toBe('dark'); // kept while the state changes
    await keepShot(dark, 'theme-dark-embed-profile-480');

    const light = (await site.open(`?${STATE}&theme=light`, { width: 1400, height: 900 }, 'dark')).page;
    await light.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    expect(await light.evaluate(() => document.documentElement.dataset.theme)).toBe('light');
    await expect.poll(() => sceneShows(light, SCENE_BG.light)).toBeGreaterThan(0.3);

    const bad = (await site.open(`?${STATE}&theme=purple`, { width: 1400, height: 900 }, 'dark')).page;
    await bad.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    expect(await bad.getByTestId('notice').textContent()).toMatch(/theme="purple" is not light, dark or auto/);
    expect(await bad.evaluate(() => document.documentElement.dataset.theme)).toBe('dark');
  });
});

describe('auto-height', () => {
  it('the embedded page posts its content height to the host whenever it changes', async () => {
    const host = await site.browser().newPage({ viewport: { width: 800, height: 900 } });
    await host.goto(`${site.url()}embed.js`); // any page of the same site; its content is replaced
    await host.setContent('<iframe id="f" width="480" height="300"></iframe>');
    await host.evaluate(() => {
      const seen: unknown[] = [];
      (window as unknown as { seen: unknown[] }).seen = seen;
      window.addEventListener('message', (e) => seen.push(e.data));
    });
    await host.locator('#f').evaluate((f, src) => {
      (f as HTMLIFrameElement).src = src;
    }, `${site.url()}?${STATE}&view=formulas&embed=1`);
    const heights = () =>
      host.evaluate(() =>
        (window as unknown as { seen: Array<{ type?: string; height?: number }> }).seen
          .filter((m) => m.type === 'path-interval:resize')
          .map((m) => m.height as number),
      );
    await expect.poll(async () => (await heights()).at(-1) ?? 0, { timeout: 15_000 }).toBeGreaterThan(400);
    const frame = host.frameLocator('#f');
    await frame.getByTestId('teaching').locator('.formula').first().waitFor();
    const content = await frame.locator('#app').evaluate((e) => Math.ceil(e.getBoundingClientRect().height));
    await expect.poll(async () => (await heights()).at(-1)).toBe(content);
    // Content that grows (a longer state message) is posted again.
    const before = (await heights()).length;
    await frame.locator('#app').evaluate((e) => {
      const extra = document.createElement('div');
      extra.className = 'grow-test';
      extra.textContent = 'x';
      e.append(extra);
    });
    await expect.poll(async () => (await heights()).length).toBeGreaterThan(before);
    await host.close();
  });

  it('a page that is not in a frame posts nothing', async () => {
    // Every message the page gets from its start (a page not in a frame is its own parent).
    const page = await site.browser().newPage({ viewport: { width: 480, height: 400 } });
    await page.addInitScript(() => {
      const seen: unknown[] = [];
      (window as unknown as { __messages: unknown[] }).__messages = seen;
      window.addEventListener('message', (e) => seen.push(e.data));
    });
    await page.goto(`${site.url()}?${STATE}&embed=1`);
    await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
    const posted = await page.evaluate(async () => {
      const app = document.getElementById('app') as HTMLElement;
      // The content grows (a framed page would post its height, from its ResizeObserver); once this
      // test's own observer, registered after the page's, has run, a message the page posted is
      // queued: a marker posted after it arrives after it.
      await new Promise<void>((resolve) => {
        let first = true;
        new ResizeObserver(() => {
          if (first) {
            first = false;
            const extra = document.createElement('div');
            extra.textContent = 'grow';
            app.append(extra);
          } else resolve();
        }).observe(app);
      });
      await new Promise<void>((resolve) => {
        window.addEventListener('message', (e) => e.data === 'marker' && resolve());
        window.postMessage('marker', '*');
      });
      return (window as unknown as { __messages: unknown[] }).__messages.filter((m) => m !== 'marker');
    });
    expect(posted).toEqual([]);
    await page.close();
  });
});

describe('the custom element <path-interval-calculator>', () => {
  /** Spellings of addresses that would run a script (or load a page of no origin of ours): each is refused. */
  const REFUSED = [
    'javascript:parent.__xss=4//',
    ' JavaScript:parent.__xss=5//',
    'java\tscript:parent.__xss=6//',
    'data:text/html,<script>parent.__xss=7</script>',
    'vbscript:msgbox(8)',
  ];

  it('loads only http(s) and relative src addresses: a javascript: src is refused with a warning naming src, and no script runs', async () => {
    const host = await site.browser().newPage({ viewport: { width: 800, height: 900 } });
    const warnings: string[] = [];
    host.on('console', (m) => {
      if (m.type() === 'warning' && !isGlDriverNote(m.text())) warnings.push(m.text());
    });
    await host.goto(`${site.url()}embed.js`); // a page of the calculator's site; its content is replaced
    await host.setContent(`<script src="${site.url()}embed.js"></script>`);
    await host.waitForFunction(() => customElements.get('path-interval-calculator') !== undefined);
    // The refused ones, then a relative and an absolute http address, each taking its page's height.
    const good = ['./', site.url()];
    await host.evaluate(
      ({ refused, good }) => {
        const w = window as unknown as { resized: string[] };
        w.resized = [];
        for (const [i, src] of [...refused, ...good].entries()) {
          const el = document.createElement('path-interval-calculator');
          el.id = `calc-${i}`;
          el.setAttribute('src', src);
          el.setAttribute('view', 'formulas');
          // Short, so that all seven stand in the window: the frames load lazily, when in view.
          el.setAttribute('height', '120');
          el.addEventListener('path-interval:resize', () => w.resized.push(el.id));
          document.body.append(el);
        }
      },
      { refused: REFUSED, good },
    );
    const resized = () => host.evaluate(() => new Set((window as unknown as { resized: string[] }).resized).size);
    // Both good ones loaded the calculator and posted its height: by then a script address would have run.
    await expect.poll(resized, { timeout: 20_000 }).toBe(good.length);
    expect(await host.evaluate(() => (window as unknown as { __xss?: unknown }).__xss)).toBeUndefined();
    for (const [i, src] of REFUSED.entries()) {
      expect(await host.locator(`#calc-${i} iframe`).getAttribute('src'), src).toBe('about:blank');
      expect(
        warnings.some((w) =>
          w.includes(`the src attribute ${JSON.stringify(src)} is not an http(s) or relative address`),
        ),
        `warning for ${JSON.stringify(src)} in ${JSON.stringify(warnings)}`,
      ).toBe(true);
    }
    const relative = await host.locator(`#calc-${REFUSED.length} iframe`).getAttribute('src');
    expect(relative).toBe(`${site.url()}?view=formulas&embed=1`);
    expect(await host.locator(`#calc-${REFUSED.length + 1} iframe`).getAttribute('src')).toBe(relative);
    // An address changed to a script address later: refused too, the frame emptied.
    const before = warnings.length;
    await host.evaluate(() => document.getElementById('calc-5')?.setAttribute('src', 'javascript:parent.__xss=9//'));
    await expect.poll(() => host.locator('#calc-5 iframe').getAttribute('src')).toBe('about:blank');
    expect(warnings.slice(before).join('\n')).toMatch(/the src attribute "javascript:parent.__xss=9\/\/"/);
    // The address an element would load: https and protocol-relative kept, the refused ones null.
    const urls = await host.evaluate((refused) => {
      const url = (src: string) => {
        const el = document.createElement('path-interval-calculator') as HTMLElement & { url: URL | null };
        el.setAttribute('src', src);
        el.setAttribute('r', '3');
        return el.url?.href ?? null;
      };
      return {
        https: url('https://calc.example/tool/'),
        protocolRelative: url('//calc.example/tool/'),
        refused: refused.map(url),
      };
    }, REFUSED);
    expect(urls).toEqual({
      https: 'https://calc.example/tool/?R=3&embed=1',
      protocolRelative: `${new URL(site.url()).protocol}//calc.example/tool/?R=3&embed=1`,
      refused: REFUSED.map(() => null),
    });
    // Every attribute of the field registry (the surface, D, ...) becomes its query parameter.
    const taken = await host.evaluate(
      (attributes) => {
        const el = document.createElement('path-interval-calculator') as HTMLElement & { url: URL | null };
        el.setAttribute('src', 'https://calc.example/');
        attributes.forEach(([a], i) => {
          el.setAttribute(a, `v${i}`);
        });
        return Object.fromEntries(el.url?.searchParams ?? []);
      },
      EMBED_ATTRIBUTES.map(([a, p]) => [a, p] as [string, string]),
    );
    expect(taken).toEqual({ ...Object.fromEntries(EMBED_ATTRIBUTES.map(([, p], i) => [p, `v${i}`])), embed: '1' });
    await host.close();
  });
});

describe('copy embed code', () => {
  it('copies the iframe and the custom element for the current state and view, and says so', async () => {
    const context = await site.browser().newContext({
      viewport: { width: 1400, height: 900 },
      permissions: ['clipboard-read', 'clipboard-write'],
    });
    const page = await context.newPage();
    await page.goto(`${site.url()}?R=3&Rcr=1&rho=5&tilt=5&h=0.05&unit=mm`);
    await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    await page.getByRole('tab', { name: 'Formulas' }).click();
    await page.getByTestId('copy-embed').click();
    await expect.poll(() => page.getByTestId('copy-embed-status').textContent()).toMatch(/Embed code copied/);
    expect(await page.getByTestId('copy-embed-status').isVisible()).toBe(true);
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    const src = /<iframe src="([^"]+)"/.exec(copied)?.[1]?.replace(/&amp;/g, '&') ?? '';
    const url = new URL(src);
    expect(url.href.startsWith(site.url())).toBe(true);
    expect(Object.fromEntries(url.searchParams)).toEqual({
      R: '3',
      Rcr: '1',
      rho: '5',
      tilt: '5',
      h: '0.05',
      unit: 'mm',
      view: 'formulas',
      embed: '1',
    });
    expect(copied).toContain(`<script src="${site.url()}embed.js" defer></script>`);
    expect(copied).toMatch(
      /<path-interval-calculator r="3" rcr="1" rho="5" tilt="5" h="0.05" unit="mm" view="formulas"><\/path-interval-calculator>/,
    );
    // The copied iframe opens that view embedded, with the same numbers.
    const embedded = await context.newPage();
    await embedded.setViewportSize({ width: 480, height: 600 });
    await embedded.goto(src);
    await embedded.getByTestId('teaching').locator('.formula').first().waitFor();
    expect(await embedded.evaluate(() => document.documentElement.classList.contains('single-view'))).toBe(true);
    await keepShot(page, 'copy-embed-confirmed');
    await context.close();
  });

  it('where the clipboard is refused, the code is shown selected to copy by hand', async () => {
    const { page } = await site.open(`?${STATE}`);
    await page.evaluate(() => {
      Object.defineProperty(navigator, 'clipboard', { value: { writeText: () => Promise.reject(new Error('no')) } });
    });
    await page.getByTestId('copy-embed').click();
    await expect.poll(() => page.getByTestId('copy-embed-status').textContent()).toMatch(/refused/);
    const box = page.getByTestId('embed-code');
    expect(await box.isVisible()).toBe(true);
    expect(await box.inputValue()).toMatch(/<iframe src="[^"]*view=profile/);
  });
});

describe('every view fits', () => {
  it('each view embedded at 480 px: no horizontal scrolling, nothing cut off (light and dark)', async () => {
    // One load per view (an embed shows one view, no tabs); the dark scheme by emulateMedia.
    for (const view of VIEWS) {
      const { page } = await site.open(`?${STATE}&view=${view}&embed=1`, { width: 480, height: 700 }, 'light');
      await page.locator(`#panel-${view} > *`).first().waitFor();
      for (const theme of ['light', 'dark'] as const) {
        await viewAs(page, { width: 480, height: 700 }, theme);
        const width = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
        expect(width[0], `${view} ${theme}`).toBeLessThanOrEqual(width[1] as number);
        expect(await clippedElements(page), `${view} ${theme}`).toEqual([]);
        await keepShot(page, `embed-${view}-480-${theme}`, { fullPage: true });
        if (theme === 'dark') continue;
        // What was cut off before: the paper tables' Bedi column and the stepper's camera buttons.
        if (view === 'tables') {
          const bedi = page.locator('[data-testid="paper-half-0-bedi"]');
          await bedi.waitFor();
          const box = await bedi.boundingBox();
          expect((box?.x ?? 1e9) + (box?.width ?? 0)).toBeLessThanOrEqual(480);
        }
        if (view === 'stepper') {
          const top = page.locator('[data-camera="top"]');
          await top.waitFor();
          expect(await top.isVisible()).toBe(true);
          const topBox = await top.boundingBox();
          expect((topBox?.x ?? 1e9) + (topBox?.width ?? 0)).toBeLessThanOrEqual(480);
        }
      }
    }
  }, 120_000);

  it('the full page at 360, 390, 414 and 768 px: no horizontal scrolling in any view', async () => {
    // One load; the sizes by setViewportSize, the views by their tabs.
    const { page } = await site.open(`?${STATE}`, { width: 360, height: 780 });
    for (const [width, height] of [
      [360, 780],
      [390, 844],
      [414, 896],
      [768, 1024],
    ] as const) {
      await viewAs(page, { width, height });
      for (const view of VIEWS) {
        await showView(page, view);
        await pageSettled(page);
        const scroll = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
        expect(scroll[0], `${view} at ${width}`).toBeLessThanOrEqual(scroll[1] as number);
        expect(await clippedElements(page), `${view} at ${width}`).toEqual([]);
        if (view === 'profile' || view === 'tables') await keepShot(page, `full-${view}-${width}`, { fullPage: true });
      }
    }
  }, 180_000);
});

/** Host pages (written by the tests) served on another port: another origin than the calculator's, as a documentation site is. */
const HOSTS_DIR = `${ROOT}test-results/embed-hosts`;
let hosts: StaticSite | null = null;
beforeAll(async () => {
  mkdirSync(HOSTS_DIR, { recursive: true });
  hosts = await serveStatic(HOSTS_DIR, 'host');
});
afterAll(async () => {
  await hosts?.close();
});
let hostPages = 0;
/** The tab the host pages load in, one after the other (a fresh document each). */
let hostTab: Page | null = null;

/**
 * A host page on another origin than the calculator's, in `scheme`: it loads embed.js from the
 * calculator's site and then has `body`; it counts the elements' resize events (`window.resized`).
 * Loaded in the file's host tab (a fresh document; the tab kept for the next host page).
 */
async function hostPage(scheme: 'light' | 'dark', body: string): Promise<Page> {
  if (hosts === null) throw new Error('the host server is not started');
  const name = `host-${++hostPages}.html`;
  writeFileSync(
    `${HOSTS_DIR}/${name}`,
    '<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Host</title>' +
      "<script>window.resized = 0; addEventListener('path-interval:resize', () => { window.resized += 1; }, true);</script>" +
      `<script src="${site.url()}embed.js"></script></head><body><main>${body}</main></body></html>`,
  );
  if (hostTab === null || hostTab.isClosed())
    hostTab = await site.browser().newPage({ viewport: { width: 900, height: 1000 }, colorScheme: scheme });
  else {
    await hostTab.goto('about:blank');
    await hostTab.emulateMedia({ colorScheme: scheme });
  }
  await hostTab.goto(`${hosts.url}${name}`);
  return hostTab;
}

/** The frame of the element `#id` once its page has started (posted its height) and drawn `drawn`. */
async function startedFrame(host: Page, id: string, drawn: string): Promise<Frame> {
  await expect
    .poll(() => host.evaluate(() => (window as unknown as { resized: number }).resized), { timeout: 20_000 })
    .toBeGreaterThan(0);
  const frame = await (await host.locator(`#${id} iframe`).elementHandle())?.contentFrame();
  if (!frame) throw new Error(`no frame in #${id}`);
  await frame.locator(drawn).first().waitFor({ timeout: 20_000 });
  return frame;
}

/** What the embedded page shows of its theme: the theme, its background, the marker this test left on its window. */
const look = (frame: Frame) =>
  frame.evaluate(() => ({
    theme: document.documentElement.dataset.theme,
    background: getComputedStyle(document.documentElement).backgroundColor,
    marker: (window as unknown as { marker?: string }).marker ?? null,
  }));
const LIGHT_BG = 'rgb(255, 255, 255)';
const DARK_BG = 'rgb(18, 22, 31)';
const PROFILE = '[data-testid="profile-view"] polygon.scallop';

describe('the theme of <path-interval-calculator>, changed without reloading the frame', () => {
  it('a new theme attribute (light, dark, auto) restyles the embedded page in place; another value loads the address', async () => {
    const host = await hostPage(
      'light',
      '<path-interval-calculator id="calc" view="profile" r="3" rcr="1" rho="5" h="0.05" theme="light"></path-interval-calculator>',
    );
    const element = host.locator('#calc');
    const iframe = host.locator('#calc iframe');
    const frame = await startedFrame(host, 'calc', PROFILE);
    const src = await iframe.getAttribute('src');
    expect(new URL(src ?? '').searchParams.get('theme')).toBe('light');
    await frame.evaluate(() => {
      (window as unknown as { marker: string }).marker = 'same document';
    });
    expect(await look(frame)).toEqual({ theme: 'light', background: LIGHT_BG, marker: 'same document' });

    await element.evaluate((e) => e.setAttribute('theme', 'dark'));
    await expect.poll(() => look(frame)).toEqual({ theme: 'dark', background: DARK_BG, marker: 'same document' });
    expect(await iframe.getAttribute('src')).toBe(src); // not reloaded
    // The drawing took the dark palette too (the profile's exact curve).
    const stroke = () =>
      frame
        .locator('.profile-svg .curve-exact')
        .first()
        .evaluate((e) => getComputedStyle(e).stroke);
    await expect.poll(stroke).toBe('rgb(243, 244, 246)');
    // The embedded page's own address keeps the theme in force.
    await expect.poll(() => frame.evaluate(() => new URL(location.href).searchParams.get('theme'))).toBe('dark');
    await keepShot(host, 'embed-theme-attribute-dark');
    expect(await axeViolations(frame), 'restyled dark').toEqual([]);

    // auto: the host page's scheme (light), then as it changes.
    await element.evaluate((e) => e.setAttribute('theme', 'auto'));
    await expect.poll(() => look(frame)).toEqual({ theme: 'light', background: LIGHT_BG, marker: 'same document' });
    await host.emulateMedia({ colorScheme: 'dark' });
    await expect.poll(() => look(frame)).toEqual({ theme: 'dark', background: DARK_BG, marker: 'same document' });
    expect(await iframe.getAttribute('src')).toBe(src);

    // A word the page does not take is no theme message: the address is loaded, and the page says so.
    await element.evaluate((e) => e.setAttribute('theme', 'purple'));
    await expect.poll(() => iframe.getAttribute('src')).toContain('theme=purple');
    const reloaded = await startedFrame(host, 'calc', PROFILE);
    await expect
      .poll(() => reloaded.getByTestId('notice').textContent())
      .toMatch(/theme="purple" is not light, dark or auto/);
    expect((await look(reloaded)).marker).toBeNull();
  });

  it('theme="auto" takes the host page\'s colour scheme and follows it as it changes, in place', async () => {
    const host = await hostPage(
      'dark',
      '<path-interval-calculator id="auto" view="profile" r="3" rcr="1" rho="5" h="0.05" theme="auto"></path-interval-calculator>',
    );
    const iframe = host.locator('#auto iframe');
    const frame = await startedFrame(host, 'auto', PROFILE);
    const src = await iframe.getAttribute('src');
    // The host's scheme, resolved by the element: the page is told dark (it does not follow its own).
    expect(new URL(src ?? '').searchParams.get('theme')).toBe('dark');
    await frame.evaluate(() => {
      (window as unknown as { marker: string }).marker = 'same document';
    });
    expect(await look(frame)).toEqual({ theme: 'dark', background: DARK_BG, marker: 'same document' });
    await keepShot(host, 'embed-theme-auto-dark');
    await host.emulateMedia({ colorScheme: 'light' });
    await expect.poll(() => look(frame)).toEqual({ theme: 'light', background: LIGHT_BG, marker: 'same document' });
    expect(await iframe.getAttribute('src')).toBe(src);
    await keepShot(host, 'embed-theme-auto-light');
    expect(await axeViolations(frame), 'restyled light').toEqual([]);
  });

  it("the embedded page takes a theme message only from its host's window and origin, with a theme word", async () => {
    const host = await hostPage(
      'light',
      '<path-interval-calculator id="calc" view="profile" r="3" rcr="1" rho="5" h="0.05" theme="light"></path-interval-calculator>',
    );
    const frame = await startedFrame(host, 'calc', PROFILE);
    const hostOrigin = new URL(hosts?.url ?? '').origin;
    expect(await frame.evaluate(() => location.ancestorOrigins[0])).toBe(hostOrigin);
    // From another origin (as the host's window), and from the host's origin but another window.
    const synthetic = (origin: string, fromParent: boolean) =>
      frame.evaluate(
        ({ origin, fromParent }) => {
          const data = { type: 'path-interval:theme', theme: 'dark' };
          const source = fromParent ? window.parent : window;
          window.dispatchEvent(new MessageEvent('message', { data, origin, source }));
          return document.documentElement.dataset.theme;
        },
        { origin, fromParent },
      );
    expect(await synthetic('http://evil.example', true)).toBe('light');
    expect(await synthetic(hostOrigin, false)).toBe('light');
    // The check is not blind: the same message from the host's window and origin is taken.
    expect(await synthetic(hostOrigin, true)).toBe('dark');
    expect(await synthetic(hostOrigin, false)).toBe('dark'); // (and stays)

    // Real messages from the host with data that is no theme word: ignored, in order, then a good one.
    await frame.evaluate(() => {
      const w = window as unknown as { seen: number };
      w.seen = 0;
      window.addEventListener('message', () => {
        w.seen += 1;
      });
    });
    const hostile: unknown[] = [
      'light',
      { type: 'path-interval:theme', theme: 'Light' },
      { type: 'path-interval:theme', theme: ['light'] },
      { type: 'path-interval:theme', theme: '<img src=x onerror="parent.__xss=1">' },
      { type: 'path-interval:resize', theme: 'light', height: 1e9 },
      { type: 'path-interval:theme', theme: { value: 'light' } },
      null,
    ];
    await host.locator('#calc iframe').evaluate((f, messages) => {
      for (const m of messages) (f as HTMLIFrameElement).contentWindow?.postMessage(m, '*');
    }, hostile);
    await expect.poll(() => frame.evaluate(() => (window as unknown as { seen: number }).seen)).toBe(hostile.length);
    expect((await look(frame)).theme).toBe('dark');
    expect(await frame.locator('img[src="x"]').count()).toBe(0);
    await host.locator('#calc iframe').evaluate((f) => {
      (f as HTMLIFrameElement).contentWindow?.postMessage({ type: 'path-interval:theme', theme: 'light' }, '*');
    });
    await expect.poll(async () => (await look(frame)).theme).toBe('light');
  });
});

describe('hostile attribute values of <path-interval-calculator>', () => {
  it('quotes, markup, javascript:, fragments, separators and huge numbers stay query values: no injection, no NaN', async () => {
    const values: Record<string, string> = {
      r: '3" onload="parent.__xss=1',
      rcr: 'javascript:parent.__xss=2//',
      rho: '<script>parent.__xss=3</script>',
      h: '1e999',
      tilt: '9'.repeat(400),
      'surface-radius': '-1e308',
      unit: 'mm&embed=0&src=javascript:parent.__xss=4//',
      view: 'profile#top',
      theme: '"><img src=x onerror="parent.__xss=5">',
      pattern: 'zigzag\n\u0000%00%22',
      l: '../../etc/passwd?x=1',
    };
    const host = await hostPage('light', '<p>Hostile attributes</p>');
    await host.evaluate((values) => {
      const el = document.createElement('path-interval-calculator');
      el.id = 'calc';
      el.setAttribute('title', '"><img src=x onerror="parent.__xss=6">');
      for (const [name, value] of Object.entries(values)) el.setAttribute(name, value);
      document.querySelector('main')?.append(el);
    }, values);
    const frame = await startedFrame(host, 'calc', '[data-testid="notice"]');
    const src = new URL((await host.locator('#calc iframe').getAttribute('src')) ?? '');
    // The calculator's own address, each value once under its parameter, exactly as given; embed=1 once; no fragment.
    expect(src.origin + src.pathname).toBe(new URL(site.url()).origin + new URL(site.url()).pathname);
    expect(src.hash).toBe('');
    expect(src.searchParams.getAll('embed')).toEqual(['1']);
    expect(src.searchParams.has('src')).toBe(false);
    const param = Object.fromEntries(EMBED_ATTRIBUTES);
    for (const [name, value] of Object.entries(values)) {
      expect(src.searchParams.getAll(param[name] as string), name).toEqual([value]);
    }
    expect([...src.searchParams.keys()].length).toBe(Object.keys(values).length + 1);
    // Nothing ran, nothing was injected into either page, the frame's name is the text as given.
    expect(await host.evaluate(() => (window as unknown as { __xss?: unknown }).__xss)).toBeUndefined();
    expect(await host.locator('img').count()).toBe(0);
    expect(await frame.locator('img[src="x"], script:not([src])').count()).toBe(0);
    expect(await host.locator('#calc iframe').getAttribute('title')).toBe('"><img src=x onerror="parent.__xss=6">');
    // The page names the values it could not take, and shows no NaN or Infinity.
    const notice = (await frame.getByTestId('notice').textContent()) ?? '';
    expect(notice).toMatch(/Rcr="javascript:parent\.__" in the link is not a number/);
    expect(notice).toMatch(/h="1e999" in the link is not a number/);
    const text = (await frame.locator('body').textContent()) ?? '';
    expect(text).not.toMatch(/NaN|Infinity|-0(?![.\d])/);
    await keepShot(host, 'embed-hostile-attributes', { fullPage: true });
  });
});

describe('<path-interval-calculator> below the fold: its height reserved, no jump', () => {
  /** The embeds, in order down an 860 px column, far below the fold: [id, attributes, what it draws]. */
  const EMBEDS = [
    ['e-profile', 'view="profile"', PROFILE],
    ['e-tables', 'view="tables"', '[data-testid="paper-table-half"] tr[data-condition]'],
    ['e-card', 'view="result"', '[data-testid="card-summary"]'],
    ['e-full', '', '[data-testid="scene-canvas"]'],
    ['e-sized', 'view="formulas" height="500"', '.formula'],
  ] as const;
  const TOOL = 'r="3" rcr="1" rho="5" h="0.05" unit="mm" theme="light"';

  it('loads each lazily when scrolled to, its height the same before and after; the full calculator in one column; the result card', async () => {
    const host = await hostPage('light', '<style>main { width: 860px; margin: 0 auto; }</style>');
    await host.waitForFunction(() => customElements.get('path-interval-calculator') !== undefined);
    // Every address a frame navigates to, from before the elements exist.
    const navigated: string[] = [];
    host.on('request', (r) => {
      if (r.isNavigationRequest() && r.frame() !== host.mainFrame()) navigated.push(r.url());
    });
    // The column: 4000 px of text before each element; each element counts its started pages.
    await host.evaluate(
      ({ embeds, tool }) => {
        const w = window as unknown as { started: Record<string, number> };
        w.started = {};
        const main = document.querySelector('main') as HTMLElement;
        for (const [id, attributes] of embeds) {
          main.insertAdjacentHTML(
            'beforeend',
            `<div style="height:4000px">Text of the host page.</div><path-interval-calculator id="${id}" ${attributes} ${tool}></path-interval-calculator>`,
          );
          document.getElementById(id)?.addEventListener('path-interval:resize', () => {
            w.started[id] = (w.started[id] ?? 0) + 1;
          });
        }
        main.insertAdjacentHTML('beforeend', '<div style="height:4000px">The end of the page.</div>');
      },
      { embeds: EMBEDS.map(([id, attributes]): [string, string] => [id, attributes]), tool: TOOL },
    );
    const loaded = async (id: string) =>
      navigated.includes((await host.locator(`#${id} iframe`).getAttribute('src')) ?? 'none');
    const started = (id: string) =>
      host.evaluate((i) => (window as unknown as { started: Record<string, number> }).started[i] ?? 0, id);
    const box = (id: string) =>
      host.locator(`#${id}`).evaluate((e) => {
        const r = e.getBoundingClientRect();
        return { top: Math.round(r.top), height: Math.round(r.height), width: Math.round(r.width) };
      });
    const before: Record<string, number> = {};
    for (const [id] of EMBEDS) {
      before[id] = (await box(id)).height;
    }
    expect(before['e-sized']).toBe(500);
    expect(await loaded('e-profile'), 'e-profile loaded before it was scrolled to').toBe(false);
    expect(Math.min(...Object.values(before))).toBeGreaterThanOrEqual(120);

    for (const [index, [id, , drawn]] of EMBEDS.entries()) {
      await host.locator(`#${id}`).evaluate((e) => e.scrollIntoView({ block: 'start' }));
      const top = (await box(id)).top;
      await expect.poll(() => started(id), { timeout: 20_000, message: id }).toBeGreaterThan(0);
      const frame = await (await host.locator(`#${id} iframe`).elementHandle())?.contentFrame();
      if (!frame) throw new Error(`no frame in #${id}`);
      await frame.locator(drawn).first().waitFor({ timeout: 20_000 });
      await animationFrames(host);
      // Loaded and drawn: the same height (within 3 px) and the same place on screen.
      const after = await box(id);
      expect(
        Math.abs(after.height - (before[id] as number)),
        `${id}: ${before[id]} -> ${after.height}`,
      ).toBeLessThanOrEqual(3);
      expect(Math.abs(after.top - top), `${id} moved`).toBeLessThanOrEqual(3);
      // Loaded once scrolled to; the embeds further down have not loaded (lazily: the next is 4000 px below).
      expect(await loaded(id), `${id} loaded`).toBe(true);
      const next = EMBEDS[index + 1];
      if (next) expect(await loaded(next[0]), `${next[0]} loaded early`).toBe(false);
      const inside = await frame.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth);
      expect(inside, `${id}: no sideways scrolling`).toBe(true);
      // The view's own height fits its content at 860 px (no scrolling inside); a given height
      // smaller than the content scrolls inside instead.
      const fits = await frame.evaluate(() => document.documentElement.scrollHeight <= window.innerHeight + 1);
      expect(fits, `${id}: content within its reserved height`).toBe(id !== 'e-sized');

      if (id === 'e-full') {
        // The whole calculator at 860 px: inputs, results and scene in one column, the scene >= 300 px tall.
        const parts = await frame.evaluate(() =>
          ['.controls', '.results', '.view', '[data-testid="scene-canvas"]'].map((s) => {
            const r = (document.querySelector(s) as HTMLElement).getBoundingClientRect();
            return {
              s,
              left: Math.round(r.left),
              top: Math.round(r.top),
              width: Math.round(r.width),
              height: Math.round(r.height),
            };
          }),
        );
        const [controls, results, view, canvas] = parts as [
          (typeof parts)[0],
          (typeof parts)[0],
          (typeof parts)[0],
          (typeof parts)[0],
        ];
        expect(results.top, 'results below the inputs').toBeGreaterThanOrEqual(controls.top + controls.height - 1);
        expect(view.top, 'scene below the results').toBeGreaterThanOrEqual(results.top + results.height - 1);
        for (const p of parts) expect(p.width, `${p.s} spans the column`).toBeGreaterThan(780);
        expect(canvas.height).toBeGreaterThanOrEqual(300);
        await host.locator('#e-full').evaluate((e) => e.scrollIntoView({ block: 'start' }));
        await keepShot(host, 'embed-full-860-top');
        await frame.locator('.view').evaluate((e) => e.scrollIntoView({ block: 'end' }));
        await keepShot(host, 'embed-full-860-scene');
      }
      if (id === 'e-card') {
        // The card: the inputs in a line, the answer, Copy; no inputs panel, no views, no scene loaded.
        expect(await frame.getByTestId('card-summary').textContent()).toBe(
          'R 3 mm, Rcr 1 mm, lead 5°, tilt 0°, one-way, plane, h 0.05 mm',
        );
        await expect.poll(() => frame.getByTestId('result-exact-interval').textContent()).toMatch(/^2\.887\d* mm$/);
        const copy = frame.locator('.headline .big button.copy');
        expect(await copy.isVisible()).toBe(true);
        await expect.poll(() => copy.isEnabled()).toBe(true);
        for (const hidden of ['.controls', '.teaching', '.view', '.procedures'])
          expect(await frame.locator(hidden).isVisible(), hidden).toBe(false);
        expect(await frame.locator('canvas').count()).toBe(0);
        expect(await frame.evaluate(() => document.documentElement.scrollHeight <= window.innerHeight)).toBe(true);
        expect(await frame.getByTestId('notice').isVisible()).toBe(false);
        await keepShot(host.locator('#e-card'), 'embed-result-card');
      }
    }
  }, 120_000);
});
