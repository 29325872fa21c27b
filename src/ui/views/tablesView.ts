/**
 * The paper's Tables 2-5 regenerated beside the printed values. A computed value that does
 * not round to the printed digits is highlighted; clicking a condition loads it.
 */
import { PROCEDURES, type ProcedureKey } from '../../core/procedures/procedures';
import type { PaperTableRow } from '../../core/procedures/teaching';
import { formatLen } from '../format';
import { ScrollCues } from '../scrollCue';
import { html, type TeachingView, type ViewContext } from './common';

type Key = 'threeD' | 'sekine' | 'redonnet' | 'bedi';
const KEYS: ReadonlyArray<[Key, ProcedureKey]> = [
  ['threeD', 'exact'],
  ['sekine', 'sekine'],
  ['redonnet', 'redonnet'],
  ['bedi', 'bedi'],
];

export class TablesView implements TeachingView {
  readonly id = 'tables';
  readonly title = "The paper's tables";
  readonly element = html('div', { class: 'view-tables', 'data-testid': 'paper-tables' });
  private rows: readonly PaperTableRow[] = [];
  private readonly why: HTMLElement;
  /** Each table's box, shaded at an edge with more of the table beyond it (a narrow phone). */
  private readonly cues = new ScrollCues();

  constructor(onLoad: (c: { R: number; Rcr: number; rho: number; h: number }) => void) {
    const note = html(
      'p',
      { class: 'view-note' },
      'Each cell: printed / recomputed, in mm as the paper prints them (in either unit). Highlighted: the recomputed value does not round to the printed digits. ' +
        'Tables 4-5 evaluate Eqs. 12-13 at the printed 3D L/2, as the paper did. Click a condition to load it.',
    );
    const why = html(
      'p',
      { class: 'view-note', 'data-testid': 'paper-tables-why' },
      "Why the printed 3D column is 0.0005-0.013 mm low: the paper's Figure 1 leaves two things open, whether eta of Eq. 2 is normalised and how far the search of steps 15-16 runs, " +
        'and its search range can stop just before the true maximum. One plausible reading (Eq. 2 as printed, the range from the single-contact section to the angle of its P_hp) ' +
        'returns the printed 1.879 mm for R = 3, Rcr = 1, rho = 5, h = 0.10, where the true maximum is 1.892 mm. ' +
        "The exact values here agree with brute-force sampling of the torus surface and with the paper's own procedure run to convergence (the step-by-step view), so they are not tuned to the printed column.",
    );
    this.why = why;
    this.element.append(note, why);
    this.element.addEventListener('click', (e) => {
      const tr = (e.target as HTMLElement).closest('tr[data-condition]');
      const row = tr ? this.rows[Number(tr.getAttribute('data-condition'))] : undefined;
      if (row) onLoad({ R: row.R, Rcr: row.Rcr, rho: row.rho, h: row.h });
    });
  }

  private table(caption: string, what: 'half' | 'height'): HTMLTableElement {
    // A grid of selectable rows: the row of the condition on screen is the selected one.
    const table = html('table', { class: 'paper-table', role: 'grid', 'data-testid': `paper-table-${what}` });
    table.append(html('caption', {}, caption));
    const head = html('tr');
    for (const t of [
      'Table',
      // Each column names its unit: the paper's conditions in mm and degrees, whatever the page's unit.
      'R [mm]',
      'Rcr [mm]',
      'rho [\u00b0]',
      what === 'half' ? 'h [mm]' : 'L/2 (3D) [mm]',
      ...KEYS.map(([, p]) => PROCEDURES[p].shortLabel),
    ]) {
      head.append(html('th', { scope: 'col' }, t));
    }
    const thead = html('thead');
    thead.append(head);
    const tbody = html('tbody');
    this.rows.forEach((r, i) => {
      const tr = html('tr', {
        'data-condition': String(i),
        tabindex: '0',
        'aria-selected': 'false',
        title: 'Load this condition into the calculator',
      });
      tr.addEventListener('keydown', (e) => {
        if (e.key === 'Enter') tr.click();
      });
      tr.append(
        html('td', {}, String(what === 'half' ? r.table : r.table + 2)),
        html('td', {}, String(r.R)),
        html('td', {}, String(r.Rcr)),
        html('td', {}, String(r.rho)),
        html('td', {}, String(what === 'half' ? r.h : r.printedHalf.threeD)),
      );
      for (const [key, proc] of KEYS) {
        const printed = what === 'half' ? r.printedHalf[key] : r.printedHeight[key];
        const computed = what === 'half' ? r.computedHalf[key] : r.computedHeight[key];
        const off = Math.abs(computed - printed) > 0.0005 + 1e-12;
        const td = html('td', {
          class: off ? 'deviates' : '',
          'data-procedure': proc,
          'data-testid': `paper-${what}-${i}-${proc}`,
        });
        td.append(
          html('span', { class: 'printed' }, printed.toFixed(3)),
          document.createTextNode(' / '),
          html('span', { class: 'computed' }, formatLen(computed, 'mm')),
        );
        tr.append(td);
      }
      tbody.append(tr);
    });
    table.append(thead, tbody);
    return table;
  }

  /**
   * A table in a box that scrolls sideways when the screen is narrower than the table (360 px),
   * focusable so keys reach it, its edge with more beyond it shaded (scrollCue.ts).
   */
  private scrolling(table: HTMLTableElement, name: string): HTMLElement {
    const box = html('div', {
      class: 'table-scroll',
      tabindex: '0',
      role: 'group',
      'aria-label': `${name} (scrolls sideways when wider than the screen)`,
    });
    box.append(table);
    const frame = html('div', { class: 'table-frame' });
    frame.append(box);
    this.cues.watch(box, frame);
    return frame;
  }

  /** The tables are recomputed in the worker; they are fixed conditions, so they are built once. */
  update(ctx: ViewContext): void {
    if (this.rows.length === 0) {
      this.rows = ctx.data.tables;
      this.why.after(
        this.scrolling(this.table('Tables 2-3: L/2 [mm] for h', 'half'), 'Tables 2-3'),
        this.scrolling(this.table('Tables 4-5: h [mm] at the printed 3D L/2', 'height'), 'Tables 4-5'),
      );
    }
    this.markSelected(ctx);
  }

  /** Marks the rows whose condition is the one on screen (the paper's case: plane, no tilt, one-way). */
  private markSelected(ctx: ViewContext): void {
    const f = ctx.data.forward;
    const paperCase = f.tiltAngleDeg === 0 && f.pattern === 'one-way' && f.surface.kind === 'plane';
    for (const tr of this.element.querySelectorAll<HTMLElement>('tr[data-condition]')) {
      const r = this.rows[Number(tr.dataset.condition)];
      const on =
        paperCase &&
        r !== undefined &&
        r.R === f.toolRadiusMm &&
        r.Rcr === f.cornerRadiusMm &&
        r.rho === f.leadAngleDeg &&
        r.h === f.scallopHeightMm;
      tr.setAttribute('aria-selected', String(on));
    }
  }

  highlight(key: ProcedureKey | null): void {
    for (const td of this.element.querySelectorAll<HTMLElement>('td[data-procedure]')) {
      td.classList.toggle('emph', key !== null && td.dataset.procedure === key);
    }
  }
}
