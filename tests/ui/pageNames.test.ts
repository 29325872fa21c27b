/**
 * The page's own readers of the registry's names (DOM modules, so checked here under the page's
 * types): the theme takes each of its words from the link, and the "Copy embed code" element
 * carries every state of the link under the registry's attributes, which embed.js (generated from
 * the same registry, tests/fieldRegistry.test.ts) turns back into the same link.
 */
import { describe, expect, it } from 'vitest';
import { EMBED_ATTRIBUTES, FIELDS } from '../../src/core/input/fields';
import { embedCode } from '../../src/ui/embedCode';
import { parseUrl, toSearch } from '../../src/ui/state';
import { parseTheme } from '../../src/ui/themeChoice';

describe('theme', () => {
  it('takes each of the registry words under its parameter; another word gets a notice naming it', () => {
    const { url, values } = FIELDS.theme;
    for (const value of values)
      expect(parseTheme(`?${url}=${value}`)).toEqual({ override: value === 'auto' ? null : value, notice: null });
    expect(parseTheme(`?${url}=zzz`).notice).toMatch(new RegExp(`^${url}="zzz" is not light, dark or auto;`));
    expect(parseTheme('?').override).toBeNull();
  });
});

describe('the embed code', () => {
  it('writes every state of the link as the element attributes, which map back to the same link', () => {
    const searches = [
      '?D=12&Rcr=1&rho=5&tilt=-3&pattern=zigzag&surfaceRadius=-40&surfaceAxis=cross&target=ra&ra=0.002&unit=in',
      '?R=3&Rcr=1&rho=5&mode=inverse&L=2.5&unit=mm',
    ];
    const param = new Map(EMBED_ATTRIBUTES);
    for (const search of searches) {
      const state = parseUrl(search).state;
      const link = toSearch(state, { view: 'chart', theme: 'dark' });
      const code = embedCode('https://calc.example/', link);
      const element = /<path-interval-calculator ([^>]*)>/.exec(code)?.[1] ?? '';
      const attributes = [...element.matchAll(/([a-z-]+)="([^"]*)"/g)].map((m): [string, string] => [
        m[1] as string,
        m[2] as string,
      ]);
      // Every attribute is one of the element's; mapped back, they are the link itself.
      for (const [a] of attributes) expect(param.has(a), a).toBe(true);
      const back = new URLSearchParams(attributes.map(([a, v]): [string, string] => [param.get(a) as string, v]));
      expect(`?${back}`).toBe(link);
      expect(parseUrl(`?${back}`).state).toEqual(state);
    }
  });
});
