/**
 * The hand-written service worker's precache list (src/build/serviceWorker.ts): which of a built
 * site's files it lists, each with a revision that follows the file's bytes, and a cache name that
 * changes with any of them (so a new version installs a new cache and drops the old one).
 */
import { describe, expect, it } from 'vitest';
import { precacheList, serviceWorkerScript } from '../../src/build/serviceWorker';

const bytes = (text: string) => new TextEncoder().encode(text);
const SITE = new Map(
  Object.entries({
    'index.html': '<html>',
    'sw.js': 'old worker',
    'manifest.webmanifest': '{}',
    'embed.js': 'embed',
    'icon-192.png': 'png',
    'assets/index-1.js': 'a',
    'assets/index-1.js.map': '{}',
    'assets/index-2.css': 'b',
    'reference/scallop-reference.csv': 'rows',
    'reference/scallop-reference.json': '{}',
  }).map(([k, v]) => [k, bytes(v)]),
);

/** The cache name a script names (`const CACHE="..."`). */
const cacheOf = (script: string) => /const CACHE="([^"]+)"/.exec(script)?.[1];

describe('the service worker precache list', () => {
  it('lists the pages, scripts, styles, images and manifest, sorted: not itself, source maps or the reference data', () => {
    expect(precacheList(SITE).map(([path]) => path)).toEqual([
      'assets/index-1.js',
      'assets/index-2.css',
      'embed.js',
      'icon-192.png',
      'index.html',
      'manifest.webmanifest',
    ]);
  });

  it("gives each file a revision of its bytes: one file changed changes its revision and the cache's name only", () => {
    const before = precacheList(SITE);
    const after = precacheList(new Map([...SITE, ['embed.js', bytes('embed, new')]]));
    const changed = after.filter(([path, revision]) => before.find(([p]) => p === path)?.[1] !== revision);
    expect(changed.map(([path]) => path)).toEqual(['embed.js']);
    expect(before.every(([, revision]) => /^[0-9a-f]{16}$/.test(revision))).toBe(true);
    expect(cacheOf(serviceWorkerScript(after))).not.toBe(cacheOf(serviceWorkerScript(before)));
    expect(cacheOf(serviceWorkerScript(precacheList(SITE)))).toBe(cacheOf(serviceWorkerScript(before)));
  });

  it('writes a script that parses and names every listed file', () => {
    const script = serviceWorkerScript(precacheList(SITE));
    expect(() => new Function(script)).not.toThrow();
    for (const [path] of precacheList(SITE)) expect(script).toContain(JSON.stringify(path));
    expect(cacheOf(script)).toMatch(/^path-interval-[0-9a-f]{16}$/);
  });
});
