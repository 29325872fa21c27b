/**
 * The lookup table download (`download-table`): the exact step-over of the tool and pattern on
 * screen over a grid of scallop heights x lead angles x tilts (core/lookupTable.ts), computed by
 * the worker's `table` job on its own worker (three-axis: the programmed step over slopes x scallop
 * heights, core/output/threeAxisLookup.ts), saved as a CSV in the command line's batch format
 * in the user's unit (every dimensioned column's header names it: `h_in`, `rho_deg`; full
 * precision). The button is enabled only while the inputs on screen make a valid
 * question; the file answers the tool, pattern and surface asked for at the click (its name says
 * which), and a reply is saved only if it echoes that request. Loaded on the first press
 * (lazyButton.ts), not with the first result.
 */

import type { LengthUnit } from '../core/input/units';
import type { RestartInfo } from '../worker/client';
import type { PageRequest } from '../worker/pageProtocol';
import { sameTableRequest, type TableReply, type TableRequest } from '../worker/protocol';
import { tableClient } from '../worker/workers';
import { catalogue } from './i18n/words';
import { reasonDetail, reasonIn, setDetail } from './i18n/workerReason';

/** The download button and its status line (see the module comment). */
export class LookupDownload {
  private current: PageRequest | null = null;
  private unit: LengthUnit = 'mm';
  private asked: TableRequest | null = null;
  /** The first click waits for the grid's code (tableRequest.ts): the button stays disabled meanwhile. */
  private loadingGrid = false;
  private client: ReturnType<typeof tableClient> | null = null;
  /** The file's name and summary (lookupFile.ts), loaded with the grid's code on the first click. */
  private file: typeof import('./lookupFile') | null = null;

  constructor(
    private readonly button: HTMLButtonElement,
    private readonly status: HTMLElement,
  ) {
    button.disabled = true;
    button.addEventListener('click', () => this.open());
  }

  /**
   * The inputs on screen changed: the request they ask, or null (invalid, or being typed). The file
   * is in `unit`, the user's.
   */
  want(request: PageRequest | null, unit: LengthUnit): void {
    this.current = request;
    this.unit = unit;
    this.button.disabled = this.current === null || this.asked !== null || this.loadingGrid;
  }

  /** Asks the table of the question on screen (a press of the button). */
  open(): void {
    void this.ask();
  }

  private async ask(): Promise<void> {
    if (this.current === null || this.asked !== null || this.loadingGrid) return;
    const current = this.current;
    this.button.disabled = true;
    this.status.textContent = catalogue()?.said.tableComputing ?? 'Computing the table in the worker...';
    // The grid's code loads on the first click (not with the first result).
    this.loadingGrid = true;
    const [{ tableRequestOf }, file] = await Promise.all([import('./tableRequest'), import('./lookupFile')]);
    this.file = file;
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
    if (info.gaveUp) {
      this.asked = null;
      this.button.disabled = this.current === null;
    }
    // In the language in force (the reason worded by workerReason.ts), an exception's text in the hover title.
    const c = catalogue();
    setDetail(this.status, reasonDetail(info.reason, c));
    this.status.textContent =
      c !== null
        ? c.said.tableWorker(info.gaveUp, reasonIn(info.reason, c))
        : info.gaveUp
          ? `No table: the table's worker gave up (${info.reason}). Click to try again.`
          : `The table's worker was restarted (${info.reason}); computing again...`;
  }

  private received(reply: TableReply): void {
    if (!sameTableRequest(reply.request, this.asked)) return;
    this.asked = null;
    this.status.removeAttribute('title');
    this.button.disabled = this.current === null;
    if (!reply.ok) {
      this.status.textContent = `No table: ${reply.reason}`;
      return;
    }
    const url = URL.createObjectURL(new Blob([reply.csv], { type: 'text/csv;charset=utf-8' }));
    const link = document.createElement('a');
    link.href = url;
    link.download = this.file?.tableFileName(reply.request) ?? 'step-over-table.csv';
    document.body.append(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10_000);
    this.status.textContent = this.file?.tableSummary(reply, catalogue()) ?? '';
  }
}
