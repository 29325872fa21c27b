/** Shared pieces of the teaching views. */
import type { FIELDS } from '../../core/input/fields';
import type { ProcedureKey } from '../../core/procedures/procedures';
import type { TeachReply } from '../../worker/protocol';
import type { CurvedTeachReply, ThreeAxisTeachReply } from '../../worker/teachProtocol';
import type { Unit } from '../state';

export type TeachOk = Extract<TeachReply, { ok: true }>;

/** What every view receives on each update: the teaching data of a reply, and the unit to show. */
export interface ViewContext {
  /** The data answers the inputs on screen (checked by the page before any view sees it). */
  readonly data: TeachOk;
  readonly unit: Unit;
}

/** A teaching view's id, as the link's `view=` names it (the field registry's values but `result`, an embed's card). */
export type ViewId = Exclude<(typeof FIELDS.view.values)[number], 'result'>;

/** The kinds of question beyond a plane or a cylinder that a view may draw. */
export type PageKind = 'curved' | 'three-axis';

/**
 * A doubly curved point's or three-axis machining's teaching data (a reply to the inputs on
 * screen, checked by the page), and the unit to show.
 */
export type PageViewContext =
  | { readonly kind: 'curved'; readonly data: Extract<CurvedTeachReply, { ok: true }>; readonly unit: Unit }
  | { readonly kind: 'three-axis'; readonly data: Extract<ThreeAxisTeachReply, { ok: true }>; readonly unit: Unit };

export interface TeachingView {
  readonly id: ViewId;
  readonly title: string;
  readonly element: HTMLElement;
  update(ctx: ViewContext): void;
  /** The kinds of page question this view draws (with updatePage); none when absent. */
  readonly pageKinds?: readonly PageKind[];
  /** Draws a page question's data of one of its pageKinds. */
  updatePage?(ctx: PageViewContext): void;
  /**
   * Draws a sloped plane machined three-axis as the plane at its equivalent posture (`equivalent`),
   * with the page question beside it (the formulas add the posture's); update(equivalent) when absent.
   */
  updateEquivalent?(equivalent: ViewContext, page: PageViewContext): void;
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
