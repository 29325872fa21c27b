/**
 * Cross-feed profile (2D, SVG): three passes L apart (mirrored on alternate passes for zigzag)
 * with the scallops shaded, both cusps, the flanks' widths to each cusp, the ring ellipse the
 * profile is offset from, and the profiles each approximation assumes. Zoom with the wheel or
 * the buttons, pan by dragging; the vertical scale can be exaggerated, and then says so.
 *
 * On a cylinder the same, on the curved surface: each pass's exact profile (the plane profile
 * turned about the axis, axis along the feed; the tool revolved about it, axis across, where this
 * section through the axis shows the surface straight), the h pseudo surface, the approximations'
 * profiles tangent at each contact, and where the plane's answer and the corrected procedures put
 * the next pass. Heights are exaggerated radially, the surface's curvature kept at true scale.
 *
 * This module is the view: its tools, notes and legend, and the plot's size. The drawing over a
 * surface is profileDrawing.ts, its layout profileLayout.ts, the scale bars profileScaleBars.ts,
 * pan and zoom profilePanZoom.ts.
 */

import { autoExaggeration } from '../../core/output/drawingScale';
import { sectionRadiusMm } from '../../core/output/sectionProfile';
import {
  CURVATURE_ROW_KEYS,
  CURVATURE_ROWS,
  type CurvatureRowKey,
  PROCEDURE_KEYS,
  PROCEDURES,
  type ProcedureKey,
} from '../../core/procedures/procedures';
import type { Surface } from '../../core/surfaces/cylinder';
import type { ExactSummary, ProfileCurveSet } from '../../worker/protocol';
import { formatLenUnit } from '../format';
import { localDecimal } from '../i18n/langChoice';
import { catalogue } from '../i18n/words';
import type { Unit } from '../state';
import {
  html,
  type PageKind,
  type PageViewContext,
  svg,
  type TeachingView,
  untilted,
  type ViewContext,
} from './common';
import { radiusWords } from './pageChartText';
import { curvedProfileSection, drawProfile, LABELS_DEPTH, type ProfileSection, profileSection } from './profileDrawing';
import { placeLabels } from './profileLabels';
import { type Box, grownHeightPx, type PlotRoom, profileLayout } from './profileLayout';
import { PanZoom } from './profilePanZoom';
import { profileWords } from './profileWords';
import './profile.css';
import { drawScaleBars } from './profileScaleBars';

/** The least on-screen height of the plot's texts (CSS px; presentation mode asks for more). */
const MIN_TEXT_PX = 12;

/** How the view words a surface: the plot's label, the note above it, and the exaggeration's. */
interface SurfaceWords {
  readonly ariaLabel: string;
  /** What the section shows (which axis, how the passes are made), or null on a plane. */
  readonly note: string | null;
  /** What is exaggerated, and what is not. */
  readonly heights: string;
  readonly trueScale: string;
}

/** A text with the language in force's decimal sign. */
function local(text: string): string {
  return localDecimal(text, catalogue());
}

function surfaceWords(surface: Surface, unit: Unit): SurfaceWords {
  const w = profileWords();
  if (surface.kind === 'plane') return { ariaLabel: w.plotPlane, note: null, heights: w.heightsPlane, trueScale: '' };
  const axis = surface.axis;
  const side = surface.radiusMm > 0 ? 'convex' : 'concave';
  return {
    ariaLabel: w.plotCylinder(side, axis),
    note: local(w.noteCylinder(side, formatLenUnit(Math.abs(surface.radiusMm), unit), axis)),
    heights: w.heightsSurface,
    trueScale: w.curvatureTrue,
  };
}

/** What one drawing of the view takes. */
interface Drawable {
  readonly section: ProfileSection;
  readonly exact: ExactSummary;
  readonly approximations: ProfileCurveSet['approximations'];
  readonly untilted: boolean;
  readonly unit: Unit;
  readonly toolRadiusMm: number;
  readonly words: SurfaceWords;
}

type CurvedMarkKey = ProfileSection['comparison'][number]['key'];

/** A doubly curved point's section shows no approximation's profile (they assume a plane). */
const NO_APPROXIMATIONS: ProfileCurveSet['approximations'] = {
  sekine: null,
  redonnet: null,
  bedi: null,
  osculating: null,
  cornerBall: null,
};

/** How the view words a doubly curved point's section. */
function curvedWords(feedRadiusMm: number, crossRadiusMm: number, unit: Unit): SurfaceWords {
  const w = profileWords();
  const side = (r: number) => (r > 0 ? 'convex' : 'concave');
  const words = (r: number) => radiusWords(r, unit, catalogue()?.radius);
  return {
    ariaLabel: w.plotCurved(side(feedRadiusMm), side(crossRadiusMm)),
    note: local(w.noteCurved(words(feedRadiusMm), words(crossRadiusMm))),
    heights: w.heightsSurface,
    trueScale: w.curvatureTrue,
  };
}

export class ProfileView implements TeachingView {
  readonly id = 'profile';
  readonly title = 'Cross-feed profile';
  readonly element = html('div', { class: 'view-profile', 'data-testid': 'profile-view' });
  private readonly plot = svg('svg', {
    class: 'profile-svg',
    role: 'img',
    'aria-label': 'Cross-feed profile of three adjacent passes',
  });
  private readonly layer = svg('g');
  /** The scale bars (redrawn with every zoom and pan, so they keep their size on screen). */
  private readonly bars = svg('g', { class: 'scale-bars', 'data-testid': 'profile-scale-bar' });
  /** The vertical exaggeration drawn now. */
  private shownK = 1;
  private readonly scaleNote = html('span', { class: 'scale-note', 'data-testid': 'profile-scale' });
  private readonly exaggeration = html('select', {
    'aria-label': 'Vertical scale',
    'data-testid': 'profile-exaggeration',
  });
  private readonly panZoom = new PanZoom(this.plot, (b) => this.boxShown(b));
  private ctx: ViewContext | null = null;
  private readonly curves = new Map<ProcedureKey, SVGElement[]>();
  /** On a curved surface: what the section shows (which axis, how the passes are made). */
  private readonly surfaceNote = html('p', { class: 'view-note', 'data-testid': 'profile-cylinder-note' });
  /** Where "Zoom to cusp" goes (display coordinates). */
  private cuspAt: { x: number; y: number; widthMm: number } | null = null;
  /** A doubly curved point's data shown (then ctx is the last plane's or cylinder's), or null. */
  private pageCtx: PageViewContext | null = null;
  readonly pageKinds: readonly PageKind[] = ['curved'];

  /** The buttons, the note on the approximations and the legend's words (worded by speak). */
  private readonly zoomIn = html('button', { type: 'button' }, '+');
  private readonly zoomOut = html('button', { type: 'button' }, '\u2212');
  private readonly reset = html('button', { type: 'button', 'data-testid': 'profile-reset' });
  private readonly cusp = html('button', { type: 'button', 'data-testid': 'profile-cusp' });
  private readonly approxNote = html('p', { class: 'view-note plane-model', 'data-testid': 'profile-approx-note' });

  constructor() {
    this.exaggeration.append(html('option', { value: 'auto' }));
    for (const k of [1, 5, 20, 100]) this.exaggeration.append(html('option', { value: String(k) }));
    this.exaggeration.value = 'auto';
    this.exaggeration.addEventListener('change', () => this.redraw());
    const tools = html('div', { class: 'view-tools' });
    const { zoomIn, zoomOut, reset, cusp } = this;
    zoomIn.addEventListener('click', () => this.panZoom.zoom(0.5));
    zoomOut.addEventListener('click', () => this.panZoom.zoom(2));
    reset.addEventListener('click', () => this.panZoom.show(this.panZoom.home));
    cusp.addEventListener('click', () => this.zoomToCusp());
    tools.append(this.exaggeration, zoomIn, zoomOut, cusp, reset, this.scaleNote);
    this.plot.append(this.layer, this.bars);
    this.surfaceNote.hidden = true;
    this.element.append(tools, this.surfaceNote, this.plot, this.legend(), this.approxNote);
    this.speak();
    this.plotObserver.observe(this.plot);
  }

  /**
   * The view's fixed words and the procedures' names in the language in force, and its `lang` (its
   * part of the views, English otherwise).
   */
  private speak(): void {
    const w = profileWords();
    const text = (e: Element, t: string) => {
      if (e.textContent !== t) e.textContent = t;
    };
    this.exaggeration.setAttribute('aria-label', w.exaggeration);
    for (const option of this.exaggeration.options) {
      const k = Number(option.value);
      text(option, option.value === 'auto' ? w.auto : k === 1 ? w.trueScale : local(w.vertical(k)));
    }
    this.zoomIn.setAttribute('aria-label', w.zoomIn);
    this.zoomOut.setAttribute('aria-label', w.zoomOut);
    text(this.reset, w.reset);
    text(this.cusp, w.cusp);
    text(this.approxNote, w.approximations);
    for (const e of this.element.querySelectorAll<HTMLElement>('[data-word]'))
      text(e, w[e.dataset.word as 'ring' | 'nextPass' | 'cylinderAlong' | 'cylinderAcross']);
    // The legend's procedures (data-name: the registry's key, a procedure's or a cylinder's row's).
    const names = catalogue()?.procedures;
    for (const e of this.element.querySelectorAll<HTMLElement>('[data-name]')) {
      const key = e.dataset.name ?? '';
      const name =
        key in PROCEDURES
          ? (names?.names[key as ProcedureKey] ?? PROCEDURES[key as ProcedureKey])
          : (names?.rows[key as CurvatureRowKey] ?? CURVATURE_ROWS[key as CurvatureRowKey]);
      text(e, name.shortLabel);
    }
    const lang = catalogue()?.lang;
    if (lang === undefined) this.element.removeAttribute('lang');
    else this.element.lang = lang;
  }

  /** The plot's width as last laid out (px; 0 before it is), and its height as the stylesheet sets it. */
  private plotWidthPx = 0;
  private baseHeightPx = 0;
  /** The plot's height as laid out (px; the stylesheet's, the grown one, or what a flex column gives). */
  private shownHeightPx = 0;
  /** The height the plot was grown to for an exaggerated drawing (px), or null. */
  private grownPx: number | null = null;
  /**
   * Sizes read when the browser reports a change, after its layout (reading them while drawing
   * forced a layout of the whole page twice per update: 5-10 ms on every new answer); a new size
   * draws the view again for it.
   */
  private readonly plotObserver = new ResizeObserver(() => {
    // Only a new width or a new stylesheet height calls for a new drawing: the plot's own growth
    // (grownPx, set by the drawing) does not.
    const shownHeightPx = this.shownHeightPx;
    if (this.readPlotSize() && this.plotWidthPx > 0) this.redraw();
    // Grown (or not: presentation mode's plot takes the height its column leaves): the labels
    // follow the height the plot has.
    else if (this.shownHeightPx !== shownHeightPx) this.panZoom.show(this.panZoom.box);
  });

  /** Reads the plot's laid-out size; true when its width or its stylesheet height changed. */
  private readPlotSize(): boolean {
    const w = this.plot.clientWidth;
    const h = this.plot.clientHeight;
    const changed = w !== this.plotWidthPx || (this.grownPx === null && h !== this.baseHeightPx);
    this.plotWidthPx = w;
    this.shownHeightPx = h;
    if (this.grownPx === null) this.baseHeightPx = h;
    // Presentation mode (present.css) asks for texts at least this high; read with the size, as
    // entering or leaving it resizes the plot.
    const style = getComputedStyle(this.plot);
    this.fontFamily = style.fontFamily;
    const min = Number.parseFloat(style.getPropertyValue('--svg-text-min-px'));
    const minTextPx = Math.max(MIN_TEXT_PX, Number.isFinite(min) ? min : 0);
    this.fixedHeight = style.getPropertyValue('--profile-fixed-height').trim() === '1';
    const textChanged = minTextPx !== this.minTextPx;
    this.minTextPx = minTextPx;
    return changed || textChanged;
  }

  /** The least on-screen height of the plot's texts (px; else they are a 60th of its width). */
  private minTextPx = MIN_TEXT_PX;
  /** True in a frame of a fixed height: the plot keeps the stylesheet's height (no growth). */
  private fixedHeight = false;
  /** The plot's font (its labels are measured in it). */
  private fontFamily = 'sans-serif';

  private legend(): HTMLElement {
    const legend = html('p', { class: 'view-legend' });
    for (const key of PROCEDURE_KEYS) {
      const item = html('span', {
        class: key === 'exact' ? 'legend-item' : 'legend-item plane-model',
        'data-procedure': key,
      });
      item.append(html('span', { class: 'swatch' }), html('span', { 'data-name': key }));
      legend.append(item);
    }
    // The words (data-word: ProfileWords' keys) are written by speak().
    const word = (key: string) => html('span', { 'data-word': key });
    const ring = html('span', { class: 'legend-item plane-model' });
    ring.append(html('span', { class: 'swatch swatch-faint' }), word('ring'));
    legend.append(ring);
    // On a cylinder: where the plane's answer and the corrected procedures put the next pass.
    for (const key of CURVATURE_ROW_KEYS) {
      const item = html('span', { class: 'legend-item cylinder-only', 'data-curvature': key });
      item.append(html('span', { class: 'swatch' }), html('span', { 'data-name': key }), word('nextPass'));
      legend.append(item);
    }
    // At a doubly curved point: where each cylinder's answer puts the next pass.
    for (const key of ['cylinderAlong', 'cylinderAcross'] as const) {
      const item = html('span', { class: 'legend-item cylinder-only', 'data-curvature': key });
      item.append(html('span', { class: 'swatch' }), word(key), word('nextPass'));
      legend.append(item);
    }
    return legend;
  }

  update(ctx: ViewContext): void {
    this.ctx = ctx;
    this.pageCtx = null;
    const { data, unit } = ctx;
    const section = profileSection(data);
    this.draw({
      section,
      exact: data.exact,
      approximations: data.curves.approximations,
      untilted: untilted(ctx),
      unit,
      toolRadiusMm: data.forward.toolRadiusMm,
      words: surfaceWords(section.surface, unit),
    });
  }

  /** A doubly curved point: its section across the feed (the circle of radius Rc) with the exact passes and the comparison marks. */
  updatePage(ctx: PageViewContext): void {
    if (ctx.kind !== 'curved') return;
    this.pageCtx = ctx;
    const d = ctx.data.section;
    this.draw({
      section: curvedProfileSection(d),
      exact: d.exact,
      approximations: NO_APPROXIMATIONS,
      untilted: d.untilted,
      unit: ctx.unit,
      toolRadiusMm: d.toolRadiusMm,
      words: curvedWords(d.feedRadiusMm, d.crossRadiusMm, ctx.unit),
    });
  }

  /** Draws again what is shown (a new size, a new exaggeration). */
  private redraw(): void {
    if (this.pageCtx !== null) this.updatePage(this.pageCtx);
    else if (this.ctx !== null) this.update(this.ctx);
  }

  private draw(input: Drawable): void {
    const { section, words, unit } = input;
    this.speak();
    const comparing = section.comparison.length > 0;
    const keys = new Set(section.comparison.map((c) => c.key));
    this.element.classList.toggle('on-cylinder', section.surface.kind !== 'plane');
    for (const e of this.element.querySelectorAll<HTMLElement>('.legend-item.cylinder-only'))
      e.hidden = !comparing || !keys.has(e.dataset.curvature as CurvedMarkKey);
    // At a doubly curved point no approximation's profile (nor the ring ellipse) is drawn.
    for (const e of this.element.querySelectorAll<HTMLElement>('.plane-model'))
      e.hidden = input.approximations === NO_APPROXIMATIONS;
    this.surfaceNote.hidden = words.note === null;
    if (words.note !== null) this.surfaceNote.textContent = words.note;
    this.plot.setAttribute('aria-label', words.ariaLabel);
    const ex = input.exact;
    const wanted = this.verticalScale(input.toolRadiusMm, ex);
    const room = this.plotRoom();
    const layout = profileLayout({
      toolRadiusMm: input.toolRadiusMm,
      intervalMm: ex.intervalMm,
      cuspHeightMm: ex.cuspHeightMm,
      highestCuspMm: Math.max(ex.right.heightMm, ex.left.heightMm),
      contactOffsetMm: ex.contactOffsetMm,
      sectionRadiusMm: sectionRadiusMm(section.surface),
      wantedK: wanted,
      room,
    });
    const { k } = layout;
    const drawing = (labelSize: number) =>
      drawProfile(this.layer, this.curves, {
        section,
        exact: ex,
        approximations: input.approximations,
        untilted: input.untilted,
        unit,
        layout,
        labelSize,
      });
    // The labels' rows are spaced by their size at home, which depends on the home box they make
    // taller (its height grows linearly with the size: h0 + c size). Drawn for the width's share;
    // when home then comes out too tall for it, drawn again for the size that fits itself.
    const aspect = this.plotAspect();
    const guess = this.textSize({ x: 0, y: 0, w: layout.toMm - layout.fromMm, h: 0 }, aspect);
    let drawn = drawing(guess);
    const needed = this.textSize(drawn.home, aspect);
    if (needed > 1.01 * guess) {
      const first = drawn.home.h;
      drawn = drawing(needed);
      const c = (drawn.home.h - first) / (needed - guess);
      const h0 = first - c * guess;
      const px = this.textSize({ x: 0, y: 0, w: 0, h: 1 }, aspect);
      // size = px (h0 + c size): the size that fits its own home (the plot too short for any: the last).
      const fits = 1 - c * px > 0.2 ? (1.01 * px * h0) / (1 - c * px) : needed;
      drawn = drawing(Math.max(guess, fits));
    }
    this.shownK = k;
    this.cuspAt = { x: drawn.cuspX, y: drawn.cuspY, widthMm: Math.abs(ex.right.yMm) };
    // A strong exaggeration: the plot grows (up to its limit) rather than the drawing shrinking to a strip.
    // The labels take their height in pixels whatever the drawing's scale: the plot may grow by it
    // too; not at all in a frame of a fixed height (an embedded view: profile.css), where the legend
    // below it would leave the frame.
    const labelsPx = (LABELS_DEPTH + 1.6) * this.textSize({ x: 0, y: 0, w: 0, h: 1 }, 1 / room.widthPx);
    const grown = this.fixedHeight
      ? null
      : grownHeightPx({ ...room, maxHeightPx: room.maxHeightPx + labelsPx }, drawn.home, this.plotWidthPx > 0);
    if (grown !== this.grownPx) {
      this.grownPx = grown;
      this.plot.style.height = grown === null ? '' : `${grown}px`;
    }
    this.panZoom.home = drawn.home;
    this.panZoom.show(drawn.home);
    this.scaleNote.textContent = local(
      profileWords().scale(
        k,
        words.heights,
        this.exaggeration.value === 'auto',
        k < wanted ? wanted : null,
        words.trueScale,
      ),
    );
    this.highlight(this.highlighted);
  }

  /**
   * The chosen exaggeration, or with "auto" the largest 1-2-5 step at which the drawn band
   * (up to min(R, 4h)) stays within about a third of one step-over's width.
   */
  private verticalScale(R: number, exact: ExactSummary): number {
    const chosen = Number(this.exaggeration.value);
    if (chosen > 0) return chosen;
    const width = exact.intervalMm + 0.4 * R;
    return autoExaggeration(width, Math.min(R, 4 * exact.cuspHeightMm));
  }

  private highlighted: ProcedureKey | null = null;

  highlight(key: ProcedureKey | null): void {
    this.highlighted = key;
    for (const [k, els] of this.curves) for (const e of els) e.classList.toggle('dimmed', key !== null && k !== key);
  }

  private zoomToCusp(): void {
    if (this.cuspAt === null) return;
    this.panZoom.zoomTo(this.cuspAt.x, this.cuspAt.y, Math.max(0.05 * this.cuspAt.widthMm, 0.002));
  }

  /**
   * The texts' height in display units for a box shown in a plot of height over width `aspect`: a
   * 60th of the plot's width in pixels, or more to reach minTextPx; the viewBox is fitted into the
   * plot keeping its aspect, so a pixel is the larger of the box's width and height shares.
   */
  private textSize(b: Box, aspect: number): number {
    const widthPx = this.plotWidthPx || 800;
    const unitsPerPx = Math.max(b.w / widthPx, b.h / (aspect * widthPx));
    return unitsPerPx * Math.max(widthPx / 60, this.minTextPx);
  }

  /** A box is shown: texts keep their on-screen size whatever the zoom, and the scale bars follow. */
  private boxShown(b: Box): void {
    const aspect = this.plotAspect();
    const size = this.textSize(b, aspect);
    if (this.ctx !== null || this.pageCtx !== null)
      drawScaleBars(this.bars, b, aspect, this.shownK, (this.pageCtx ?? this.ctx)?.unit ?? 'mm', size);
    else this.bars.replaceChildren();
    // The viewBox is fitted into the plot keeping its aspect: what is shown is b and the spare room
    // on one of its sides.
    const w = Math.max(b.w, b.h / aspect);
    const h = Math.max(b.h, b.w * aspect);
    placeLabels(this.plot, { x: b.x + (b.w - w) / 2, y: b.y + (b.h - h) / 2, w, h }, size, this.fontFamily);
  }

  /**
   * The plot's width and its height as the stylesheet sets it (any height it was grown to is
   * reset), and the most it may grow to for an exaggerated drawing (pixels; a guess while the
   * plot is not laid out).
   */
  private plotRoom(): PlotRoom {
    // Before the first size report, read it once (one forced layout in the view's life) rather
    // than draw for a guessed size and again when the report comes.
    if (this.plotWidthPx === 0) this.readPlotSize();
    const widthPx = this.plotWidthPx || 800;
    const baseHeightPx = this.baseHeightPx || 320;
    return {
      widthPx,
      baseHeightPx,
      maxHeightPx: Math.max(baseHeightPx, Math.min(2 * baseHeightPx, 0.7 * window.innerHeight)),
    };
  }

  /** Height over width of the plot on screen (0.4 while it is not laid out). */
  private plotAspect(): number {
    const w = this.plotWidthPx;
    const h = this.shownHeightPx;
    return w > 0 && h > 0 ? h / w : 0.4;
  }
}
