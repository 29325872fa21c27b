/**
 * The shop sheet (issue 21; button `shop-sheet`): a modal dialog with, for the tool, posture,
 * pattern and surface on screen, the matrix of step-over by scallop height (rows) and lead angle
 * (columns; in three-axis machining the surface slope, the step as programmed), in the user's
 * unit (core/output/shopSheet.ts; words and files in shopSheetText.ts). The rows are an editable
 * list of heights; "Download CSV" saves the matrix (the unit in the header and the file name);
 * "Print" prints the sheet alone on one page (shopSheet.css). The button is enabled while the
 * inputs on screen make a valid question. Computed on the main thread when opened or when the
 * list changes (at most 12 x 7 cells: milliseconds on a plane, a third of a second at a doubly
 * curved point).
 */

import { formatInputNumber, fromMm, type LengthUnit, toMm, unitSymbol } from '../core/input/units';
import {
  passesOf,
  SHEET_HEIGHTS,
  SHEET_MARKS,
  type SheetCase,
  type SheetCell,
  type ShopSheet,
  shopSheet,
} from '../core/output/shopSheet';
import type { PageRequest } from '../worker/pageProtocol';
import { formatDeg } from './format';
import type { SheetWords } from './i18n/catalogue';
import { localDecimal } from './i18n/langChoice';
import { catalogue, describeError, describeThreeAxis } from './i18n/words';
import {
  cellText,
  heightsText,
  MAX_SHEET_ROWS,
  marksUsed,
  NO_SCALLOP_STAR,
  ownHeightMm,
  parseHeights,
  sheetCaseOf,
  sheetCsv,
  sheetFileName,
  sheetRows,
  sheetTitleLines,
  stepSymbol,
} from './shopSheetText';
import { EN_SHEET } from './shopSheetWords';
import { shownToolNameLines } from './toolName';

/** The sheet's words in the language in force (English: the sheet as written). */
function sheetWords(): SheetWords {
  return catalogue()?.sheet ?? EN_SHEET;
}

/** A text's numbers with the decimal sign of the language in force (German 0,05; every digit kept). */
function local(text: string): string {
  return localDecimal(text, catalogue());
}

/**
 * A refused cell's reason in the language in force, from what it is made of (the input errors',
 * the three-axis errors' or the sheet's own sentences); English: the core's reason. `typed` is the
 * row's h as the sheet shows it.
 */
function reasonOf(
  cell: Extract<SheetCell, { ok: false }>,
  c: SheetCase,
  unit: LengthUnit,
  typed: string,
): { readonly text: string; readonly english: boolean } {
  const words = catalogue();
  if (words === null) return { text: cell.reason, english: true };
  const own = words.sheet.refusals;
  const r = cell.refusal;
  const waterline = c.kind === 'three-axis' && passesOf(c.problem) === 'waterline';
  const text =
    r.kind === 'input'
      ? r.errors.map((e) => describeError(e, unit, e.field === 'h' ? { typed } : {})).join(' ')
      : r.kind === 'three-axis'
        ? r.errors
            .map((e) => describeThreeAxis(e, unit, e.field === 'h' ? typed : null, waterline) ?? e.message)
            .join(' ')
        : r.kind === 'curved-wall'
          ? own.curvedWall(local(`${formatInputNumber(fromMm(r.limitMm, unit))} ${unitSymbol(unit)}`), typed)
          : r.kind === 'lead-range'
            ? own.leadRange
            : r.kind === 'curved-gouge'
              ? own.curvedGouge
              : own.noStepDown;
  return { text, english: false };
}

/** An element with a class, optional test id and text (text only: nothing is parsed as HTML). */
function el<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  className = '',
  text = '',
  testId = '',
): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  if (className !== '') e.className = className;
  if (text !== '') e.textContent = text;
  if (testId !== '') e.dataset.testid = testId;
  return e;
}

/** Saves text as a file through a temporary link. */
function saveText(text: string, fileName: string, type: string): void {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** The class on <html> while the sheet is open: the print stylesheet then prints the sheet alone. */
const OPEN_CLASS = 'shop-sheet-open';

/** The button and its dialog (see the module comment). */
export class ShopSheetPanel {
  private case: SheetCase | null = null;
  private unit: LengthUnit = 'mm';
  /** The scallop height the question on screen gives (mm; a row of the sheet), or null. */
  private ownMm: number | null = null;
  /** The heights the user listed, in their unit (kept while the unit stays; a new unit starts from its defaults). */
  private heights: { unit: LengthUnit; values: readonly number[] } = { unit: 'mm', values: SHEET_HEIGHTS.mm };
  private sheet: ShopSheet | null = null;
  private readonly dialog: HTMLDialogElement;
  private readonly title: HTMLHeadingElement;
  private readonly lines: HTMLDivElement;
  private readonly table: HTMLTableElement;
  private readonly legend: HTMLUListElement;
  /** The full reason of the mark last tapped or clicked (a touch screen has no hover). */
  private readonly reason: HTMLParagraphElement;
  private readonly heightsInput: HTMLInputElement;
  private readonly heightsLabel: HTMLLabelElement;
  private readonly heightsError: HTMLParagraphElement;
  private readonly status: HTMLParagraphElement;
  private readonly scroll: HTMLDivElement;
  private readonly csv: HTMLButtonElement;
  private readonly print: HTMLButtonElement;
  private readonly close: HTMLButtonElement;

  constructor(private readonly button: HTMLButtonElement) {
    button.disabled = true;
    button.addEventListener('click', () => this.open());
    const d = el('dialog', 'shop-sheet', '', 'shop-sheet-dialog');
    d.setAttribute('aria-labelledby', 'shop-sheet-title');
    this.dialog = d;
    const page = el('div', 'sheet-page');
    this.title = el('h2', '', '', 'shop-sheet-title');
    this.title.id = 'shop-sheet-title';
    this.lines = el('div', 'sheet-lines', '', 'shop-sheet-lines');
    const scroll = el('div', 'sheet-scroll');
    this.scroll = scroll;
    // A scrolling region is reachable by keyboard (axe: scrollable-region-focusable).
    scroll.tabIndex = 0;
    scroll.setAttribute('role', 'region');
    this.table = el('table', 'sheet-table', '', 'shop-sheet-table');
    scroll.append(this.table);
    this.reason = el('p', 'sheet-reason', '', 'shop-sheet-reason');
    this.reason.setAttribute('role', 'status');
    this.reason.hidden = true;
    this.legend = el('ul', 'sheet-legend', '', 'shop-sheet-legend');
    page.append(this.title, this.lines, scroll, this.reason, this.legend);

    const tools = el('div', 'sheet-tools');
    const field = el('div', 'sheet-heights');
    this.heightsLabel = el('label');
    this.heightsLabel.htmlFor = 'shop-sheet-heights';
    this.heightsInput = el('input', '', '', 'shop-sheet-heights');
    this.heightsInput.id = 'shop-sheet-heights';
    this.heightsInput.type = 'text';
    this.heightsInput.inputMode = 'decimal';
    this.heightsInput.autocomplete = 'off';
    this.heightsInput.spellcheck = false;
    this.heightsInput.setAttribute('aria-describedby', 'shop-sheet-heights-error');
    this.heightsError = el('p', 'error', '', 'shop-sheet-heights-error');
    this.heightsError.id = 'shop-sheet-heights-error';
    field.append(this.heightsLabel, this.heightsInput, this.heightsError);
    this.heightsInput.addEventListener('change', () => this.listed());
    this.heightsInput.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') this.listed();
    });
    const buttons = el('div', 'sheet-buttons');
    // Their words are the language's when the sheet is drawn (render).
    const csv = el('button', '', '', 'shop-sheet-csv');
    csv.type = 'button';
    csv.addEventListener('click', () => this.download());
    const print = el('button', '', '', 'shop-sheet-print');
    print.type = 'button';
    print.addEventListener('click', () => window.print());
    const close = el('button', '', '', 'shop-sheet-close');
    close.type = 'button';
    close.addEventListener('click', () => this.dialog.close());
    buttons.append(csv, print, close);
    this.csv = csv;
    this.print = print;
    this.close = close;
    this.status = el('p', 'sheet-status', '', 'shop-sheet-status');
    this.status.setAttribute('role', 'status');
    tools.append(field, buttons, this.status);
    d.append(page, tools);
    d.addEventListener('close', () => document.documentElement.classList.remove(OPEN_CLASS));
    document.body.append(d);
  }

  /**
   * The inputs on screen changed: the question they ask (its tool, posture, pattern and surface
   * make the sheet), or null (invalid, or being typed), and the user's unit.
   */
  want(request: PageRequest | null, unit: LengthUnit): void {
    this.case = request === null ? null : sheetCaseOf(request);
    this.ownMm = request === null ? null : ownHeightMm(request);
    this.unit = unit;
    this.button.disabled = this.case === null;
    if (this.dialog.open && this.case !== null) this.render();
  }

  /** Opens the dialog on the sheet of the inputs on screen (nothing while they make no question). */
  open(): void {
    if (this.case === null) return;
    this.status.textContent = '';
    this.render();
    document.documentElement.classList.add(OPEN_CLASS);
    this.dialog.showModal();
  }

  /** The heights in the user's unit: the listed ones, or the unit's defaults after a change of unit. */
  private heightsInUnit(): readonly number[] {
    if (this.heights.unit !== this.unit) this.heights = { unit: this.unit, values: SHEET_HEIGHTS[this.unit] };
    return this.heights.values;
  }

  /** The user listed heights: the sheet again, or the list's message (the last sheet stays). */
  private listed(): void {
    const parsed = parseHeights(this.heightsInput.value, this.unit, sheetWords());
    if (!parsed.ok) {
      this.heightsError.textContent = parsed.message;
      this.heightsInput.setAttribute('aria-invalid', 'true');
      return;
    }
    const values = parsed.mm.map((mm) => Number(fromMm(mm, this.unit).toPrecision(12)));
    this.heights = { unit: this.unit, values };
    this.render();
  }

  private render(): void {
    const c = this.case;
    if (c === null) return;
    const unit = this.unit;
    const u = unitSymbol(unit);
    const words = sheetWords();
    const heights = this.heightsInUnit();
    this.heightsInput.value = heightsText(heights);
    this.heightsInput.removeAttribute('aria-invalid');
    this.heightsError.textContent = '';
    this.heightsLabel.textContent = words.heightsLabel(u, MAX_SHEET_ROWS);
    this.scroll.setAttribute('aria-label', words.region);
    this.csv.textContent = words.csv;
    this.print.textContent = words.print;
    this.close.textContent = words.close;
    const rows = sheetRows(heights, this.ownMm, unit);
    const sheet = shopSheet(
      c,
      rows.values.map((v) => toMm(v, unit)),
      unit,
    );
    this.sheet = sheet;
    this.title.textContent = words.title(stepSymbol(sheet), u);
    const date = new Date().toISOString().slice(0, 10);
    // The tool's own name as the user wrote it; the sheet's lines with the locale's decimal sign.
    this.lines.replaceChildren(
      ...[...shownToolNameLines(), ...sheetTitleLines(c, sheet, unit, date, words).map(local)].map((t) =>
        el('p', 'sheet-line', t),
      ),
    );
    this.renderTable(c, sheet, unit, rows, words);
    this.renderLegend(sheet, rows.own, u, words);
    this.reason.hidden = true;
    this.reason.textContent = '';
  }

  private renderTable(
    c: SheetCase,
    sheet: ShopSheet,
    unit: LengthUnit,
    rows: { values: readonly number[]; own: number | null },
    words: SheetWords,
  ): void {
    const u = unitSymbol(unit);
    const column = words.column[sheet.columnKind];
    const caption = el('caption', 'sr-only', words.caption(stepSymbol(sheet), u, sheet.columnKind));
    const head = el('tr');
    // The corner names both axes and their units, on two lines (narrow on a phone).
    const corner = el('th', 'corner');
    corner.scope = 'col';
    const axis = (name: string, unitText: string, arrow: string) => {
      const line = el('span', '', name);
      line.append(el('span', 'unit', ` (${unitText})`), ` ${arrow}`);
      return line;
    };
    corner.append(axis(column, words.deg, '\u2192'), axis('h', u, '\u2193'));
    head.append(corner);
    for (const deg of sheet.columnsDeg) {
      const th = el('th', '', local(formatDeg(deg)));
      th.scope = 'col';
      head.append(th);
    }
    const thead = el('thead');
    thead.append(head);
    const tbody = el('tbody');
    sheet.scallopHeightsMm.forEach((_, i) => {
      const value = rows.values[i] ?? 0;
      const own = value === rows.own;
      const tr = el('tr', own ? 'own-h' : '', '', own ? 'shop-sheet-own-row' : '');
      const th = el('th', '', local(heightsText([value])));
      th.scope = 'row';
      if (own) th.append(el('span', 'sr-only', words.yourH));
      tr.append(th);
      (sheet.cells[i] ?? []).forEach((cell, j) => {
        const td = el('td', cell.ok ? '' : 'refused', cell.ok ? local(cellText(cell, unit)) : '');
        if (!cell.ok) {
          // Hover shows the title; a tap or a click (a button: keyboard too) writes the reason below the table.
          // The reason in the language in force; the core's English sentence says so by its lang.
          const why = reasonOf(cell, c, unit, heightsText([value]));
          td.title = why.text;
          if (why.english) td.lang = 'en';
          const letter = cellText(cell, unit);
          const mark = el('button', 'mark', letter);
          mark.type = 'button';
          mark.lang = document.documentElement.lang;
          const where = local(
            words.where(`${heightsText([value])} ${u}`, sheet.columnKind, formatDeg(sheet.columnsDeg[j] ?? 0)),
          );
          mark.setAttribute('aria-label', words.markLabel(letter, where));
          mark.addEventListener('click', () => {
            this.reason.hidden = false;
            const reason = el('span', '', why.text);
            if (why.english) reason.lang = 'en';
            this.reason.replaceChildren(words.markReason(letter, where), reason);
          });
          td.append(mark);
        }
        tr.append(td);
      });
      tbody.append(tr);
    });
    this.table.replaceChildren(caption, thead, tbody);
  }

  private renderLegend(sheet: ShopSheet, own: number | null, u: string, words: SheetWords): void {
    const used = marksUsed(sheet);
    const items = used.marks.map((m) => el('li', '', `${SHEET_MARKS[m].letter}: ${words.marks[m]}`));
    if (used.noScallop) items.push(el('li', '', `${NO_SCALLOP_STAR} ${words.noScallop}`));
    if (own !== null) items.push(el('li', '', words.ownRow(local(`${heightsText([own])} ${u}`))));
    // How to read a mark's reason: on screen only, worded for the pointer (shopSheet.css shows one).
    if (used.marks.length > 0)
      items.push(el('li', 'hint-hover', words.hintHover), el('li', 'hint-touch', words.hintTouch));
    this.legend.replaceChildren(...items);
  }

  private download(): void {
    if (this.case === null || this.sheet === null) return;
    const name = sheetFileName(this.case, this.unit);
    saveText(sheetCsv(this.sheet, this.unit), name, 'text/csv;charset=utf-8');
    this.status.textContent = sheetWords().saved(name);
  }
}
