/**
 * The cross-feed profile's labels (issue 28 point 6): each a text on an opaque halo, placed so that it
 * is whole inside the box shown and never on top of another label of its row. A label is anchored at
 * a point (its start, end or middle there); once the texts' size is known (profileView.ts, with every
 * zoom), {@link placeLabels} measures each text, packs each row's labels apart along x, keeps them
 * inside the box and draws their halos. The drawing places the rows themselves, below the surface,
 * where no curve runs (profileDrawing.ts).
 */
import { localDecimal } from '../i18n/langChoice';
import { catalogue } from '../i18n/words';
import { svg } from './common';
import type { Box } from './profileLayout';

/** Where a label's anchor is on its text. */
export type LabelAlign = 'start' | 'middle' | 'end';

/** Space kept between two labels of a row, and around a text inside its halo (font sizes). */
const GAP_EM = 0.5;
const PAD_EM = 0.15;

/** A text's top and bottom from its baseline (font sizes), generous for any sans-serif face. */
const ASCENT_EM = 0.95;
const DESCENT_EM = 0.27;

/**
 * Adds a label to `parent`: a group of its halo and its text, anchored at (x, y) (the baseline),
 * `align` its text there. Labels of one `row` (a name) are kept apart along x; a label without a row
 * is only kept inside the box.
 */
export function addLabel(
  parent: SVGElement,
  x: number,
  y: number,
  label: string,
  options: { align?: LabelAlign; row?: string; cls?: string; testId?: string } = {},
): SVGTextElement {
  const group = svg('g', { class: 'label' });
  const halo = svg('rect', { class: 'label-halo' });
  const text = svg('text', { x, y, class: options.cls ?? 'dim-text', 'text-anchor': 'middle' });
  if (options.testId) text.setAttribute('data-testid', options.testId);
  text.dataset.anchorX = String(x);
  text.dataset.align = options.align ?? 'middle';
  if (options.row) text.dataset.row = options.row;
  // Its numbers with the decimal sign of the language in force (every digit kept).
  text.textContent = localDecimal(label, catalogue());
  group.append(halo, text);
  parent.append(group);
  return text as SVGTextElement;
}

/** Measures texts in the page's font (a canvas: no layout of the page), width per font size. */
let measure: CanvasRenderingContext2D | null = null;
function widthEm(text: string, fontFamily: string): number {
  measure ??= document.createElement('canvas').getContext('2d');
  if (measure === null) return 0.62 * text.length;
  measure.font = `100px ${fontFamily}`;
  return measure.measureText(text).width / 100;
}

/**
 * Sizes and places every label under `root` for the box `b` shown: texts `size` high (display
 * units), each row's labels packed apart from their anchors, every label inside `b`, halos drawn.
 */
export function placeLabels(root: SVGElement, b: Box, size: number, fontFamily: string): void {
  const rows = new Map<string, { text: SVGTextElement; centre: number; half: number }[]>();
  const lone: { text: SVGTextElement; centre: number; half: number }[] = [];
  for (const text of root.querySelectorAll<SVGTextElement>('text[data-anchor-x]')) {
    text.setAttribute('font-size', String(size));
    const half = (widthEm(text.textContent ?? '', fontFamily) * size) / 2;
    const anchor = Number(text.dataset.anchorX);
    const align = text.dataset.align;
    const centre = align === 'start' ? anchor + half : align === 'end' ? anchor - half : anchor;
    const item = { text, centre, half };
    const row = text.dataset.row;
    if (row === undefined) lone.push(item);
    else rows.set(row, [...(rows.get(row) ?? []), item]);
  }
  const pad = PAD_EM * size;
  const left = b.x + pad;
  const right = b.x + b.w - pad;
  const gap = GAP_EM * size;
  for (const items of rows.values()) {
    items.sort((p, q) => p.centre - q.centre);
    // Apart from the left, then back inside on the right, then inside on the left (the left wins).
    items.forEach((it, i) => {
      const prev = items[i - 1];
      if (prev) it.centre = Math.max(it.centre, prev.centre + prev.half + gap + it.half);
    });
    for (let i = items.length - 1; i >= 0; i--) {
      const it = items[i] as (typeof items)[number];
      const next = items[i + 1];
      it.centre = Math.min(it.centre, right - it.half, next ? next.centre - next.half - gap - it.half : Infinity);
    }
    for (const it of items) it.centre = Math.max(it.centre, left + it.half);
  }
  for (const it of lone) it.centre = Math.max(left + it.half, Math.min(it.centre, right - it.half));
  for (const items of [...rows.values(), lone])
    for (const { text, centre, half } of items) {
      text.setAttribute('x', String(centre));
      const y = Number(text.getAttribute('y'));
      const halo = text.previousElementSibling;
      if (halo === null) continue;
      halo.setAttribute('x', String(centre - half - pad));
      halo.setAttribute('y', String(y - ASCENT_EM * size - pad));
      halo.setAttribute('width', String(2 * (half + pad)));
      halo.setAttribute('height', String((ASCENT_EM + DESCENT_EM) * size + 2 * pad));
      halo.setAttribute('rx', String(pad));
    }
}
