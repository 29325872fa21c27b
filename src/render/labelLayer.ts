/**
 * The 3D scene's HTML overlay: labels anchored at points of the scene, placed after each frame so
 * that none covers another, a marked point or a badge, or runs out of the scene (labelLayout.ts);
 * and the legend entries the frame uses (`data-drawn` on the scene box, read by the legend and the
 * tests). What three.js's CSS2DRenderer did, in the lines this scene needs (1.2 kB gzip less).
 *
 * Objects of the scene take part through their userData: `legend` (a legend entry's key,
 * index.html's `data-legend`) and `marker` (a marked point labels keep clear of); labels are
 * {@link LabelAnchor} objects, children of what they name.
 */
import { type Camera, Object3D, type Scene, Vector3 } from 'three';
import { type LabelPlacement, type LabelRequest, leaderLine, type PixelRect, placeLabels } from './labelLayout';

/**
 * A label anchored at a 3D point: an object of the scene that carries an HTML element. After each
 * frame the layer centres the outer element on the point's projection (its inline transform is set
 * through the CSSOM) and offsets the inner one, which carries the class and the text; a leader
 * line (the outer element's second child) joins the point to the label's nearest edge whenever
 * the label sits away from its point.
 */
export class LabelAnchor extends Object3D {
  readonly element = document.createElement('div');
  /** Its request to the layout, updated in place each frame. */
  readonly request: { -readonly [K in keyof LabelRequest]: LabelRequest[K] };

  /**
   * @param side where it would like to sit (x right, y down; `[0, 0]` centred on its point)
   * @param priority higher is placed first (labelLayout.ts)
   */
  constructor(text: string, className: string, side: readonly [number, number], priority: number) {
    super();
    this.element.className = 'scene-label-anchor';
    const inner = document.createElement('span');
    inner.className = `scene-label ${className}`;
    inner.textContent = text;
    const leader = document.createElement('span');
    leader.className = 'scene-leader';
    leader.style.display = 'none';
    this.element.append(inner, leader);
    this.request = { anchorXPx: 0, anchorYPx: 0, widthPx: 0, heightPx: 0, side, priority };
    this.userData.labelAnchor = true;
  }

  /** Its text ('' while it has none: then it is not shown). */
  labelText(): string {
    return this.element.firstElementChild?.textContent ?? '';
  }

  /** Sets its text. */
  setText(text: string): void {
    const inner = this.element.firstElementChild;
    if (inner && inner.textContent !== text) inner.textContent = text;
  }
}

/** Marks an object with the key of its legend entry (index.html, `data-legend`). */
export function legend<T extends Object3D>(object: T, key: string): T {
  object.userData.legend = key;
  return object;
}

/** Whether an object and all its ancestors are visible. */
function shown(object: Object3D): boolean {
  for (let o: Object3D | null = object; o !== null; o = o.parent) if (!o.visible) return false;
  return true;
}

/** Half the side of the box a marked point keeps clear of labels (px). */
const MARKER_HALF_PX = 4;

/** The overlay of one scene box: made once, laid out after every frame (`layout`). */
export class LabelLayer {
  /** The layer of the labels' elements, over the canvas. */
  private readonly layer = document.createElement('div');
  /**
   * Sizes of the labels and badges, as the browser last laid them out: read when it reports a
   * change (after its layout, where reading costs nothing), never forced in the middle of a frame.
   * A change redraws, so a label whose text grew is placed again in the next frame.
   */
  private readonly sizeObserver = new ResizeObserver((entries) => this.sizesChanged(entries));
  private readonly sizes = new WeakMap<Element, { readonly widthPx: number; readonly heightPx: number }>();
  /** The badges' boxes in the scene (px), while shown. */
  private readonly badgeRects = new Map<Element, PixelRect>();
  /** One frame's lists, kept from frame to frame (emptied, not made anew). */
  private readonly obstacles: PixelRect[] = [];
  private readonly markerRects: Array<{ left: number; top: number; right: number; bottom: number }> = [];
  private readonly placedLabels: LabelAnchor[] = [];
  private readonly requests: LabelRequest[] = [];
  private readonly drawn = new Set<string>();

  /** `redraw` asks the view for a frame (a label's or a badge's size changed). */
  constructor(
    private readonly container: HTMLElement,
    private readonly redraw: () => void,
  ) {
    this.layer.className = 'scene-labels';
    container.append(this.layer);
  }

  /** Keeps labels clear of a badge drawn over the scene (its box read whenever it changes). */
  watchBadge(badge: HTMLElement): void {
    this.sizeObserver.observe(badge);
  }

  /**
   * Places the labels of `scene`, just rendered through `camera` into a `widthPx` x `heightPx` box,
   * and records which legend entries the frame uses.
   */
  layout(scene: Scene, camera: Camera, widthPx: number, heightPx: number): void {
    const point = new Vector3();
    const obstacles = this.obstacles;
    const labels = this.placedLabels;
    const requests = this.requests;
    const drawn = this.drawn;
    obstacles.length = 0;
    labels.length = 0;
    requests.length = 0;
    drawn.clear();
    for (const rect of this.badgeRects.values()) obstacles.push(rect);
    let markers = 0;
    scene.traverse((o) => {
      if (!shown(o)) {
        if (o instanceof LabelAnchor) o.element.style.display = 'none';
        return;
      }
      if (typeof o.userData.legend === 'string') drawn.add(o.userData.legend);
      const isMarker = o.userData.marker === true;
      if (!isMarker && !(o instanceof LabelAnchor)) return;
      // Its place on screen (px) and depth (-1 near plane, 1 far plane).
      point.setFromMatrixPosition(o.matrixWorld).project(camera);
      const x = (point.x * 0.5 + 0.5) * widthPx;
      const y = (-point.y * 0.5 + 0.5) * heightPx;
      if (isMarker) {
        const rect = this.markerRects[markers] ?? { left: 0, top: 0, right: 0, bottom: 0 };
        this.markerRects[markers++] = rect;
        rect.left = x - MARKER_HALF_PX;
        rect.top = y - MARKER_HALF_PX;
        rect.right = x + MARKER_HALF_PX;
        rect.bottom = y + MARKER_HALF_PX;
        obstacles.push(rect);
      }
      if (!(o instanceof LabelAnchor)) return;
      // Centred on its point's projection; hidden behind the camera or beyond the far plane.
      const inView = point.z >= -1 && point.z <= 1;
      o.element.style.display = inView ? '' : 'none';
      if (!inView) return;
      o.element.style.transform = `translate(-50%, -50%) translate(${x}px, ${y}px)`;
      if (o.element.parentNode !== this.layer) this.layer.append(o.element);
      const inner = o.element.firstElementChild as HTMLElement | null;
      if (!inner || inner.textContent === '') return;
      const size = this.sizes.get(inner);
      if (size === undefined) {
        this.sizeObserver.observe(inner); // placed once its size is known (the next frame)
        inner.style.visibility = 'hidden';
        return;
      }
      const r = o.request;
      r.anchorXPx = x;
      r.anchorYPx = y;
      r.widthPx = size.widthPx;
      r.heightPx = size.heightPx;
      labels.push(o);
      requests.push(r);
    });
    const placements: LabelPlacement[] = placeLabels(requests, widthPx, heightPx, obstacles);
    for (let i = 0; i < labels.length; i++) {
      const p = placements[i];
      const label = labels[i] as LabelAnchor;
      const inner = label.element.firstElementChild as HTMLElement;
      const leader = label.element.lastElementChild as HTMLElement;
      if (!p?.visible) {
        inner.style.visibility = 'hidden';
        leader.style.display = 'none';
        continue;
      }
      inner.style.visibility = '';
      inner.style.transform = `translate(${p.dxPx.toFixed(1)}px, ${p.dyPx.toFixed(1)}px)`;
      const line = leaderLine(p.dxPx, p.dyPx, label.request.widthPx, label.request.heightPx);
      leader.style.display = line === null ? 'none' : '';
      if (line !== null) {
        leader.style.width = `${line.lengthPx.toFixed(1)}px`;
        leader.style.transform = `rotate(${line.angleDeg.toFixed(1)}deg)`;
      }
    }
    const keys = [...drawn].sort().join(' ');
    if (this.container.dataset.drawn !== keys) this.container.dataset.drawn = keys;
  }

  /** Labels and badges laid out anew: their sizes (and the badges' places) for the next layout. */
  private sizesChanged(entries: readonly ResizeObserverEntry[]): void {
    for (const entry of entries) {
      const el = entry.target as HTMLElement;
      const widthPx = el.offsetWidth;
      const heightPx = el.offsetHeight;
      if (el.classList.contains('scene-label')) this.sizes.set(el, { widthPx, heightPx });
      else if (widthPx > 0 && heightPx > 0)
        this.badgeRects.set(el, {
          left: el.offsetLeft,
          top: el.offsetTop,
          right: el.offsetLeft + widthPx,
          bottom: el.offsetTop + heightPx,
        });
      else this.badgeRects.delete(el);
    }
    this.redraw();
  }

  /** Stops watching sizes and removes the layer. */
  dispose(): void {
    this.sizeObserver.disconnect();
    this.layer.remove();
  }
}
