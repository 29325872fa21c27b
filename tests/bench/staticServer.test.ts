/**
 * The browser tests' static server (src/bench/staticServer.ts): the sub-path only, a folder's
 * index.html, 404 for the rest, the headers asked for, and a file written again served anew
 * (it keeps what it served in memory).
 */
import { mkdirSync, mkdtempSync, rmSync, utimesSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type StaticSite, serveStatic } from '../../src/bench/staticServer';

let dir = '';
let site: StaticSite | null = null;
beforeAll(async () => {
  dir = mkdtempSync(join(tmpdir(), 'static-server-'));
  mkdirSync(join(dir, 'sub'));
  writeFileSync(join(dir, 'index.html'), '<p>root</p>');
  writeFileSync(join(dir, 'sub', 'index.html'), '<p>sub</p>');
  writeFileSync(join(dir, 'a.js'), 'one');
  site = await serveStatic(dir, 'docs/site', { 'x-test': 'yes' });
});
afterAll(async () => {
  await site?.close();
  rmSync(dir, { recursive: true, force: true });
});

const get = async (path: string) => {
  if (site === null) throw new Error('not started');
  const r = await fetch(new URL(path, site.url));
  return {
    status: r.status,
    type: r.headers.get('content-type'),
    header: r.headers.get('x-test'),
    body: await r.text(),
  };
};

describe('serveStatic', () => {
  it('serves the sub-path: files with their type and the headers, folders by their index.html, 404 elsewhere', async () => {
    expect(await get('')).toEqual({
      status: 200,
      type: 'text/html; charset=utf-8',
      header: 'yes',
      body: '<p>root</p>',
    });
    expect((await get('sub/')).body).toBe('<p>sub</p>');
    expect(await get('a.js?x=1')).toMatchObject({ status: 200, type: 'text/javascript; charset=utf-8', body: 'one' });
    expect((await get('missing.js')).status).toBe(404);
    expect((await get('/a.js')).status).toBe(404); // outside the sub-path
    expect((await get('../../a.js')).status).toBe(404);
  });

  it('a file written again is served with its new contents, whatever its size', async () => {
    expect((await get('a.js')).body).toBe('one');
    writeFileSync(join(dir, 'a.js'), 'two');
    // Same size, a later change time (a file system may keep whole seconds).
    utimesSync(join(dir, 'a.js'), new Date(), new Date(Date.now() + 5000));
    expect((await get('a.js')).body).toBe('two');
    writeFileSync(join(dir, 'a.js'), 'three!');
    expect((await get('a.js')).body).toBe('three!');
  });
});
