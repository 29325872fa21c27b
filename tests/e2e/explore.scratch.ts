import { readFileSync } from 'node:fs';
import { launchChromium } from '../../src/bench/browser';
import { serveStatic } from '../../src/bench/staticServer';

const VIEWS = ['profile', 'chart', 'tables', 'stepper', 'formulas', 'surface'];
const axeSource = readFileSync('node_modules/axe-core/axe.min.js', 'utf8');
const site = await serveStatic('test-results/site-e2e', 'x');
const browser = await launchChromium();
const mode = process.argv[2] ?? 'width';
if (mode === 'width') {
  for (const [w, h, embed] of [
    [480, 600, true],
    [360, 800, false],
    [390, 844, false],
    [414, 900, false],
    [768, 1024, false],
  ] as const) {
    const page = await browser.newPage({ viewport: { width: w, height: h } });
    for (const view of [...VIEWS, '']) {
      await page.goto(
        `${site.url}?R=3&Rcr=1&rho=5&h=0.05&unit=mm${view ? `&view=${view}` : ''}${embed ? '&embed=1' : ''}`,
      );
      await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
      await page.waitForTimeout(1200);
      const r = (await page.evaluate(`(() => {
        const iw = innerWidth;
        function scrolled(e) { for (let a = e.parentElement; a && a !== document.body; a = a.parentElement) { const o = getComputedStyle(a).overflowX; if (o === 'auto' || o === 'scroll') return true; } return false; }
        const wide = [...document.querySelectorAll('body *')].filter((e) => { const b = e.getBoundingClientRect(); return (b.right > iw + 0.5 || b.left < -0.5) && b.width > 0 && b.height > 0 && !scrolled(e) && !(e.ownerSVGElement) && !e.closest('.sr-only') && getComputedStyle(e).visibility !== 'hidden'; }).slice(0, 6).map((e) => e.tagName + '.' + (e.getAttribute('class') || '').slice(0, 30) + '[' + (e.getAttribute('data-testid') || '') + '] r=' + Math.round(e.getBoundingClientRect().right));
        return { sw: document.documentElement.scrollWidth, iw, wide };
      })()`)) as { sw: number; iw: number; wide: string[] };
      console.log(w, embed ? 'embed' : 'full', view || '-', r.sw, r.iw, r.wide.join(' | '));
    }
    await page.close();
  }
} else {
  for (const theme of ['light', 'dark'])
    for (const embed of [false, true])
      for (const view of [...VIEWS, '']) {
        if (!embed && view === '') continue;
        const page = await browser.newPage({ viewport: { width: embed ? 480 : 1400, height: 900 } });
        await page.goto(
          `${site.url}?R=3&Rcr=1&rho=5&h=0.05&unit=mm&theme=${theme}${view ? `&view=${view}` : ''}${embed ? '&embed=1' : ''}`,
        );
        await page.getByTestId('result-exact-half').filter({ hasText: /\d/ }).waitFor({ state: 'attached' });
        await page.waitForTimeout(1500);
        await page.addScriptTag({ content: axeSource });
        const res = await page.evaluate(async () => {
          const r = await (
            window as unknown as {
              axe: {
                run: (
                  o?: unknown,
                ) => Promise<{
                  violations: Array<{ id: string; nodes: Array<{ target: string[]; failureSummary: string }> }>;
                }>;
              };
            }
          ).axe.run();
          return r.violations.map(
            (v) =>
              `${v.id}: ${v.nodes.length} ${v.nodes
                .slice(0, 3)
                .map((n) => n.target.join(' ') + ' ' + n.failureSummary.replace(/\n/g, ' ').slice(0, 160))
                .join(' || ')}`,
          );
        });
        console.log(theme, embed ? 'embed' : 'full', view || '-', res.length ? `\n  ${res.join('\n  ')}` : 'OK');
        await page.screenshot({ path: `/tmp/embed-explore/${theme}-${embed ? 'e' : 'f'}-${view || 'all'}.png` });
        await page.close();
      }
}
await browser.close();
await site.close();
