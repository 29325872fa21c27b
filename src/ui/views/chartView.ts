/**
 * Comparison charts (uPlot): the step-over L of every procedure against the lead rho and against
 * the tilt beta (the other angle, the tool, the pattern and h fixed), each with the current angle
 * dashed, and each approximation's signed error against exact along the lead.
 */
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { APPROXIMATION_KEYS, PROCEDURE_KEYS, PROCEDURES, type ProcedureKey } from '../../core/procedures';
import { fromMm, unitSymbol } from '../../core/units';
import type { Sweep } from '../../worker/protocol';
import { formatDeg, formatLen } from '../format';
import { html, type TeachingView, type ViewContext } from './common';

const MARKER = '#e11d48';

/** One chart: its box, its plot once built, the keys it shows and the angle it marks. */
interface Chart {
  readonly box: HTMLElement;
  readonly keys: readonly ProcedureKey[];
  plot: uPlot | null;
  current: number;
}

/** On a cylinder, what the charts' exact curve is and what the approximations' are. */
function cylinderSummary(ctx: ViewContext): string {
  const s = ctx.data.forward.surface;
  if (s.kind !== 'cylinder') return '';
  const side = s.radiusMm > 0 ? 'convex' : 'concave';
  return ` On this ${side} cylinder (axis ${s.axis === 'feed' ? 'along' : 'across'} the feed) the exact curve is the cylinder's (none where the posture would gouge the surface or h is beyond its flanks); the approximations are as on a plane, as in the table.`;
}

export class ChartView implements TeachingView {
  readonly id = 'chart';
  readonly title = 'L against lead and tilt';
  readonly element = html('div', { class: 'view-chart', 'data-testid': 'comparison-chart' });
  private readonly lead: Chart = {
    box: html('div', { class: 'chart-box', 'data-testid': 'chart-lead' }),
    keys: PROCEDURE_KEYS,
    plot: null,
    current: 0,
  };
  private readonly error: Chart = {
    box: html('div', { class: 'chart-box', 'data-testid': 'chart-error' }),
    keys: APPROXIMATION_KEYS,
    plot: null,
    current: 0,
  };
  private readonly tilt: Chart = {
    box: html('div', { class: 'chart-box', 'data-testid': 'chart-tilt' }),
    keys: PROCEDURE_KEYS,
    plot: null,
    current: 0,
  };
  private readonly errorUnit = html('select', { 'aria-label': 'Error unit', 'data-testid': 'chart-error-unit' });
  private readonly rhoAxis = html('select', { 'aria-label': 'Lead angle axis', 'data-testid': 'chart-rho-axis' });
  /** The charted values at the current posture, as text (charts are pictures to a screen reader). */
  private readonly summary = html('p', { class: 'view-note', 'data-testid': 'chart-summary', 'aria-live': 'polite' });
  private ctx: ViewContext | null = null;
  private highlighted: ProcedureKey | null = null;
  /** Unit, error unit, axis and width the charts were built for. */
  private shape = '';

  constructor() {
    this.errorUnit.append(
      html('option', { value: 'pct' }, 'error in %'),
      html('option', { value: 'mm' }, 'error in length'),
    );
    this.errorUnit.addEventListener('change', () => this.ctx && this.rebuild(this.ctx));
    // A log axis spreads the small lead angles, where the procedures part ways.
    this.rhoAxis.append(
      html('option', { value: 'log' }, 'rho axis: log'),
      html('option', { value: 'linear' }, 'rho axis: linear'),
    );
    this.rhoAxis.addEventListener('change', () => this.ctx && this.rebuild(this.ctx));
    const tools = html('div', { class: 'view-tools' });
    tools.append(this.errorUnit, this.rhoAxis);
    this.element.append(this.summary, this.lead.box, tools, this.error.box, this.tilt.box);
  }

  private width(): number {
    return Math.max(280, Math.min(900, this.element.clientWidth || 600));
  }

  /** Draws the dashed line at the chart's current angle. */
  private marker(chart: Chart): uPlot.Plugin {
    return {
      hooks: {
        draw: (u: uPlot) => {
          const x = u.valToPos(chart.current, 'x', true);
          const ctx = u.ctx;
          ctx.save();
          ctx.strokeStyle = MARKER;
          ctx.setLineDash([4, 4]);
          ctx.beginPath();
          ctx.moveTo(x, u.bbox.top);
          ctx.lineTo(x, u.bbox.top + u.bbox.height);
          ctx.stroke();
          ctx.restore();
        },
      },
    };
  }

  update(ctx: ViewContext): void {
    this.ctx = ctx;
    this.rebuild(ctx);
  }

  private rebuild(ctx: ViewContext): void {
    const { lead, tilt } = ctx.data.sweeps;
    const rho = ctx.data.forward.leadAngleDeg;
    const beta = ctx.data.forward.tiltAngleDeg;
    this.lead.current = this.error.current = rho;
    this.tilt.current = beta;
    const unit = unitSymbol(ctx.unit);
    const k = fromMm(1, ctx.unit);
    const scaled = (s: Sweep): uPlot.AlignedData => [
      [...s.angleDeg],
      ...PROCEDURE_KEYS.map((key) => s.values[key].map((v) => (v === null ? null : v * k))),
    ];
    const pct = this.errorUnit.value === 'pct';
    const log = this.rhoAxis.value === 'log';
    const exact = lead.values.exact;
    const errorData: uPlot.AlignedData = [
      [...lead.angleDeg],
      ...APPROXIMATION_KEYS.map((key) =>
        lead.values[key].map((v, i) => {
          const e = exact[i];
          if (v === null || e === null || e === undefined) return null;
          return pct ? (100 * (v - e)) / e : (v - e) * k;
        }),
      ),
    ];
    const at = tilt.angleDeg.indexOf(beta);
    this.summary.textContent =
      at < 0
        ? NO_SUMMARY
        : `At rho = ${formatDeg(rho)} deg, beta = ${formatDeg(beta)} deg, L [${unit}]: ${PROCEDURE_KEYS.map((key) => {
            const v = tilt.values[key][at];
            return `${PROCEDURES[key].shortLabel} ${v === null || v === undefined ? 'n/a' : formatLen(v, ctx.unit)}`;
          }).join(', ')}.${cylinderSummary(ctx)}`;
    const titles = {
      lead: `L against lead rho (R, Rcr, beta, h fixed; dashed: current rho = ${formatDeg(rho)})`,
      error: 'Signed error of each approximation against exact, along the lead',
      tilt: `L against tilt beta (R, Rcr, rho, h fixed; dashed: current beta = ${formatDeg(beta)})`,
    };
    const leadOnly = beta !== 0;
    const key = `${unit}|${pct}|${log}|${this.width()}|${leadOnly}`;
    const charts: Array<[Chart, uPlot.AlignedData, string]> = [
      [this.lead, scaled(lead), titles.lead],
      [this.error, errorData, titles.error],
      [this.tilt, scaled(tilt), titles.tilt],
    ];
    if (key === this.shape && charts.every(([c]) => c.plot !== null)) {
      // Same axes: new data only (cheaper than building the charts again).
      for (const [c, data, title] of charts) {
        c.plot?.setData(data);
        const t = c.box.querySelector('.u-title');
        if (t) t.textContent = title;
      }
      return;
    }
    this.shape = key;
    const series = (keys: readonly ProcedureKey[]): uPlot.Series[] => [
      { label: 'angle [deg]' },
      ...keys.map((k) => ({
        label: `${PROCEDURES[k].shortLabel}${leadOnly && PROCEDURES[k].leadOnly ? ' (lead only)' : ''}`,
        stroke: PROCEDURES[k].colour,
        width: k === 'exact' ? 2.5 : 1.6,
        spanGaps: false,
      })),
    ];
    const options = (chart: Chart, title: string, xLabel: string, yLabel: string, logX: boolean): uPlot.Options => ({
      title,
      width: this.width(),
      height: 200,
      focus: { alpha: 0.25 },
      cursor: { focus: { prox: 16 } },
      // The charted range exactly (a log scale would otherwise snap out to whole decades).
      scales: { x: { time: false, distr: logX ? 3 : 1, range: (_u, min, max) => [min, max] } },
      axes: [{ label: xLabel }, { label: yLabel }],
      plugins: [this.marker(chart)],
      series: series(chart.keys),
    });
    const specs: Array<[Chart, uPlot.AlignedData, uPlot.Options]> = [
      [this.lead, scaled(lead), options(this.lead, titles.lead, 'lead angle rho [deg]', `L [${unit}]`, log)],
      [
        this.error,
        errorData,
        options(this.error, titles.error, 'lead angle rho [deg]', pct ? 'error [%]' : `error [${unit}]`, log),
      ],
      [this.tilt, scaled(tilt), options(this.tilt, titles.tilt, 'tilt angle beta [deg]', `L [${unit}]`, false)],
    ];
    for (const [chart, data, opts] of specs) {
      chart.plot?.destroy();
      chart.plot = new uPlot(opts, data, chart.box);
    }
    this.highlight(this.highlighted);
  }

  highlight(key: ProcedureKey | null): void {
    this.highlighted = key;
    for (const chart of [this.lead, this.error, this.tilt]) {
      if (!chart.plot) continue;
      const idx = key === null ? -1 : chart.keys.indexOf(key);
      chart.plot.setSeries(idx >= 0 ? idx + 1 : null, { focus: idx >= 0 });
    }
  }

  setVisible(visible: boolean): void {
    if (visible && this.ctx) this.rebuild(this.ctx);
  }
}

const NO_SUMMARY = 'The current posture is outside the charted range.';
