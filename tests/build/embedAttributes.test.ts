/**
 * The `<path-interval-calculator>` element takes every state the page's URL takes: each URL
 * parameter the page actually reads (recorded while the page's readers parse links, not listed
 * here) is one the element forwards from an attribute (PARAMS in public/embed.js, generated from
 * the field registry by src/build/embedAttributes.ts), but `embed`, which the element sets itself,
 * and `present`, the full page's projector layout.
 * A parameter added to the page's reading, or dropped from the generation, fails here.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { EMBED_SCRIPT } from '../../src/build/embedAttributes';
import { FIELDS, URL_PARAMS } from '../../src/core/input/fields';
import { chooseLang } from '../../src/ui/i18n/langChoice';
import { parseUrl } from '../../src/ui/state';
import { parseTheme } from '../../src/ui/themeChoice';

/** The attribute -> parameter table and the theme words of public/embed.js, as the script itself holds them. */
function embedScriptTables(): { params: Record<string, string>; themes: string[] } {
  const source = readFileSync(EMBED_SCRIPT, 'utf8');
  const params = /const PARAMS = (\{[^}]*\});/.exec(source)?.[1];
  const themes = /const THEMES = (\[[^\]]*\]);/.exec(source)?.[1];
  if (params === undefined || themes === undefined) throw new Error('embed.js has no PARAMS or THEMES');
  return {
    params: new Function(`return ${params};`)() as Record<string, string>,
    themes: new Function(`return ${themes};`)() as string[],
  };
}

/** The names the page's link readers ask a query string for while they parse `searches`. */
function paramsRead(searches: readonly string[]): Set<string> {
  const read = new Set<string>();
  for (const method of ['get', 'getAll', 'has'] as const) {
    const original = URLSearchParams.prototype[method] as (this: URLSearchParams, name: string) => unknown;
    vi.spyOn(URLSearchParams.prototype, method).mockImplementation(function (this: URLSearchParams, name: string) {
      read.add(name);
      return original.call(this, name);
    } as never);
  }
  for (const search of searches) {
    parseUrl(search);
    parseTheme(search);
    chooseLang(search, null, []);
  }
  return read;
}

afterEach(() => {
  vi.restoreAllMocks();
});

/** Links of every kind: none, five-axis and three-axis, forward and inverse, each surface. */
const LINKS = [
  '',
  '?R=3&Rcr=1&rho=5&h=0.05&unit=mm',
  '?D=6&Rcr=1&rho=5&tilt=3&pattern=zigzag&surfaceRadius=-40&surfaceAxis=cross&target=ra&ra=0.002&unit=in',
  '?R=3&Rcr=1&rho=5&mode=inverse&L=2&feedRadius=50&crossRadius=-80&view=chart&theme=dark&embed=1',
  '?R=3&Rcr=1&machine=3axis&slope=30&passes=waterline&mode=inverse&dz=0.2&feedRadius=40',
  '?R=3&Rcr=1&machine=3axis&slope=30&rasterAngle=20&mode=inverse&Lxy=0.5&theme=auto&lang=de',
];

describe('the embed element takes every URL parameter the page reads', () => {
  it("every parameter the page's readers ask for is an attribute's parameter of embed.js (but embed and present)", () => {
    const { params } = embedScriptTables();
    const forwarded = new Set(Object.values(params));
    const read = paramsRead(LINKS);
    // The recording saw the page read (not an empty pass).
    expect(read.size).toBeGreaterThan(10);
    // The parameters the field registry gives no attribute (`embed`, which the element sets, and
    // `present`, the full page's projector layout): the full page's only.
    const fullPageOnly = new Set<string>(
      Object.values(FIELDS).flatMap((s): string[] => (s.url !== null && s.embed === null ? [s.url] : [])),
    );
    expect(fullPageOnly.size).toBeGreaterThan(0);
    const notForwarded = [...read].filter((p) => !fullPageOnly.has(p) && !forwarded.has(p));
    expect(notForwarded).toEqual([]);
    // And the element forwards nothing the page does not read (each attribute reaches the page).
    expect([...forwarded].filter((p) => !read.has(p))).toEqual([]);
    expect([...read].sort()).toEqual([...URL_PARAMS].sort());
  });

  it("the theme attribute takes the page's theme words", () => {
    expect(embedScriptTables().themes).toEqual([...FIELDS.theme.values]);
  });

  it('the page reads its link only through those readers (parseUrl, parseTheme, chooseLang)', () => {
    const dir = new URL('../../src/ui/', import.meta.url);
    const files = readdirSync(dir, { recursive: true, encoding: 'utf8' }).filter((f) => f.endsWith('.ts'));
    const readers: string[] = [];
    for (const file of files) {
      const source = readFileSync(new URL(file, dir), 'utf8');
      for (const line of source.split('\n'))
        if (/location\.(search|href|hash)\b/.test(line) && !/replaceState/.test(line))
          readers.push(`${file}: ${line.trim()}`);
    }
    expect(readers).toEqual([
      // Read once, as the visit began; parseUrl, parseTheme, the link's language and chooseLang take it.
      'app.ts: const linkSearch = window.location.search;',
    ]);
  });
});
