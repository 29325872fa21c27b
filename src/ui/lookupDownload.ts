/**
 * The lookup table download (`download-table`): the exact step-over of the tool and pattern on
 * screen over a grid of scallop heights x lead angles x tilts (core/lookupTable.ts), computed by
 * the worker's `table` job on its own worker, saved as a CSV in the command line's batch format
 * (mm, full precision). The button is enabled only while the inputs on screen make a valid
 * question; the file answers the tool, pattern and surface asked for at the click (its name says
 * which), and a reply is saved only if it echoes that request.
 */

import { formatInputNumber } from '../core/input/units';
import { lookupGrid } from '../core/output/lookupTable';
import { PLANE } from '../core/surfaces/cylinder';
import type { RestartInfo } from '../worker/client';
import { type CurvedRequest, isCurvedRequest } from '../worker/pageProtocol';
import { type SolveRequest, sameTableRequest, type TableReply, type TableRequest } from '../worker/protocol';
import { tableClient } from '../worker/workers';
import { THREE_AXIS_TABLE_NOTE } from './threeAxisNotes';

/** The table request for the tool, pattern and surface of a solve request (or of a doubly curved point's). */
export function tableRequestOf(request: SolveRequest | CurvedRequest): TableRequest {
  const i = request.input;
  const tool = {
    toolRadiusMm: i.toolRadiusMm,
    cornerRadiusMm: i.cornerRadiusMm,
    pattern: i.pattern,
    surface: isCurvedRequest(request) ? PLANE : request.input.surface,
  };
  const grid = lookupGrid(tool);
  return isCurvedRequest(request)
    ? { tool, grid, radii: { feedRadiusMm: request.input.feedRadiusMm, crossRadiusMm: request.input.crossRadiusMm } }
    : { tool, grid };
}

/**
 * The file name of a table: its tool, pattern and surface, in mm:
 * `step-over-table_R3_Rcr1_one-way_plane.csv`, on a cylinder `..._one-way_Rs-30_cross.csv` (the
 * signed radius, negative for a concave cylinder, and the axis, as the CSV's columns give them).
 */
export function tableFileName(request: TableRequest): string {
  const t = request.tool;
  const s = t.surface;
  const r = request.radii;
  const surface =
    r !== undefined
      ? `Rf${formatInputNumber(r.feedRadiusMm)}_Rc${formatInputNumber(r.crossRadiusMm)}`
      : s.kind === 'cylinder'
        ? `Rs${formatInputNumber(s.radiusMm)}_${s.axis}`
        : 'plane';
  return `step-over-table_R${formatInputNumber(t.toolRadiusMm)}_Rcr${formatInputNumber(t.cornerRadiusMm)}_${t.pattern}_${surface}.csv`;
}

/** What the status line says about a table saved. */
export function tableSummary(reply: Extract<TableReply, { ok: true }>): string {
  const g = reply.request.grid;
  const range = (v: readonly number[]) => `${formatInputNumber(v[0] ?? 0)} to ${formatInputNumber(v.at(-1) ?? 0)}`;
  return (
    `Saved ${tableFileName(reply.request)}: ${reply.rows} rows, h ${range(g.scallopHeightsMm)} mm ` +
    `x lead ${range(g.leadAnglesDeg)} deg x tilt ${range(g.tiltAnglesDeg)} deg; ` +
    `${reply.emptyCells} cells outside the valid domain are left empty, the reason in the error column.`
  );
}

/** The download button and its status line (see the module comment). */
export class LookupDownload {
  private current: SolveRequest | CurvedRequest | null = null;
  private asked: TableRequest | null = null;
  private client: ReturnType<typeof tableClient> | null = null;

  constructor(
    private readonly button: HTMLButtonElement,
    private readonly status: HTMLElement,
  ) {
    button.disabled = true;
    button.addEventListener('click', () => this.ask());
  }

  /**
   * The inputs on screen changed: the request they ask, or null (invalid, or being typed). With
   * `threeAxis` the button stays disabled and the status line says why (THREE_AXIS_TABLE_NOTE).
   */
  want(request: SolveRequest | CurvedRequest | null, threeAxis = false): void {
    this.current = threeAxis ? null : request;
    this.button.disabled = this.current === null || this.asked !== null;
    if (this.asked !== null) return;
    if (threeAxis) this.status.textContent = THREE_AXIS_TABLE_NOTE;
    else if (this.status.textContent === THREE_AXIS_TABLE_NOTE) this.status.textContent = '';
  }

  private ask(): void {
    if (this.current === null) return;
    const request = tableRequestOf(this.current);
    this.asked = request;
    this.button.disabled = true;
    this.status.textContent = 'Computing the table in the worker...';
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
