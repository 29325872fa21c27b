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
import type { Unit } from '../state';
import { html } from './common';
import { type ChartGapBand, type ChartLine, lineChart } from './lineChart';
import { crossingSentence, deg, refusalNotes } from './pageChartText';

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
    const u = unitSymbol(unit);
    const name = stepName(d.passes);
    const otherName = d.passes === 'raster' ? 'dz (waterline)' : `Lxy (raster, psi = ${deg(d.crossingRasterAngleDeg)})`;
    const own = d.passes === 'raster' ? `Lxy (raster, psi = ${deg(d.rasterAngleDeg)})` : 'dz (waterline)';
    // The slope axis runs to 90 degrees; the lines stop at the largest valid slope.
    const open = d.largestSlopeDeg < 90;
    const x = open ? [...d.slopeDeg, 90] : [...d.slopeDeg];
    const pad = <T>(v: readonly T[]): (T | null)[] => (open ? [...v, null] : [...v]);
    const flat = (v: number) => x.map((a) => (a <= d.largestSlopeDeg ? v : null));
    const k = fromMm(1, unit);
    const gaps: ChartGapBand[] = open
      ? [{ key: 'step', colourBy: 'series', from: d.largestSlopeDeg, to: 90, reason: 'h at or above the limit' }]
      : [];
    const stepLines: ChartLine[] = [
      { key: 'step', colourBy: 'series', values: pad(d.stepMm) },
      ...(d.otherStepMm.some((v) => v !== null)
        ? [{ key: 'other', colourBy: 'series' as const, values: pad(d.otherStepMm) }]
        : []),
      { key: 'floor', colourBy: 'series', values: flat(d.flatFloorStepMm) },
    ];
    const slope = `slope = ${deg(d.currentSlopeDeg)}`;
    this.sentence.textContent = crossingSentence(d, unit);
    this.step.title.textContent = `Programmed step [${u}] against slope [deg] for h = ${formatLenUnit(d.hMm, unit, 'height')} (R, Rcr fixed; dashed: current ${slope})`;
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
        xLabel: 'slope alpha [deg]',
        yLabel: `step [${u}]`,
        description: `${this.step.title.textContent}. ${this.sentence.textContent}`,
      }),
    );
    const len = (v: number | null) => (v === null ? 'n/a' : formatLenUnit(v, unit));
    this.step.legend.replaceChildren(
      html('li', { class: 'chart-legend-head' }, `at ${slope}:`),
      entry('step', own, len(d.currentStepMm), 'chart-slope-value-step'),
      ...(stepLines.some((l) => l.key === 'other')
        ? [entry('other', otherName, len(d.currentOtherStepMm), 'chart-slope-value-other')]
        : []),
      entry('floor', "flat floor's step Lxy0", len(d.flatFloorStepMm), 'chart-slope-value-floor'),
    );
    const constant = `${name} = ${formatLenUnit(d.constantStepMm, unit)}`;
    this.cusp.title.textContent = `Scallop [${u}] a constant ${constant} leaves, against slope [deg] (dotted: h = ${formatLenUnit(d.hMm, unit, 'height')})`;
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
        xLabel: 'slope alpha [deg]',
        yLabel: `scallop [${u}]`,
        description: this.cusp.title.textContent,
      }),
    );
    this.cusp.legend.replaceChildren(
      html('li', { class: 'chart-legend-head' }, `at ${slope}:`),
      entry(
        'cusp',
        `scallop of ${constant}`,
        d.currentCuspAtConstantStepMm === null ? 'n/a' : formatLenUnit(d.currentCuspAtConstantStepMm, unit, 'height'),
        'chart-slope-value-cusp',
      ),
    );
    this.notes.replaceChildren(
      ...refusalNotes(d, unit).map((t) => html('li', {}, t)),
      ...(open
        ? [
            html(
              'li',
              {},
              `No step above ${deg(d.largestSlopeDeg)}: there h = ${formatLenUnit(d.hMm, unit, 'height')} reaches the largest scallop the tool can leave (its flank or shank${d.onRevolution ? ', or the end of the surface' : ''}); 90° is a vertical wall.`,
            ),
          ]
        : []),
    );
  }
}
