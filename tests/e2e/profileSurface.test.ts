/**
 * The cross-feed profile is one drawing over the design surface (issue 18): a plane and the
 * cylinders are drawn by the same code, so what the plane's drawing did the curved ones now do too.
 * The height scale bar says the exaggeration drawn as soon as one is chosen (on a cylinder it said
 * the previous one until the next zoom), and a strong exaggeration grows the plot so the scallops
 * span it (on a cylinder the drawing shrank to a narrow strip). Its labels (issue 28 point 6) are at
 * least 12 px at every width (16 presenting), whole inside the plot, crossed by no curve and on no
 * other label, measured from the SVG's boxes; presenting at 1280 x 720 the legend is in view.
 */
import type { Page } from 'playwright-core';
import { describe, expect, it } from 'vitest';
import { keepShot, pageSettled, useSite, viewAs } from './harness';

const { open } = useSite('docs/profile-surface');

const SURFACES = [
  ['plane', ''],
  ['convex cylinder, axis along the feed', '&surfaceRadius=12&surfaceAxis=feed'],
  ['concave cylinder, axis along the feed', '&surfaceRadius=-40&surfaceAxis=feed'],
  ['concave cylinder, axis across the feed', '&surfaceRadius=-60&surfaceAxis=cross'],
] as const;

describe('the profile over any surface', () => {
  for (const [name, query] of SURFACES) {
    it(`${name}: the height scale bar follows the chosen exaggeration; x100 fills the plot`, async () => {
      const { page, errors } = await open(`?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=profile${query}`, {
        width: 1440,
        height: 900,
      });
      const view = page.getByTestId('profile-view');
      await view.locator('polyline.curve-exact').first().waitFor({ state: 'attached' });
      await view.scrollIntoViewIfNeeded();
      const bar = page.getByTestId('profile-scale-bar-z');
      for (const k of ['20', '5']) {
        await page.getByTestId('profile-exaggeration').selectOption(k);
        await expect.poll(() => page.getByTestId('profile-scale').textContent()).toMatch(new RegExp(`x${k}\\b`));
        expect(await bar.textContent()).toMatch(new RegExp(`\\(drawn x${k}\\)$`));
      }
      await page.getByTestId('profile-exaggeration').selectOption('100');
      await expect.poll(() => bar.textContent()).toMatch(/\(drawn x100\)$/);
      const plot = await view.locator('svg.profile-svg').boundingBox();
      const scallop = await page.getByTestId('profile-scallop').boundingBox();
      if (!plot || !scallop) throw new Error('no profile');
      await keepShot(view, `profile-surface-x100-${name.replaceAll(/[ ,]+/g, '-')}`);
      // A third of the width at least: on a convex cylinder the exaggerated heights, drawn radially,
      // fan out over the passes (a plane's reach half of it, teachScene.test.ts).
      expect(scallop.width / plot.width, 'the scallops span the plot').toBeGreaterThan(0.3);
      expect(scallop.height / plot.height, 'the scallops are tall enough to read').toBeGreaterThan(0.2);
      expect(errors).toEqual([]);
    });
  }
});

/**
 * Every label of the profile as drawn now (issue 28 point 6), from the SVG's own boxes on screen: a
 * problem when its text is under `minPx` CSS px, not wholly inside the plot, crossed by a curve (a
 * pass's profile, an approximation's, the ring ellipse, the h line, the surface, the scallops'
 * outline) or on top of another label. Also the number of labels and the smallest text seen.
 */
async function labelProblems(
  page: Page,
  minPx: number,
): Promise<{ labels: number; smallestPx: number; problems: string[] }> {
  return page.getByTestId('profile-view').evaluate((view, least) => {
    const plot = view.querySelector('svg.profile-svg') as SVGSVGElement;
    const frame = plot.getBoundingClientRect();
    const inside = { left: frame.left + plot.clientLeft, top: frame.top + plot.clientTop };
    const bounds = { ...inside, right: inside.left + plot.clientWidth, bottom: inside.top + plot.clientHeight };
    const problems: string[] = [];
    // Each curve as segments on screen.
    const segments: Array<[number, number, number, number, string]> = [];
    for (const line of plot.querySelectorAll<SVGPolylineElement | SVGPolygonElement>(
      'polyline.curve, polyline.ring, polyline.hplane, polyline.ground, polygon.scallop',
    )) {
      const m = line.getScreenCTM();
      if (m === null) continue;
      const pts = [...line.points].map((p) => [m.a * p.x + m.c * p.y + m.e, m.b * p.x + m.d * p.y + m.f] as const);
      if (line.tagName === 'polygon' && pts.length > 0) pts.push(pts[0] as (typeof pts)[number]);
      for (let i = 1; i < pts.length; i++) {
        const [a, b] = [pts[i - 1], pts[i]] as [readonly [number, number], readonly [number, number]];
        segments.push([a[0], a[1], b[0], b[1], line.getAttribute('class') ?? '']);
      }
    }
    /** True when the segment meets the rectangle (Liang-Barsky clipping). */
    const meets = (s: (typeof segments)[number], r: DOMRect): boolean => {
      const [x1, y1, x2, y2] = s;
      let t0 = 0;
      let t1 = 1;
      const dx = x2 - x1;
      const dy = y2 - y1;
      for (const [p, q] of [
        [-dx, x1 - r.left],
        [dx, r.right - x1],
        [-dy, y1 - r.top],
        [dy, r.bottom - y1],
      ] as const) {
        if (p === 0) {
          if (q < 0) return false;
        } else {
          const t = q / p;
          if (p < 0) t0 = Math.max(t0, t);
          else t1 = Math.min(t1, t);
        }
      }
      return t0 <= t1;
    };
    const texts = [...plot.querySelectorAll<SVGTextElement>('text')].filter((t) => (t.textContent ?? '') !== '');
    const boxes: DOMRect[] = [];
    let smallestPx = Number.POSITIVE_INFINITY;
    for (const t of texts) {
      const label = `"${t.textContent}"`;
      const m = t.getScreenCTM();
      const px = Number(t.getAttribute('font-size')) * Math.abs(m?.d ?? 0);
      smallestPx = Math.min(smallestPx, px);
      if (!(px >= least - 0.01)) problems.push(`${label}: ${px.toFixed(1)} px`);
      const r = t.getBoundingClientRect();
      if (
        r.left < bounds.left - 0.5 ||
        r.right > bounds.right + 0.5 ||
        r.top < bounds.top - 0.5 ||
        r.bottom > bounds.bottom + 0.5
      )
        problems.push(
          `${label}: cut (${r.left.toFixed(0)}..${r.right.toFixed(0)} x ${r.top.toFixed(0)}..${r.bottom.toFixed(0)} in ${bounds.left.toFixed(0)}..${bounds.right.toFixed(0)} x ${bounds.top.toFixed(0)}..${bounds.bottom.toFixed(0)})`,
        );
      // The text's own box, a pixel in from its edges (a glyph's box touches its neighbours').
      const core = new DOMRect(r.left + 1, r.top + 1, r.width - 2, r.height - 2);
      const crossing = segments.find((s) => meets(s, core));
      if (crossing) problems.push(`${label}: crossed by ${crossing[4]}`);
      for (const other of boxes)
        if (core.left < other.right && other.left < core.right && core.top < other.bottom && other.top < core.bottom)
          problems.push(`${label}: on another label`);
      boxes.push(core);
    }
    return { labels: texts.length, smallestPx, problems };
  }, minPx);
}

describe("the profile's labels (issue 28 point 6)", () => {
  it('at least 12 px from 336 to 1920 wide and 16 px presenting at 1280 x 720, whole, never crossed; the legend in view', async () => {
    const { page, errors } = await open('?R=3&Rcr=1&rho=5&h=0.05&unit=mm&view=profile', { width: 336, height: 800 });
    const view = page.getByTestId('profile-view');
    await view.locator('polyline.curve-exact').first().waitFor({ state: 'attached' });
    for (const width of [336, 360, 390, 820, 1280, 1920]) {
      await viewAs(page, { width, height: 900 });
      await view.scrollIntoViewIfNeeded();
      const { labels, smallestPx, problems } = await labelProblems(page, 12);
      // h, L/2, L and the two scale bars'.
      expect(labels, `${width}`).toBe(5);
      expect(problems, `${width} px wide`).toEqual([]);
      expect(smallestPx).toBeGreaterThanOrEqual(12);
      if (width === 336 || width === 1280) await keepShot(view, `profile-labels-${width}`);
    }
    // Presenting on a 1280 x 720 projector (the button, as a presenter does).
    await viewAs(page, { width: 1280, height: 720 });
    await page.getByTestId('present-toggle').click();
    await expect.poll(() => page.evaluate(() => document.documentElement.classList.contains('present'))).toBe(true);
    await pageSettled(page);
    await expect.poll(async () => (await labelProblems(page, 16)).problems).toEqual([]);
    expect(await legendCut(page)).toEqual([]);
    await keepShot(page, 'profile-present-1280x720-plane');
    expect(errors).toEqual([]);
  }, 90_000);

  it('presenting a tilted pass on a convex cylinder at 1280 x 720: "L = ... (arc)", h, wR, wL and O whole and uncrossed; the legend in view', async () => {
    const { page, errors } = await open(
      '?R=3&Rcr=1&rho=5&tilt=10&h=0.05&unit=mm&surfaceRadius=12&surfaceAxis=feed&view=profile&present=1',
      { width: 1280, height: 720 },
    );
    const view = page.getByTestId('profile-view');
    await view.locator('polyline.curve-exact').first().waitFor({ state: 'attached' });
    await pageSettled(page);
    const { labels, problems } = await labelProblems(page, 16);
    // h, h', wR, wL, L (arc), O and the two scale bars'.
    expect(labels).toBe(8);
    expect(problems).toEqual([]);
    expect(await view.locator('text', { hasText: /^L = .* \(arc\)$/ }).count()).toBe(1);
    expect(await legendCut(page)).toEqual([]);
    await keepShot(page, 'profile-present-1280x720-cylinder');
    expect(errors).toEqual([]);
  }, 90_000);
});

describe('a flat end lying flat (no scallop)', () => {
  it('draws the profile with finite points only and no console error (the envelope is +infinity at the very edge of the flat)', async () => {
    const { page, errors } = await open('?R=3&Rcr=0&rho=0&h=0.05&unit=mm&view=profile', { width: 1280, height: 800 });
    const polygon = page.getByTestId('profile-scallop');
    await polygon.waitFor({ state: 'attached' });
    await pageSettled(page);
    const points = (await polygon.getAttribute('points')) ?? '';
    expect(points.split(/[ ,]/).length).toBeGreaterThan(100);
    expect(
      points.split(/[ ,]/).every((v) => Number.isFinite(Number(v))),
      points.slice(0, 80),
    ).toBe(true);
    expect(errors).toEqual([]);
  });
});

/** The profile's legend items shown that are not wholly inside the teaching column's visible box (unscrolled). */
async function legendCut(page: Page): Promise<string[]> {
  return page.evaluate(() => {
    const column = document.querySelector('.teaching') as HTMLElement;
    column.scrollTop = 0;
    const c = column.getBoundingClientRect();
    const out: string[] = [];
    for (const item of document.querySelectorAll<HTMLElement>(
      '[data-testid="profile-view"] .view-legend .legend-item',
    )) {
      if (item.hidden || item.getClientRects().length === 0) continue;
      const r = item.getBoundingClientRect();
      if (r.top < c.top - 0.5 || r.bottom > c.bottom + 0.5 || r.left < c.left - 0.5 || r.right > c.right + 0.5)
        out.push(
          `${item.textContent}: ${r.top.toFixed(0)}..${r.bottom.toFixed(0)} in ${c.top.toFixed(0)}..${c.bottom.toFixed(0)}`,
        );
    }
    return out;
  });
}
