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

/**
 * The least space between two labels (px): enough that labels stacked near one point (the axes'
 * names beside a three-axis scene's dimensions on a phone) read as separate boxes, each with its leader.
 */
export const LABEL_GAP_PX = 5;

/** Clearances tried between a label's box and its anchor, nearest first (px). */
const GAPS_PX = [6, 14, 26, 42];
/** Directions tried after the preferred one, every 45 degrees. */
const DIRECTIONS: ReadonlyArray<readonly [number, number]> = Array.from({ length: 8 }, (_, i) => {
  const a = (i * Math.PI) / 4;
  return [Math.round(Math.cos(a) * 1e6) / 1e6, Math.round(Math.sin(a) * 1e6) / 1e6] as const;
});

/** Whether two rectangles overlap, each grown by `gapPx` / 2. */
export function rectsIntersect(a: PixelRect, b: PixelRect, gapPx = 0): boolean {
  return overlaps(a.left, a.top, a.right, a.bottom, b, gapPx);
}

/** {@link rectsIntersect} for a rectangle given by its sides. */
function overlaps(left: number, top: number, right: number, bottom: number, b: PixelRect, gapPx: number): boolean {
  return left < b.right + gapPx && b.left < right + gapPx && top < b.bottom + gapPx && b.top < bottom + gapPx;
}

/** The side a centred label tries first when its anchor's place is taken: above. */
const ABOVE = [0, -1] as const;

/** The directions after a preferred side, by how far they turn from it (kept per side: a label's side is fixed). */
const TURNS = new WeakMap<readonly [number, number], ReadonlyArray<readonly [number, number]>>();

function directionsFrom(pref: readonly [number, number]): ReadonlyArray<readonly [number, number]> {
  let dirs = TURNS.get(pref);
  if (dirs === undefined) {
    const turn = (d: readonly [number, number]) => -(d[0] * pref[0] + d[1] * pref[1]) / (Math.hypot(...pref) || 1);
    dirs = [...DIRECTIONS].sort((a, b) => turn(a) - turn(b));
    TURNS.set(pref, dirs);
  }
  return dirs;
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
  gapPx = LABEL_GAP_PX,
): LabelPlacement[] {
  const placed: PixelRect[] = [...obstacles];
  const out: LabelPlacement[] = labels.map(() => HIDDEN);
  const order = labels.map((_, i) => i).sort((a, b) => (labels[b]?.priority ?? 0) - (labels[a]?.priority ?? 0));
  /** Places label `l` (index i) at the offset (dx, dy) if it fits there; whether it did. */
  const tryAt = (i: number, l: LabelRequest, dx: number, dy: number): boolean => {
    const { anchorXPx: ax, anchorYPx: ay, widthPx: w, heightPx: h } = l;
    const left = ax + dx - w / 2;
    const top = ay + dy - h / 2;
    const right = ax + dx + w / 2;
    const bottom = ay + dy + h / 2;
    if (left < 1 || top < 1 || right > widthPx - 1 || bottom > heightPx - 1) return false;
    for (const p of placed) if (overlaps(left, top, right, bottom, p, gapPx)) return false;
    placed.push({ left, top, right, bottom });
    out[i] = { dxPx: dx, dyPx: dy, visible: true };
    return true;
  };
  /** Tries the direction d (need not be unit length) with the box `gapPx` clear of the anchor along it. */
  const tryDirection = (i: number, l: LabelRequest, d: readonly [number, number], gap: number): boolean => {
    const n = Math.hypot(d[0], d[1]);
    if (n === 0) return tryAt(i, l, 0, 0);
    const x = d[0] / n;
    const y = d[1] / n;
    // Scale the direction until the box clears the anchor by gap along it.
    const tx = x === 0 ? Number.POSITIVE_INFINITY : (l.widthPx / 2 + gap) / Math.abs(x);
    const ty = y === 0 ? Number.POSITIVE_INFINITY : (l.heightPx / 2 + gap) / Math.abs(y);
    const t = Math.min(tx, ty);
    return tryAt(i, l, x * t, y * t);
  };
  for (const i of order) {
    const l = labels[i] as LabelRequest;
    const { anchorXPx: ax, anchorYPx: ay, widthPx: w, heightPx: h } = l;
    if (!(ax >= 0 && ax <= widthPx && ay >= 0 && ay <= heightPx) || !(w > 0 && h > 0)) continue;
    const centred = l.side[0] === 0 && l.side[1] === 0;
    if (centred && tryAt(i, l, 0, 0)) continue;
    // Nearest first; at each clearance the preferred side, then the others by how far they turn from it.
    const pref = centred ? ABOVE : l.side;
    const dirs = directionsFrom(pref);
    search: for (const gap of GAPS_PX) {
      if (tryDirection(i, l, pref, gap)) break;
      for (const d of dirs) if (tryDirection(i, l, d, gap)) break search;
    }
  }
  return out;
}

/** A label not placed. */
const HIDDEN: LabelPlacement = { dxPx: 0, dyPx: 0, visible: false };

/** Leaders shorter than this are not drawn: the label sits at its point (px). */
const LEADER_MIN_PX = 4;

/**
 * The leader line from a label's point to the nearest edge of its box, the box's centre `dx, dy`
 * from the point and `widthPx` x `heightPx` in size: its length and angle (from +x, clockwise on
 * screen, degrees), or null when the point is inside the box or the line would be too short to see.
 */
export function leaderLine(
  dxPx: number,
  dyPx: number,
  widthPx: number,
  heightPx: number,
): { lengthPx: number; angleDeg: number } | null {
  const ax = Math.abs(dxPx);
  const ay = Math.abs(dyPx);
  // The share of the way from the box's centre to the point that lies inside the box.
  const inside = Math.min(
    ax === 0 ? Number.POSITIVE_INFINITY : widthPx / 2 / ax,
    ay === 0 ? Number.POSITIVE_INFINITY : heightPx / 2 / ay,
  );
  if (!(inside < 1)) return null;
  const lengthPx = Math.hypot(dxPx, dyPx) * (1 - inside);
  if (lengthPx < LEADER_MIN_PX) return null;
  return { lengthPx, angleDeg: (Math.atan2(dyPx, dxPx) * 180) / Math.PI };
}
