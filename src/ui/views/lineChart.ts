/**
 * One SVG line chart: a plot frame with 1-2-5 grid and tick labels, one line per procedure
 * (broken where it has no value), a band along the top where a procedure has no answer, and the
 * dashed marker at the current angle. Every colour comes from the stylesheet through classes and
 * `data-procedure` (theme custom properties), so the chart follows the theme and prints crisply.
 */
import type { ProcedureKey } from '../../core/procedures/procedures';
import { localDecimal } from '../i18n/langChoice';
import { catalogue } from '../i18n/words';
import { extent, linearScale, linePath, logScale, type Scale, tickLabel } from './chartScale';
import { svg } from './common';

/**
 * One line: a value (or null) per x sample. Coloured by `key` as a procedure's (the default) or,
 * with `colourBy: 'series'`, as one of chart.css's series (`data-series`: step, other, floor...).
 */
export interface ChartLine {
  readonly key: ProcedureKey | string;
  readonly values: ReadonlyArray<number | null>;
  readonly colourBy?: 'procedure' | 'series';
}

/** Where one line has no answer along x (data units of x); coloured as its line. */
export interface ChartGapBand {
  readonly key: ProcedureKey | string;
  readonly colourBy?: 'procedure' | 'series';
  readonly from: number;
  readonly to: number;
  readonly reason: string;
}

export interface LineChartSpec {
  /** Drawing width in CSS pixels (the SVG scales to its box). */
  readonly widthPx: number;
  /** Height of the plot area alone, CSS pixels. */
  readonly plotHeightPx: number;
  readonly x: readonly number[];
  readonly logX: boolean;
  readonly lines: readonly ChartLine[];
  /** Factor from the lines' values to the y axis's unit (e.g. mm to inch). */
  readonly yFactor: number;
  readonly gaps: readonly ChartGapBand[];
  /** The current angle, dashed; not drawn when outside the charted range. */
  readonly markerX: number;
  /** A dot at the current point (x, y in the lines' units), or none. */
  readonly markerPoint?: { readonly x: number; readonly y: number } | null;
  readonly xLabel: string;
  readonly yLabel: string;
  /** Read by a screen reader in place of the picture. */
  readonly description: string;
}

const MARGIN = { left: 56, right: 12, top: 12, bottom: 40 } as const;
const GAP_BAND_PX = 4;

/** The x scale of a chart (log for the lead on request, else linear over the charted range exactly). */
function xScale(spec: LineChartSpec, left: number, right: number): Scale {
  const lo = spec.x[0] ?? 0;
  const hi = spec.x.at(-1) ?? 1;
  return spec.logX && lo > 0
    ? logScale(lo, hi, left, right)
    : linearScale(lo, hi, left, right, Math.max(3, Math.floor((right - left) / 70)), false);
}

/** Builds the chart's SVG element. */
export function lineChart(spec: LineChartSpec): SVGSVGElement {
  const width = Math.round(spec.widthPx);
  const height = spec.plotHeightPx + MARGIN.top + MARGIN.bottom;
  const left = MARGIN.left;
  const right = width - MARGIN.right;
  const top = MARGIN.top;
  const bottom = MARGIN.top + spec.plotHeightPx;
  const root = svg('svg', {
    class: 'chart-svg',
    viewBox: `0 0 ${width} ${height}`,
    role: 'img',
    'aria-label': spec.description,
  });
  const x = xScale(spec, left, right);
  const lines = spec.lines.map((l) => ({
    key: l.key,
    colourBy: l.colourBy,
    values: l.values.map((v) => (v === null ? null : v * spec.yFactor)),
  }));
  const range = extent(lines.map((l) => l.values));
  const y = linearScale(range.min, range.max, bottom, top, 6, true);
  // The ticks' numbers with the locale's decimal sign (every chart's: the views', the finish box's, the target Sa's).
  const tick = (t: number, scale: Scale) => localDecimal(tickLabel(t, scale), catalogue());
  root.append(svg('rect', { class: 'chart-frame', x: left, y: top, width: right - left, height: bottom - top }));
  for (const t of x.ticks) {
    const px = x.toPixel(t);
    root.append(
      svg('line', { class: 'chart-grid', x1: px, x2: px, y1: top, y2: bottom }),
      text('chart-tick', px, bottom + 14, 'middle', tick(t, x)),
    );
  }
  for (const t of y.ticks) {
    const py = y.toPixel(t);
    root.append(
      svg('line', { class: t === 0 ? 'chart-grid chart-zero' : 'chart-grid', x1: left, x2: right, y1: py, y2: py }),
      text('chart-tick', left - 4, py + 4, 'end', tick(t, y)),
    );
  }
  root.append(text('chart-axis-label', (left + right) / 2, bottom + 32, 'middle', spec.xLabel));
  const yLabel = text('chart-axis-label', 12, (top + bottom) / 2, 'middle', spec.yLabel);
  yLabel.setAttribute('transform', `rotate(-90 12 ${(top + bottom) / 2})`);
  root.append(yLabel);
  // Where a procedure has no answer: a band in its colour along the top, its reason as a tooltip.
  spec.gaps.forEach((g, i) => {
    const x1 = x.toPixel(g.from);
    const band = svg('rect', {
      class: 'chart-gap',
      [`data-${g.colourBy ?? 'procedure'}`]: g.key,
      x: x1,
      y: top + 1 + (i % 6) * GAP_BAND_PX,
      width: Math.max(2, x.toPixel(g.to) - x1),
      height: GAP_BAND_PX - 1,
    });
    band.append(svgTitle(g.reason));
    root.append(band);
  });
  for (const line of lines) {
    root.append(
      svg('path', {
        class: line.key === 'exact' ? 'chart-line chart-line-exact' : 'chart-line',
        [`data-${line.colourBy ?? 'procedure'}`]: line.key,
        d: linePath(spec.x, line.values, x.toPixel, y.toPixel),
      }),
    );
  }
  if (spec.markerX >= x.min && spec.markerX <= x.max) {
    const px = x.toPixel(spec.markerX);
    root.append(svg('line', { class: 'chart-marker', x1: px, x2: px, y1: top, y2: bottom }));
  }
  const p = spec.markerPoint;
  if (p && Number.isFinite(p.y) && p.x >= x.min && p.x <= x.max) {
    const py = y.toPixel(p.y * spec.yFactor);
    root.append(svg('circle', { class: 'chart-point', cx: x.toPixel(p.x).toFixed(1), cy: py.toFixed(1), r: 4 }));
  }
  return root;
}

function text(cls: string, x: number, y: number, anchor: 'start' | 'middle' | 'end', content: string): SVGTextElement {
  const t = svg('text', { class: cls, x: x.toFixed(1), y: y.toFixed(1), 'text-anchor': anchor });
  t.textContent = content;
  return t;
}

function svgTitle(content: string): SVGTitleElement {
  const t = svg('title');
  t.textContent = content;
  return t;
}
