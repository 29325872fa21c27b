/** Shared pieces of the teaching views. */
import type { FIELDS } from '../../core/input/fields';
import type { ProcedureKey } from '../../core/procedures/procedures';
import type { TeachReply } from '../../worker/protocol';
import type { Unit } from '../state';

export type TeachOk = Extract<TeachReply, { ok: true }>;

/** What every view receives on each update: the teaching data of a reply, and the unit to show. */
export interface ViewContext {
  /** The data answers the inputs on screen (checked by the page before any view sees it). */
  readonly data: TeachOk;
  readonly unit: Unit;
}

/** A teaching view's id, as the link's `view=` names it (the field registry's values). */
export type ViewId = (typeof FIELDS.view.values)[number];

export interface TeachingView {
  readonly id: ViewId;
  readonly title: string;
  readonly element: HTMLElement;
  update(ctx: ViewContext): void;
  /** Emphasises one procedure (or none). */
  highlight(key: ProcedureKey | null): void;
  /** Called when the view is shown or hidden (charts size themselves when shown). */
  setVisible?(visible: boolean): void;
}

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

/** Is the tilt zero, so the profile is symmetric and the paper's L/2 is each flank's width? */
export function untilted(ctx: ViewContext): boolean {
  return ctx.data.forward.tiltAngleDeg === 0;
}
