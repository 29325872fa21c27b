/**
 * Where the 3D scene's camera looks from (pure: no DOM, no three.js; tested in Node): the three
 * preset directions (isometric, along the feed, from above) and the fit of a perspective camera to
 * a set of points seen from a given direction, so that every point lies inside the view with a
 * margin and the points' extent fills the view's limiting dimension (issue 21: the whole tool,
 * shank included, in every posture and preset view).
 */

export type CameraPreset = 'iso' | 'feed' | 'top';

/** A 3D vector (mm, or a direction). */
export type Vec3 = readonly [number, number, number];

/** A preset's viewing direction: from the target towards the camera (unit), and the camera's up. */
export interface PresetDirection {
  readonly towardsCamera: Vec3;
  readonly up: Vec3;
}

/**
 * The presets' directions. Isometric: from the front right, above (X the feed to the right and
 * towards the viewer, Y away, Z up). Along the feed: from ahead of the tool looking back against
 * the feed, Z up, so that +Y runs to the right as in the profile view (P_hp R on the right). Top:
 * from above, X (the feed) to the right and +Y up the screen, the usual plan view of a CAM
 * program, so that P_hp R (the +Y flank) is drawn above the path.
 */
export function presetDirection(preset: CameraPreset): PresetDirection {
  if (preset === 'feed') return { towardsCamera: [1, 0, 0], up: [0, 0, 1] };
  if (preset === 'top') return { towardsCamera: [0, 0, 1], up: [0, 1, 0] };
  const n = Math.hypot(0.75, 0.85, 0.6);
  return { towardsCamera: [0.75 / n, -0.85 / n, 0.6 / n], up: [0, 0, 1] };
}

/** The direction towards the isometric camera (world). */
const TOWARDS_VIEWER = presetDirection('iso').towardsCamera;

/**
 * The ends of the drawn passes along the feed (x = fromMm, toMm), the one nearer the isometric
 * camera first: the feed turned into the world by `frame` (column-major 4 x 4; none: the identity).
 */
export function nearerEndFirst(
  fromMm: number,
  toMm: number,
  frame: readonly number[] | undefined,
): readonly [number, number] {
  const [fx, fy, fz] = frame === undefined ? [1, 0, 0] : [frame[0] ?? 1, frame[1] ?? 0, frame[2] ?? 0];
  const towards = fx * TOWARDS_VIEWER[0] + fy * TOWARDS_VIEWER[1] + fz * TOWARDS_VIEWER[2];
  return towards * (toMm - fromMm) >= 0 ? [toMm, fromMm] : [fromMm, toMm];
}

/** Where the camera goes: its position and the point it looks at (mm); the distance between them. */
export interface CameraFit {
  readonly position: Vec3;
  readonly target: Vec3;
  readonly distanceMm: number;
}

/** How a fit is asked. */
export interface FitOptions {
  /** The camera's vertical field of view (degrees, 0 < fov < 180). */
  readonly fovDeg: number;
  /** The view's width over its height (> 0). */
  readonly aspect: number;
  /**
   * The share of the view's half-size kept free at the limiting dimension's edges (0 <= margin < 1):
   * the points' extent then fills 1 - margin of the limiting dimension.
   */
  readonly margin: number;
}

const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
function unit(a: Vec3): Vec3 {
  const n = Math.hypot(a[0], a[1], a[2]);
  return n > 0 ? [a[0] / n, a[1] / n, a[2] / n] : [0, 0, 1];
}

/**
 * The camera's frame as three.js's `lookAt` makes it: right, up on screen, and forward (into the
 * view), from the direction towards the camera and the camera's up vector (not parallel to it).
 */
export function cameraBasis(towardsCamera: Vec3, up: Vec3): { right: Vec3; upOnScreen: Vec3; forward: Vec3 } {
  const back = unit(towardsCamera);
  let right = cross(up, back);
  if (Math.hypot(...right) < 1e-9) right = cross(Math.abs(back[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0], back);
  right = unit(right);
  return { right, upOnScreen: cross(back, right), forward: [-back[0], -back[1], -back[2]] };
}

/**
 * Fits a perspective camera looking along `-towardsCamera` (with `up`) to the points `xyz` (flat
 * x, y, z, mm; at least one): the nearest camera place from which every point projects inside the
 * view shrunk by `margin`, so the points' extent fills exactly 1 - margin of the limiting dimension
 * (the other dimension less). The camera is centred on the points' projected extent; its target
 * is on its axis at the middle of the points' depths (the orbit turns about it).
 *
 * In the camera's frame (x right, y up, z forward) a point is inside when
 * |x - cx| <= k (z - cz), k = tan(fov/2) (1 - margin) (times the aspect across): for each axis the
 * farthest-forward camera satisfying every point is cz = (B - A) / (2k) with A = max(x - k z) and
 * B = min(x + k z), centred at cx = (A + B) / 2; the camera takes the smaller cz of the two axes.
 * Returns null for no points or a degenerate view.
 */
export function fitCamera(
  xyz: ArrayLike<number>,
  count: number,
  towardsCamera: Vec3,
  up: Vec3,
  options: FitOptions,
): CameraFit | null {
  const { fovDeg, aspect, margin } = options;
  if (!(count > 0) || !(fovDeg > 0 && fovDeg < 180) || !(aspect > 0) || !(margin >= 0 && margin < 1)) return null;
  const { right, upOnScreen, forward } = cameraBasis(towardsCamera, up);
  const ky = Math.tan((fovDeg * Math.PI) / 360) * (1 - margin);
  const kx = ky * aspect;
  let ax = Number.NEGATIVE_INFINITY;
  let bx = Number.POSITIVE_INFINITY;
  let ay = Number.NEGATIVE_INFINITY;
  let by = Number.POSITIVE_INFINITY;
  let nearZ = Number.POSITIVE_INFINITY;
  let farZ = Number.NEGATIVE_INFINITY;
  let extent = 0;
  for (let i = 0; i < count; i++) {
    const p: Vec3 = [xyz[3 * i] as number, xyz[3 * i + 1] as number, xyz[3 * i + 2] as number];
    if (!p.every(Number.isFinite)) continue;
    const x = dot(p, right);
    const y = dot(p, upOnScreen);
    const z = dot(p, forward);
    ax = Math.max(ax, x - kx * z);
    bx = Math.min(bx, x + kx * z);
    ay = Math.max(ay, y - ky * z);
    by = Math.min(by, y + ky * z);
    nearZ = Math.min(nearZ, z);
    farZ = Math.max(farZ, z);
    extent = Math.max(extent, Math.abs(x), Math.abs(y), Math.abs(z));
  }
  if (!Number.isFinite(nearZ)) return null;
  const cx = (ax + bx) / 2;
  const cy = (ay + by) / 2;
  // A single point (or points on one line of sight) has no extent: stand back by its size.
  const least = Math.max(extent, 1e-9) * 1e-3;
  const cz = Math.min((bx - ax) / (2 * kx), (by - ay) / (2 * ky), nearZ - least);
  const distanceMm = (nearZ + farZ) / 2 - cz;
  const at = (s: number, t: number, u: number): Vec3 => [
    s * right[0] + t * upOnScreen[0] + u * forward[0],
    s * right[1] + t * upOnScreen[1] + u * forward[1],
    s * right[2] + t * upOnScreen[2] + u * forward[2],
  ];
  return { position: at(cx, cy, cz), target: at(cx, cy, cz + distanceMm), distanceMm };
}

/**
 * Projects the points `xyz` (flat, mm) through a camera at `position` looking at `target` with
 * `up` into normalised device coordinates (x right and y up, each -1 to 1 across the view), as
 * three.js's perspective projection does; points behind the camera give null.
 */
export function projectPoints(
  xyz: ArrayLike<number>,
  count: number,
  fit: { readonly position: Vec3; readonly target: Vec3 },
  up: Vec3,
  options: Pick<FitOptions, 'fovDeg' | 'aspect'>,
): Array<readonly [number, number] | null> {
  const { position, target } = fit;
  const { right, upOnScreen, forward } = cameraBasis(
    [position[0] - target[0], position[1] - target[1], position[2] - target[2]],
    up,
  );
  const ty = Math.tan((options.fovDeg * Math.PI) / 360);
  const tx = ty * options.aspect;
  const out: Array<readonly [number, number] | null> = [];
  for (let i = 0; i < count; i++) {
    const d: Vec3 = [
      (xyz[3 * i] as number) - position[0],
      (xyz[3 * i + 1] as number) - position[1],
      (xyz[3 * i + 2] as number) - position[2],
    ];
    const z = dot(d, forward);
    out.push(z > 0 ? [dot(d, right) / (z * tx), dot(d, upOnScreen) / (z * ty)] : null);
  }
  return out;
}

/**
 * How much of the view the projected points fill: the largest of their extents across and up,
 * each as a share of the view's width or height (1: edge to edge), and whether all lie inside.
 */
export function viewFill(ndc: ReadonlyArray<readonly [number, number] | null>): { fill: number; inside: boolean } {
  let minX = Number.POSITIVE_INFINITY;
  let maxX = Number.NEGATIVE_INFINITY;
  let minY = Number.POSITIVE_INFINITY;
  let maxY = Number.NEGATIVE_INFINITY;
  let inside = ndc.length > 0;
  for (const p of ndc) {
    if (p === null) {
      inside = false;
      continue;
    }
    minX = Math.min(minX, p[0]);
    maxX = Math.max(maxX, p[0]);
    minY = Math.min(minY, p[1]);
    maxY = Math.max(maxY, p[1]);
    if (Math.abs(p[0]) > 1 || Math.abs(p[1]) > 1) inside = false;
  }
  const fill = Number.isFinite(minX) ? Math.max((maxX - minX) / 2, (maxY - minY) / 2) : 0;
  return { fill, inside };
}
