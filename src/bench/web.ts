/**
 * Web benchmark in headless Debian Chromium against the built site on loopback:
 *  - input event to updated results and the next rendered frame (median, target <= 16 ms), with
 *    the h slider dragged by the pointer, and beside it the same with arrow keys (see KEY_NOTE),
 *  - cold load to first result (median, target <= 1 s),
 *  - JavaScript shipped, gzip -9 (targets: <= 60 kB to the first result, <= 200 kB in all, every
 *    .js file the build emits).
 *
 * The sizes are those of the production build (dist/). The timings run on the instrumented build
 * (`vite build --mode e2e`): the same page plus the probe (src/ui/probe.ts) that reports when an
 * input's answer reached a frame; the production build carries no such hook.
 *
 *   npm run bench:web              readable table
 *   npm run bench:web -- --json    and a last line holding one JSON object
 *   ... -- --prebuilt DIR          no build: dist/ and the instrumented build in DIR as they are
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import type { Page } from 'playwright-core';
import { build } from 'vite';
import { launchChromium } from './browser';
import { jsSizes } from './chunks';
import { gzip9, siteFiles } from './siteFiles';
import { serveStatic } from './staticServer';

interface Hooks {
  __pathInterval: {
    latencies(): number[];
    pointerLatencies(): number[];
    firstResultMs(): number | null;
    frames(): number;
  };
}

function median(values: number[]): number {
  const s = [...values].sort((a, b) => a - b);
  const mid = s.length >> 1;
  return s.length % 2 ? (s[mid] as number) : ((s[mid - 1] as number) + (s[mid] as number)) / 2;
}

/** One step of an input gesture; each step must change the slider's value. */
type Step = (i: number) => Promise<void>;

/**
 * Latencies of `moves` inputs, one every 100 ms (a slider moved slowly), after 10 warm-up inputs
 * (JIT, shader compilation) that are not counted. The probe records, for each input event, the
 * time to the first frame that shows its answer.
 */
async function measure(
  page: Page,
  moves: number,
  gesture: { start(): Promise<void>; step: Step; end(): Promise<void> },
) {
  const probe = () => page.evaluate(() => (window as unknown as Hooks).__pathInterval.latencies().length);
  const pointerCount = () => page.evaluate(() => (window as unknown as Hooks).__pathInterval.pointerLatencies().length);
  // The input events the gesture caused, and the frames drawn: what to say when none reached a frame.
  const events = () =>
    page.evaluate(() => {
      const w = window as unknown as { __benchInputs?: number } & Hooks;
      if (w.__benchInputs === undefined) {
        w.__benchInputs = 0;
        window.addEventListener('input', () => (w.__benchInputs = (w.__benchInputs ?? 0) + 1), true);
      }
      return { inputs: w.__benchInputs, frames: w.__pathInterval.frames() };
    });
  const before = await events();
  await gesture.start();
  for (let i = 0; i < 10; i++) {
    await gesture.step(i);
    await page.waitForTimeout(100);
  }
  await page.waitForTimeout(300);
  const warm = await probe();
  const warmPointer = await pointerCount();
  for (let i = 0; i < moves; i++) {
    await gesture.step(10 + i);
    await page.waitForTimeout(100);
  }
  await gesture.end();
  // Each input normally gets its own frame; on a loaded machine two inputs can share one (the
  // browser coalesces them) and the probe then counts one. Wait for all, but at most 5 s.
  const deadline = Date.now() + 5000;
  while ((await probe()) < warm + moves && Date.now() < deadline) await page.waitForTimeout(100);
  const got = (await page.evaluate(() => (window as unknown as Hooks).__pathInterval.latencies())).slice(
    warm,
    warm + moves,
  );
  if (got.length === 0) {
    const after = await events();
    throw new Error(
      `no input reached a frame (${after.inputs - before.inputs} input events, ${after.frames - before.frames} frames drawn)`,
    );
  }
  const fromPointer = (await page.evaluate(() => (window as unknown as Hooks).__pathInterval.pointerLatencies())).slice(
    warmPointer,
    warmPointer + moves,
  );
  return { fromInput: got, fromPointer };
}

/** A pointer drag of the slider's thumb, 3 px per step, back and forth (continuous input, as a hand). */
function dragSlider(page: Page, testId: string) {
  let x0 = 0;
  let y = 0;
  return {
    async start() {
      const slider = page.getByTestId(testId);
      // The inputs' column is taller than a laptop's viewport (the slider may sit below the fold):
      // a mouse outside the viewport moves nothing, so scroll the slider in first.
      await slider.scrollIntoViewIfNeeded();
      const box = await slider.boundingBox();
      const viewport = page.viewportSize();
      if (box === null) throw new Error(`${testId} is not visible`);
      x0 = box.x + box.width * 0.3;
      y = box.y + box.height / 2;
      if (viewport !== null && (y < 0 || y > viewport.height || x0 + 30 > viewport.width))
        throw new Error(`${testId} at (${x0.toFixed(0)}, ${y.toFixed(0)}) px is outside the viewport`);
      await page.mouse.move(x0, y);
      await page.mouse.down();
    },
    async step(i: number) {
      const phase = i % 20;
      await page.mouse.move(x0 + 3 * (phase < 10 ? phase + 1 : 19 - phase), y);
    },
    async end() {
      await page.mouse.up();
    },
  };
}

/** Arrow keys on the focused slider, alternating (discrete input). */
function pressArrows(page: Page, testId: string) {
  return {
    async start() {
      await page.getByTestId(testId).focus();
    },
    async step(i: number) {
      await page.keyboard.press(i % 2 ? 'ArrowLeft' : 'ArrowRight');
    },
    async end() {},
  };
}

/**
 * Why arrow keys measure slower: after a discrete input (a key press), Chromium defers some of the
 * page's tasks, among them the worker's reply, until the next frame or about 50 ms
 * (DeferRendererTasksAfterInput); on a software rasteriser that frame is late. With the feature
 * disabled (--disable-features=DeferRendererTasksAfterInput) key presses measure like the drag.
 */
const KEY_NOTE =
  'note: arrow keys are discrete input; Chromium defers the worker reply after one until the next frame (up to ~50 ms).';

const json = process.argv.includes('--json');
const quick = process.argv.includes('--quick');
const root = fileURLToPath(new URL('../..', import.meta.url));
// `--prebuilt DIR`: dist/ and the instrumented build in DIR are already there (the browser tests'
// global set-up built both), so nothing is built again.
const prebuiltArg = process.argv.indexOf('--prebuilt');
const prebuilt = prebuiltArg >= 0 ? process.argv[prebuiltArg + 1] : undefined;
const instrumented = prebuilt ?? 'test-results/site-bench';
if (prebuilt === undefined) {
  await build({ root, logLevel: 'warn' });
  await build({ root, logLevel: 'warn', mode: 'e2e', build: { outDir: instrumented, emptyOutDir: true } });
}

// The JavaScript shipped (chunks.ts jsSizes): every .js file the build emits (the service worker and
// embed.js included), each gzip -9, summed; and the first result's: the page's scripts and the
// solver worker's, each with the chunks it imports statically (counted once). The 3D scene, three.js,
// the teaching views, the shop sheet, the tool shelf and the worker's later jobs load on first use.
const js = jsSizes(siteFiles(`${root}dist`), readFileSync(`${root}dist/index.html`, 'utf8'), gzip9);

const site = await serveStatic(`${root}${instrumented}`, 'bench/path-interval');
const browser = await launchChromium({ gpuCompositing: true });
try {
  const coldLoads: number[] = [];
  for (let i = 0; i < (quick ? 2 : 7); i++) {
    const context = await browser.newContext();
    const page = await context.newPage();
    await page.goto(`${site.url}?R=3&Rcr=1&rho=5&h=0.05&unit=mm`);
    await page.waitForFunction(() => (window as unknown as Hooks).__pathInterval?.firstResultMs() !== null);
    coldLoads.push(await page.evaluate(() => (window as unknown as Hooks).__pathInterval.firstResultMs() as number));
    await context.close();
  }

  const page = await browser.newPage({ viewport: { width: 1400, height: 900 } });
  await page.goto(`${site.url}?R=3&Rcr=1&rho=5&h=0.05&unit=mm`);
  await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor();
  await page.waitForFunction(() => (window as unknown as Hooks).__pathInterval.frames() > 0);
  const moves = quick ? 5 : 40;
  const drag = await measure(page, moves, dragSlider(page, 'slider-h'));
  const latencies = drag.fromInput;
  const keyLatencies = (await measure(page, moves, pressArrows(page, 'slider-h'))).fromInput;

  const rows: Array<[string, string]> = [
    [
      'input -> results + next frame, median',
      `${median(latencies).toFixed(1)} ms (slider dragged: ${latencies.length} moves, max ${Math.max(...latencies).toFixed(1)} ms)`,
    ],
    [
      '  from the pointer event time stamp, median',
      drag.fromPointer.length > 0 ? `${median(drag.fromPointer).toFixed(1)} ms (when the browser got the move)` : '-',
    ],
    [
      '  the same with arrow keys, median',
      `${median(keyLatencies).toFixed(1)} ms (${keyLatencies.length} presses; see note)`,
    ],
    ['cold load -> first result, median', `${median(coldLoads).toFixed(0)} ms (${coldLoads.length} loads)`],
    [
      'JavaScript to first result (page + worker)',
      `${(js.firstResultGzip / 1024).toFixed(1)} kB gzip (target <= 60; ${js.firstResult.length} files)`,
    ],
    [
      'JavaScript shipped in all (every .js file)',
      `${(js.totalGzip / 1024).toFixed(1)} kB gzip (target <= 200; ${js.files} files), ${(js.totalRaw / 1024).toFixed(1)} kB raw`,
    ],
  ];
  console.log('Web benchmark: headless Chromium (SwiftShader WebGL), built site on loopback');
  for (const [k, v] of rows) console.log(`${k.padEnd(46)}${v}`);
  console.log(KEY_NOTE);
  if (json) {
    console.log(
      JSON.stringify({
        inputToFrameMsMedian: Number(median(latencies).toFixed(2)),
        pointerToFrameMsMedian: drag.fromPointer.length > 0 ? Number(median(drag.fromPointer).toFixed(2)) : null,
        keyInputToFrameMsMedian: Number(median(keyLatencies).toFixed(2)),
        coldLoadMsMedian: Number(median(coldLoads).toFixed(1)),
        jsInitialGzipKb: Number((js.firstResultGzip / 1024).toFixed(1)),
        jsGzipKb: Number((js.totalGzip / 1024).toFixed(1)),
      }),
    );
  }
} finally {
  await browser.close();
  await site.close();
}
