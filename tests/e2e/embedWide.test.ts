/**
 * A wide embed of the whole calculator (issue 28 point 9's leftover): from 1000 px wide its columns
 * stand side by side, so the element reserves that layout's height before its frame loads (not the
 * one column's 1280 px), and the page it loads then fits it: the frame's content no taller than the
 * reserve (nothing scrolls inside it) and the reserve within 8 % of the content (no band of empty
 * space under it). At 1280 and 1920 px; one host page, the element's width set.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { useSite } from './harness';

const site = useSite('docs/embed-wide', { scene: false });

/** The reserved height (the iframe's, CSS px) and the page's content height inside it, once it has loaded. */
async function reserveAndContent(host: Page): Promise<{ reserved: number; content: number }> {
  const iframe = host.locator('#calc iframe');
  const frame = await (await iframe.elementHandle())?.contentFrame();
  if (!frame) throw new Error('no frame');
  await frame.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
  const reserved = await iframe.evaluate((e) => e.getBoundingClientRect().height);
  // The frame's page laid out for its answer, in a frame too short for it: its content height (its
  // root fills the frame's height at least, so a frame as tall as the reserve would measure itself),
  // polled until it holds still; then the frame back to its reserve.
  await iframe.evaluate((e) => {
    (e as HTMLElement).style.height = '200px';
  });
  let last = -1;
  await expect
    .poll(async () => {
      const now = await frame.evaluate(() => document.documentElement.scrollHeight);
      const still = now === last;
      last = now;
      return still;
    })
    .toBe(true);
  await iframe.evaluate((e, h) => {
    (e as HTMLElement).style.height = `${h}px`;
  }, reserved);
  return { reserved, content: last };
}

describe('a wide embed of the whole calculator', () => {
  it('reserves its side-by-side layout height at 1280 and 1920 px, before and after the frame loads', async () => {
    const host = await site.browser().newPage({ viewport: { width: 1960, height: 1000 } });
    await host.goto(`${site.url()}embed.js`); // a page of the calculator's site; its content is replaced
    await host.setContent(`<script src="${site.url()}embed.js"></script>`);
    await host.waitForFunction(() => customElements.get('path-interval-calculator') !== undefined);
    for (const width of [1280, 1920]) {
      const before = await host.evaluate((w) => {
        document.querySelector('#calc')?.remove();
        const el = document.createElement('path-interval-calculator');
        el.id = 'calc';
        for (const [k, v] of Object.entries({ r: '3', rcr: '1', rho: '5', h: '0.05', unit: 'mm' }))
          el.setAttribute(k, v);
        el.style.width = `${w}px`;
        document.body.append(el);
        return (el.querySelector('iframe') as HTMLIFrameElement).getBoundingClientRect().height;
      }, width);
      const { reserved, content } = await reserveAndContent(host);
      console.log(
        `embed ${width} px wide: reserved ${before} px before the load, ${reserved} after; content ${content} px`,
      );
      expect(reserved, `${width}: kept`).toBe(before);
      expect(content, `${width}: the content fits the reserve`).toBeLessThanOrEqual(reserved);
      expect(reserved, `${width}: no empty band under the content`).toBeLessThanOrEqual(content * 1.08);
    }
    await host.close();
  });
});
