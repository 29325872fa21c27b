/**
 * The teaching views in one tabbed panel. Views are built on first use; `?view=` opens one.
 */
import type { ProcedureKey } from '../../worker/protocol';
import { ChartView } from './chartView';
import { html, type TeachingView, type ViewContext } from './common';
import { FormulasView } from './formulasView';
import { ProfileView } from './profileView';
import { StepperView, type TraceDisplay } from './stepperView';
import { TablesView } from './tablesView';

export type ViewId = TeachingView['id'];
export const VIEW_IDS: readonly ViewId[] = ['profile', 'chart', 'tables', 'stepper', 'formulas'];

export class TeachingPanel {
  private readonly views: TeachingView[];
  private readonly tabs = new Map<ViewId, HTMLButtonElement>();
  private active: ViewId;
  private ctx: ViewContext | null = null;
  private highlighted: ProcedureKey | null = null;

  constructor(
    private readonly root: HTMLElement,
    display: TraceDisplay,
    onLoadCondition: (c: { R: number; Rcr: number; rho: number; h: number }) => void,
    initial: ViewId,
  ) {
    this.views = [
      new ProfileView(),
      new ChartView(),
      new TablesView(onLoadCondition),
      new StepperView(display),
      new FormulasView(),
    ];
    this.active = initial;
    const list = html('div', { role: 'tablist', 'aria-label': 'Teaching views', class: 'tabs' });
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
    root.append(list, panels);
    this.show(initial);
  }

  private arrowKeys(e: KeyboardEvent, id: ViewId): void {
    const i = VIEW_IDS.indexOf(id);
    const next =
      e.key === 'ArrowRight'
        ? VIEW_IDS[(i + 1) % VIEW_IDS.length]
        : e.key === 'ArrowLeft'
          ? VIEW_IDS[(i + VIEW_IDS.length - 1) % VIEW_IDS.length]
          : null;
    if (next) {
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
      if (on && this.ctx) view.update(this.ctx);
      view.setVisible?.(on);
    }
    this.root.dataset.activeView = id;
  }

  /** New results: only the visible view redraws now; the others when shown. */
  update(ctx: ViewContext): void {
    this.ctx = ctx;
    for (const view of this.views) {
      if (view.id === this.active || view.id === 'tables') view.update(ctx);
    }
    this.highlight(this.highlighted);
  }

  highlight(key: ProcedureKey | null): void {
    this.highlighted = key;
    for (const view of this.views) view.highlight(key);
  }
}
