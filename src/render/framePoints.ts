/**
 * The points the 3D scene's camera is fitted to (cameraFit.ts), gathered from the objects that take
 * part, in world coordinates (mm): objects say how through `userData.framed`: `box` (the 8 corners
 * of their geometry's bounding box: the tool, shank included; square to `userData.boxAxis` when it
 * is given, so that the box of a turned body stays tight around it), `points` (the points a line or a
 * point cloud draws now) or `origin` (their own place: a marked point); every label shown takes
 * part by its anchor. Hidden objects (or of a hidden parent) do not.
 */
import { type BufferAttribute, type BufferGeometry, type Object3D, Vector3 } from 'three';

/** A label's anchor (labelLayer.ts LabelAnchor, marked `userData.labelAnchor`), told apart without the DOM. */
interface LabelLike extends Object3D {
  labelText(): string;
}
const isLabel = (o: Object3D): o is LabelLike => o.userData.labelAnchor === true;

/** How an object takes part in the camera's fit. */
export type Framed = 'box' | 'points' | 'origin';

/** Marks an object as taking part in the camera's fit; `focus`: also in the step-through's close-up. */
export function framed<T extends Object3D>(object: T, how: Framed, focus = false): T {
  object.userData.framed = how;
  if (focus) object.userData.focus = true;
  return object;
}

function shown(object: Object3D): boolean {
  for (let o: Object3D | null = object; o !== null; o = o.parent) if (!o.visible) return false;
  return true;
}

const p = new Vector3();

/**
 * Appends to `out` the 8 corners (flat xyz) of the box around `count` points `xyz` (flat) whose
 * edges run along `axis` (a unit vector) and two directions square to it, one of them `facing` (the
 * direction towards the camera) made square to the axis when it is not along it: a box tight around
 * a body turned about that axis (the tool, whatever its posture), whose outline as seen from
 * `facing` is the body's own across the axis, where the box along the coordinate axes of a tilted
 * body stands far out of it (three-axis: the view was left empty above and below the tool).
 */
export function axisBoxCorners(
  xyz: ArrayLike<number>,
  count: number,
  axis: readonly [number, number, number],
  out: number[],
  facing: readonly [number, number, number] = [1, 0, 0],
): void {
  const a = new Vector3(...axis);
  // u: `facing` square to the axis (or a coordinate axis when it lies along it); v = axis x u.
  const u = new Vector3(...facing);
  u.addScaledVector(a, -u.dot(a));
  if (u.length() < 1e-6) {
    u.set(Math.abs(a.x) < 0.9 ? 1 : 0, Math.abs(a.x) < 0.9 ? 0 : 1, 0);
    u.addScaledVector(a, -u.dot(a));
  }
  const frame = [u.normalize(), a.clone().cross(u), a];
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  const q = new Vector3();
  for (let i = 0; i < count; i++) {
    q.fromArray(xyz as ArrayLike<number> as number[], 3 * i);
    frame.forEach((f, k) => {
      lo[k] = Math.min(lo[k] as number, q.dot(f));
      hi[k] = Math.max(hi[k] as number, q.dot(f));
    });
  }
  for (let i = 0; i < 8 && count > 0; i++) {
    q.set(0, 0, 0);
    for (const [k, f] of frame.entries()) q.addScaledVector(f, ((i >> k) & 1 ? hi[k] : lo[k]) as number);
    out.push(q.x, q.y, q.z);
  }
}

/** The corners of an object's box about its axis, and the direction it faces in its coordinates (reused). */
const corners: number[] = [];
const facingLocal: [number, number, number] = [0, 0, 0];

/**
 * Appends to `out` (flat xyz, world mm) the points of the objects under `root` that take part: all
 * of them (`focus` false), or only those marked for the step-through's close-up (`focus` true,
 * their labels included). World matrices must be up to date. `towardsCamera` (world): the direction
 * the boxes about an axis face (the camera's, so that they are tight as seen). Returns the number of points.
 */
export function gatherFramePoints(
  root: Object3D,
  out: number[],
  focus: boolean,
  towardsCamera: readonly [number, number, number] = [1, 0, 0],
): number {
  out.length = 0;
  root.traverse((o) => {
    const inFocus = (x: Object3D) => {
      for (let a: Object3D | null = x; a !== null; a = a.parent) if (a.userData.focus === true) return true;
      return false;
    };
    const label = isLabel(o);
    const how: Framed | undefined = label ? 'origin' : (o.userData.framed as Framed | undefined);
    if (how === undefined || (focus && !inFocus(o)) || !shown(o)) return;
    if (label && o.labelText() === '') return;
    const push = () => out.push(p.x, p.y, p.z);
    if (how === 'origin') {
      p.setFromMatrixPosition(o.matrixWorld);
      push();
      return;
    }
    const geometry = (o as Object3D & { geometry?: BufferGeometry }).geometry;
    if (geometry === undefined) return;
    const boxAxis = o.userData.boxAxis as readonly [number, number, number] | undefined;
    if (how === 'box' && boxAxis !== undefined) {
      const attr = geometry.getAttribute('position') as BufferAttribute | undefined;
      if (attr === undefined) return;
      corners.length = 0;
      // The direction in the object's coordinates: its world matrix is a rigid motion (turned, not scaled).
      const e = o.matrixWorld.elements;
      for (let k = 0; k < 3; k++)
        facingLocal[k] =
          (e[4 * k] as number) * towardsCamera[0] +
          (e[4 * k + 1] as number) * towardsCamera[1] +
          (e[4 * k + 2] as number) * towardsCamera[2];
      axisBoxCorners(attr.array, attr.count, boxAxis, corners, facingLocal);
      for (let i = 0; i < corners.length; i += 3) {
        p.fromArray(corners, i).applyMatrix4(o.matrixWorld);
        push();
      }
      return;
    }
    if (how === 'box') {
      if (geometry.boundingBox === null) geometry.computeBoundingBox();
      const box = geometry.boundingBox;
      if (box === null || box.isEmpty()) return;
      for (let i = 0; i < 8; i++) {
        p.set(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y, i & 4 ? box.max.z : box.min.z);
        p.applyMatrix4(o.matrixWorld);
        push();
      }
      return;
    }
    const attr = geometry.getAttribute('position') as BufferAttribute | undefined;
    if (attr === undefined) return;
    const { start, count } = geometry.drawRange;
    const end = Math.min(attr.count, start + count);
    for (let i = start; i < end; i++) {
      p.fromBufferAttribute(attr, i).applyMatrix4(o.matrixWorld);
      push();
    }
  });
  return out.length / 3;
}
