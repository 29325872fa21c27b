/**
 * Builds the static site twice for the browser tests: the production site (dist/, what ships)
 * and the instrumented one (mode `e2e`, test-results/site-e2e/), which adds the test probe
 * (src/ui/probe.ts) and nothing else.
 */
import { fileURLToPath } from 'node:url';
import { build } from 'vite';

export const E2E_OUT_DIR = 'test-results/site-e2e';

export default async function setup(): Promise<void> {
  const root = fileURLToPath(new URL('../..', import.meta.url));
  await build({ root, logLevel: 'warn' });
  await build({ root, logLevel: 'warn', mode: 'e2e', build: { outDir: E2E_OUT_DIR, emptyOutDir: true } });
}
