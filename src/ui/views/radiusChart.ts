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
import type { RadiusWords } from '../i18n/catalogue';
import { localDecimal } from '../i18n/langChoice';
import { catalogue } from '../i18n/words';
import type { Unit } from '../state';
import { html } from './common';
import { type ChartGapBand, lineChart } from './lineChart';
import { radiusNames as names, radiusGapNotes, radiusWords } from './pageChartText';
import { EN_RADIUS } from './radiusWords';

/** The charts' words in the language in force (English: as written). */
function words(): RadiusWords {
  return catalogue()?.radius ?? EN_RADIUS;
}

/** A text's numbers with the decimal sign of the language in force (German 0,05; every digit kept). */
function local(text: string): string {
  return localDecimal(text, catalogue());
}

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
    const w = words();
    this.title.textContent = local(
      w.title(u, self, other, radiusWords(s.heldMm, unit, w), radiusWords(s.currentMm, unit, w)),
    );
    const k = fromMm(1, unit);
    const x = s.radiusMm.map((r) => r * k);
    const straight = s.straightMm;
    const bands: ChartGapBand[] = s.gaps.map((g) => ({
      key: g.side,
      colourBy: 'series',
      from: g.fromMm * k,
      to: g.toMm * k,
      reason: g.reason === 'gouging' ? w.band.gouging : w.band.limit,
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
        xLabel: w.xLabel(self, u),
        yLabel: `L [${u}]`,
        description: w.description(this.title.textContent),
      }),
    );
    const len = (v: number | null) => (v === null ? w.seeBelow : local(formatLenUnit(v, unit)));
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
      html('li', { class: 'chart-legend-head' }, local(w.legendHead(self, radiusWords(s.currentMm, unit, w)))),
      item('convex', w.branch(self, 'convex'), valueAt(s, 'convex')),
      item('concave', w.branch(self, 'concave'), valueAt(s, 'concave')),
      item('straight', w.branch(self, 'straight'), straight),
    );
    this.notes.replaceChildren(...radiusGapNotes(s, unit, w).map((t) => html('li', {}, local(t))));
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
    const w = words();
    const lang = catalogue()?.lang;
    if (lang === undefined) this.element.removeAttribute('lang');
    else this.element.lang = lang;
    this.summary.textContent = local(
      w.summary(
        radiusWords(feed.currentMm, unit, w),
        radiusWords(cross.currentMm, unit, w),
        formatLenUnit(L, unit),
        formatLenUnit(feed.straightMm, unit),
        formatLenUnit(cross.straightMm, unit),
      ),
    );
    this.feed.draw(feed, unit, widthPx);
    this.cross.draw(cross, unit, widthPx);
  }
}
