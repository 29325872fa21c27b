/**
 * The source files the site's build takes in place of others (issue 27 point 2): Node (the command
 * line, the library, the tests) loads every surface model at import, the site loads the doubly
 * curved point's on first use (src/core/surfaces/registry.ts), so that the first result does not
 * carry it. One map for the build (siteSourcesPlugin) and for the reading of the first result's
 * static imports (staticGraph.ts staticClosure), so the two agree.
 */
import { basename } from 'node:path';
import type { Plugin } from 'vite';

/** Each replaced source file (absolute) with the site's own, for the sources under `src` (ending in '/'). */
export function siteSources(src: string): ReadonlyMap<string, string> {
  return new Map([[`${src}core/surfaces/models/loadedAtOnce.ts`, `${src}core/surfaces/models/loadedOnFirstUse.ts`]]);
}

/** The build's side: an import that resolves to a replaced file resolves to its replacement (builds only). */
export function siteSourcesPlugin(replacements: ReadonlyMap<string, string>): Plugin {
  const names = new Set([...replacements.keys()].map((f) => basename(f).replace(/\.ts$/, '')));
  return {
    name: 'path-interval:site-sources',
    apply: 'build',
    enforce: 'pre',
    async resolveId(source, importer, options) {
      const last = source.slice(source.lastIndexOf('/') + 1).replace(/\.ts$/, '');
      if (importer === undefined || !names.has(last)) return null;
      const resolved = await this.resolve(source, importer, { ...options, skipSelf: true });
      return resolved === null ? null : (replacements.get(resolved.id) ?? null);
    },
  };
}
