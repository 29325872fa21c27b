/**
 * Web benchmark in headless Debian Chromium against the built site on loopback:
 *  - input event to updated results and the next rendered frame (median, target <= 16 ms),
 *  - cold load to first result (median, target <= 1 s),
 *  - JavaScript shipped, gzip (target <= 200 kB): to the first result, and in all.
 *
 * The sizes are those of the production build (dist/). The timings run on the instrumented build
 * (`vite build --mode e2e`): the same page plus the probe (src/ui/probe.ts) that reports when an
 * input's answer reached a frame; the production build carries no such hook.
 *
 *   npm run bench:web              readable table
 *   npm run bench:web -- --json    and a last line holding one JSON object
 */
import { readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { gzipSync } from 'node:zlib';
import { build } from 'vite';
import { launchChromium } from './browser';
import { serveStatic } from './staticServer';

interface Hooks {
  __pathInterval: { latencies(): number[]; firstResultMs(): number | null; frames(): number };
}

function median(values: number[]): number {
  const s = [...values].sort((a, b) => a - b);
  const mid = s.length >> 1;
  return s.length % 2 ? (s[mid] as number) : ((s[mid - 1] as number) + (s[mid] as number)) / 2;
}

const json = process.argv.includes('--json');
const quick = process.argv.includes('--quick');
const root = fileURLToPath(new URL('../..', import.meta.url));
await build({ root, logLevel: 'warn' });
const instrumented = 'test-results/site-bench';
await build({ root, logLevel: 'warn', mode: 'e2e', build: { outDir: instrumented, emptyOutDir: true } });

// Initial JS: the page's entry script (from index.html) and the solver worker. The teaching
// views' chunk (charts, maths typesetting) loads after the first result.
const assets = `${root}dist/assets`;
const indexHtml = readFileSync(`${root}dist/index.html`, 'utf8');
let gzipBytes = 0;
let rawBytes = 0;
let initialGzipBytes = 0;
for (const name of readdirSync(assets).filter((n) => n.endsWith('.js'))) {
  const data = readFileSync(`${assets}/${name}`);
  const gz = gzipSync(data, { level: 9 }).length;
  rawBytes += data.length;
  gzipBytes += gz;
  if (indexHtml.includes(name) || name.startsWith('solver.worker')) initialGzipBytes += gz;
}

const site = await serveStatic(`${root}${instrumented}`, 'bench/path-interval');
const browser = await launchChromium();
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
  await page.getByTestId('slider-h').focus();
  const moves = quick ? 5 : 40;
  // Warm-up moves (JIT, shader compilation) are not counted.
  for (let i = 0; i < 10; i++) {
    await page.keyboard.press(i % 2 ? 'ArrowLeft' : 'ArrowRight');
    await page.waitForTimeout(100);
  }
  const warm = await page.evaluate(() => (window as unknown as Hooks).__pathInterval.latencies().length);
  // One key press every 100 ms (a slider dragged slowly); each must reach a rendered frame.
  for (let i = 0; i < moves; i++) {
    await page.keyboard.press(i % 2 ? 'ArrowLeft' : 'ArrowRight');
    await page.waitForTimeout(100);
  }
  await page.waitForFunction((n) => (window as unknown as Hooks).__pathInterval.latencies().length >= n, warm + moves);
  const latencies = (await page.evaluate(() => (window as unknown as Hooks).__pathInterval.latencies())).slice(warm);

  const rows: Array<[string, string]> = [
    [
      'input -> results + next frame, median',
      `${median(latencies).toFixed(1)} ms (${latencies.length} moves, max ${Math.max(...latencies).toFixed(1)} ms)`,
    ],
    ['cold load -> first result, median', `${median(coldLoads).toFixed(0)} ms (${coldLoads.length} loads)`],
    ['JavaScript to first result (page + worker)', `${(initialGzipBytes / 1024).toFixed(1)} kB gzip`],
    [
      'JavaScript shipped in all (+ teaching views)',
      `${(gzipBytes / 1024).toFixed(1)} kB gzip, ${(rawBytes / 1024).toFixed(1)} kB raw`,
    ],
  ];
  console.log('Web benchmark: headless Chromium (SwiftShader WebGL), built site on loopback');
  for (const [k, v] of rows) console.log(`${k.padEnd(46)}${v}`);
  if (json) {
    console.log(
      JSON.stringify({
        inputToFrameMsMedian: Number(median(latencies).toFixed(2)),
        coldLoadMsMedian: Number(median(coldLoads).toFixed(1)),
        jsInitialGzipKb: Number((initialGzipBytes / 1024).toFixed(1)),
        jsGzipKb: Number((gzipBytes / 1024).toFixed(1)),
      }),
    );
  }
} finally {
  await browser.close();
  await site.close();
}
