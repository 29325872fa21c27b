/**
 * The points the 3D scene's camera is fitted to (cameraFit.ts), gathered from the objects that take
 * part, in world coordinates (mm): objects say how through `userData.framed`: `box` (the 8 corners
 * of their geometry's bounding box: the tool, shank included), `points` (the points a line or a
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
 * Appends to `out` (flat xyz, world mm) the points of the objects under `root` that take part: all
 * of them (`focus` false), or only those marked for the step-through's close-up (`focus` true,
 * their labels included). World matrices must be up to date. Returns the number of points.
 */
export function gatherFramePoints(root: Object3D, out: number[], focus: boolean): number {
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
