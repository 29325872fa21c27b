/**
 * What a dynamic import preloads (Vite's build.modulePreload.resolveDependencies): the chunks the
 * imported module needs, less those its importer already imported statically (they are loaded
 * before the importer runs, so listing them in the importer only costs bytes in the first result),
 * and nothing in the solver worker or a chunk it runs (a worker has no document to add preload links
 * to, and Vite's helper touches it when there is a link to add: the registry's load of the doubly
 * curved model, in the core chunk that page and worker share, ran there from the worker's jobs).
 * The plugin records each chunk's static imports as the bundle is written, before Vite's own
 * preload step reads the resolver.
 */
import type { Plugin } from 'vite';

/** A chunk's static imports by file name, and the closure of a chunk's (itself included). */
function closure(start: string, imports: ReadonlyMap<string, readonly string[]>): Set<string> {
  const seen = new Set<string>([start]);
  const stack = [start];
  for (let file = stack.pop(); file !== undefined; file = stack.pop()) {
    for (const next of imports.get(file) ?? []) {
      if (!seen.has(next)) {
        seen.add(next);
        stack.push(next);
      }
    }
  }
  return seen;
}

/** The plugin and the resolver that reads what it recorded. */
export function preloadDeps(): {
  plugin: Plugin;
  resolveDependencies: (file: string, deps: string[], context: { hostId: string; hostType: 'html' | 'js' }) => string[];
} {
  const imports = new Map<string, readonly string[]>();
  return {
    plugin: {
      name: 'path-interval:preload-deps',
      apply: 'build',
      generateBundle: {
        order: 'pre',
        handler(_options, bundle) {
          imports.clear();
          for (const [fileName, item] of Object.entries(bundle))
            if (item.type === 'chunk') imports.set(fileName, item.imports);
        },
      },
    },
    resolveDependencies: (_file, deps, { hostId, hostType }) => {
      if (hostType !== 'js') return deps;
      const worker = [...imports.keys()].filter((f) => /solver\.worker/.test(f));
      if (/solver\.worker/.test(hostId) || worker.some((w) => closure(w, imports).has(hostId))) return [];
      const loaded = closure(hostId, imports);
      return deps.filter((dep) => !loaded.has(dep));
    },
  };
}
