/**
 * The technical writer's embedding, driven as a documentation page would: light and dark (system
 * and `theme=`), the height posted to the host, the "Copy embed code" button, and every view
 * fitting its 480 px embed and the full page fitting phones and tablets (no sideways scrolling,
 * nothing cut off).
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { EMBED_ATTRIBUTES } from '../../src/core/input/fields';
import { pageSettled, SHOTS, useSite } from './harness';
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
    await page.screenshot({ path: `${SHOTS}/theme-dark-system-1400.png` });
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
    await dark.screenshot({ path: `${SHOTS}/theme-dark-embed-profile-480.png` });

    const light = (await site.open(`?${STATE}&theme=light`, { width: 1400, height: 900 }, 'dark')).page;
    await light.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    expect(await light.evaluate(() => document.documentElement.dataset.theme)).toBe('light');
    await expect.poll(() => sceneShows(light, SCENE_BG.light)).toBeGreaterThan(0.3);

    const bad = (await site.open(`?${STATE}&theme=purple`, { width: 1400, height: 900 }, 'dark')).page;
    await bad.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
    expect(await bad.getByTestId('notice').textContent()).toMatch(/theme="purple" is not light or dark/);
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
      if (m.type() === 'warning') warnings.push(m.text());
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
    await page.screenshot({ path: `${SHOTS}/copy-embed-confirmed.png` });
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
    for (const theme of ['light', 'dark'] as const) {
      const page = await site.browser().newPage({ viewport: { width: 480, height: 700 }, colorScheme: theme });
      for (const view of VIEWS) {
        await page.goto(`${site.url()}?${STATE}&view=${view}&embed=1`);
        await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
        await page.locator(`#panel-${view} > *`).first().waitFor();
        await pageSettled(page);
        const width = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
        expect(width[0], `${view}`).toBeLessThanOrEqual(width[1] as number);
        expect(await clippedElements(page), `${view} ${theme}`).toEqual([]);
        await page.screenshot({ path: `${SHOTS}/embed-${view}-480-${theme}.png`, fullPage: true });
      }
      await page.close();
    }
    // What was cut off before: the paper tables' Bedi column and the stepper's camera buttons.
    const page = await site.browser().newPage({ viewport: { width: 480, height: 700 } });
    await page.goto(`${site.url()}?${STATE}&view=tables&embed=1`);
    const bedi = page.locator('[data-testid="paper-half-0-bedi"]');
    await bedi.waitFor();
    const box = await bedi.boundingBox();
    expect((box?.x ?? 1e9) + (box?.width ?? 0)).toBeLessThanOrEqual(480);
    await page.goto(`${site.url()}?${STATE}&view=stepper&embed=1`);
    const top = page.locator('[data-camera="top"]');
    await top.waitFor();
    expect(await top.isVisible()).toBe(true);
    const topBox = await top.boundingBox();
    expect((topBox?.x ?? 1e9) + (topBox?.width ?? 0)).toBeLessThanOrEqual(480);
    await page.close();
  }, 120_000);

  it('the full page at 360, 390, 414 and 768 px: no horizontal scrolling in any view', async () => {
    for (const [width, height] of [
      [360, 780],
      [390, 844],
      [414, 896],
      [768, 1024],
    ] as const) {
      const page = await site.browser().newPage({ viewport: { width, height } });
      for (const view of VIEWS) {
        await page.goto(`${site.url()}?${STATE}&view=${view}`);
        await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
        await page.locator(`#panel-${view} > *`).first().waitFor();
        await pageSettled(page);
        const scroll = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
        expect(scroll[0], `${view} at ${width}`).toBeLessThanOrEqual(scroll[1] as number);
        expect(await clippedElements(page), `${view} at ${width}`).toEqual([]);
        if (view === 'profile' || view === 'tables')
          await page.screenshot({ path: `${SHOTS}/full-${view}-${width}.png`, fullPage: true });
      }
      await page.close();
    }
  }, 180_000);
});
