/**
 * Build step: the site's public scripts (public/embed.js, plain JavaScript kept readable in the
 * repository and served without a build in development) are written minified into the built site,
 * by the same minifier as the bundled chunks (Oxc), as classic scripts (not modules). embed.js
 * weighs about 4.4 kB gzip as written and under 2 kB minified (issue 27 point 2, the 200 kB of
 * JavaScript in all). Runs when the site is written, before the service worker's list of
 * revisions (serviceWorker.ts, at closeBundle) hashes the files.
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { minifySync, type Plugin } from 'vite';

/** The public scripts minified in the built site, by path in the site. */
export const PUBLIC_SCRIPTS = ['embed.js'] as const;

/** `code` (a classic script) minified; throws on a parse error (the build stops). */
export function minifyScript(fileName: string, code: string): string {
  const out = minifySync(fileName, code, { module: false });
  if (out.errors.length > 0) throw new Error(`${fileName}: ${out.errors.map((e) => e.message).join('; ')}`);
  return out.code;
}

/** Vite plugin: the built site's public scripts minified (builds only). */
export function publicScriptsPlugin(): Plugin {
  return {
    name: 'path-interval:public-scripts',
    apply: 'build',
    writeBundle(output) {
      for (const name of PUBLIC_SCRIPTS) {
        const file = join(output.dir ?? '', name);
        writeFileSync(file, minifyScript(name, readFileSync(file, 'utf8')));
      }
    },
  };
}
