/**
 * The charts of L against each principal radius at a doubly curved point (issue 19), drawn from
 * the worker's data (worker/data/radiusSweep.ts): L against |Rf| (Rc held) and against |Rc| (Rf
 * held) on a log axis, the convex and the concave branch, L with that radius straight dotted, the
 * current point marked; where the tool gouges or h reaches the flank limit there is no L, and a
 * band and a note say over which radii and why.
 */
import { fromMm, unitSymbol } from '../../core/input/units';
import type { RadiusSweepData } from '../../worker/teachProtocol';
import { formatLenUnit } from '../format';
import type { Unit } from '../state';
import { html } from './common';
import { type ChartGapBand, lineChart } from './lineChart';
import { radiusNames as names, radiusGapNotes, radiusWords } from './pageChartText';

const PLOT_HEIGHT_PX = 240;

/** The value at the current |radius| on a branch, or null. */
function valueAt(s: RadiusSweepData, branch: 'convex' | 'concave'): number | null {
  const i = s.radiusMm.indexOf(Math.abs(s.currentMm));
  return i < 0 ? null : (s[branch][i] ?? null);
}

/** One chart of L against one radius. */
class RadiusFigure {
  readonly figure: HTMLElement;
  private readonly title = html('figcaption', { class: 'chart-title' });
  private readonly legend: HTMLElement;
  private readonly picture = html('div', { class: 'chart-picture' });
  private readonly notes: HTMLElement;

  constructor(private readonly testId: string) {
    this.figure = html('figure', { class: 'chart-box', 'data-testid': testId });
    this.legend = html('ul', { class: 'chart-legend', 'data-testid': `${testId}-legend` });
    this.notes = html('ul', { class: 'chart-gaps', 'data-testid': `${testId}-gaps` });
    this.figure.append(this.title, this.legend, this.picture, this.notes);
  }

  draw(s: RadiusSweepData, unit: Unit, widthPx: number): void {
    const { self, other } = names(s.which);
    const u = unitSymbol(unit);
    const cur = Math.abs(s.currentMm);
    this.title.textContent = `L [${u}] against |${self}| [${u}], log axis (${other} held ${radiusWords(s.heldMm, unit)}; R, Rcr, posture, h fixed; dashed: current ${self} = ${radiusWords(s.currentMm, unit)})`;
    const k = fromMm(1, unit);
    const x = s.radiusMm.map((r) => r * k);
    const straight = s.straightMm;
    const bands: ChartGapBand[] = s.gaps.map((g) => ({
      key: g.side,
      colourBy: 'series',
      from: g.fromMm * k,
      to: g.toMm * k,
      reason: g.reason === 'gouging' ? 'gouging' : 'h at or above the limit',
    }));
    this.picture.replaceChildren(
      lineChart({
        widthPx,
        plotHeightPx: PLOT_HEIGHT_PX,
        x,
        logX: true,
        lines: [
          { key: 'convex', colourBy: 'series', values: s.convex },
          { key: 'concave', colourBy: 'series', values: s.concave },
          ...(straight === null
            ? []
            : [{ key: 'straight', colourBy: 'series' as const, values: x.map(() => straight) }]),
        ],
        yFactor: k,
        gaps: bands,
        markerX: cur * k,
        markerPoint: s.currentIntervalMm === null ? null : { x: cur * k, y: s.currentIntervalMm },
        xLabel: `|${self}| [${u}] (log)`,
        yLabel: `L [${u}]`,
        description: `${this.title.textContent}. The values at the current radius are listed beside the chart.`,
      }),
    );
    const len = (v: number | null) => (v === null ? 'n/a (see below)' : formatLenUnit(v, unit));
    const item = (series: string, name: string, v: number | null) => {
      const li = html('li', { class: 'legend-item', 'data-series': series });
      li.append(
        html('span', { class: 'swatch' }),
        html('span', { class: 'legend-name' }, name),
        html('span', { class: 'legend-value', 'data-testid': `${this.testId}-value-${series}` }, len(v)),
      );
      return li;
    };
    this.legend.replaceChildren(
      html('li', { class: 'chart-legend-head' }, `at ${self} ${radiusWords(s.currentMm, unit)}:`),
      item('convex', `${self} convex`, valueAt(s, 'convex')),
      item('concave', `${self} concave`, valueAt(s, 'concave')),
      item('straight', `${self} straight`, straight),
    );
    this.notes.replaceChildren(...radiusGapNotes(s, unit).map((t) => html('li', {}, t)));
  }
}

/** The doubly curved point's charts: L against Rf and against Rc. */
export class RadiusCharts {
  readonly element = html('div', { class: 'radius-charts', 'data-testid': 'chart-radius-view' });
  private readonly feed = new RadiusFigure('chart-radius-feed');
  private readonly cross = new RadiusFigure('chart-radius-cross');
  private readonly summary = html('p', {
    class: 'view-note',
    'data-testid': 'chart-radius-summary',
    'aria-live': 'polite',
  });

  constructor() {
    this.element.append(this.summary, this.feed.figure, this.cross.figure);
  }

  draw(feed: RadiusSweepData, cross: RadiusSweepData, unit: Unit, widthPx: number): void {
    const L = feed.currentIntervalMm;
    this.summary.textContent = `At Rf ${radiusWords(feed.currentMm, unit)}, Rc ${radiusWords(cross.currentMm, unit)}: L = ${formatLenUnit(L, unit)}; with Rf straight ${formatLenUnit(feed.straightMm, unit)}, with Rc straight ${formatLenUnit(cross.straightMm, unit)}.`;
    this.feed.draw(feed, unit, widthPx);
    this.cross.draw(cross, unit, widthPx);
  }
}
