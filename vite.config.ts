import { defineConfig } from 'vitest/config';
import { formulaMathmlPlugin } from './src/build/formulaMathml.ts';

export default defineConfig({
  // Relative base: the built site works from any host and any sub-path.
  base: './',
  // The formulas view's MathML is typeset here, at build time, so no TeX engine is shipped.
  plugins: [formulaMathmlPlugin()],
  // three.js alone is about 600 kB raw (150 kB gzip) in the entry chunk; the benchmark tracks
  // the gzip size against its 200 kB budget, so Rollup's generic 500 kB warning is raised.
  build: { chunkSizeWarningLimit: 700 },
  test: {
    include: ['tests/**/*.test.ts'],
    environment: 'node',
    testTimeout: 30_000,
    hookTimeout: 60_000,
    globalSetup: ['tests/e2e/globalSetup.ts'],
    // Browser tests and benchmarks share one machine of 2 cores: run files one at a time.
    fileParallelism: false,
  },
});
