/**
 * Serves the example documentation site (tests/docs-site/, built into test-results/docs-site) at
 * /docs/ and the calculator's production build (dist/) at /calculator/ on one loopback origin, as
 * tests/e2e/docsSite.test.ts does, until stopped with Ctrl+C. `npm run docs:example` builds both
 * first; see tests/docs-site/docs/building.md.
 */
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { serveStaticMounts } from '../../src/bench/staticServer';

const root = fileURLToPath(new URL('../..', import.meta.url));
const mounts = [
  { root: `${root}test-results/docs-site`, subPath: 'docs' },
  { root: `${root}dist`, subPath: 'calculator' },
];
for (const m of mounts)
  if (!existsSync(`${m.root}/index.html`)) {
    console.error(`${m.root}/index.html is missing: run npm run docs:example (it builds both sites first).`);
    process.exit(1);
  }
const server = await serveStaticMounts(mounts);
console.log(`Example documentation: ${server.urls[0]}index.html (the calculator: ${server.urls[1]}); Ctrl+C stops.`);
process.on('SIGINT', () => {
  void server.close().then(() => process.exit(0));
});
