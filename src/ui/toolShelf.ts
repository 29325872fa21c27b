/**
 * The shop's own tools on the page: saved tools kept in the browser (savedTools.ts) and a Fusion
 * 360 tool library imported through a file picker or dropped on the shelf (core/input/toolLibrary.ts);
 * choosing one fills the tool fields and names the answer; each tool is listed in its own unit, and
 * one in another unit than the page's offers that unit in one tap. Names are shown as text
 * (textContent), never as HTML.
 */

import { checkTool, LIBRARY_MAX_CHARS, type LibraryTool, parseFusionLibrary } from '../core/input/toolLibrary';
import { type LengthUnit, unitSymbol } from '../core/input/units';
import { browserStorage } from './browserStorage';
import { html } from './dom';
import { fieldText } from './fieldText';
import { SavedTools, type ToolStorage } from './savedTools';
import { toolLabel, toolLength } from './toolName';

/** What the shelf asks of the page. */
export interface ToolShelfEvents {
  /** A tool was chosen: fill the tool fields with its D and corner radius (mm), and keep its name. */
  readonly onTool: (tool: LibraryTool) => void;
  /** The user took the unit a chosen tool is sized in (the one-tap offer after choosing it). */
  readonly onUnit: (unit: LengthUnit) => void;
  /** The tool the fields hold now: D and corner radius in mm (text when a field is not a number). */
  readonly current: () => { readonly diameterMm: number | string; readonly cornerRadiusMm: number | string };
}

/** The most problem lines listed after an import (the rest counted). */
const PROBLEMS_SHOWN = 8;

/** The saved tools' list, the save and delete controls, and the library import with its list. */
export class ToolShelf {
  private readonly saved: SavedTools;
  private library: readonly LibraryTool[] = [];
  private unit: LengthUnit = 'mm';
  private readonly savedList: HTMLSelectElement;
  private readonly libraryList: HTMLSelectElement;
  private readonly name: HTMLInputElement;
  private readonly flutes: HTMLInputElement;
  private readonly status: HTMLElement;

  constructor(
    root: HTMLElement,
    private readonly events: ToolShelfEvents,
    storage: ToolStorage | null = browserStorage(),
  ) {
    this.saved = new SavedTools(storage);
    this.savedList = html('select', { 'data-testid': 'saved-tools', 'aria-label': 'Saved tools' });
    this.libraryList = html('select', {
      'data-testid': 'library-tools',
      'aria-label': 'Tools of the imported library',
    });
    this.libraryList.hidden = true;
    this.name = html('input', {
      type: 'text',
      'data-testid': 'tool-name',
      placeholder: 'name',
      'aria-label': 'Tool name',
      maxlength: '80',
    });
    this.flutes = html('input', {
      type: 'text',
      inputmode: 'numeric',
      'data-testid': 'tool-flutes',
      placeholder: 'flutes',
      'aria-label': 'Flutes',
      size: '3',
    });
    const save = html('button', { type: 'button', 'data-testid': 'save-tool' }, 'Save this tool');
    const remove = html('button', { type: 'button', 'data-testid': 'delete-tool' }, 'Delete');
    const file = html('input', {
      type: 'file',
      accept: '.json,application/json',
      'data-testid': 'tool-library-import',
    });
    this.status = html('div', { class: 'tool-shelf-status', 'data-testid': 'tool-library-status', role: 'status' });
    const saveLine = html('div', { class: 'tool-shelf-line' });
    saveLine.append(this.name, this.flutes, save);
    const savedLine = html('div', { class: 'tool-shelf-line' });
    savedLine.append(this.savedList, remove);
    const importLabel = html(
      'label',
      { class: 'tool-shelf-import' },
      'Import a Fusion 360 tool library (JSON), or drop it here ',
    );
    importLabel.append(file);
    root.append(savedLine, saveLine, importLabel, this.libraryList, this.status);
    this.savedList.addEventListener('change', () => this.choose(this.saved.tools, this.savedList));
    this.libraryList.addEventListener('change', () => this.choose(this.library, this.libraryList));
    save.addEventListener('click', () => this.saveCurrent());
    remove.addEventListener('click', () => {
      const tool = this.saved.tools[Number(this.savedList.value)];
      if (tool === undefined) {
        this.say(['Choose a saved tool to delete.']);
        return;
      }
      this.saved.remove(tool.name);
      this.drawSaved();
      this.say([this.saved.problem ?? `Deleted "${tool.name}".`]);
    });
    file.addEventListener('change', () => {
      const f = file.files?.[0];
      if (f) void this.importFile(f);
      file.value = '';
    });
    root.addEventListener('dragover', (e) => {
      e.preventDefault();
      root.classList.add('dragging');
    });
    root.addEventListener('dragleave', () => root.classList.remove('dragging'));
    root.addEventListener('drop', (e) => {
      e.preventDefault();
      root.classList.remove('dragging');
      const f = e.dataTransfer?.files[0];
      if (f) void this.importFile(f);
    });
    this.drawSaved();
    if (this.saved.problem !== null) this.say([this.saved.problem]);
  }

  /** The page's unit (a tool is listed in its own; a new tool is saved in this one). */
  render(unit: LengthUnit): void {
    if (unit === this.unit) return;
    this.unit = unit;
    // The offer to switch to a chosen tool's unit is taken or moot.
    this.offer?.remove();
    this.offer = null;
  }

  private offer: HTMLButtonElement | null = null;

  private choose(tools: readonly LibraryTool[], list: HTMLSelectElement): void {
    const tool = tools[Number(list.value)];
    if (list.value === '' || tool === undefined) return;
    this.events.onTool(tool);
    this.name.value = tool.name;
    this.flutes.value = tool.flutes === null ? '' : String(tool.flutes);
    this.say([`Filled D and the corner radius of "${tool.name}".`]);
    if (tool.unit === this.unit) return;
    // One tap to the unit the tool is sized in (the fields then read its own numbers: 0.5, 0.03).
    const word = tool.unit === 'in' ? 'inch' : 'mm';
    const offer = html('button', { type: 'button', 'data-testid': 'tool-unit-offer' }, `Work in ${word}`);
    offer.title = `"${tool.name}" is sized in ${word}: show every number in ${word}.`;
    offer.addEventListener('click', () => this.events.onUnit(tool.unit));
    this.status.append(html('p', {}, `This tool is sized in ${word} (D ${toolLength(tool.diameterMm, tool.unit)}). `));
    this.status.lastElementChild?.append(offer);
    this.offer = offer;
  }

  private saveCurrent(): void {
    const { diameterMm, cornerRadiusMm } = this.events.current();
    const flutesText = this.flutes.value.trim();
    const flutes = flutesText === '' ? null : Number(flutesText);
    const d = typeof diameterMm === 'number' ? `D${fieldText('R', diameterMm, this.unit)}` : 'tool';
    const r = typeof cornerRadiusMm === 'number' ? ` R${fieldText('R', cornerRadiusMm, this.unit)}` : '';
    const name = this.name.value.trim() || `${d}${r} ${unitSymbol(this.unit)}`;
    const checked = checkTool(name, diameterMm, cornerRadiusMm, flutes, this.unit);
    if (!checked.ok) {
      this.say([`Not saved: the tool's ${checked.field} ${checked.why}.`]);
      return;
    }
    this.saved.save(checked.tool);
    this.drawSaved();
    this.savedList.value = '0';
    this.say([this.saved.problem ?? `Saved "${checked.tool.name}" in this browser.`]);
  }

  /** Reads a Fusion 360 library file and lists its tools (the status says what was read and what not). */
  async importFile(file: File): Promise<void> {
    if (file.size > LIBRARY_MAX_CHARS)
      return this.say([`"${file.name}" is over ${LIBRARY_MAX_CHARS / 1e6} MB: not a tool library.`]);
    let text: string;
    try {
      text = await file.text();
    } catch {
      this.say([`"${file.name}" could not be read.`]);
      return;
    }
    const read = parseFusionLibrary(text);
    // A file with no tool leaves the list imported before as it was.
    if (read.tools.length > 0) {
      this.library = read.tools;
      this.drawLibrary();
    }
    const head = `"${file.name}": ${read.tools.length} tool${read.tools.length === 1 ? '' : 's'} read${read.tools.length > 0 ? '; choose one below' : ''}.`;
    const more = read.problems.length - PROBLEMS_SHOWN;
    this.say([head, ...read.problems.slice(0, PROBLEMS_SHOWN), ...(more > 0 ? [`and ${more} more.`] : [])]);
  }

  private drawSaved(): void {
    const n = this.saved.tools.length;
    this.fill(this.savedList, this.saved.tools, n === 0 ? 'no saved tools yet' : `saved tools (${n})`);
  }

  private drawLibrary(): void {
    this.libraryList.hidden = this.library.length === 0;
    this.fill(this.libraryList, this.library, `library tools (${this.library.length})`);
  }

  private fill(list: HTMLSelectElement, tools: readonly LibraryTool[], prompt: string): void {
    list.replaceChildren(html('option', { value: '' }, prompt));
    tools.forEach((t, i) => {
      list.append(html('option', { value: String(i) }, toolLabel(t)));
    });
  }

  /** Shows lines in the status (as text). */
  private say(lines: readonly string[]): void {
    this.status.replaceChildren(...lines.map((line) => html('p', {}, line)));
  }
}
