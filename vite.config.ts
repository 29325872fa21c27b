import { availableParallelism } from 'node:os';
import { fileURLToPath } from 'node:url';
import { VitePWA } from 'vite-plugin-pwa';
import { defineConfig } from 'vitest/config';
import { embedAttributesPlugin } from './src/build/embedAttributes.ts';
import { formulaMathmlPlugin } from './src/build/formulaMathml.ts';
import { shaderWhitespacePlugin } from './src/build/shaderWhitespace.ts';
import { sharedWorkerPlugin } from './src/build/sharedWorker.ts';

/**
 * The installable web app: a Workbox service worker (vite-plugin-pwa, generateSW) precaches the
 * whole site, so after the first visit the calculator works offline. `autoUpdate`: a deployed new
 * version is fetched in the background and takes over on the next load (nothing to click).
 * Registered by a separate file (registerSW.js), not an inline script, so the strict CSP holds.
 * The instrumented e2e build leaves it out (tests there intercept worker scripts, which a service
 * worker would answer first); the offline test runs against the production build.
 */
function pwa(mode: string) {
  return VitePWA({
    disable: mode === 'e2e',
    registerType: 'autoUpdate',
    injectRegister: 'script',
    includeAssets: ['embed.js', 'icon-192.png', 'icon-512.png', 'icon-maskable-512.png'],
    manifest: {
      name: 'Step-over of a filleted end mill',
      short_name: 'Step-over',
      description:
        'Exact path interval (step-over) of an inclined filleted (bull-nose) end mill for a chosen scallop height, beside the published approximations.',
      start_url: './',
      scope: './',
      display: 'standalone',
      theme_color: '#1d4ed8',
      background_color: '#ffffff',
      icons: [
        { src: 'icon-192.png', sizes: '192x192', type: 'image/png' },
        { src: 'icon-512.png', sizes: '512x512', type: 'image/png' },
        { src: 'icon-maskable-512.png', sizes: '512x512', type: 'image/png', purpose: 'maskable' },
      ],
    },
    workbox: {
      globPatterns: ['**/*.{js,css,html,png,svg,webmanifest}'],
      // Every address of the page (its state is in the query) opens the cached page offline.
      navigateFallback: 'index.html',
      cleanupOutdatedCaches: true,
      // A new version takes over at once, and the first visit's page is controlled (offline at once).
      skipWaiting: true,
      clientsClaim: true,
      maximumFileSizeToCacheInBytes: 4 * 1024 * 1024,
    },
  });
}

/**
 * Two named chunks: `three` (three.js and the two 3D views' shared helpers, the WebGL view, the
 * orbit controller and the clipping planes, loaded with the 3D views after the first result) and
 * `core` (the pure modules that the page, its views and the solver worker all load: one copy,
 * cached once). Fewer, larger chunks also compress better against the 200 kB gzip budget than the
 * small shared chunks Rollup would make. The core's modules that only one lazy view uses (the 3D
 * scene's marks, the profile's section) go with that view instead of delaying the first result.
 */
const VIEW_ONLY_CORE = /\/src\/core\/output\/(sceneMarks|sectionProfile)\./;

function chunkOf(id: string): string | null {
  if (id.includes('/node_modules/three/') || /\/src\/render\/(orbit|clipPlanes|view3d)/.test(id)) return 'three';
  if (VIEW_ONLY_CORE.test(id)) return null;
  if (/\/src\/(core\/|worker\/(rpc|protocol))/.test(id)) return 'core';
  return null;
}

/** Tests that drive headless Chromium or read the built sites (dist/, test-results/site-e2e/). */
const BROWSER_TESTS = ['tests/e2e/**/*.test.ts', 'tests/build/sharedWorker.test.ts', 'tests/bench/web.test.ts'];
/**
 * Browser tests that write screenshots for a person to look at (the scene gallery; its check of no
 * page errors sceneCamera.test.ts makes on the same postures, light and dark): run by `npm run shots`
 * (E2E_SHOTS=1, which also keeps the other tests' screenshots, tests/e2e/harness.ts keepShot), not
 * by `npm test`.
 */
const SHOT_ONLY_TESTS = process.env.E2E_SHOTS ? [] : ['tests/e2e/sceneGallery.test.ts'];

/**
 * `vite build --mode lib` (npm run build:lib): the solver core as a library, one ES module in
 * dist-lib/ (its types from tsconfig.lib.json beside it), the entry of package.json's `exports`.
 */
const LIBRARY = {
  publicDir: false as const,
  build: {
    outDir: 'dist-lib',
    emptyOutDir: true,
    lib: { entry: 'src/core/library.ts', formats: ['es' as const], fileName: () => 'path-interval.js' },
  },
};

/**
 * The site's build takes three.js from its sources, through src/render/threeParts.ts (the parts the
 * page uses): the bundled `three` keeps the animation system and the loaders alive through its
 * top-level prototype writes. The dev server and the tests keep the bundled module.
 */
const THREE_FROM_SOURCES = [
  { find: /^three$/, replacement: fileURLToPath(new URL('./src/render/threeParts.ts', import.meta.url)) },
];

export default defineConfig(({ mode, command }) =>
  mode === 'lib'
    ? LIBRARY
    : {
        // Relative base: the built site works from any host and any sub-path.
        base: './',
        resolve: command === 'build' ? { alias: THREE_FROM_SOURCES } : {},
        // The formulas view's MathML is typeset here, at build time, so no TeX engine is shipped.
        // three.js's shaders ship without comments and indentation (src/build/shaderWhitespace.ts).
        // public/embed.js's attributes must be the field registry's (src/build/embedAttributes.ts).
        plugins: [
          formulaMathmlPlugin(),
          sharedWorkerPlugin(),
          embedAttributesPlugin(),
          shaderWhitespacePlugin(),
          pwa(mode),
        ],
        // three.js alone is about 560 kB raw (130 kB gzip) in its chunk; the benchmark tracks the gzip
        // size against its 200 kB budget, so Rollup's generic 500 kB warning is raised.
        build: {
          chunkSizeWarningLimit: 700,
          // Every browser the page supports has module preload; the polyfill would only add bytes.
          modulePreload: { polyfill: false },
          rollupOptions: { output: { manualChunks: chunkOf } },
        },
        test: {
          testTimeout: 30_000,
          hookTimeout: 60_000,
          environment: 'node',
          // Two projects: `node` (pure modules, the worker's API, the CLI in process; no site build,
          // files in parallel on every core) and `browser` (headless Chromium against the built sites,
          // which its global set-up builds once; one file at a time, since a page and its workers
          // share 2 cores). Vitest runs a project of one file at a time after the others, so `npm test`
          // (tests/support/runTests.mjs) runs the two as two Vitest processes at once, the Node one
          // niced. `npx vitest run --project node` runs the Node tests alone.
          projects: [
            {
              extends: true,
              test: {
                name: 'node',
                include: ['tests/**/*.test.ts'],
                exclude: BROWSER_TESTS,
                globalSetup: ['tests/support/cliBundleSetup.ts'],
                // Vitest's default leaves a core free (one worker on 2 cores).
                maxWorkers: availableParallelism(),
              },
            },
            {
              extends: true,
              test: {
                name: 'browser',
                include: BROWSER_TESTS,
                exclude: SHOT_ONLY_TESTS,
                globalSetup: ['tests/e2e/globalSetup.ts'],
                fileParallelism: false,
                // A page under load answers late: every poll waits up to 15 s for its condition (not 1 s).
                expect: { poll: { timeout: 15_000 } },
              },
            },
          ],
        },
      },
);
