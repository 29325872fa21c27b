/**
 * Highlighting a procedure across the page: hovering or focusing a procedure anywhere shows it
 * for a moment; a click (or Enter) on a results row selects it, and the selection stays until
 * clicked again. Reports the key to show; marks the results rows itself.
 */
import { PROCEDURE_KEYS, type ProcedureKey } from '../core/procedures/procedures';

function keyOf(target: EventTarget | null): ProcedureKey | null {
  const el = target instanceof Element ? target.closest<HTMLElement>('[data-procedure]') : null;
  const key = el?.dataset.procedure;
  return PROCEDURE_KEYS.find((k) => k === key) ?? null;
}

export class Highlighter {
  private highlighted: ProcedureKey | null = null;
  private selected: ProcedureKey | null = null;

  constructor(
    private readonly root: HTMLElement,
    private readonly onChange: (key: ProcedureKey | null) => void,
  ) {
    // Its rows are selectable (click, Enter): the results table is a grid with aria-selected rows.
    root.querySelector('.procedures')?.setAttribute('role', 'grid');
    root.addEventListener('mouseover', (e) => this.set(keyOf(e.target) ?? this.selected));
    root.addEventListener('focusin', (e) => this.set(keyOf(e.target) ?? this.selected));
    root.addEventListener('click', (e) => this.select(e.target));
    root.addEventListener('keydown', (e) => {
      if (e.key === 'Enter') this.select(e.target);
    });
  }

  get current(): ProcedureKey | null {
    return this.highlighted;
  }

  private select(target: EventTarget | null): void {
    const row = target instanceof Element ? target.closest('.procedures tr[data-procedure]') : null;
    if (!row) return;
    const key = keyOf(row);
    this.selected = key === this.selected ? null : key;
    this.set(this.selected ?? key);
    this.markRows();
  }

  private set(key: ProcedureKey | null): void {
    if (key === this.highlighted) return;
    this.highlighted = key;
    this.onChange(key);
    this.markRows();
  }

  /** Marks the highlighted and the selected row of the results table (again after it is redrawn). */
  markRows(): void {
    for (const tr of this.root.querySelectorAll<HTMLElement>('.procedures tr[data-procedure]')) {
      tr.classList.toggle('emph', this.highlighted !== null && tr.dataset.procedure === this.highlighted);
      tr.classList.toggle('selected', tr.dataset.procedure === this.selected);
      tr.setAttribute('aria-selected', String(tr.dataset.procedure === this.selected));
    }
  }
}
