/**
 * The lookup table download (`download-table`): the exact step-over of the tool and pattern on
 * screen over a grid of scallop heights x lead angles x tilts (core/lookupTable.ts), computed by
 * the worker's `table` job on its own worker, saved as a CSV in the command line's batch format
 * in the user's unit (every dimensioned column's header names it: `h_in`, `rho_deg`; full
 * precision). The button is enabled only while the inputs on screen make a valid
 * question; the file answers the tool, pattern and surface asked for at the click (its name says
 * which), and a reply is saved only if it echoes that request.
 */

import { formatInputNumber, fromMm, type LengthUnit, unitSymbol } from '../core/input/units';
import type { RestartInfo } from '../worker/client';
import type { CurvedRequest } from '../worker/pageProtocol';
import { type SolveRequest, sameTableRequest, type TableReply, type TableRequest } from '../worker/protocol';
import { tableClient } from '../worker/workers';
import { THREE_AXIS_TABLE_NOTE } from './threeAxisNotes';

/**
 * The file name of a table: its tool, pattern and surface, then its unit, lengths in that unit:
 * `step-over-table_5-axis_R3_Rcr1_one-way_plane_mm.csv` (the machine first: the grid spans the
 * five-axis lead and tilt), on a cylinder `..._one-way_Rs-30_cross_mm.csv`
 * (the signed radius, negative for a concave cylinder, and the axis, as the CSV's columns give
 * them); in inches `step-over-table_5-axis_R0.25_Rcr0.0625_one-way_plane_in.csv`.
 */
export function tableFileName(request: TableRequest): string {
  const unit = request.unit ?? 'mm';
  const n = (mm: number) => formatInputNumber(fromMm(mm, unit));
  const t = request.tool;
  const s = t.surface;
  const r = request.radii;
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
  return (
    `Saved ${tableFileName(reply.request)}: ${reply.rows} rows, h ${range(h)} ${unitSymbol(unit)} ` +
    `x lead ${range(g.leadAnglesDeg)} deg x tilt ${range(g.tiltAnglesDeg)} deg; ` +
    `${reply.emptyCells} cells outside the valid domain are left empty, the reason in the error column.`
  );
}

/** The download button and its status line (see the module comment). */
export class LookupDownload {
  private current: SolveRequest | CurvedRequest | null = null;
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
   * The inputs on screen changed: the request they ask, or null (invalid, or being typed). With
   * `threeAxis` the button stays disabled and the status line says why (THREE_AXIS_TABLE_NOTE).
   * The file is in `unit`, the user's.
   */
  want(request: SolveRequest | CurvedRequest | null, unit: LengthUnit, threeAxis = false): void {
    this.current = threeAxis ? null : request;
    this.unit = unit;
    this.button.disabled = this.current === null || this.asked !== null || this.loadingGrid;
    if (this.asked !== null || this.loadingGrid) return;
    if (threeAxis) this.status.textContent = THREE_AXIS_TABLE_NOTE;
    else if (this.status.textContent === THREE_AXIS_TABLE_NOTE) this.status.textContent = '';
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
