/** Every file of a built site (dist/), by its path in the site, for jsSizes (chunks.ts). */
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import { gzipSync } from 'node:zlib';

/** The files under `dir`, recursively, by path relative to it (forward slashes). */
export function siteFiles(dir: string): Map<string, Uint8Array> {
  const out = new Map<string, Uint8Array>();
  const walk = (d: string) => {
    for (const e of readdirSync(d, { withFileTypes: true })) {
      const p = join(d, e.name);
      if (e.isDirectory()) walk(p);
      else out.set(relative(dir, p).split('\\').join('/'), readFileSync(p));
    }
  };
  walk(dir);
  return out;
}

/** gzip -9 size in bytes, as the budget counts. */
export const gzip9 = (data: Uint8Array): number => gzipSync(data, { level: 9 }).length;
