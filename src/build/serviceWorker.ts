/**
 * Build step: the installable web app without Workbox. After the site is written, a small
 * hand-written service worker (sw.js, {@link serviceWorkerScript}) is generated with the list of
 * the site's files to precache and each file's revision (a hash of its bytes); the web app
 * manifest (manifest.webmanifest) is emitted and index.html links it. The page registers sw.js
 * itself (src/main.ts), never inside a cross-origin frame.
 *
 * What the worker does (as Workbox's generateSW with skipWaiting, clientsClaim,
 * cleanupOutdatedCaches and navigateFallback index.html did):
 *  - install: fetches every listed file past the HTTP cache into a cache named after the list's
 *    revisions, and takes over at once (a deployed new version is used on the next load);
 *  - activate: deletes the site's caches of earlier versions and controls the open pages;
 *  - fetch: a listed file is answered from the cache (any query ignored); the page's address with
 *    any query (its state) is answered with the cached index.html; everything else goes to the
 *    network untouched (the reference data files, other sites).
 */
import { createHash } from 'node:crypto';
import { writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import type { Plugin } from 'vite';
import { siteFiles } from '../bench/siteFiles.ts';

/** The files precached: the site's pages, scripts, styles, images and manifest (not the reference data). */
const PRECACHED = /\.(js|css|html|png|svg|webmanifest)$/;
/** The service worker's own file (never in its own list). */
export const SERVICE_WORKER_FILE = 'sw.js';
/** Prefix of the site's cache names: an activated worker deletes the others with it. */
const CACHE_PREFIX = 'path-interval-';

/** One precached file: its path in the site and the first 16 hex digits of its bytes' SHA-256. */
export type PrecacheEntry = readonly [path: string, revision: string];

/** The precache list of a built site: `files` by path in the site (forward slashes), sorted by path. */
export function precacheList(files: ReadonlyMap<string, Uint8Array>): PrecacheEntry[] {
  return [...files]
    .filter(([path]) => PRECACHED.test(path) && path !== SERVICE_WORKER_FILE)
    .map(([path, bytes]): PrecacheEntry => [path, createHash('sha256').update(bytes).digest('hex').slice(0, 16)])
    .sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0));
}

/**
 * The service worker's script for a precache list. Its cache is named after a hash of the whole
 * list (paths and revisions), so that a change to any file installs a new cache and the next
 * activation drops the old one.
 */
export function serviceWorkerScript(list: readonly PrecacheEntry[]): string {
  const version = createHash('sha256').update(JSON.stringify(list)).digest('hex').slice(0, 16);
  return `const FILES=${JSON.stringify(list.map(([path]) => path))};
const CACHE=${JSON.stringify(CACHE_PREFIX + version)};
const at=(p)=>new URL(p,self.registration.scope).href;
const PAGE=at("index.html");
self.addEventListener("install",(e)=>{self.skipWaiting();e.waitUntil(caches.open(CACHE).then((c)=>Promise.all(FILES.map((p)=>fetch(at(p),{cache:"reload"}).then((r)=>{if(!r.ok)throw new Error(p+": "+r.status);return c.put(at(p),r)})))))});
self.addEventListener("activate",(e)=>{e.waitUntil(caches.keys().then((keys)=>Promise.all(keys.filter((k)=>k.startsWith(${JSON.stringify(CACHE_PREFIX)})&&k!==CACHE).map((k)=>caches.delete(k)))).then(()=>self.clients.claim()))});
self.addEventListener("fetch",(e)=>{const r=e.request;if(r.method!=="GET")return;const u=new URL(r.url);u.search="";u.hash="";let key=u.href;if(r.mode==="navigate"&&(key===self.registration.scope||key===PAGE))key=PAGE;else if(!FILES.some((p)=>at(p)===key))return;e.respondWith(caches.open(CACHE).then((c)=>c.match(key)).then((hit)=>hit||fetch(r)))});
`;
}

/**
 * Vite plugin: emits `manifest.webmanifest` (the given manifest), links it from index.html, and once
 * the site is written generates sw.js over it ({@link precacheList}, {@link serviceWorkerScript}).
 * `disable` (the instrumented e2e build) leaves all three out.
 */
export function serviceWorkerPlugin(options: { manifest: object; disable: boolean }): Plugin {
  let outDir = '';
  return {
    name: 'service-worker',
    apply: 'build',
    configResolved(config) {
      outDir = resolve(config.root, config.build.outDir);
    },
    transformIndexHtml() {
      if (options.disable) return [];
      return [{ tag: 'link', attrs: { rel: 'manifest', href: './manifest.webmanifest' }, injectTo: 'head' }];
    },
    generateBundle() {
      if (options.disable) return;
      this.emitFile({ type: 'asset', fileName: 'manifest.webmanifest', source: JSON.stringify(options.manifest) });
    },
    closeBundle() {
      if (options.disable) return;
      writeFileSync(join(outDir, SERVICE_WORKER_FILE), serviceWorkerScript(precacheList(siteFiles(outDir))));
    },
  };
}
