/**
 * A minimal static server for the built site under a sub-path (as a docs host would serve
 * it), on loopback only. Anything outside the sub-path is 404, so absolute asset URLs fail.
 */
import { readFileSync, type Stats, statSync } from 'node:fs';
import { createServer, type Server } from 'node:http';
import { extname, join, normalize } from 'node:path';

const TYPES: Record<string, string> = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.json': 'application/json',
  '.webmanifest': 'application/manifest+json',
};

export interface StaticSite {
  readonly url: string;
  close(): Promise<void>;
}

/**
 * Serves `root` under `subPath` on loopback. `headers` are sent with every page and asset (for
 * example a Content-Security-Policy, as a documentation host would send it).
 */
export function serveStatic(
  root: string,
  subPath: string,
  headers: Readonly<Record<string, string>> = {},
): Promise<StaticSite> {
  return serveStaticMounts([{ root, subPath }], headers).then((site) => ({
    url: site.urls[0] as string,
    close: site.close,
  }));
}

/** A file's stats, or null when there is none (nothing thrown). */
function fileStats(file: string): Stats | null {
  return statSync(file, { throwIfNoEntry: false }) ?? null;
}

/**
 * Files served, kept in memory with the size and time of their last change: a page load asks for
 * the same dozens of assets again and again (the browser tests load hundreds of pages), and
 * reading each from disk with a stream cost the tests' own process more CPU than anything else it
 * did there. A file written again (a test's host page) is read again.
 */
const served = new Map<string, { readonly mtimeMs: number; readonly size: number; readonly bytes: Buffer }>();

function contents(file: string, stats: Stats): Buffer {
  const kept = served.get(file);
  if (kept && kept.mtimeMs === stats.mtimeMs && kept.size === stats.size) return kept.bytes;
  const bytes = readFileSync(file);
  served.set(file, { mtimeMs: stats.mtimeMs, size: stats.size, bytes });
  return bytes;
}

export interface StaticMounts {
  /** The URL of each mount, in the order given. */
  readonly urls: readonly string[];
  close(): Promise<void>;
}

/**
 * Serves several directories, each under its own sub-path, on one loopback origin (a
 * documentation site and the calculator it embeds, as one host would serve them).
 */
export function serveStaticMounts(
  mounts: ReadonlyArray<{ readonly root: string; readonly subPath: string }>,
  headers: Readonly<Record<string, string>> = {},
): Promise<StaticMounts> {
  const prefixes = mounts.map((m) => ({ root: m.root, prefix: `/${m.subPath.replace(/^\/|\/$/g, '')}/` }));
  const server: Server = createServer((req, res) => {
    const path = decodeURIComponent((req.url ?? '/').split('?')[0] ?? '/');
    const mount = prefixes.find((m) => path.startsWith(m.prefix));
    if (!mount) {
      res.writeHead(404).end('not found');
      return;
    }
    const rel = normalize(path.slice(mount.prefix.length) || 'index.html').replace(/^(\.\.[/\\])+/, '');
    let file = join(mount.root, rel);
    let stats = fileStats(file);
    if (stats?.isDirectory()) {
      file = join(file, 'index.html');
      stats = fileStats(file);
    }
    if (!stats?.isFile()) {
      res.writeHead(404).end('not found');
      return;
    }
    res.writeHead(200, { ...headers, 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' });
    res.end(contents(file, stats));
  });
  return new Promise((resolve) => {
    server.listen(0, '127.0.0.1', () => {
      const address = server.address();
      const port = typeof address === 'object' && address ? address.port : 0;
      resolve({
        urls: prefixes.map((m) => `http://127.0.0.1:${port}${m.prefix}`),
        close: () => new Promise<void>((done) => server.close(() => done())),
      });
    });
  });
}
