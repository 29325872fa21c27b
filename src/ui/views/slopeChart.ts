/**
 * The chart "step against slope" for three-axis machining (issue 20), drawn from the worker's data
 * (worker/data/slopeChart.ts): the exact programmed step (Lxy for raster at the current raster
 * angle, dz for waterline) from 0 to 90 degrees for the current tool and h, the other strategy's
 * step on the plane beside it, the flat floor's step as a line; under it the scallop the constant
 * step leaves at each slope against h; the current slope dashed on both. One sentence above says
 * where raster and waterline cross, in the user's unit.
 */
import { fromMm, unitSymbol } from '../../core/input/units';
import type { SlopeChartData } from '../../worker/teachProtocol';
import { formatLenUnit } from '../format';
import type { SlopeWords } from '../i18n/catalogue';
import { localDecimal } from '../i18n/langChoice';
import { catalogue } from '../i18n/words';
import type { Unit } from '../state';
import { html } from './common';
import { type ChartGapBand, type ChartLine, lineChart } from './lineChart';
import { crossingSentence, deg, refusalNotes } from './pageChartText';
import { EN_SLOPE } from './slopeWords';

/** Height of each plot area (CSS px). */
const PLOT_HEIGHT_PX = 240;

/** The strategy's step by name: Lxy (raster) or dz (waterline). */
function stepName(passes: SlopeChartData['passes']): string {
  return passes === 'raster' ? 'Lxy' : 'dz';
}

/** One figure: title, legend (values at the current slope), picture. */
interface Figure {
  readonly figure: HTMLElement;
  readonly title: HTMLElement;
  readonly legend: HTMLElement;
  readonly picture: HTMLElement;
}

function figure(testId: string): Figure {
  const f = html('figure', { class: 'chart-box', 'data-testid': testId });
  const title = html('figcaption', { class: 'chart-title' });
  const legend = html('ul', { class: 'chart-legend', 'data-testid': `${testId}-legend` });
  const picture = html('div', { class: 'chart-picture' });
  f.append(title, legend, picture);
  return { figure: f, title, legend, picture };
}

/** A legend entry: swatch, name and the value at the current slope. */
function entry(series: string, name: string, value: string, testId: string): HTMLElement {
  const item = html('li', { class: 'legend-item', 'data-series': series });
  item.append(
    html('span', { class: 'swatch' }),
    html('span', { class: 'legend-name' }, name),
    html('span', { class: 'legend-value', 'data-testid': testId }, value),
  );
  return item;
}

/** The three-axis chart: the sentence, the step against slope and the scallop of a constant step. */
export class SlopeChart {
  readonly element = html('div', { class: 'slope-chart', 'data-testid': 'chart-slope-view' });
  private readonly sentence = html('p', {
    class: 'view-note chart-sentence',
    'data-testid': 'chart-crossing',
    'aria-live': 'polite',
  });
  private readonly step = figure('chart-slope');
  private readonly cusp = figure('chart-slope-cusp');
  private readonly notes = html('ul', { class: 'chart-gaps', 'data-testid': 'chart-slope-gaps' });

  constructor() {
    this.element.append(this.sentence, this.step.figure, this.cusp.figure, this.notes);
  }

  /** Draws the data for the unit, `widthPx` wide. */
  draw(d: SlopeChartData, unit: Unit, widthPx: number): void {
    const words: SlopeWords = catalogue()?.slope ?? EN_SLOPE;
    // Numbers with the decimal sign of the language in force (German 0,05; every digit kept).
    const local = (text: string) => localDecimal(text, catalogue());
    const lang = catalogue()?.lang;
    if (lang === undefined) this.element.removeAttribute('lang');
    else this.element.lang = lang;
    const u = unitSymbol(unit);
    const name = stepName(d.passes);
    const otherName = words.strategy(d.passes === 'raster' ? 'waterline' : 'raster', deg(d.crossingRasterAngleDeg));
    const own = words.strategy(d.passes, deg(d.rasterAngleDeg));
    // The slope axis runs to 90 degrees; the lines stop at the largest valid slope.
    const open = d.largestSlopeDeg < 90;
    const x = open ? [...d.slopeDeg, 90] : [...d.slopeDeg];
    const pad = <T>(v: readonly T[]): (T | null)[] => (open ? [...v, null] : [...v]);
    const flat = (v: number) => x.map((a) => (a <= d.largestSlopeDeg ? v : null));
    const k = fromMm(1, unit);
    const gaps: ChartGapBand[] = open
      ? [{ key: 'step', colourBy: 'series', from: d.largestSlopeDeg, to: 90, reason: words.gap }]
      : [];
    const stepLines: ChartLine[] = [
      { key: 'step', colourBy: 'series', values: pad(d.stepMm) },
      ...(d.otherStepMm.some((v) => v !== null)
        ? [{ key: 'other', colourBy: 'series' as const, values: pad(d.otherStepMm) }]
        : []),
      { key: 'floor', colourBy: 'series', values: flat(d.flatFloorStepMm) },
    ];
    const slope = deg(d.currentSlopeDeg);
    this.sentence.textContent = local(crossingSentence(d, unit, words));
    this.step.title.textContent = local(words.stepTitle(u, formatLenUnit(d.hMm, unit, 'height'), slope));
    this.step.picture.replaceChildren(
      lineChart({
        widthPx,
        plotHeightPx: PLOT_HEIGHT_PX,
        x,
        logX: false,
        lines: stepLines,
        yFactor: k,
        gaps,
        markerX: d.currentSlopeDeg,
        markerPoint: d.currentStepMm === null ? null : { x: d.currentSlopeDeg, y: d.currentStepMm },
        xLabel: words.slopeAxis,
        yLabel: words.stepAxis(u),
        description: words.description(this.step.title.textContent, this.sentence.textContent),
      }),
    );
    const len = (v: number | null) => (v === null ? words.none : local(formatLenUnit(v, unit)));
    this.step.legend.replaceChildren(
      html('li', { class: 'chart-legend-head' }, local(words.legendHead(slope))),
      entry('step', own, len(d.currentStepMm), 'chart-slope-value-step'),
      ...(stepLines.some((l) => l.key === 'other')
        ? [entry('other', otherName, len(d.currentOtherStepMm), 'chart-slope-value-other')]
        : []),
      entry('floor', words.floor, len(d.flatFloorStepMm), 'chart-slope-value-floor'),
    );
    const constant = `${name} = ${formatLenUnit(d.constantStepMm, unit)}`;
    this.cusp.title.textContent = local(words.cuspTitle(u, constant, formatLenUnit(d.hMm, unit, 'height')));
    this.cusp.picture.replaceChildren(
      lineChart({
        widthPx,
        plotHeightPx: PLOT_HEIGHT_PX * 0.7,
        x,
        logX: false,
        lines: [
          { key: 'cusp', colourBy: 'series', values: pad(d.cuspAtConstantStepMm) },
          { key: 'h', colourBy: 'series', values: flat(d.hMm) },
        ],
        yFactor: k,
        gaps,
        markerX: d.currentSlopeDeg,
        markerPoint:
          d.currentCuspAtConstantStepMm === null ? null : { x: d.currentSlopeDeg, y: d.currentCuspAtConstantStepMm },
        xLabel: words.slopeAxis,
        yLabel: words.scallopAxis(u),
        description: this.cusp.title.textContent,
      }),
    );
    this.cusp.legend.replaceChildren(
      html('li', { class: 'chart-legend-head' }, local(words.legendHead(slope))),
      entry(
        'cusp',
        local(words.scallopOf(constant)),
        d.currentCuspAtConstantStepMm === null
          ? words.none
          : local(formatLenUnit(d.currentCuspAtConstantStepMm, unit, 'height')),
        'chart-slope-value-cusp',
      ),
    );
    this.notes.replaceChildren(
      ...refusalNotes(d, unit, words).map((t) => html('li', {}, local(t))),
      ...(open
        ? [
            html(
              'li',
              {},
              local(words.noStepAbove(deg(d.largestSlopeDeg), formatLenUnit(d.hMm, unit, 'height'), d.onRevolution)),
            ),
          ]
        : []),
    );
  }
}
