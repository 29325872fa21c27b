/**
 * The paper's Tables 2-5 regenerated beside the printed values. A computed value that does
 * not round to the printed digits is highlighted; clicking a condition loads it.
 */
import { PROCEDURES, type ProcedureKey } from '../../core/procedures/procedures';
import type { PaperTableRow } from '../../core/procedures/teaching';
import { formatLen } from '../format';
import { localDecimal } from '../i18n/langChoice';
import type { TableWords } from '../i18n/teachWords';
import { catalogue } from '../i18n/words';
import { ScrollCues } from '../scrollCue';
import { html, type TeachingView, type ViewContext } from './common';
import { EN_TABLES } from './tableWords';

/** The view's words in the language in force (English: tableWords.ts). */
function words(): TableWords {
  return catalogue()?.tables ?? EN_TABLES;
}

/** A text with the language in force's decimal sign. */
function local(text: string): string {
  return localDecimal(text, catalogue());
}

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
  private readonly note: HTMLElement;
  private readonly why: HTMLElement;
  /** The two tables' boxes, and the language they were built in (null: English; undefined: not built). */
  private frames: HTMLElement[] = [];
  private builtLang: string | null | undefined;
  /** The procedure emphasised (kept for a table built again). */
  private highlighted: ProcedureKey | null = null;
  /** Each table's box, shaded at an edge with more of the table beyond it (a narrow phone). */
  private readonly cues = new ScrollCues();

  constructor(onLoad: (c: { R: number; Rcr: number; rho: number; h: number }) => void) {
    const note = html('p', { class: 'view-note' }, EN_TABLES.note);
    const why = html('p', { class: 'view-note', 'data-testid': 'paper-tables-why' }, EN_TABLES.why);
    this.note = note;
    this.why = why;
    this.element.append(note, why);
    this.element.addEventListener('click', (e) => {
      const tr = (e.target as HTMLElement).closest('tr[data-condition]');
      const row = tr ? this.rows[Number(tr.getAttribute('data-condition'))] : undefined;
      if (row) onLoad({ R: row.R, Rcr: row.Rcr, rho: row.rho, h: row.h });
    });
  }

  private table(caption: string, what: 'half' | 'height', w: TableWords): HTMLTableElement {
    // A grid of selectable rows: the row of the condition on screen is the selected one.
    const table = html('table', { class: 'paper-table', role: 'grid', 'data-testid': `paper-table-${what}` });
    table.append(html('caption', {}, caption));
    const head = html('tr');
    const names = catalogue()?.procedures.names ?? PROCEDURES;
    for (const t of [
      w.table,
      // Each column names its unit: the paper's conditions in mm and degrees, whatever the page's unit.
      'R [mm]',
      'Rcr [mm]',
      'rho [\u00b0]',
      what === 'half' ? 'h [mm]' : w.printedHalf,
      ...KEYS.map(([, p]) => names[p].shortLabel),
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
        title: w.load,
      });
      tr.addEventListener('keydown', (e) => {
        if (e.key === 'Enter') tr.click();
      });
      tr.append(
        html('td', {}, String(what === 'half' ? r.table : r.table + 2)),
        html('td', {}, local(String(r.R))),
        html('td', {}, local(String(r.Rcr))),
        html('td', {}, local(String(r.rho))),
        html('td', {}, local(String(what === 'half' ? r.h : r.printedHalf.threeD))),
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
          html('span', { class: 'printed' }, local(printed.toFixed(3))),
          document.createTextNode(' / '),
          html('span', { class: 'computed' }, local(formatLen(computed, 'mm'))),
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
  private scrolling(table: HTMLTableElement, name: string, w: TableWords): HTMLElement {
    const box = html('div', {
      class: 'table-scroll',
      tabindex: '0',
      role: 'group',
      'aria-label': w.region(name),
    });
    box.append(table);
    const frame = html('div', { class: 'table-frame' });
    frame.append(box);
    this.cues.watch(box, frame);
    return frame;
  }

  /**
   * The tables are recomputed in the worker; they are fixed conditions, so they are built once, and
   * again in another language (its words, its decimal sign).
   */
  update(ctx: ViewContext): void {
    const lang = catalogue()?.lang ?? null;
    if (this.rows.length === 0) this.rows = ctx.data.tables;
    if (this.builtLang !== lang) {
      this.builtLang = lang;
      const w = words();
      this.note.textContent = local(w.note);
      this.why.textContent = local(w.why);
      for (const frame of this.frames) frame.remove();
      this.cues.clear();
      this.frames = [
        this.scrolling(this.table(w.halfCaption, 'half', w), w.halfName, w),
        this.scrolling(this.table(w.heightCaption, 'height', w), w.heightName, w),
      ];
      this.why.after(...this.frames);
      if (lang === null) this.element.removeAttribute('lang');
      else this.element.lang = lang;
      this.highlight(this.highlighted);
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
    this.highlighted = key;
    for (const td of this.element.querySelectorAll<HTMLElement>('td[data-procedure]')) {
      td.classList.toggle('emph', key !== null && td.dataset.procedure === key);
    }
  }
}
