/**
 * Pan and zoom of an SVG plot through its viewBox: the wheel zooms about the pointer, a drag pans
 * (a vertical swipe that the page takes as a scroll, `touch-action: pan-y`, ends the drag), and the
 * view's buttons zoom about the middle or go back home. Every change is reported, so the owner can
 * keep its texts and scale bars at their size on screen.
 */
import type { Box } from './profileLayout';

/** Pan and zoom of one plot: the box shown and the home box. */
export class PanZoom {
  /** The box shown (display coordinates). */
  private shown: Box = { x: 0, y: 0, w: 1, h: 1 };
  /** The box "Reset view" goes back to: the whole drawing. */
  home: Box = { x: 0, y: 0, w: 1, h: 1 };

  /** `onChange` is called with the box after every change. */
  constructor(
    private readonly plot: SVGSVGElement,
    private readonly onChange: (box: Box) => void,
  ) {
    plot.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        const r = plot.getBoundingClientRect();
        const b = this.shown;
        const cx = b.x + ((e.clientX - r.left) / r.width) * b.w;
        const cy = b.y + ((e.clientY - r.top) / r.height) * b.h;
        this.zoom(e.deltaY > 0 ? 1.25 : 0.8, cx, cy);
      },
      { passive: false },
    );
    let drag: { x: number; y: number; box: Box } | null = null;
    plot.addEventListener('pointerdown', (e) => {
      drag = { x: e.clientX, y: e.clientY, box: this.shown };
      plot.setPointerCapture(e.pointerId);
    });
    plot.addEventListener('pointermove', (e) => {
      if (!drag) return;
      const r = plot.getBoundingClientRect();
      this.show({
        ...drag.box,
        x: drag.box.x - ((e.clientX - drag.x) / r.width) * drag.box.w,
        y: drag.box.y - ((e.clientY - drag.y) / r.height) * drag.box.h,
      });
    });
    const end = () => {
      drag = null;
    };
    plot.addEventListener('pointerup', end);
    plot.addEventListener('pointercancel', end);
  }

  /** The box shown. */
  get box(): Box {
    return this.shown;
  }

  /** Shows a box. */
  show(b: Box): void {
    this.shown = b;
    this.plot.setAttribute('viewBox', `${b.x} ${b.y} ${b.w} ${b.h}`);
    this.onChange(b);
  }

  /** Zooms by `factor` (< 1 in) about (cx, cy), the middle of the box shown by default. */
  zoom(factor: number, cx = this.shown.x + this.shown.w / 2, cy = this.shown.y + this.shown.h / 2): void {
    const b = this.shown;
    this.show({ x: cx - (cx - b.x) * factor, y: cy - (cy - b.y) * factor, w: b.w * factor, h: b.h * factor });
  }

  /**
   * Zooms to a point (cx, cy), `halfWidth` either side of it, at the home box's aspect.
   */
  zoomTo(cx: number, cy: number, halfWidth: number): void {
    const hh = (2 * halfWidth * this.home.h) / this.home.w;
    this.show({ x: cx - halfWidth, y: cy - hh / 2, w: 2 * halfWidth, h: hh });
  }
}
