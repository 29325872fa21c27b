/** Shared pieces of the teaching views. */
import type { ProcedureKey, SolveReply } from '../../worker/protocol';
import type { Unit } from '../state';

export type OkReply = Extract<SolveReply, { ok: true }>;

/** What every view receives on each update. */
export interface ViewContext {
  readonly reply: OkReply;
  readonly unit: Unit;
  /** Inputs in mm and degrees. */
  readonly R: number;
  readonly Rcr: number;
  readonly rho: number;
}

export interface TeachingView {
  readonly id: 'profile' | 'chart' | 'tables' | 'stepper' | 'formulas';
  readonly title: string;
  readonly element: HTMLElement;
  update(ctx: ViewContext): void;
  /** Emphasises one procedure (or none). */
  highlight(key: ProcedureKey | null): void;
  /** Called when the view is shown or hidden (charts size themselves when shown). */
  setVisible?(visible: boolean): void;
}

/** One colour per procedure, the same in every view and legend. */
export const COLOURS: Record<ProcedureKey, string> = {
  exact: '#111827',
  sekine: '#d97706',
  redonnet: '#7c3aed',
  bedi: '#0891b2',
};

export const LABELS: Record<ProcedureKey, string> = {
  exact: 'Exact (3D)',
  sekine: 'Sekine et al.',
  redonnet: 'Redonnet et al.',
  bedi: 'Bedi et al.',
};

export const PROCEDURE_KEYS: readonly ProcedureKey[] = ['exact', 'sekine', 'redonnet', 'bedi'];

export { html } from '../dom';

const SVG_NS = 'http://www.w3.org/2000/svg';

export function svg<K extends keyof SVGElementTagNameMap>(
  tag: K,
  props: Record<string, string | number> = {},
): SVGElementTagNameMap[K] {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(props)) e.setAttribute(k, String(v));
  return e;
}

/** Length in the user's unit: 4 decimals in mm, 5 in inch. */
export function formatLength(mm: number, unit: Unit): string {
  return unit === 'mm' ? mm.toFixed(4) : (mm / 25.4).toFixed(5);
}
