/**
 * Measurement aid (issue 27): with `E2E_COUNT_LOADS=<file>` set, counts the page loads a browser
 * test file makes (`goto` to a real address, `reload`, `newPage`) and appends one line per file to
 * <file>. Off (nothing patched) without the variable.
 */
import { appendFileSync } from 'node:fs';
import type { Browser } from 'playwright-core';
import { expect } from 'vitest';

const counts = { goto: 0, reload: 0, newPage: 0 };
let patched = false;

/** Patches Playwright's page and context classes once per worker process when asked to. */
export async function countLoads(browser: Browser): Promise<void> {
  if (!process.env.E2E_COUNT_LOADS || patched) return;
  patched = true;
  const context = await browser.newContext();
  const page = await context.newPage();
  const pageProto = Object.getPrototypeOf(page);
  const contextProto = Object.getPrototypeOf(context);
  await context.close();
  const goto = pageProto.goto;
  pageProto.goto = function (this: unknown, url: string, ...rest: unknown[]) {
    if (!url.startsWith('about:')) counts.goto++;
    return goto.call(this, url, ...rest);
  };
  const reload = pageProto.reload;
  pageProto.reload = function (this: unknown, ...rest: unknown[]) {
    counts.reload++;
    return reload.call(this, ...rest);
  };
  const newPage = contextProto.newPage;
  contextProto.newPage = function (this: unknown, ...rest: unknown[]) {
    counts.newPage++;
    return newPage.call(this, ...rest);
  };
}

/** Appends this file's counts (called after the file's tests). */
export function reportLoads(): void {
  const file = process.env.E2E_COUNT_LOADS;
  if (!file || !patched) return;
  const path = expect.getState().testPath ?? '?';
  appendFileSync(
    file,
    `${path.replace(/.*\/tests\//, 'tests/')} goto=${counts.goto} reload=${counts.reload} newPage=${counts.newPage}\n`,
  );
  // A worker runs several files in one process (isolate: false): the next file counts from zero.
  counts.goto = 0;
  counts.reload = 0;
  counts.newPage = 0;
}
