import { describe, expect, it } from 'vitest';
import { importClosure, jsSizes, staticImports } from '../../src/bench/chunks';

describe('the import graph of built chunks', () => {
  it('finds static imports and re-exports, not dynamic imports or other strings', () => {
    const code =
      'import{a as b,c}from"./core-1.js";import"./side-2.js";export{d}from"./more-3.js";' +
      'const s="./not-an-import.js";const p=()=>import("./lazy-4.js");x.from("./nope.js");';
    expect(staticImports(code)).toEqual(['core-1.js', 'side-2.js', 'more-3.js']);
    expect(staticImports("import {\n a } from './spaced-5.js';")).toEqual(['spaced-5.js']);
  });

  it('follows imports transitively, once each, only through known scripts', () => {
    const files: Record<string, string> = {
      'index.js': 'import{a}from"./core.js";const v=()=>import("./views.js");',
      'worker.js': 'import{a}from"./core.js";import{b}from"./geo.js";',
      'core.js': 'import"./index.js";export const a=1;',
      'geo.js': 'import{t}from"./missing.js";',
      'views.js': 'import{c}from"./three.js";',
      'three.js': '',
    };
    const names = Object.keys(files);
    const read = (n: string) => files[n] as string;
    expect([...importClosure(['index.js'], names, read)].sort()).toEqual(['core.js', 'index.js']);
    expect([...importClosure(['index.js', 'worker.js'], names, read)].sort()).toEqual([
      'core.js',
      'geo.js',
      'index.js',
      'worker.js',
    ]);
  });
});

describe('jsSizes: the JavaScript a built site ships', () => {
  // Each file's "gzip size" is its length here, so the sums can be read off.
  const site = new Map<string, Uint8Array>(
    Object.entries({
      'index.html': '',
      'registerSW.js': 'x'.repeat(1),
      'sw.js': 'x'.repeat(10),
      'embed.js': 'x'.repeat(100),
      'assets/index-1.js': 'import{a}from"./core-2.js";const v=()=>import("./views-4.js");',
      'assets/core-2.js': 'export const a=1;',
      'assets/solver.worker-3.js': 'import{a}from"./core-2.js";import{s}from"./solve-5.js";',
      'assets/solve-5.js': 'export const s=1;',
      'assets/views-4.js': 'import{t}from"./three-6.js";',
      'assets/three-6.js': 'x'.repeat(1000),
      'assets/index-1.css': 'x'.repeat(5000),
    }).map(([k, v]) => [k, new TextEncoder().encode(v)]),
  );
  const html =
    '<script type="module" crossorigin src="./assets/index-1.js"></script><script id="vite-plugin-pwa:register-sw" src="./registerSW.js"></script>';
  const sizes = jsSizes(site, html, (d) => d.length);

  it('counts every .js file of the site, the service worker and embed.js included, and no other file', () => {
    const js = [...site].filter(([p]) => p.endsWith('.js'));
    expect(sizes.files).toBe(9);
    expect(sizes.totalGzip).toBe(js.reduce((sum, [, d]) => sum + d.length, 0));
  });

  it("counts to the first result the page's scripts and the worker's, with their static imports, once each", () => {
    expect(sizes.firstResult).toEqual([
      'assets/core-2.js',
      'assets/index-1.js',
      'assets/solve-5.js',
      'assets/solver.worker-3.js',
      'registerSW.js',
    ]);
    const first = sizes.firstResult.reduce((sum, p) => sum + (site.get(p)?.length ?? 0), 0);
    expect(sizes.firstResultGzip).toBe(first);
  });
});
