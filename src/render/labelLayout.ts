/**
 * Placement of the 3D scene's labels on screen (pure: no DOM, no three.js). Each label names a
 * point (its anchor, in pixels of the scene box) and would like to sit on one side of it; the
 * labels are placed one after the other, most important first, each at the first position near
 * its anchor that stays inside the box and clear of the labels already placed and of the other
 * obstacles (badges, the marked points). A label with no such position is hidden rather than
 * drawn cut off or over another one.
 */

/** A rectangle in pixels of the scene box (left < right, top < bottom). */
export interface PixelRect {
  readonly left: number;
  readonly top: number;
  readonly right: number;
  readonly bottom: number;
}

/** One label to place. */
export interface LabelRequest {
  /** The point it names, in pixels from the scene box's top left. */
  readonly anchorXPx: number;
  readonly anchorYPx: number;
  /** Its size on screen. */
  readonly widthPx: number;
  readonly heightPx: number;
  /**
   * The side it would like to sit on, as a direction (x right, y down; need not be unit length);
   * `[0, 0]` centres it on its anchor (the axes' names at the arrow tips).
   */
  readonly side: readonly [number, number];
  /** Higher is placed first (keeps its preferred side when two compete). */
  readonly priority: number;
}

/** Where a label goes: the offset of its centre from its anchor, or hidden. */
export interface LabelPlacement {
  readonly dxPx: number;
  readonly dyPx: number;
  readonly visible: boolean;
}

/** Clearances tried between a label's box and its anchor, nearest first (px). */
const GAPS_PX = [6, 14, 26, 42];
/** Directions tried after the preferred one, every 45 degrees. */
const DIRECTIONS: ReadonlyArray<readonly [number, number]> = Array.from({ length: 8 }, (_, i) => {
  const a = (i * Math.PI) / 4;
  return [Math.round(Math.cos(a) * 1e6) / 1e6, Math.round(Math.sin(a) * 1e6) / 1e6] as const;
});

/** Whether two rectangles overlap, each grown by `gapPx` / 2. */
export function rectsIntersect(a: PixelRect, b: PixelRect, gapPx = 0): boolean {
  return a.left < b.right + gapPx && b.left < a.right + gapPx && a.top < b.bottom + gapPx && b.top < a.bottom + gapPx;
}

/** The offset of a label's centre that puts its box `gapPx` clear of the anchor in direction `dir`. */
function offsetFor(dir: readonly [number, number], widthPx: number, heightPx: number, gapPx: number): [number, number] {
  const [ux, uy] = dir;
  const n = Math.hypot(ux, uy);
  if (n === 0) return [0, 0];
  const x = ux / n;
  const y = uy / n;
  // Scale the direction until the box clears the anchor by gapPx along it.
  const tx = x === 0 ? Number.POSITIVE_INFINITY : (widthPx / 2 + gapPx) / Math.abs(x);
  const ty = y === 0 ? Number.POSITIVE_INFINITY : (heightPx / 2 + gapPx) / Math.abs(y);
  const t = Math.min(tx, ty);
  return [x * t, y * t];
}

/**
 * Places labels without overlap inside a `widthPx` x `heightPx` box.
 * @param labels the labels, in any order (the result follows it).
 * @param obstacles boxes no label may cover (badges drawn on the scene, marked points).
 * @param gapPx the least space kept between two labels.
 * @returns one placement per label; a label whose anchor lies outside the box, or that finds no
 *   free position near it, is hidden.
 */
export function placeLabels(
  labels: readonly LabelRequest[],
  widthPx: number,
  heightPx: number,
  obstacles: readonly PixelRect[] = [],
  gapPx = 2,
): LabelPlacement[] {
  const placed: PixelRect[] = [...obstacles];
  const out: LabelPlacement[] = labels.map(() => ({ dxPx: 0, dyPx: 0, visible: false }));
  const order = labels.map((_, i) => i).sort((a, b) => (labels[b]?.priority ?? 0) - (labels[a]?.priority ?? 0));
  for (const i of order) {
    const l = labels[i] as LabelRequest;
    const { anchorXPx: ax, anchorYPx: ay, widthPx: w, heightPx: h } = l;
    if (!(ax >= 0 && ax <= widthPx && ay >= 0 && ay <= heightPx) || !(w > 0 && h > 0)) continue;
    const centred = l.side[0] === 0 && l.side[1] === 0;
    const candidates: Array<[number, number]> = [];
    if (centred) candidates.push([0, 0]);
    // Nearest first; at each clearance the preferred side, then the others by how far they turn from it.
    const pref = centred ? ([0, -1] as const) : l.side;
    const turn = (d: readonly [number, number]) => -(d[0] * pref[0] + d[1] * pref[1]) / (Math.hypot(...pref) || 1);
    const dirs = [...DIRECTIONS].sort((a, b) => turn(a) - turn(b));
    for (const gap of GAPS_PX) {
      candidates.push(offsetFor(pref, w, h, gap));
      for (const d of dirs) candidates.push(offsetFor(d, w, h, gap));
    }
    for (const [dx, dy] of candidates) {
      const r = { left: ax + dx - w / 2, top: ay + dy - h / 2, right: ax + dx + w / 2, bottom: ay + dy + h / 2 };
      if (r.left < 1 || r.top < 1 || r.right > widthPx - 1 || r.bottom > heightPx - 1) continue;
      if (placed.some((p) => rectsIntersect(r, p, gapPx))) continue;
      placed.push(r);
      out[i] = { dxPx: dx, dyPx: dy, visible: true };
      break;
    }
  }
  return out;
}
