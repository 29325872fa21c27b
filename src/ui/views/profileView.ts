/**
 * Cross-feed profile (2D, SVG): two adjacent passes L apart with the scallop shaded, the
 * ring ellipse the profile is offset from, and the profiles each approximation assumes.
 * Zoom with the wheel or the buttons, pan by dragging; the vertical scale can be
 * exaggerated, and then says so.
 */
import type { ProcedureKey } from '../../worker/protocol';
import { COLOURS, formatLength, html, LABELS, svg, type TeachingView, type ViewContext } from './common';
import { autoExaggeration } from './scale';

type Box = { x: number; y: number; w: number; h: number };

export class ProfileView implements TeachingView {
  readonly id = 'profile';
  readonly title = 'Cross-feed profile';
  readonly element = html('div', { class: 'view-profile', 'data-testid': 'profile-view' });
  private readonly plot = svg('svg', {
    class: 'profile-svg',
    role: 'img',
    'aria-label': 'Cross-feed profile of two adjacent passes',
  });
  private readonly layer = svg('g');
  private readonly scaleNote = html('span', { class: 'scale-note', 'data-testid': 'profile-scale' });
  private readonly exaggeration = html('select', {
    'aria-label': 'Vertical scale',
    'data-testid': 'profile-exaggeration',
  });
  private home: Box = { x: 0, y: 0, w: 1, h: 1 };
  private box: Box = { x: 0, y: 0, w: 1, h: 1 };
  private ctx: ViewContext | null = null;
  private readonly curves = new Map<ProcedureKey, SVGElement[]>();

  constructor() {
    this.exaggeration.append(html('option', { value: 'auto' }, 'vertical: auto'));
    for (const k of [1, 5, 20, 100])
      this.exaggeration.append(html('option', { value: String(k) }, k === 1 ? 'true scale' : `vertical x${k}`));
    this.exaggeration.value = 'auto';
    this.exaggeration.addEventListener('change', () => this.ctx && this.update(this.ctx));
    const tools = html('div', { class: 'view-tools' });
    const zoomIn = html('button', { type: 'button', 'aria-label': 'Zoom in' }, '+');
    const zoomOut = html('button', { type: 'button', 'aria-label': 'Zoom out' }, '\u2212');
    const reset = html('button', { type: 'button', 'data-testid': 'profile-reset' }, 'Reset view');
    const cusp = html('button', { type: 'button', 'data-testid': 'profile-cusp' }, 'Zoom to cusp');
    zoomIn.addEventListener('click', () => this.zoom(0.5));
    zoomOut.addEventListener('click', () => this.zoom(2));
    reset.addEventListener('click', () => this.setBox(this.home));
    cusp.addEventListener('click', () => this.zoomToCusp());
    tools.append(this.exaggeration, zoomIn, zoomOut, cusp, reset, this.scaleNote);
    this.plot.append(this.layer);
    this.element.append(tools, this.plot, this.legend());
    this.wirePanZoom();
  }

  private legend(): HTMLElement {
    const legend = html('p', { class: 'view-legend' });
    for (const key of ['exact', 'sekine', 'redonnet', 'bedi'] as const) {
      const item = html('span', { class: 'legend-item', 'data-procedure': key });
      item.append(
        html('span', { class: 'swatch', style: `background:${COLOURS[key]}` }),
        document.createTextNode(LABELS[key]),
      );
      legend.append(item);
    }
    const ring = html('span', { class: 'legend-item' });
    ring.append(
      html('span', { class: 'swatch swatch-faint' }),
      document.createTextNode('ring ellipse (Rb, Rb sin rho)'),
    );
    legend.append(ring);
    return legend;
  }

  update(ctx: ViewContext): void {
    this.ctx = ctx;
    const t = ctx.reply.teaching;
    if (!t) return;
    const L = 2 * ctx.reply.halfIntervalMm;
    const h = ctx.reply.scallopHeightMm;
    const R = ctx.R;
    const k = this.verticalScale(ctx);
    const Y = (y: number) => y;
    const Z = (z: number) => -z * k;
    this.layer.replaceChildren();
    this.curves.clear();
    const path = (pts: Float64Array, centre: number, mirror: boolean, maxZ: number) => {
      const parts: string[] = [];
      for (let i = 0; i < pts.length; i += 2) {
        const z = pts[i + 1] as number;
        if (z > maxZ) break;
        parts.push(`${Y(centre + (mirror ? -1 : 1) * (pts[i] as number))},${Z(z)}`);
      }
      return parts.join(' ');
    };
    const top = Math.min(R, 4 * h);
    // Scallop: material left between the passes, under the lower envelope of both profiles.
    const env: string[] = [];
    const exact = t.curves.exact;
    const heightAt = (y: number) => {
      const a = Math.abs(y);
      for (let i = 2; i < exact.length; i += 2) {
        const y1 = exact[i] as number;
        if (y1 >= a) {
          const y0 = exact[i - 2] as number;
          const z0 = exact[i - 1] as number;
          const z1 = exact[i + 1] as number;
          return y1 > y0 ? z0 + ((z1 - z0) * (a - y0)) / (y1 - y0) : z1;
        }
      }
      return Number.POSITIVE_INFINITY;
    };
    const n = 400;
    env.push(`${Y(0)},${Z(0)}`);
    for (let i = 0; i <= n; i++) {
      const y = (L * i) / n;
      env.push(`${Y(y)},${Z(Math.min(heightAt(y), heightAt(y - L)))}`);
    }
    env.push(`${Y(L)},${Z(0)}`);
    this.layer.append(svg('polygon', { points: env.join(' '), class: 'scallop', 'data-testid': 'profile-scallop' }));
    // Designed plane and h pseudo plane.
    const span = { from: -0.2 * R, to: L + 0.2 * R };
    this.layer.append(svg('line', { x1: span.from, y1: Z(0), x2: span.to, y2: Z(0), class: 'ground' }));
    this.layer.append(svg('line', { x1: span.from, y1: Z(h), x2: span.to, y2: Z(h), class: 'hplane' }));
    // Each curve is drawn for both passes (centres 0 and L), both sides of each.
    const placements: ReadonlyArray<readonly [number, boolean]> = [
      [0, false],
      [0, true],
      [L, false],
      [L, true],
    ];
    // Ring ellipse, faint, for both passes.
    for (const [c, m] of placements) {
      this.layer.append(
        svg('polyline', { points: path(t.curves.ringEllipse, c, m, Number.POSITIVE_INFINITY), class: 'ring' }),
      );
    }
    const draw = (key: ProcedureKey, pts: Float64Array | null) => {
      if (!pts) return;
      const els: SVGElement[] = [];
      for (const [c, m] of placements) {
        const line = svg('polyline', {
          points: path(pts, c, m, top),
          class: `curve curve-${key}`,
          stroke: COLOURS[key],
          'data-procedure': key,
        });
        els.push(line);
        this.layer.append(line);
      }
      this.curves.set(key, els);
    };
    draw('sekine', t.curves.sekine);
    draw('redonnet', t.curves.redonnet);
    draw('bedi', t.curves.bedi);
    draw('exact', t.curves.exact);
    // Dimensions: h at the cusp, L/2 and L under the plane.
    const d = 0.06 * R;
    const half = L / 2;
    const dims: Array<[number, number, number, number, string]> = [
      [half, Z(0), half, Z(h), `h = ${formatLength(h, ctx.unit)}`],
      [0, Z(0) + 2 * d, half, Z(0) + 2 * d, `L/2 = ${formatLength(half, ctx.unit)}`],
      [0, Z(0) + 4 * d, L, Z(0) + 4 * d, `L = ${formatLength(L, ctx.unit)}`],
    ];
    for (const [x1, y1, x2, y2, label] of dims) {
      this.layer.append(svg('line', { x1, y1, x2, y2, class: 'dim' }));
      const text = svg('text', {
        x: (x1 + x2) / 2 + (x1 === x2 ? d / 2 : 0),
        y: (y1 + y2) / 2 - (x1 === x2 ? 0 : d / 3),
        class: 'dim-text',
      });
      text.textContent = label;
      this.layer.append(text);
    }
    const bottom = Z(0) + 5 * d;
    this.home = { x: span.from, y: Z(top) - d, w: span.to - span.from, h: bottom - Z(top) + d };
    this.setBox(this.home);
    const auto = this.exaggeration.value === 'auto' ? ' (auto)' : '';
    this.scaleNote.textContent = k === 1 ? `true scale${auto}` : `vertical scale exaggerated x${k}${auto}`;
  }

  /**
   * The chosen exaggeration, or with "auto" the largest 1-2-5 step at which the drawn band
   * (up to min(R, 4h)) stays within about a third of the view's width.
   */
  private verticalScale(ctx: ViewContext): number {
    const chosen = Number(this.exaggeration.value);
    if (chosen > 0) return chosen;
    const width = 2 * ctx.reply.halfIntervalMm + 0.4 * ctx.R;
    return autoExaggeration(width, Math.min(ctx.R, 4 * ctx.reply.scallopHeightMm));
  }

  highlight(key: ProcedureKey | null): void {
    for (const [k, els] of this.curves) for (const e of els) e.classList.toggle('dimmed', key !== null && k !== key);
  }

  private zoomToCusp(): void {
    if (!this.ctx) return;
    const half = this.ctx.reply.halfIntervalMm;
    const k = this.verticalScale(this.ctx);
    const h = this.ctx.reply.scallopHeightMm;
    const w = Math.max(0.05 * half, 0.002);
    this.setBox({
      x: half - w,
      y: -h * k - (w * this.home.h) / this.home.w,
      w: 2 * w,
      h: (2 * w * this.home.h) / this.home.w,
    });
  }

  private zoom(factor: number, cx = this.box.x + this.box.w / 2, cy = this.box.y + this.box.h / 2): void {
    this.setBox({
      x: cx - (cx - this.box.x) * factor,
      y: cy - (cy - this.box.y) * factor,
      w: this.box.w * factor,
      h: this.box.h * factor,
    });
  }

  private setBox(b: Box): void {
    this.box = b;
    this.plot.setAttribute('viewBox', `${b.x} ${b.y} ${b.w} ${b.h}`);
    // Text keeps its on-screen size whatever the zoom.
    const size = String(b.w / 45);
    for (const t of this.layer.querySelectorAll('text')) t.setAttribute('font-size', size);
  }

  private wirePanZoom(): void {
    this.plot.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        const r = this.plot.getBoundingClientRect();
        const cx = this.box.x + ((e.clientX - r.left) / r.width) * this.box.w;
        const cy = this.box.y + ((e.clientY - r.top) / r.height) * this.box.h;
        this.zoom(e.deltaY > 0 ? 1.25 : 0.8, cx, cy);
      },
      { passive: false },
    );
    let drag: { x: number; y: number; box: Box } | null = null;
    this.plot.addEventListener('pointerdown', (e) => {
      drag = { x: e.clientX, y: e.clientY, box: this.box };
      this.plot.setPointerCapture(e.pointerId);
    });
    this.plot.addEventListener('pointermove', (e) => {
      if (!drag) return;
      const r = this.plot.getBoundingClientRect();
      this.setBox({
        ...drag.box,
        x: drag.box.x - ((e.clientX - drag.x) / r.width) * drag.box.w,
        y: drag.box.y - ((e.clientY - drag.y) / r.height) * drag.box.h,
      });
    });
    this.plot.addEventListener('pointerup', () => {
      drag = null;
    });
  }
}
