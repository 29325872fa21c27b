import { defineConfig } from 'vitest/config';
import { formulaMathmlPlugin } from './src/build/formulaMathml';

export default defineConfig({
  // Relative base: the built site works from any host and any sub-path.
  base: './',
  // The formulas view's MathML is typeset here, at build time, so no TeX engine is shipped.
  plugins: [formulaMathmlPlugin()],
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
