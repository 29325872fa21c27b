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
 */

import { autoExaggeration, EXAGGERATION_STEPS, scaleBar } from '../../core/drawingScale';
import {
  CURVATURE_ROW_KEYS,
  CURVATURE_ROWS,
  PROCEDURE_KEYS,
  PROCEDURES,
  type ProcedureKey,
} from '../../core/procedures';
import { fromSurfaceSection, toSurfaceSection } from '../../core/surfaceGeometry';
import type { CylinderCurves } from '../../worker/protocol';
import { formatLen, formatLenUnit } from '../format';
import { html, svg, type TeachingView, untilted, type ViewContext } from './common';

type Box = { x: number; y: number; w: number; h: number };

/** z of a profile (flat y, z, y increasing) at y, or +infinity outside it (linear between samples). */
function profileHeight(pts: Float64Array, y: number): number {
  const n = pts.length / 2;
  if (n < 2 || y < (pts[0] as number) || y > (pts[2 * (n - 1)] as number)) return Number.POSITIVE_INFINITY;
  let lo = 0;
  let hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if ((pts[2 * mid] as number) <= y) lo = mid;
    else hi = mid;
  }
  const y0 = pts[2 * lo] as number;
  const y1 = pts[2 * hi] as number;
  const z0 = pts[2 * lo + 1] as number;
  const z1 = pts[2 * hi + 1] as number;
  return y1 > y0 ? z0 + ((z1 - z0) * (y - y0)) / (y1 - y0) : Math.min(z0, z1);
}

/**
 * A profile (flat s, h) from its left end to its right end, keeping from the contact (the point
 * nearest s = 0) outwards only the points that go on outwards: in surface coordinates a flank can
 * turn back near its widest point, and profileHeight needs s increasing.
 */
function monotoneProfile(pts: Float64Array): Float64Array {
  const n = pts.length / 2;
  if (n < 2) return pts;
  let j0 = 0;
  for (let i = 1; i < n; i++) if (Math.abs(pts[2 * i] as number) < Math.abs(pts[2 * j0] as number)) j0 = i;
  const right: number[] = [pts[2 * j0] as number, pts[2 * j0 + 1] as number];
  for (let i = j0 + 1, last = pts[2 * j0] as number; i < n; i++) {
    const sMm = pts[2 * i] as number;
    if (sMm <= last) break;
    right.push(sMm, pts[2 * i + 1] as number);
    last = sMm;
  }
  const left: number[] = [];
  for (let i = j0 - 1, last = pts[2 * j0] as number; i >= 0; i--) {
    const sMm = pts[2 * i] as number;
    if (sMm >= last) break;
    left.unshift(sMm, pts[2 * i + 1] as number);
    last = sMm;
  }
  return Float64Array.from([...left, ...right]);
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
  private home: Box = { x: 0, y: 0, w: 1, h: 1 };
  private box: Box = { x: 0, y: 0, w: 1, h: 1 };
  private ctx: ViewContext | null = null;
  private readonly curves = new Map<ProcedureKey, SVGElement[]>();
  /** On a cylinder: what the section shows (which axis, how the passes are made). */
  private readonly cylinderNote = html('p', { class: 'view-note', 'data-testid': 'profile-cylinder-note' });
  /** Where "Zoom to cusp" goes (display coordinates), set on a cylinder. */
  private cuspAt: { x: number; y: number; k: number } | null = null;

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
    this.plot.append(this.layer, this.bars);
    this.cylinderNote.hidden = true;
    const approxNote = html(
      'p',
      { class: 'view-note', 'data-testid': 'profile-approx-note' },
      "The approximations' profiles are drawn at the exact step-over L (at each pass the exact answer puts), to compare their shapes with the exact profile; the step-over each of them gives is in the results table.",
    );
    this.element.append(tools, this.cylinderNote, this.plot, this.legend(), approxNote);
    this.wirePanZoom();
    this.plotObserver.observe(this.plot);
  }

  /** The plot's width as last laid out (px; 0 before it is), and its height as the stylesheet sets it. */
  private plotWidthPx = 0;
  private baseHeightPx = 0;
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
    if (this.readPlotSize() && this.ctx !== null && this.plotWidthPx > 0) this.update(this.ctx);
  });

  /** Reads the plot's laid-out size; true when its width or its stylesheet height changed. */
  private readPlotSize(): boolean {
    const w = this.plot.clientWidth;
    const h = this.plot.clientHeight;
    const changed = w !== this.plotWidthPx || (this.grownPx === null && h !== this.baseHeightPx);
    this.plotWidthPx = w;
    if (this.grownPx === null) this.baseHeightPx = h;
    return changed;
  }

  private legend(): HTMLElement {
    const legend = html('p', { class: 'view-legend' });
    for (const key of PROCEDURE_KEYS) {
      const item = html('span', { class: 'legend-item', 'data-procedure': key });
      item.append(html('span', { class: 'swatch' }), document.createTextNode(PROCEDURES[key].shortLabel));
      legend.append(item);
    }
    const ring = html('span', { class: 'legend-item' });
    ring.append(html('span', { class: 'swatch swatch-faint' }), document.createTextNode('ring ellipse (a = Rb, b)'));
    legend.append(ring);
    // On a cylinder: where the plane's answer and the corrected procedures put the next pass.
    for (const key of CURVATURE_ROW_KEYS) {
      const item = html('span', { class: 'legend-item cylinder-only', 'data-curvature': key });
      item.append(
        html('span', { class: 'swatch' }),
        document.createTextNode(`${CURVATURE_ROWS[key].shortLabel}: next pass`),
      );
      legend.append(item);
    }
    return legend;
  }

  update(ctx: ViewContext): void {
    this.ctx = ctx;
    const cylinder = ctx.data.cylinder;
    this.element.classList.toggle('on-cylinder', cylinder !== null);
    for (const e of this.element.querySelectorAll<HTMLElement>('.legend-item.cylinder-only'))
      e.hidden = cylinder === null;
    this.cylinderNote.hidden = cylinder === null;
    if (cylinder !== null) {
      this.updateCylinder(ctx, cylinder);
      return;
    }
    this.cuspAt = null;
    this.plot.setAttribute('aria-label', 'Cross-feed profile of three adjacent passes');
    const { data } = ctx;
    const ex = data.exact;
    const L = ex.intervalMm;
    const h = ex.cuspHeightMm;
    const R = data.forward.toolRadiusMm;
    const k = this.verticalScale(ctx);
    const Z = (z: number) => -z * k;
    const mirrored = ex.pattern === 'zigzag';
    // Passes: contact at -L, 0, L; for zigzag the neighbours are mirror images.
    const passes: ReadonlyArray<readonly [number, 1 | -1]> = [
      [-L, mirrored ? -1 : 1],
      [0, 1],
      [L, mirrored ? -1 : 1],
    ];
    this.layer.replaceChildren();
    this.curves.clear();
    this.shownK = k;
    const y0 = ex.contactOffsetMm;
    const span = { from: Math.min(-L - 0.2 * R, -y0 - 0.1 * R), to: Math.max(L + 0.2 * R, -y0 + 0.1 * R) };
    const d = 0.03 * (span.to - span.from);
    // The band drawn: up to min(R, 4h), but an exaggerated band no taller than the view's shape
    // allows over the full width (else the drawing shrinks to a strip): at least the cusps with a margin.
    const room = this.plotRoom();
    const hTop = Math.max(ex.right.heightMm, ex.left.heightMm);
    const fits = ((room.maxHeightPx / room.widthPx) * (span.to - span.from) - 6 * d) / k;
    const top = Math.max(Math.min(R, 4 * h, fits), Math.min(R, 4 * h, 1.5 * hTop));
    const profile = data.curves.profile;
    const passHeight = (y: number, [c, m]: readonly [number, 1 | -1]) => profileHeight(profile, m * (y - c));
    // Scallops: material left between the passes, under the lower envelope of the three profiles.
    const n = 600;
    const env: string[] = [`${-L},${Z(0)}`];
    for (let i = 0; i <= n; i++) {
      const y = -L + (2 * L * i) / n;
      env.push(`${y},${Z(Math.min(...passes.map((p) => passHeight(y, p))))}`);
    }
    env.push(`${L},${Z(0)}`);
    this.layer.append(svg('polygon', { points: env.join(' '), class: 'scallop', 'data-testid': 'profile-scallop' }));
    // The three passes, and the tool centre O (-y0 from the contact) when it lies beyond them.
    this.layer.append(svg('line', { x1: span.from, y1: Z(0), x2: span.to, y2: Z(0), class: 'ground' }));
    this.layer.append(svg('line', { x1: span.from, y1: Z(h), x2: span.to, y2: Z(h), class: 'hplane' }));
    // The ring ellipse of the middle pass, faint.
    const ring: string[] = [];
    const ringPts = data.curves.ringEllipse;
    for (let i = 0; i < ringPts.length; i += 2) ring.push(`${ringPts[i]},${Z(ringPts[i + 1] as number)}`);
    this.layer.append(svg('polyline', { points: ring.join(' '), class: 'ring' }));
    const polyline = (key: ProcedureKey, points: string) => this.addCurve(key, points);
    // The approximations: symmetric, their right halves drawn on both sides of each pass.
    for (const key of PROCEDURE_KEYS) {
      if (key === 'exact') continue;
      const pts = data.curves.approximations[key];
      if (!pts) continue;
      for (const [c] of passes) {
        for (const side of [1, -1]) {
          const parts: string[] = [];
          for (let i = 0; i < pts.length; i += 2) {
            const z = pts[i + 1] as number;
            if (z > top) break;
            parts.push(`${c + side * (pts[i] as number)},${Z(z)}`);
          }
          polyline(key, parts.join(' '));
        }
      }
    }
    // The exact profile of each pass, whole (both flanks).
    for (const [c, m] of passes) {
      const parts: string[] = [];
      for (let i = 0; i < profile.length; i += 2) {
        const z = profile[i + 1] as number;
        if (z <= top) parts.push(`${c + m * (profile[i] as number)},${Z(z)}`);
      }
      polyline('exact', parts.join(' '));
    }
    this.drawDimensions(ctx, k, top, d);
    const bottom = Z(0) + 5 * d;
    this.home = { x: span.from, y: Z(top) - d, w: span.to - span.from, h: bottom - Z(top) + d };
    // A strong exaggeration: the plot grows (up to its limit) rather than the drawing shrinking to a strip.
    const wantedPx = (room.widthPx * this.home.h) / this.home.w;
    const grown =
      wantedPx > room.baseHeightPx && this.plotWidthPx > 0 ? Math.round(Math.min(wantedPx, room.maxHeightPx)) : null;
    if (grown !== this.grownPx) {
      this.grownPx = grown;
      this.plot.style.height = grown === null ? '' : `${grown}px`;
    }
    this.setBox(this.home);
    const auto = this.exaggeration.value === 'auto' ? ' (auto)' : '';
    this.scaleNote.textContent = k === 1 ? `true scale${auto}` : `vertical scale exaggerated x${k}${auto}`;
    this.highlight(this.highlighted);
  }

  /**
   * The view on a cylinder, in surface coordinates (arc length across the feed, radial height)
   * mapped to the section: D(s, hr) is the point hr above the surface at s, the height exaggerated
   * by k, the surface itself at true scale.
   */
  private updateCylinder(ctx: ViewContext, cyl: CylinderCurves): void {
    const { data, unit } = ctx;
    const surface = cyl.surface;
    const ex = data.exact;
    const L = ex.intervalMm;
    const h = ex.cuspHeightMm;
    const R = data.forward.toolRadiusMm;
    const top = Math.min(R, 4 * h);
    const feed = surface.axis === 'feed';
    const abs = Math.abs(surface.radiusMm);
    const side = surface.radiusMm > 0 ? 'convex' : 'concave';
    // A concave trough seen along its axis folds over if the heights grow past its radius: cap k.
    const wanted = this.verticalScale(ctx);
    const kMax = feed && surface.radiusMm < 0 ? (0.5 * abs) / top : Number.POSITIVE_INFINITY;
    let k = wanted;
    if (k > kMax) k = Math.max(1, ...EXAGGERATION_STEPS.filter((step) => step <= kMax));
    const D = (sMm: number, hr: number): [number, number] => {
      const [y, z] = fromSurfaceSection(surface, sMm, k * hr);
      return [y, -z];
    };
    const pt = (sMm: number, hr: number) => D(sMm, hr).join(',');
    this.plot.setAttribute(
      'aria-label',
      `Cross-feed profile of three adjacent passes on a ${side} cylinder, axis ${feed ? 'along' : 'across'} the feed`,
    );
    this.cylinderNote.textContent = feed
      ? `On a ${side} cylinder of radius ${formatLenUnit(abs, unit)}, axis along the feed: each pass leaves the plane profile, the next one turned about the cylinder's axis by L/|Rs|; L is measured along the arc. Heights radially, from the surface.`
      : `On a ${side} cylinder of radius ${formatLenUnit(abs, unit)}, axis across the feed: this section through the cylinder's axis shows the surface straight; each pass is the tool revolved about the axis (its profile is not the plane's), the next one stepped L along the axis. Heights radially, from the surface.`;
    const mirrored = ex.pattern === 'zigzag';
    const passes: ReadonlyArray<readonly [number, 1 | -1]> = [
      [-L, mirrored ? -1 : 1],
      [0, 1],
      [L, mirrored ? -1 : 1],
    ];
    this.layer.replaceChildren();
    this.curves.clear();
    const profile = monotoneProfile(cyl.passProfile);
    const passHeight = (sMm: number, [c, m]: readonly [number, 1 | -1]) => profileHeight(profile, m * (sMm - c));
    const y0 = ex.contactOffsetMm;
    // The arc shown, kept within half a turn of a small cylinder.
    const limit = feed ? 0.98 * Math.PI * abs : Number.POSITIVE_INFINITY;
    const span = {
      from: Math.max(-limit, Math.min(-L - 0.2 * R, -y0 - 0.1 * R)),
      to: Math.min(limit, Math.max(L + 0.2 * R, -y0 + 0.1 * R)),
    };
    const along = (from: number, to: number, hr: (sMm: number) => number, n = 240) => {
      const parts: string[] = [];
      for (let i = 0; i <= n; i++) {
        const sMm = from + ((to - from) * i) / n;
        parts.push(pt(sMm, hr(sMm)));
      }
      return parts;
    };
    // Scallops: between the surface and the lower envelope of the three passes.
    const envelope = along(-L, L, (sMm) => Math.min(...passes.map((p) => passHeight(sMm, p))), 600);
    const floor = along(L, -L, () => 0, 120);
    this.layer.append(
      svg('polygon', { points: [...envelope, ...floor].join(' '), class: 'scallop', 'data-testid': 'profile-scallop' }),
    );
    this.layer.append(
      svg('polyline', {
        points: along(span.from, span.to, () => 0).join(' '),
        class: 'ground surface-curve',
        'data-testid': 'profile-surface',
      }),
    );
    this.layer.append(
      svg('polyline', {
        points: along(span.from, span.to, () => h).join(' '),
        class: 'hplane',
        'data-testid': 'profile-h-surface',
      }),
    );
    if (feed) {
      const ring: string[] = [];
      for (let i = 0; i + 1 < cyl.ringEllipse.length; i += 2)
        ring.push(pt(cyl.ringEllipse[i] as number, cyl.ringEllipse[i + 1] as number));
      this.layer.append(svg('polyline', { points: ring.join(' '), class: 'ring' }));
    }
    const polyline = (key: ProcedureKey, points: string) => this.addCurve(key, points);
    // The approximations: their profiles tangent to the surface at each contact.
    for (const key of PROCEDURE_KEYS) {
      if (key === 'exact') continue;
      const pts = data.curves.approximations[key];
      if (!pts) continue;
      for (const sideSign of [1, -1]) {
        const local: number[] = [];
        for (let i = 0; i + 1 < pts.length; i += 2) {
          if ((pts[i + 1] as number) > top) break;
          local.push(sideSign * (pts[i] as number), pts[i + 1] as number);
        }
        const onSurface = toSurfaceSection(surface, local);
        for (const [c] of passes) {
          const parts: string[] = [];
          for (let i = 0; i + 1 < onSurface.length; i += 2)
            parts.push(pt(c + (onSurface[i] as number), onSurface[i + 1] as number));
          polyline(key, parts.join(' '));
        }
      }
    }
    // The exact profile of each pass.
    for (const [c, m] of passes) {
      const parts: string[] = [];
      for (let i = 0; i + 1 < cyl.passProfile.length; i += 2) {
        const hr = cyl.passProfile[i + 1] as number;
        if (hr <= top) parts.push(pt(c + m * (cyl.passProfile[i] as number), hr));
      }
      polyline('exact', parts.join(' '));
    }
    // Where the plane's answer and the corrected procedures put the next pass: a mark on the
    // surface at their L, and for the plane's answer that pass's exact profile, dashed.
    for (const row of cyl.comparison) {
      if (row.intervalMm === null || !(row.intervalMm < span.to)) continue;
      const sMm = row.intervalMm;
      this.layer.append(
        svg('polyline', {
          points: [pt(sMm, -0.15 * top), pt(sMm, 0.6 * top)].join(' '),
          class: 'curve comparison-mark',
          'data-curvature': row.key,
        }),
      );
      if (row.key === 'plane') {
        const m = mirrored ? -1 : 1;
        const parts: string[] = [];
        for (let i = 0; i + 1 < profile.length; i += 2) {
          const hr = profile[i + 1] as number;
          if (hr <= top) parts.push(pt(sMm + m * (profile[i] as number), hr));
        }
        this.layer.append(
          svg('polyline', {
            points: parts.join(' '),
            class: 'curve comparison-pass',
            'data-curvature': 'plane',
            'data-testid': 'profile-plane-pass',
          }),
        );
      }
    }
    // Dimensions: the cusp heights radially, L/2 (or wR, wL) and L along the surface below it.
    const [, yTop] = D(0, top);
    const [, yBase] = D(0, 0);
    const d = 0.03 * (span.to - span.from);
    const below = (n: number) => -(n * d) / k;
    const f = (mm: number) => formatLen(mm, unit);
    const fh = (mm: number) => formatLen(mm, unit, 'height');
    const { right, left } = ex;
    const name = (c: { heightMm: number }) => (c.heightMm >= Math.max(right.heightMm, left.heightMm) ? 'h' : "h'");
    const text = (x: number, y: number, label: string, cls = 'dim-text') => {
      const t = svg('text', { x, y, class: cls });
      t.textContent = label;
      this.layer.append(t);
    };
    const radial = (sMm: number, hr: number, label: string) => {
      const [a, b] = D(sMm, 0);
      const [c2, e] = D(sMm, hr);
      this.layer.append(svg('line', { x1: a, y1: b, x2: c2, y2: e, class: 'dim' }));
      text((a + c2) / 2 + d / 2, (b + e) / 2, label);
    };
    const arcDim = (from: number, to: number, level: number, label: string) => {
      this.layer.append(svg('polyline', { points: along(from, to, () => below(level), 48).join(' '), class: 'dim' }));
      const [mx, my] = D((from + to) / 2, below(level));
      text(mx, my - d / 3, label);
    };
    radial(right.yMm, right.heightMm, `${name(right)} = ${fh(right.heightMm)}`);
    const untiltedHere = untilted(ctx);
    if (!untiltedHere) radial(left.yMm, left.heightMm, `${name(left)} = ${fh(left.heightMm)}`);
    if (untiltedHere || ex.pattern === 'zigzag') arcDim(0, L / 2, 2, `L/2 = ${f(L / 2)}`);
    else {
      arcDim(0, right.yMm, 2, `wR = ${f(right.yMm)}`);
      arcDim(left.yMm, 0, 2, `wL = ${f(-left.yMm)}`);
    }
    arcDim(0, L, 4, `L = ${f(L)}${feed ? ' (arc)' : ''}`);
    if (y0 !== 0) {
      // The tool centre O: -y0 across the feed in the contact's tangent plane.
      const local: number[] = [];
      for (let i = 0; i <= 8; i++) local.push(-y0, (top * i) / 8);
      const onSurface = toSurfaceSection(surface, local);
      const parts: string[] = [];
      for (let i = 0; i + 1 < onSurface.length; i += 2)
        parts.push(pt(onSurface[i] as number, onSurface[i + 1] as number));
      this.layer.append(svg('polyline', { points: parts.join(' '), class: 'centre-line' }));
      const [ox, oy] = D(onSurface[onSurface.length - 2] as number, onSurface[onSurface.length - 1] as number);
      text(ox + d / 3, oy + d, `O (y0 = ${f(y0)})`, 'dim-text centre-text');
    }
    // Home: everything drawn, with a margin.
    let minX = Number.POSITIVE_INFINITY;
    let maxX = Number.NEGATIVE_INFINITY;
    let minY = Number.POSITIVE_INFINITY;
    let maxY = Number.NEGATIVE_INFINITY;
    for (const sMm of [span.from, span.to, 0, -L, L, (span.from + span.to) / 2]) {
      for (const hr of [top, below(5), 0]) {
        const [x, y] = D(sMm, hr);
        minX = Math.min(minX, x);
        maxX = Math.max(maxX, x);
        minY = Math.min(minY, y);
        maxY = Math.max(maxY, y);
      }
    }
    minY = Math.min(minY, yTop);
    maxY = Math.max(maxY, yBase);
    const pad = 0.02 * (maxX - minX);
    this.home = { x: minX - pad, y: minY - pad, w: maxX - minX + 2 * pad, h: maxY - minY + 2 * pad };
    this.setBox(this.home);
    const [cx, cy] = D(right.yMm, right.heightMm);
    this.cuspAt = { x: cx, y: cy, k };
    this.shownK = k;
    const auto = this.exaggeration.value === 'auto' ? ' (auto)' : '';
    const capped = k < wanted ? ` (x${wanted} would fold the trough over)` : '';
    this.scaleNote.textContent =
      k === 1
        ? `true scale${auto}${capped}`
        : `heights above the surface exaggerated x${k}${auto}${capped}; the surface's curvature at true scale`;
    this.highlight(this.highlighted);
  }

  /** Cusp heights, the flanks' widths to their cusps, L, and the tool centre O. */
  private drawDimensions(ctx: ViewContext, k: number, top: number, d: number): void {
    const { data, unit } = ctx;
    const ex = data.exact;
    const L = ex.intervalMm;
    const Z = (z: number) => -z * k;
    const f = (mm: number) => formatLen(mm, unit);
    const fh = (mm: number) => formatLen(mm, unit, 'height');
    const dims: Array<[number, number, number, number, string]> = [];
    const { right, left } = ex;
    const name = (c: { heightMm: number }) => (c.heightMm >= Math.max(right.heightMm, left.heightMm) ? 'h' : "h'");
    dims.push([right.yMm, Z(0), right.yMm, Z(right.heightMm), `${name(right)} = ${fh(right.heightMm)}`]);
    if (!untilted(ctx)) dims.push([left.yMm, Z(0), left.yMm, Z(left.heightMm), `${name(left)} = ${fh(left.heightMm)}`]);
    if (untilted(ctx) || ex.pattern === 'zigzag')
      dims.push([0, Z(0) + 2 * d, L / 2, Z(0) + 2 * d, `L/2 = ${f(L / 2)}`]);
    else {
      dims.push([0, Z(0) + 2 * d, right.yMm, Z(0) + 2 * d, `wR = ${f(right.yMm)}`]);
      dims.push([left.yMm, Z(0) + 2 * d, 0, Z(0) + 2 * d, `wL = ${f(-left.yMm)}`]);
    }
    dims.push([0, Z(0) + 4 * d, L, Z(0) + 4 * d, `L = ${f(L)}`]);
    for (const [x1, y1, x2, y2, text] of dims) {
      this.layer.append(svg('line', { x1, y1, x2, y2, class: 'dim' }));
      const t = svg('text', {
        x: (x1 + x2) / 2 + (x1 === x2 ? d / 2 : 0),
        y: (y1 + y2) / 2 - (x1 === x2 ? 0 : d / 3),
        class: 'dim-text',
      });
      t.textContent = text;
      this.layer.append(t);
    }
    // The tool centre point O lies -y0 across the feed from the contact.
    const y0 = ex.contactOffsetMm;
    if (y0 !== 0) {
      const x = -y0;
      this.layer.append(svg('line', { x1: x, y1: Z(0), x2: x, y2: Z(top), class: 'centre-line' }));
      const t = svg('text', { x: x + d / 3, y: Z(top) + d, class: 'dim-text centre-text' });
      t.textContent = `O (y0 = ${f(y0)})`;
      this.layer.append(t);
    }
  }

  /**
   * The chosen exaggeration, or with "auto" the largest 1-2-5 step at which the drawn band
   * (up to min(R, 4h)) stays within about a third of one step-over's width.
   */
  private verticalScale(ctx: ViewContext): number {
    const chosen = Number(this.exaggeration.value);
    if (chosen > 0) return chosen;
    const R = ctx.data.forward.toolRadiusMm;
    const width = ctx.data.exact.intervalMm + 0.4 * R;
    return autoExaggeration(width, Math.min(R, 4 * ctx.data.exact.cuspHeightMm));
  }

  private highlighted: ProcedureKey | null = null;

  highlight(key: ProcedureKey | null): void {
    this.highlighted = key;
    for (const [k, els] of this.curves) for (const e of els) e.classList.toggle('dimmed', key !== null && k !== key);
  }

  /** Draws one procedure's curve and keeps it for highlighting. */
  private addCurve(key: ProcedureKey, points: string): void {
    const line = svg('polyline', { points, class: `curve curve-${key}`, 'data-procedure': key });
    this.layer.append(line);
    const list = this.curves.get(key) ?? [];
    list.push(line);
    this.curves.set(key, list);
  }

  private zoomToCusp(): void {
    if (!this.ctx) return;
    if (this.cuspAt !== null) {
      const w = Math.max(0.05 * Math.abs(this.ctx.data.exact.right.yMm), 0.002);
      const hh = (2 * w * this.home.h) / this.home.w;
      this.setBox({ x: this.cuspAt.x - w, y: this.cuspAt.y - hh / 2, w: 2 * w, h: hh });
      return;
    }
    const cusp = this.ctx.data.exact.right;
    const k = this.verticalScale(this.ctx);
    const w = Math.max(0.05 * Math.abs(cusp.yMm), 0.002);
    this.setBox({
      x: cusp.yMm - w,
      y: -cusp.heightMm * k - (w * this.home.h) / this.home.w,
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
    this.drawScaleBars(b, b.w / 45);
  }

  /**
   * The plot's width and its height as the stylesheet sets it (any height it was grown to is
   * reset), and the most it may grow to for an exaggerated drawing (pixels; a guess while the
   * plot is not laid out).
   */
  private plotRoom(): { widthPx: number; baseHeightPx: number; maxHeightPx: number } {
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
    const h = this.grownPx ?? this.baseHeightPx;
    return w > 0 && h > 0 ? h / w : 0.4;
  }

  /**
   * Scale bars in the user's unit at the bottom of the view: across the feed (true scale), and
   * for heights when they are exaggerated (the bar drawn k times taller, and saying so).
   */
  private drawScaleBars(b: Box, fontSize: number): void {
    this.bars.replaceChildren();
    if (this.ctx === null) return;
    const unit = this.ctx.unit;
    // The box as drawn: the viewBox is fitted into the plot keeping its aspect, so one of its sides has room to spare.
    const aspect = this.plotAspect();
    const w = Math.max(b.w, b.h / aspect);
    const h = Math.max(b.h, b.w * aspect);
    const x0 = b.x + b.w / 2 - w / 2 + 0.03 * w;
    const yBase = b.y + b.h / 2 + h / 2 - 0.05 * h;
    const tick = 0.012 * w;
    const text = (x: number, y: number, label: string, testId: string, anchor = 'start') => {
      const t = svg('text', { x, y, class: 'dim-text scale-text', 'data-testid': testId, 'text-anchor': anchor });
      t.setAttribute('font-size', String(fontSize));
      t.textContent = label;
      this.bars.append(t);
    };
    const across = scaleBar(0.2 * w, unit);
    if (across !== null) {
      const x1 = x0 + across.lengthMm;
      this.bars.append(
        svg('polyline', {
          points: `${x0},${yBase - tick} ${x0},${yBase} ${x1},${yBase} ${x1},${yBase - tick}`,
          class: 'scale-line',
        }),
      );
      text(x0, yBase - 1.6 * tick, across.text, 'profile-scale-bar-x');
    }
    const k = this.shownK;
    if (k === 1) return;
    const up = scaleBar((0.25 * h) / k, unit);
    if (up === null) return;
    const x = x0 + 0.3 * w;
    const y1 = yBase - k * up.lengthMm;
    this.bars.append(
      svg('polyline', {
        points: `${x - tick},${y1} ${x},${y1} ${x},${yBase} ${x - tick},${yBase}`,
        class: 'scale-line',
      }),
    );
    text(x + tick, yBase - (k * up.lengthMm) / 2, `${up.text} high (drawn x${k})`, 'profile-scale-bar-z');
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
    // A vertical swipe became a page scroll (touch-action: pan-y): the drag ends.
    this.plot.addEventListener('pointercancel', () => {
      drag = null;
    });
  }
}
