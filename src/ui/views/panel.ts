/**
 * The teaching views in one tabbed panel. Views are built on first use; `?view=` opens one.
 * The panel is told when its data no longer answers the inputs on screen, and then says so.
 */

import type { ProcedureKey } from '../../core/procedures/procedures';
import type { TabName } from '../i18n/catalogue';
import { localDecimal } from '../i18n/langChoice';
import { catalogue } from '../i18n/words';
import { ChartView } from './chartView';
import { html, type PageViewContext, type TeachingView, type ViewContext, type ViewId } from './common';
import { curvedViewNote } from './curvedViewText';
import { FormulasView } from './formulasView';
import { ProfileView } from './profileView';
import { StepperView, type TraceDisplay } from './stepperView';
import { type SurfaceSource, SurfaceView } from './surfaceView';
import { TablesView } from './tablesView';
import { chartTitle, threeAxisViewNote } from './threeAxisViewText';

export type { ViewId };

export class TeachingPanel {
  private readonly views: TeachingView[];
  private readonly tabs = new Map<ViewId, HTMLButtonElement>();
  /** The tabs' list (its accessible name follows the language in force, as the tabs' names). */
  private readonly list: HTMLElement;
  private readonly ids: ViewId[];
  private readonly staleNote = html('p', { class: 'views-stale', 'data-testid': 'views-stale', role: 'status' });
  private readonly message = html('p', { class: 'view-note views-message', 'data-testid': 'views-message' });
  /** What a view shows for a three-axis question, in one neutral line (threeAxisViewText.ts). */
  private readonly pageNote = html('p', { class: 'view-note views-page-note', 'data-testid': 'views-page-note' });
  /** A three-axis question on a sloped plane: the plane at the equivalent posture, drawn by the views that draw planes. */
  private equivalent: ViewContext | null = null;
  private active: ViewId;
  private ctx: ViewContext | null = null;
  /** A doubly curved or three-axis reply to the inputs on screen, or null (the views show ctx's). */
  private pageCtx: PageViewContext | null = null;
  /** Why the data does not answer the inputs on screen (the loader's word), or null. */
  private staleText: string | null = null;
  private highlighted: ProcedureKey | null = null;

  constructor(
    private readonly root: HTMLElement,
    display: TraceDisplay,
    onLoadCondition: (c: { R: number; Rcr: number; rho: number; h: number }) => void,
    initial: ViewId,
    surface: SurfaceSource,
  ) {
    this.views = [
      new ProfileView(),
      new ChartView(),
      new TablesView(onLoadCondition),
      new StepperView(display),
      new FormulasView(),
      new SurfaceView(surface),
    ];
    this.ids = this.views.map((v) => v.id);
    this.active = initial;
    const list = html('div', { role: 'tablist', 'aria-label': 'Teaching views', class: 'tabs' });
    this.list = list;
    const panels = html('div', { class: 'tab-panels' });
    for (const view of this.views) {
      const tab = html(
        'button',
        {
          role: 'tab',
          type: 'button',
          id: `tab-${view.id}`,
          'aria-controls': `panel-${view.id}`,
          'data-view': view.id,
        },
        view.title,
      );
      tab.addEventListener('click', () => this.show(view.id));
      tab.addEventListener('keydown', (e) => this.arrowKeys(e, view.id));
      list.append(tab);
      this.tabs.set(view.id, tab);
      const panel = html('div', {
        role: 'tabpanel',
        id: `panel-${view.id}`,
        'aria-labelledby': `tab-${view.id}`,
        class: 'tab-panel',
      });
      panel.append(view.element);
      panels.append(panel);
    }
    this.staleNote.hidden = true;
    this.message.hidden = true;
    this.pageNote.hidden = true;
    root.append(list, this.staleNote, this.message, this.pageNote, panels);
    this.show(initial);
  }

  /** Arrow keys move to the next or previous tab (wrapping), Home and End to the first and last. */
  private arrowKeys(e: KeyboardEvent, id: ViewId): void {
    const i = this.ids.indexOf(id);
    const n = this.ids.length;
    const targets: Record<string, ViewId | undefined> = {
      ArrowRight: this.ids[(i + 1) % n],
      ArrowLeft: this.ids[(i + n - 1) % n],
      Home: this.ids[0],
      End: this.ids[n - 1],
    };
    const next = targets[e.key];
    if (next) {
      e.preventDefault();
      this.show(next);
      this.tabs.get(next)?.focus();
    }
  }

  get activeView(): ViewId {
    return this.active;
  }

  show(id: ViewId): void {
    this.active = id;
    for (const view of this.views) {
      const on = view.id === id;
      const tab = this.tabs.get(view.id);
      tab?.setAttribute('aria-selected', String(on));
      tab?.setAttribute('tabindex', on ? '0' : '-1');
      const panel = view.element.parentElement;
      if (panel) panel.hidden = !on;
      if (on) this.updateView(view);
      view.setVisible?.(on);
    }
    this.root.dataset.activeView = id;
    this.showStale();
  }

  /** True when the view draws the page question itself (pageKinds). */
  private drawsPage(view: TeachingView): boolean {
    return this.pageCtx !== null && (view.pageKinds?.includes(this.pageCtx.kind) ?? false);
  }

  /**
   * True when the view draws the question on screen: any plane's or cylinder's; a page question of
   * its pageKinds; a sloped plane machined three-axis as the plane at its equivalent posture.
   */
  private draws(view: TeachingView): boolean {
    return this.pageCtx === null || this.drawsPage(view) || this.equivalent !== null;
  }

  private updateView(view: TeachingView): void {
    if (this.drawsPage(view) && this.pageCtx !== null) view.updatePage?.(this.pageCtx);
    else if (this.pageCtx !== null && this.equivalent !== null) {
      if (view.updateEquivalent) view.updateEquivalent(this.equivalent, this.pageCtx);
      else view.update(this.equivalent);
    } else if (this.ctx !== null) view.update(this.ctx);
  }

  /** The language changed: the tabs named anew, and the visible view drawn in its words. */
  relabel(): void {
    this.nameTabs();
    const view = this.views.find((v) => v.id === this.active);
    if (view) this.updateView(view);
  }

  /**
   * The tab names follow what the views draw (the chart's: the five-axis sweeps, the slope's, the
   * radii's), in the language in force (i18n/words.ts; English: the views' own titles).
   */
  nameTabs(): void {
    const words = catalogue();
    const listName = words?.labels.teaching ?? 'Teaching views';
    if (this.list.getAttribute('aria-label') !== listName) this.list.setAttribute('aria-label', listName);
    for (const view of this.views) {
      const tab = this.tabs.get(view.id);
      const english = view.id === 'chart' ? chartTitle(this.pageCtx?.kind ?? null) : view.title;
      const name = words?.tabs[english as TabName] ?? english;
      if (tab && tab.textContent !== name) tab.textContent = name;
    }
  }

  /** The neutral line over the visible view for a three-axis question or a doubly curved point (what it shows), or none. */
  private showPageNote(): void {
    const page = this.staleText === null ? this.pageCtx : null;
    const text =
      page === null
        ? null
        : page.kind === 'three-axis'
          ? threeAxisViewNote(this.active, page.data, catalogue()?.viewNotes)
          : curvedViewNote(this.active, catalogue()?.viewNotes);
    this.pageNote.hidden = text === null;
    // In the language in force (its numbers with its decimal sign); the views are otherwise marked English.
    const local = text === null ? '' : localDecimal(text, catalogue());
    if (this.pageNote.textContent !== local) this.pageNote.textContent = local;
    const lang = catalogue()?.lang;
    if (lang === undefined) this.pageNote.removeAttribute('lang');
    else this.pageNote.lang = lang;
  }

  /** Data that answers the inputs on screen: only the visible view redraws now; the others when shown. */
  update(ctx: ViewContext): void {
    this.ctx = ctx;
    this.pageCtx = null;
    this.equivalent = null;
    this.nameTabs();
    this.showStale();
    this.message.hidden = true;
    this.root.classList.remove('no-data');
    for (const view of this.views) {
      if (view.id === this.active || view.id === 'tables') view.update(ctx);
    }
    this.highlight(this.highlighted);
  }

  /**
   * A doubly curved point's or three-axis machining's data that answers the inputs on screen: the
   * views that draw its kind draw it (the visible one now); the others say neutrally what they show
   * (showPageNote; their last picture answers other inputs, so it is hidden, not greyed).
   */
  updatePage(ctx: PageViewContext): void {
    this.pageCtx = ctx;
    this.equivalent =
      ctx.kind === 'three-axis' && ctx.data.plane !== null ? { data: ctx.data.plane, unit: ctx.unit } : null;
    this.message.hidden = true;
    this.root.classList.remove('no-data');
    this.nameTabs();
    for (const view of this.views) if (view.id === this.active || view.id === 'tables') this.updateView(view);
    this.showStale();
    this.highlight(this.highlighted);
  }

  /**
   * Marks every view as out of date (`text` says why) or current again (null). While marked, the
   * views keep their last picture, greyed, under the note; their numbers are not the inputs'. A
   * view that does not draw the page question on screen shows only its note.
   */
  setStale(text: string | null): void {
    this.staleText = text;
    this.showStale();
  }

  private showStale(): void {
    const active = this.views.find((v) => v.id === this.active);
    const elsewhere = active !== undefined && !this.draws(active);
    // A three-axis question's and a doubly curved point's views say what they show in the neutral
    // line (showPageNote), not here.
    const text = this.staleText;
    this.root.classList.toggle('stale', text !== null);
    this.root.classList.toggle('elsewhere', this.staleText === null && elsewhere);
    this.staleNote.hidden = text === null;
    if (this.staleNote.textContent !== (text ?? '')) this.staleNote.textContent = text ?? '';
    this.showPageNote();
  }

  /** A valid state with nothing to draw (no scallop): said in words instead of the views. */
  showMessage(text: string): void {
    this.message.textContent = text;
    this.message.hidden = false;
    this.root.classList.add('no-data');
  }

  highlight(key: ProcedureKey | null): void {
    this.highlighted = key;
    for (const view of this.views) view.highlight(key);
  }
}
