/**
 * The lookup table download (`download-table`): the exact step-over of the tool and pattern on
 * screen over a grid of scallop heights x lead angles x tilts (core/lookupTable.ts), computed by
 * the worker's `table` job on its own worker (three-axis: the programmed step over slopes x scallop
 * heights, core/output/threeAxisLookup.ts), saved as a CSV in the command line's batch format
 * in the user's unit (every dimensioned column's header names it: `h_in`, `rho_deg`; full
 * precision). The button is enabled only while the inputs on screen make a valid
 * question; the file answers the tool, pattern and surface asked for at the click (its name says
 * which), and a reply is saved only if it echoes that request.
 */

import { formatInputNumber, fromMm, type LengthUnit, unitSymbol } from '../core/input/units';
import type { RestartInfo } from '../worker/client';
import type { CurvedRequest, ThreeAxisRequest } from '../worker/pageProtocol';
import { type SolveRequest, sameTableRequest, type TableReply, type TableRequest } from '../worker/protocol';
import { tableClient } from '../worker/workers';

/**
 * The file name of a table: its tool, pattern and surface, then its unit, lengths in that unit:
 * `step-over-table_5-axis_R3_Rcr1_one-way_plane_mm.csv` (the machine first: the grid spans the
 * five-axis lead and tilt), on a cylinder `..._one-way_Rs-30_cross_mm.csv`
 * (the signed radius, negative for a concave cylinder, and the axis, as the CSV's columns give
 * them); in inches `step-over-table_5-axis_R0.25_Rcr0.0625_one-way_plane_in.csv`. Three-axis:
 * `step-over-table_3-axis_R3_Rcr1_raster30_plane_mm.csv`, `..._waterline_plane_mm.csv`, on a
 * surface of revolution `..._waterline_Rf50_Rc-20_mm.csv` (the grid spans the slope).
 */
export function tableFileName(request: TableRequest): string {
  const unit = request.unit ?? 'mm';
  const n = (mm: number) => formatInputNumber(fromMm(mm, unit));
  const t = request.tool;
  const s = t.surface;
  const r = request.radii;
  const x = request.threeAxis?.case;
  if (x !== undefined) {
    const passes = x.passes === 'raster' ? `raster${formatInputNumber(x.rasterAngleDeg ?? 0)}` : 'waterline';
    const rev = x.revolution;
    const surface =
      rev === null
        ? 'plane'
        : `Rf${rev.feedRadiusMm === null ? 'straight' : n(rev.feedRadiusMm)}_Rc${rev.crossRadiusMm === null ? 'straight' : n(rev.crossRadiusMm)}`;
    return `step-over-table_3-axis_R${n(x.toolRadiusMm)}_Rcr${n(x.cornerRadiusMm)}_${passes}_${surface}_${unitSymbol(unit)}.csv`;
  }
  const surface =
    r !== undefined
      ? `Rf${n(r.feedRadiusMm)}_Rc${n(r.crossRadiusMm)}`
      : s.kind === 'cylinder'
        ? `Rs${n(s.radiusMm)}_${s.axis}`
        : 'plane';
  return `step-over-table_5-axis_R${n(t.toolRadiusMm)}_Rcr${n(t.cornerRadiusMm)}_${t.pattern}_${surface}_${unitSymbol(unit)}.csv`;
}

/** What the status line says about a table saved. */
export function tableSummary(reply: Extract<TableReply, { ok: true }>): string {
  const g = reply.request.grid;
  const unit = reply.request.unit ?? 'mm';
  const range = (v: readonly number[]) => `${formatInputNumber(v[0] ?? 0)} to ${formatInputNumber(v.at(-1) ?? 0)}`;
  const h = g.scallopHeightsMm.map((mm) => fromMm(mm, unit));
  const axes =
    reply.request.threeAxis !== undefined
      ? `x slope ${range(reply.request.threeAxis.slopesDeg)} deg, the programmed step (${reply.request.threeAxis.case.passes === 'raster' ? 'Lxy' : 'dz'}) in each row; `
      : `x lead ${range(g.leadAnglesDeg)} deg x tilt ${range(g.tiltAnglesDeg)} deg; `;
  return (
    `Saved ${tableFileName(reply.request)}: ${reply.rows} rows, h ${range(h)} ${unitSymbol(unit)} ` +
    axes +
    `${reply.emptyCells} cells outside the valid domain are left empty, the reason in the error column.`
  );
}

/** The download button and its status line (see the module comment). */
export class LookupDownload {
  private current: SolveRequest | CurvedRequest | ThreeAxisRequest | null = null;
  private unit: LengthUnit = 'mm';
  private asked: TableRequest | null = null;
  /** The first click waits for the grid's code (tableRequest.ts): the button stays disabled meanwhile. */
  private loadingGrid = false;
  private client: ReturnType<typeof tableClient> | null = null;

  constructor(
    private readonly button: HTMLButtonElement,
    private readonly status: HTMLElement,
  ) {
    button.disabled = true;
    button.addEventListener('click', () => void this.ask());
  }

  /**
   * The inputs on screen changed: the request they ask, or null (invalid, or being typed). The file
   * is in `unit`, the user's.
   */
  want(request: SolveRequest | CurvedRequest | ThreeAxisRequest | null, unit: LengthUnit): void {
    this.current = request;
    this.unit = unit;
    this.button.disabled = this.current === null || this.asked !== null || this.loadingGrid;
  }

  private async ask(): Promise<void> {
    if (this.current === null || this.asked !== null || this.loadingGrid) return;
    const current = this.current;
    this.button.disabled = true;
    this.status.textContent = 'Computing the table in the worker...';
    // The grid's code loads on the first click (not with the first result).
    this.loadingGrid = true;
    const { tableRequestOf } = await import('./tableRequest');
    this.loadingGrid = false;
    const request = tableRequestOf(current, this.unit);
    this.asked = request;
    this.client ??= tableClient({
      onReply: (reply) => this.received(reply),
      onRestart: (info) => this.restarted(info),
    });
    this.client.request(request);
  }

  private restarted(info: RestartInfo): void {
    if (!info.gaveUp) {
      this.status.textContent = `The table's worker was restarted (${info.reason}); computing again...`;
      return;
    }
    this.asked = null;
    this.button.disabled = this.current === null;
    this.status.textContent = `No table: the table's worker gave up (${info.reason}). Click to try again.`;
  }

  private received(reply: TableReply): void {
    if (!sameTableRequest(reply.request, this.asked)) return;
    this.asked = null;
    this.button.disabled = this.current === null;
    if (!reply.ok) {
      this.status.textContent = `No table: ${reply.reason}`;
      return;
    }
    const url = URL.createObjectURL(new Blob([reply.csv], { type: 'text/csv;charset=utf-8' }));
    const link = document.createElement('a');
    link.href = url;
    link.download = tableFileName(reply.request);
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10_000);
    this.status.textContent = tableSummary(reply);
  }
}
