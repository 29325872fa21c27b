/**
 * The production build (dist/, built by the browser tests' global set-up) ships the core once:
 * the solver worker is a module chunk of the page's own build (src/build/sharedWorker.ts) that
 * imports the chunk of core code the page loads too, and nothing it loads touches the DOM.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { importClosure, staticImports } from '../../src/bench/chunks';

const DIST = fileURLToPath(new URL('../../dist', import.meta.url));

describe('the built solver worker', () => {
  const assets = `${DIST}/assets`;
  const scripts = readdirSync(assets).filter((n) => n.endsWith('.js'));
  const read = (name: string) => readFileSync(`${assets}/${name}`, 'utf8');
  const html = readFileSync(`${DIST}/index.html`, 'utf8');
  const entry = scripts.find((n) => html.includes(`<script type="module" crossorigin src="./assets/${n}"`));
  const worker = scripts.find((n) => n.startsWith('solver.worker-'));

  it('is one chunk that the page starts by its URL, and shares the core chunk with the page', () => {
    expect(entry).toBeDefined();
    expect(worker).toBeDefined();
    const page = importClosure([entry as string], scripts, read);
    const work = importClosure([worker as string], scripts, read);
    const shared = [...work].filter((n) => page.has(n));
    expect(shared.length).toBeGreaterThan(0);
    // The page's entry names the worker's file (the URL it starts it from).
    expect([...page].some((n) => read(n).includes(worker as string))).toBe(true);
    // A message of the core's validation, used by page and worker alike, is shipped once.
    const holders = scripts.filter((n) => read(n).includes('is missing: enter a number.'));
    expect(holders).toHaveLength(1);
    expect(page.has(holders[0] as string) && work.has(holders[0] as string)).toBe(true);
  });

  it('loads nothing that uses the DOM or three.js', () => {
    const work = importClosure([worker as string], scripts, read);
    for (const name of work) {
      const code = read(name);
      // Vite's preload helper wraps every dynamic import; it touches the DOM only to preload an
      // import's dependencies, and the worker's list none (vite.config.ts resolveDependencies).
      if (name.startsWith('preload-helper-')) continue;
      expect(code, name).not.toMatch(/\bdocument\.|\bwindow\.|WebGLRenderer/);
      for (const imported of staticImports(code)) expect(imported, name).not.toMatch(/^(three|index|panel|scene)-/);
    }
    expect(read(worker as string)).not.toMatch(/__vite__mapDeps/);
  });

  it("is imported by no chunk: its own script never runs on the page (the later chunks import its jobs' chunk)", () => {
    for (const name of scripts) expect(staticImports(read(name)), name).not.toContain(worker);
    expect(scripts.filter((n) => read(n).includes(`import("./${worker}")`))).toEqual([]);
  });
});
