/**
 * The import graph of a built site's scripts (Vite's output in dist/assets): which chunks a
 * script loads at once. Used by the web benchmark (the JavaScript a first result needs) and by
 * the build tests (the core shipped once). Pure: the caller reads the files.
 */

const STATIC_IMPORT = /(?:^|[;}\s])(?:import|export)[^"'`();]*?(?:from)?\s*["']\.\/([^"']+\.js)["']/g;

/**
 * The sibling chunks a minified ES module imports statically (`import{a}from"./x.js"`,
 * `import"./x.js"`, `export{b}from"./x.js"`), in order; dynamic `import("./x.js")` is not one.
 */
export function staticImports(code: string): string[] {
  return [...code.matchAll(STATIC_IMPORT)].map((m) => m[1] as string);
}

/** The scripts reached from `roots` through static imports, roots included (names in `known` only). */
export function importClosure(
  roots: readonly string[],
  known: readonly string[],
  read: (name: string) => string,
): Set<string> {
  const reached = new Set<string>();
  const visit = (name: string) => {
    if (reached.has(name) || !known.includes(name)) return;
    reached.add(name);
    for (const next of staticImports(read(name))) visit(next);
  };
  for (const root of roots) visit(root);
  return reached;
}

/** The JavaScript a built site ships, gzip -9 bytes (the budget of issue 27: 200 kB in all, 60 kB to the first result). */
export interface JsSizes {
  /** Every `.js` file of the site, each gzipped alone, summed. */
  readonly totalGzip: number;
  readonly totalRaw: number;
  /** The scripts the first result needs: the page's (index.html's scripts and what they import statically) and the solver worker's. */
  readonly firstResultGzip: number;
  /** Those scripts, by path in the site. */
  readonly firstResult: readonly string[];
  readonly files: number;
}

/**
 * The sizes of a built site's JavaScript. `files` holds every file of the site by its path
 * (`assets/index-x.js`, `sw.js`); `indexHtml` is its page. The first result's scripts are those
 * index.html loads (`src="./..."`), the worker's (`assets/solver.worker-*.js`), and every chunk
 * they import statically (importClosure); dynamic imports load later and count in the total only.
 */
export function jsSizes(
  files: ReadonlyMap<string, Uint8Array>,
  indexHtml: string,
  gzip: (data: Uint8Array) => number,
): JsSizes {
  const scripts = [...files.keys()].filter((p) => p.endsWith('.js'));
  const assets = scripts.filter((p) => p.startsWith('assets/')).map((p) => p.slice('assets/'.length));
  const text = (p: string) => new TextDecoder().decode(files.get(p));
  const loadedByPage = (p: string) => indexHtml.includes(`src="./${p}"`) || indexHtml.includes(`href="./${p}"`);
  const roots = assets.filter((n) => loadedByPage(`assets/${n}`) || n.startsWith('solver.worker-'));
  const first = new Set([...importClosure(roots, assets, (n) => text(`assets/${n}`))].map((n) => `assets/${n}`));
  for (const p of scripts) if (!p.startsWith('assets/') && loadedByPage(p)) first.add(p);
  let totalGzip = 0;
  let totalRaw = 0;
  let firstResultGzip = 0;
  for (const p of scripts) {
    const data = files.get(p) as Uint8Array;
    const gz = gzip(data);
    totalGzip += gz;
    totalRaw += data.length;
    if (first.has(p)) firstResultGzip += gz;
  }
  return { totalGzip, totalRaw, firstResultGzip, firstResult: [...first].sort(), files: scripts.length };
}
