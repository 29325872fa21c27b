import { availableParallelism } from 'node:os';
import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';
import { embedAttributesPlugin } from './src/build/embedAttributes.ts';
import { formulaMathmlPlugin } from './src/build/formulaMathml.ts';
import { preloadDeps } from './src/build/preloadDeps.ts';
import { publicScriptsPlugin } from './src/build/publicScripts.ts';
import { serviceWorkerPlugin } from './src/build/serviceWorker.ts';
import { shaderWhitespacePlugin } from './src/build/shaderWhitespace.ts';
import { sharedWorkerPlugin } from './src/build/sharedWorker.ts';
import { siteSources, siteSourcesPlugin } from './src/build/siteSources.ts';
import { staticClosure } from './src/build/staticGraph.ts';
import { threeTrimPlugin } from './src/build/threeTrim.ts';

/**
 * The installable web app: a small service worker (src/build/serviceWorker.ts, generated into sw.js
 * with the site's files and their revisions) precaches the whole site, so after the first visit the
 * calculator works offline; a deployed new version is fetched in the background and takes over on
 * the next load (nothing to click). src/main.ts registers it (not inside a cross-origin frame).
 * The instrumented e2e build leaves it out (tests there intercept worker scripts, which a service
 * worker would answer first); the offline test runs against the production build.
 */
const WEB_APP_MANIFEST = {
  name: 'Step-over of a filleted end mill',
  short_name: 'Step-over',
  description:
    'Exact path interval (step-over) of an inclined filleted (bull-nose) end mill for a chosen scallop height, beside the published approximations.',
  start_url: './',
  scope: './',
  display: 'standalone',
  theme_color: '#1d4ed8',
  background_color: '#ffffff',
  lang: 'en',
  icons: [
    { src: 'icon-192.png', sizes: '192x192', type: 'image/png' },
    { src: 'icon-512.png', sizes: '512x512', type: 'image/png' },
    { src: 'icon-maskable-512.png', sizes: '512x512', type: 'image/png', purpose: 'maskable' },
  ],
};

/**
 * The first result loads the page's entry and the solver worker, each with what it imports
 * statically (src/build/staticGraph.ts reads that from the sources: FIRST_RESULT); everything else
 * loads on first use, through dynamic imports (the doubly curved and three-axis solvers in the
 * worker, the teaching views, the shop sheet, the tool shelf, the lookup table, the 3D scene).
 * Two named chunks gather the later code: `three` (three.js and the 3D views' shared helpers, the
 * WebGL view, the orbit controller and the clipping planes, loaded after the first result), and
 * `later` (the core's and the worker's modules the first result does not need: loaded by whichever
 * first use comes first, then cached), since a few larger chunks compress better against the
 * 200 kB gzip budget than the many small shared chunks Rolldown would make; and `core`, the core
 * modules of the first result, one chunk that page and worker share (the core shipped once).
 */
const PRELOAD_DEPS = preloadDeps();
const SRC = fileURLToPath(new URL('./src/', import.meta.url));
/** The sources the site's build takes in place of Node's (src/build/siteSources.ts: the doubly curved model on first use). */
const SITE_SOURCES = siteSources(SRC);
const FIRST_RESULT = new Set([
  ...staticClosure(`${SRC}main.ts`, SRC, SITE_SOURCES).keys(),
  ...staticClosure(`${SRC}worker/solver.worker.ts`, SRC, SITE_SOURCES).keys(),
]);
const THREE_CHUNK = /\/node_modules\/three\/|\/src\/render\/(orbit|clipPlanes|view3d)\./;

/** The path under src/ of a module id (null outside src/). */
const fileOf = (id: string): string | null => (id.startsWith(SRC) ? id.slice(SRC.length) : null);

/** A core module or a worker's data builder that the first result does not load (the `later` chunk). */
function later(id: string): boolean {
  const file = fileOf(id);
  return file !== null && /^(core|worker\/data)\//.test(file) && !FIRST_RESULT.has(file);
}

/**
 * The worker's part of the first result (a plane's or a cylinder's answer: jobs/solve.ts, its data)
 * apart from its entry (the `solve` chunk), so that the later chunks, which import some of it,
 * never import the worker's own script, which must never run on the page.
 */
function firstJob(id: string): boolean {
  const file = fileOf(id);
  return file !== null && /^worker\/(jobs|data)\//.test(file) && FIRST_RESULT.has(file);
}

/**
 * A worker job that the first result does not load (the `jobs` chunk). Only the worker imports
 * these: the jobs chunk imports the worker's own script, which must never run on the page.
 */
function laterJobs(id: string): boolean {
  const file = fileOf(id);
  return file !== null && /^worker\/(jobs\/|simulate\.)/.test(file) && !FIRST_RESULT.has(file);
}

/** A core module (or the worker's protocol) that the first result loads: one `core` chunk for page and worker. */
function core(id: string): boolean {
  const file = fileOf(id);
  return file !== null && /^(core\/|worker\/(rpc|protocol|pageProtocol)\.)/.test(file) && FIRST_RESULT.has(file);
}

/** The page's parts loaded on first use but the views and the scene: the shop sheet, the tool shelf, the table's grid and download. */
function tools(id: string): boolean {
  return /\/src\/ui\/(shopSheet|shopSheetText|shopSheetWords|toolShelf|savedTools|tableRequest|lookupDownload)\.ts$/.test(
    id,
  );
}

/** Tests that drive headless Chromium or read the built sites (dist/, test-results/site-e2e/). */
const BROWSER_TESTS = [
  'tests/e2e/**/*.test.ts',
  'tests/build/sharedWorker.test.ts',
  'tests/build/jsBudget.test.ts',
  'tests/bench/web.test.ts',
];
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
        // three.js's shaders ship without comments and indentation (src/build/shaderWhitespace.ts), and
        // three.js without what the page cannot reach (src/build/threeTrim.ts: shaders of unused
        // materials and features, WebXR, shadow maps, environment maps, morph targets, render targets,
        // serialisation, raycasting, methods nothing names). The doubly curved model loads on first
        // use in the site (src/build/siteSources.ts).
        // public/embed.js's attributes must be the field registry's (src/build/embedAttributes.ts), and
        // it ships minified (src/build/publicScripts.ts).
        plugins: [
          siteSourcesPlugin(SITE_SOURCES),
          formulaMathmlPlugin(),
          sharedWorkerPlugin(),
          embedAttributesPlugin(),
          shaderWhitespacePlugin(),
          threeTrimPlugin({
            three: fileURLToPath(new URL('./node_modules/three/src/', import.meta.url)),
            parts: THREE_FROM_SOURCES[0]?.replacement ?? '',
            src: SRC,
          }),
          publicScriptsPlugin(),
          PRELOAD_DEPS.plugin,
          serviceWorkerPlugin({ manifest: WEB_APP_MANIFEST, disable: mode === 'e2e' }),
        ],
        // three.js is about 290 kB raw (77 kB gzip) in its chunk; the benchmark tracks the gzip
        // size against its 200 kB budget, so Rollup's generic 500 kB warning is raised.
        build: {
          // Vite 8's default minifier (Oxc) is kept: on this site it ships the fewest gzip bytes of those
          // tried (terser with 2 passes +0.7 kB and 48 s, with 3 passes and unsafe options +0.2 kB and
          // 92 s; esbuild +6.7 kB; Oxc with more iterations or a later target: no change), in 4 s.
          chunkSizeWarningLimit: 700,
          // Every browser the page supports has module preload; the polyfill would only add bytes.
          // The solver worker's dynamic imports preload nothing: a worker has no document to add
          // preload links to (Vite's helper then touches no DOM), and the worker loads its jobs itself.
          modulePreload: {
            polyfill: false,
            resolveDependencies: PRELOAD_DEPS.resolveDependencies,
          },
          rolldownOptions: {
            output: {
              codeSplitting: {
                groups: [
                  { name: 'three', test: THREE_CHUNK, includeDependenciesRecursively: false },
                  { name: 'core', test: core, includeDependenciesRecursively: false },
                  { name: 'solve', test: firstJob, includeDependenciesRecursively: false },
                  { name: 'later', test: later, includeDependenciesRecursively: false },
                  { name: 'jobs', test: laterJobs, includeDependenciesRecursively: false },
                  { name: 'tools', test: tools, includeDependenciesRecursively: false },
                ],
              },
            },
          },
        },
        test: {
          testTimeout: 30_000,
          hookTimeout: 60_000,
          environment: 'node',
          // Two projects: `node` (pure modules, the worker's API, the CLI in process; no site build,
          // files in parallel on every core) and `browser` (headless Chromium against the built sites,
          // which its global set-up builds once; two files at a time, each with its own Chromium).
          // `npm test` (tests/support/runTests.mjs) runs the two as two Vitest processes at once, the
          // Node one niced. `npx vitest run --project node` runs the Node tests alone.
          projects: [
            {
              extends: true,
              test: {
                name: 'node',
                include: ['tests/**/*.test.ts'],
                exclude: BROWSER_TESTS,
                globalSetup: ['tests/support/cliBundleSetup.ts'],
                // npm test runs these niced beside the browser tests on 2 cores, so a test gets a share of
                // a core: a timeout here only guards against a hang (speed is measured by the benches).
                testTimeout: 180_000,
                // Vitest's default leaves a core free (one worker on 2 cores).
                maxWorkers: availableParallelism(),
                // A worker runs file after file in one process, evaluating the modules they share
                // (src/core, the CLI, vitest's runner) once: a fresh process and module graph per
                // file cost about 0.25 s of CPU each, a third of the project's CPU on small files.
                // The tests leave nothing behind that another file reads: fake timers, stubbed
                // globals and registered throwaway surfaces are undone in afterEach, and vi.mock
                // stays with the file that declares it (Vitest keeps a mock registry per file).
                isolate: false,
              },
            },
            {
              extends: true,
              test: {
                name: 'browser',
                include: BROWSER_TESTS,
                exclude: SHOT_ONLY_TESTS,
                globalSetup: ['tests/e2e/globalSetup.ts'],
                // Two files at a time: a browser test mostly waits (debounces, replies, frames, polls);
                // one file at a time left the 2 cores two-thirds idle (8 CPU-minutes in a 12-minute run).
                maxWorkers: 2,
                // As the Node tests: a worker runs its files in one process (playwright-core, three.js
                // and the harness evaluated once, not per file; each file still starts its own
                // Chromium, tests/e2e/harness.ts): 6 small files 60.2 -> 54.4 CPU s.
                isolate: false,
                // A page under load answers late: every poll waits up to 15 s for its condition (not 1 s).
                expect: { poll: { timeout: 15_000 } },
              },
            },
          ],
        },
      },
);
