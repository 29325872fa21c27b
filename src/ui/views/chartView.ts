/**
 * Comparison charts (SVG, lineChart.ts): the step-over L of every procedure against the lead rho
 * and against the tilt beta (the other angle, the tool, the pattern and h fixed), each with the
 * current angle dashed, and each approximation's signed error against exact along the lead. Each
 * chart has a legend with every procedure's value at the current angle, and says where a
 * procedure has no answer, and why.
 */

import { formatSignificant, fromMm, unitSymbol } from '../../core/input/units';
import { APPROXIMATION_KEYS, PROCEDURE_KEYS, PROCEDURES, type ProcedureKey } from '../../core/procedures/procedures';
import type { Sweep, SweepGap } from '../../worker/protocol';
import { formatDeg, formatLenUnit, formatSignedLenUnit, formatSignedPercent } from '../format';
import type { ChartWords } from '../i18n/catalogue';
import { localDecimal } from '../i18n/langChoice';
import { catalogue } from '../i18n/words';
import { EN_CHART } from './chartWords';
import { html, type PageKind, type PageViewContext, type TeachingView, type ViewContext } from './common';
import { gapReasonIn } from './gapReasons';
import { type ChartGapBand, type ChartLine, lineChart } from './lineChart';
import { RadiusCharts } from './radiusChart';
import { SlopeChart } from './slopeChart';
import './chart.css';

/** Height of each plot area (CSS px): tall enough to read the curves apart. */
const PLOT_HEIGHT_PX = 280;

/** One chart's parts: its figure (title, picture, legend, notes on missing answers). */
interface Chart {
  readonly figure: HTMLElement;
  readonly title: HTMLElement;
  readonly picture: HTMLElement;
  readonly legend: HTMLElement;
  readonly notes: HTMLElement;
}

/** What one chart shows. */
interface ChartData {
  readonly title: string;
  readonly x: readonly number[];
  readonly logX: boolean;
  readonly lines: ReadonlyArray<ChartLine & { readonly key: ProcedureKey }>;
  /** Factor from the lines' values to the axis unit. */
  readonly yFactor: number;
  readonly gaps: { readonly [K in ProcedureKey]: readonly SweepGap[] };
  readonly current: number;
  /** Index of the current angle among the samples (-1 when it is not one). */
  readonly at: number;
  readonly angleName: 'rho' | 'beta';
  readonly xLabel: string;
  readonly yLabel: string;
  readonly value: (v: number) => string;
}

function chart(testId: string): Chart {
  const figure = html('figure', { class: 'chart-box', 'data-testid': testId });
  const title = html('figcaption', { class: 'chart-title' });
  const picture = html('div', { class: 'chart-picture' });
  const legend = html('ul', { class: 'chart-legend', 'data-testid': `${testId}-legend` });
  const notes = html('ul', { class: 'chart-gaps', 'data-testid': `${testId}-gaps` });
  figure.append(title, legend, picture, notes);
  return { figure, title, picture, legend, notes };
}

/** On a cylinder, what the charts' exact curve is and what the approximations' are. */
function cylinderSummary(ctx: ViewContext, words: ChartWords): string {
  const s = ctx.data.forward.surface;
  if (s.kind !== 'cylinder') return '';
  return words.cylinder(s.radiusMm < 0, s.axis);
}

/** A procedure's short name in the language in force (English: the registry's). */
function procedureShortName(key: ProcedureKey): string {
  return catalogue()?.procedures.names[key].shortLabel ?? PROCEDURES[key].shortLabel;
}

/** The charts' words in the language in force (English: the charts as written). */
function chartWords(): ChartWords {
  return catalogue()?.chart ?? EN_CHART;
}

/** A text's numbers with the decimal sign of the language in force (German 2,8872; every digit kept). */
function local(text: string): string {
  return localDecimal(text, catalogue());
}

export class ChartView implements TeachingView {
  readonly id = 'chart';
  readonly title = 'L against lead and tilt';
  readonly element = html('div', { class: 'view-chart', 'data-testid': 'comparison-chart' });
  private readonly lead = chart('chart-lead');
  private readonly error = chart('chart-error');
  private readonly tilt = chart('chart-tilt');
  private readonly errorUnit = html('select', { 'data-testid': 'chart-error-unit' });
  private readonly rhoAxis = html('select', { 'data-testid': 'chart-rho-axis' });
  /** The charted values at the current posture, as text (charts are pictures to a screen reader). */
  private readonly summary = html('p', { class: 'view-note', 'data-testid': 'chart-summary', 'aria-live': 'polite' });
  private ctx: ViewContext | null = null;
  private highlighted: ProcedureKey | null = null;
  private drawnWidthPx = 0;
  /** The five-axis charts on a plane or a cylinder (hidden while a page question is drawn). */
  private readonly classic = html('div', { class: 'chart-classic' });
  /** Three-axis machining's chart, and a doubly curved point's (issues 20 and 19). */
  readonly pageKinds: readonly PageKind[] = ['curved', 'three-axis'];
  private readonly slope = new SlopeChart();
  private readonly radius = new RadiusCharts();
  private pageCtx: PageViewContext | null = null;

  constructor() {
    // Their words are the language's when the charts are drawn (rebuild).
    this.errorUnit.append(html('option', { value: 'pct' }), html('option', { value: 'mm' }));
    this.errorUnit.addEventListener('change', () => this.ctx && this.rebuild(this.ctx));
    // A log axis spreads the small lead angles, where the procedures part ways.
    this.rhoAxis.append(html('option', { value: 'log' }), html('option', { value: 'linear' }));
    this.rhoAxis.addEventListener('change', () => this.ctx && this.rebuild(this.ctx));
    const tools = html('div', { class: 'view-tools' });
    tools.append(this.errorUnit, this.rhoAxis);
    this.classic.append(this.summary, this.lead.figure, tools, this.error.figure, this.tilt.figure);
    this.slope.element.hidden = true;
    this.radius.element.hidden = true;
    this.element.append(this.classic, this.slope.element, this.radius.element);
    // The drawing is laid out for its width: draw again when the box changes width.
    new ResizeObserver(() => {
      if (Math.abs(this.width() - this.drawnWidthPx) <= 4) return;
      if (this.pageCtx !== null) this.drawPage(this.pageCtx);
      else if (this.ctx) this.rebuild(this.ctx);
    }).observe(this.element);
  }

  private width(): number {
    return Math.max(240, Math.min(960, this.element.clientWidth || 600));
  }

  update(ctx: ViewContext): void {
    this.ctx = ctx;
    this.pageCtx = null;
    this.classic.hidden = false;
    this.slope.element.hidden = true;
    this.radius.element.hidden = true;
    this.rebuild(ctx);
  }

  /** A three-axis question's chart "step against slope", or a doubly curved point's L against each radius. */
  updatePage(ctx: PageViewContext): void {
    this.pageCtx = ctx;
    this.drawPage(ctx);
  }

  private drawPage(ctx: PageViewContext): void {
    this.drawnWidthPx = this.width();
    this.classic.hidden = true;
    this.slope.element.hidden = ctx.kind !== 'three-axis';
    this.radius.element.hidden = ctx.kind !== 'curved';
    if (ctx.kind === 'three-axis') this.slope.draw(ctx.data.slope, ctx.unit, this.drawnWidthPx);
    else this.radius.draw(ctx.data.feed, ctx.data.cross, ctx.unit, this.drawnWidthPx);
  }

  /** The choices' words, and the charts' language (the teaching views are otherwise marked English). */
  private name(words: ChartWords): void {
    const [pct, length] = this.errorUnit.options;
    const [log, linear] = this.rhoAxis.options;
    if (pct && length && log && linear) {
      pct.textContent = words.errorIn.pct;
      length.textContent = words.errorIn.length;
      log.textContent = words.rhoScale.log;
      linear.textContent = words.rhoScale.linear;
    }
    this.errorUnit.setAttribute('aria-label', words.errorIn.name);
    this.rhoAxis.setAttribute('aria-label', words.rhoScale.name);
    const lang = catalogue()?.lang;
    if (lang === undefined) this.classic.removeAttribute('lang');
    else this.classic.lang = lang;
  }

  private rebuild(ctx: ViewContext): void {
    const words = chartWords();
    this.name(words);
    const { lead, tilt } = ctx.data.sweeps;
    const rho = ctx.data.forward.leadAngleDeg;
    const beta = ctx.data.forward.tiltAngleDeg;
    const unit = unitSymbol(ctx.unit);
    const pct = this.errorUnit.value === 'pct';
    const logX = this.rhoAxis.value === 'log';
    const leadOnly = beta !== 0;
    // The legend's and the summary's values: each length with its unit (format.ts); the axes name theirs.
    const len = (v: number) => formatLenUnit(v, ctx.unit);
    const exact = lead.values.exact;
    const errorLines = APPROXIMATION_KEYS.map((key) => ({
      key,
      values: lead.values[key].map((v, i) => {
        const e = exact[i];
        if (v === null || e === null || e === undefined || e === 0) return null;
        return pct ? (100 * (v - e)) / e : v - e;
      }),
    }));
    const lines = (s: Sweep, keys: readonly ProcedureKey[]) => keys.map((key) => ({ key, values: s.values[key] }));
    const k = fromMm(1, ctx.unit);
    const common = { logX, current: rho, at: lead.angleDeg.indexOf(rho), angleName: 'rho' as const };
    const specs: Array<[Chart, ChartData]> = [
      [
        this.lead,
        {
          ...common,
          title: local(words.leadTitle(unit, formatDeg(rho))),
          x: lead.angleDeg,
          lines: lines(lead, PROCEDURE_KEYS),
          yFactor: k,
          gaps: lead.gaps,
          xLabel: words.leadAxis,
          yLabel: `L [${unit}]`,
          value: len,
        },
      ],
      [
        this.error,
        {
          ...common,
          title: words.errorTitle(pct ? '%' : unit),
          x: lead.angleDeg,
          lines: errorLines,
          yFactor: pct ? 1 : k,
          gaps: lead.gaps,
          xLabel: words.leadAxis,
          yLabel: words.errorAxis(pct ? '%' : unit),
          value: pct ? (v) => `${formatSignedPercent(v)} %` : (v) => formatSignedLenUnit(v, ctx.unit),
        },
      ],
      [
        this.tilt,
        {
          title: local(words.tiltTitle(unit, formatDeg(beta))),
          x: tilt.angleDeg,
          logX: false,
          lines: lines(tilt, PROCEDURE_KEYS),
          yFactor: k,
          gaps: tilt.gaps,
          current: beta,
          at: tilt.angleDeg.indexOf(beta),
          angleName: 'beta',
          xLabel: words.tiltAxis,
          yLabel: `L [${unit}]`,
          value: len,
        },
      ],
    ];
    this.drawnWidthPx = this.width();
    for (const [c, data] of specs) this.draw(c, data, leadOnly, words);
    const at = tilt.angleDeg.indexOf(beta);
    this.summary.textContent =
      at < 0
        ? words.noSummary
        : local(
            `${words.summary(
              formatDeg(rho),
              formatDeg(beta),
              PROCEDURE_KEYS.map((key) => {
                const v = tilt.values[key][at];
                return `${procedureShortName(key)} ${v === null || v === undefined ? words.none : len(v)}`;
              }).join(', '),
            )}${cylinderSummary(ctx, words)}`,
          );
    this.highlight(this.highlighted);
  }

  private draw(c: Chart, data: ChartData, leadOnly: boolean, words: ChartWords): void {
    const keys = data.lines.map((l) => l.key);
    const bands: ChartGapBand[] = keys.flatMap((key) =>
      data.gaps[key].map((g) => ({ key, from: g.fromDeg, to: g.toDeg, reason: g.reason })),
    );
    c.title.textContent = data.title;
    const picture = lineChart({
      widthPx: this.drawnWidthPx,
      plotHeightPx: PLOT_HEIGHT_PX,
      x: data.x,
      logX: data.logX,
      lines: data.lines,
      yFactor: data.yFactor,
      gaps: bands,
      markerX: data.current,
      xLabel: data.xLabel,
      yLabel: data.yLabel,
      description: words.description(data.title),
    });
    c.picture.replaceChildren(picture);
    // The legend: each procedure's value at the current angle, without hovering.
    c.legend.replaceChildren(
      html('li', { class: 'chart-legend-head' }, local(words.legendHead(data.angleName, formatDeg(data.current)))),
      ...data.lines.map((line) => {
        const v = data.at < 0 ? null : (line.values[data.at] ?? null);
        const name = `${procedureShortName(line.key)}${leadOnly && PROCEDURES[line.key].leadOnly ? words.leadOnly : ''}`;
        const item = html('li', { class: 'legend-item', 'data-procedure': line.key });
        item.append(
          html('span', { class: 'swatch' }),
          html('span', { class: 'legend-name' }, name),
          html(
            'span',
            { class: 'legend-value', 'data-testid': `${c.figure.dataset.testid}-value-${line.key}` },
            v === null || !Number.isFinite(v) ? words.seeBelow : local(data.value(v)),
          ),
        );
        return item;
      }),
    );
    // A gap's reason is the solver's sentence: in the language in force when the page knows it
    // (gapReasons.ts), else in English (said so by its lang).
    const translated = catalogue() !== null;
    c.notes.replaceChildren(
      ...gapNotes(keys, data.gaps, data.angleName, words).map(({ lead, reason }) => {
        const li = html('li', {}, local(lead));
        const worded = translated ? gapReasonIn(reason, words) : null;
        li.append(worded === null ? html('span', { lang: 'en' }, reason) : local(worded), '.');
        return li;
      }),
    );
  }

  highlight(key: ProcedureKey | null): void {
    this.highlighted = key;
    for (const el of this.element.querySelectorAll('[data-procedure]')) {
      el.classList.toggle('chart-focus', key !== null && el.getAttribute('data-procedure') === key);
      el.classList.toggle('chart-dim', key !== null && el.getAttribute('data-procedure') !== key);
    }
  }

  setVisible(visible: boolean): void {
    if (!visible) return;
    if (this.pageCtx !== null) this.drawPage(this.pageCtx);
    else if (this.ctx) this.rebuild(this.ctx);
  }
}

/**
 * One sentence per distinct gap: the procedures without an answer over one range of the angle (in
 * `words`' language), and why (the solver's reason; procedures sharing the same range and reason
 * are named together).
 */
export function gapNotes(
  keys: readonly ProcedureKey[],
  gaps: { readonly [K in ProcedureKey]: readonly SweepGap[] },
  angleName: 'rho' | 'beta',
  words: ChartWords = EN_CHART,
): Array<{ readonly lead: string; readonly reason: string }> {
  const groups = new Map<string, { names: string[]; gap: SweepGap }>();
  for (const key of keys) {
    for (const gap of gaps[key]) {
      const id = `${gap.fromDeg}|${gap.toDeg}|${gap.reason}`;
      const g = groups.get(id) ?? { names: [], gap };
      g.names.push(procedureShortName(key));
      groups.set(id, g);
    }
  }
  return [...groups.values()].map(({ names, gap }) => {
    // The edges are samples: the true edge lies between a sample and the next one.
    const deg = (d: number) => formatSignificant(d, { digits: 3, trimZeros: true });
    const to = gap.fromDeg === gap.toDeg ? null : deg(gap.toDeg);
    return { lead: words.gap(names.join(', '), angleName, deg(gap.fromDeg), to), reason: gap.reason };
  });
}
