/**
 * Comparison charts (uPlot): L/2 against rho for the four procedures at the current R, Rcr
 * and h with the current rho marked, and each approximation's signed error against exact.
 */
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import type { ProcedureKey } from '../../worker/protocol';
import { COLOURS, html, LABELS, PROCEDURE_KEYS, type TeachingView, type ViewContext } from './common';

const APPROX: readonly ProcedureKey[] = ['sekine', 'redonnet', 'bedi'];

export class ChartView implements TeachingView {
  readonly id = 'chart';
  readonly title = 'L/2 against rho';
  readonly element = html('div', { class: 'view-chart', 'data-testid': 'comparison-chart' });
  private readonly mainBox = html('div', { class: 'chart-box', 'data-testid': 'chart-half' });
  private readonly errorBox = html('div', { class: 'chart-box', 'data-testid': 'chart-error' });
  private readonly errorUnit = html('select', { 'aria-label': 'Error unit', 'data-testid': 'chart-error-unit' });
  private readonly rhoAxis = html('select', { 'aria-label': 'Lead angle axis', 'data-testid': 'chart-rho-axis' });
  /** The charted values at the current rho, as text (charts are pictures to a screen reader). */
  private readonly summary = html('p', { class: 'view-note', 'data-testid': 'chart-summary', 'aria-live': 'polite' });
  private main: uPlot | null = null;
  private error: uPlot | null = null;
  private ctx: ViewContext | null = null;
  private currentRho = 0;
  private highlighted: ProcedureKey | null = null;
  /** Unit, error unit and width the charts were built for. */
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
    this.element.append(this.summary, this.mainBox, tools, this.errorBox);
  }

  private width(): number {
    return Math.max(280, Math.min(900, this.element.clientWidth || 600));
  }

  private marker(): uPlot.Plugin {
    return {
      hooks: {
        draw: (u: uPlot) => {
          const x = u.valToPos(this.currentRho, 'x', true);
          const ctx = u.ctx;
          ctx.save();
          ctx.strokeStyle = '#e11d48';
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
    this.currentRho = ctx.rho;
    this.rebuild(ctx);
  }

  private rebuild(ctx: ViewContext): void {
    const sweep = ctx.reply.teaching?.sweep;
    if (!sweep) return;
    const k = ctx.unit === 'mm' ? 1 : 1 / 25.4;
    const unit = ctx.unit === 'mm' ? 'mm' : 'in';
    const scale = (v: number | null) => (v === null ? null : v * k);
    const mainData: uPlot.AlignedData = [sweep.rhoDeg, ...PROCEDURE_KEYS.map((key) => sweep[key].map(scale))];
    const pct = this.errorUnit.value === 'pct';
    const log = this.rhoAxis.value === 'log';
    const errorData: uPlot.AlignedData = [
      sweep.rhoDeg,
      ...APPROX.map((key) =>
        sweep[key].map((v, i) => {
          const e = sweep.exact[i];
          if (v === null || e === null || e === undefined) return null;
          return pct ? (100 * (v - e)) / e : (v - e) * k;
        }),
      ),
    ];
    const series = (keys: readonly ProcedureKey[]): uPlot.Series[] => [
      { label: 'rho [deg]' },
      ...keys.map((key) => ({
        label: LABELS[key],
        stroke: COLOURS[key],
        width: key === 'exact' ? 2.5 : 1.6,
        spanGaps: false,
      })),
    ];
    const common = (title: string, yLabel: string): Omit<uPlot.Options, 'series'> => ({
      title,
      width: this.width(),
      height: 220,
      focus: { alpha: 0.25 },
      cursor: { focus: { prox: 16 } },
      // The charted range exactly (a log scale would otherwise snap out to whole decades).
      scales: { x: { time: false, distr: log ? 3 : 1, range: (_u, min, max) => [min, max] } },
      axes: [{ label: 'lead angle rho [deg]' }, { label: yLabel }],
      plugins: [this.marker()],
    });
    const at = sweep.rhoDeg.indexOf(ctx.rho);
    this.summary.textContent =
      at < 0
        ? `rho = ${ctx.rho} deg is outside the charted range 0.5-89 deg.`
        : `At rho = ${ctx.rho} deg, L/2 [${unit}]: ${PROCEDURE_KEYS.map((key) => {
            const v = sweep[key][at];
            return `${LABELS[key]} ${v === null || v === undefined ? 'n/a' : (v * k).toFixed(ctx.unit === 'mm' ? 4 : 5)}`;
          }).join(', ')}.`;
    const title = `L/2 against rho (R, Rcr, h fixed; dashed: current rho = ${ctx.rho})`;
    const key = `${unit}|${pct}|${log}|${this.width()}`;
    if (this.main && this.error && key === this.shape) {
      // Same axes: new data only (cheaper than building the charts again).
      this.main.setData(mainData);
      this.error.setData(errorData);
      const t = this.mainBox.querySelector('.u-title');
      if (t) t.textContent = title;
      return;
    }
    this.shape = key;
    this.main?.destroy();
    this.error?.destroy();
    this.main = new uPlot(
      {
        ...common(`L/2 against rho (R, Rcr, h fixed; dashed: current rho = ${ctx.rho})`, `L/2 [${unit}]`),
        series: series(PROCEDURE_KEYS),
      },
      mainData,
      this.mainBox,
    );
    this.error = new uPlot(
      {
        ...common('Signed error of each approximation against exact', pct ? 'error [%]' : `error [${unit}]`),
        series: series(APPROX),
      },
      errorData,
      this.errorBox,
    );
    this.highlight(this.highlighted);
  }

  highlight(key: ProcedureKey | null): void {
    this.highlighted = key;
    for (const [plot, keys] of [
      [this.main, PROCEDURE_KEYS],
      [this.error, APPROX],
    ] as const) {
      if (!plot) continue;
      const idx = key === null ? -1 : keys.indexOf(key);
      plot.setSeries(idx >= 0 ? idx + 1 : null, { focus: idx >= 0 });
    }
  }

  setVisible(visible: boolean): void {
    if (visible && this.ctx) this.rebuild(this.ctx);
  }
}
