/**
 * The near and far clipping planes of a perspective camera, from the size of what is drawn: the
 * views draw tools from 0.001 mm to 1000 mm in radius, so fixed planes (0.01 and 1000 mm) clipped
 * the whole drawing at both ends of the range (issue 17). The planes enclose a sphere bounding the
 * drawing, wherever the user turned, zoomed or panned the camera; their ratio is bounded so the
 * depth buffer keeps its resolution when the camera is inside that sphere.
 */
import { Box3, type BufferGeometry, type Object3D, type PerspectiveCamera, Sphere, Vector3 } from 'three';

/** The bounding sphere is taken this much larger, so nothing on its edge is clipped (rounding). */
const SPHERE_MARGIN = 0.05;

/**
 * Smallest near plane as a fraction of the far plane. A 24-bit depth buffer resolves about
 * 2^24 * near / far steps at the far plane; 1e-4 keeps over a thousand there, and with the camera
 * outside the sphere (the fitted views) the ratio is far larger anyway.
 */
export const MIN_NEAR_OVER_FAR = 1e-4;

/** A camera's clipping planes (the scene's length unit, mm). */
export interface ClipPlanes {
  readonly nearMm: number;
  readonly farMm: number;
}

/**
 * The clipping planes that keep a sphere of radius `sphereRadiusMm` at `cameraToCentreMm` from the
 * camera wholly in view (in depth): far beyond its farthest point, near before its nearest point, or
 * `MIN_NEAR_OVER_FAR` of the far plane when the camera is inside it (or nearly so).
 *
 * @param cameraToCentreMm distance from the camera to the sphere's centre, mm, finite and >= 0
 * @param sphereRadiusMm the sphere's radius, mm, finite and > 0
 * @returns the planes (0 < near < far), or null for inputs outside those ranges (keep the old ones)
 */
export function clipPlanesMm(cameraToCentreMm: number, sphereRadiusMm: number): ClipPlanes | null {
  if (!(Number.isFinite(cameraToCentreMm) && cameraToCentreMm >= 0)) return null;
  if (!(Number.isFinite(sphereRadiusMm) && sphereRadiusMm > 0)) return null;
  const r = sphereRadiusMm * (1 + SPHERE_MARGIN);
  const farMm = cameraToCentreMm + r;
  const nearMm = Math.max(cameraToCentreMm - r, MIN_NEAR_OVER_FAR * farMm);
  return { nearMm, farMm };
}

/**
 * Sets a camera's near and far planes so that `sphere` (world coordinates, mm), seen from where the
 * camera now is, lies between them (clipPlanesMm); called before each frame, so they follow every
 * refit, turn, zoom and pan. An empty sphere (nothing drawn) leaves them as they are.
 *
 * @returns whether the planes changed (the projection matrix was then updated)
 */
export function fitClipPlanes(camera: PerspectiveCamera, sphere: Sphere): boolean {
  const planes = clipPlanesMm(camera.position.distanceTo(sphere.center), sphere.radius);
  if (planes === null || (planes.nearMm === camera.near && planes.farMm === camera.far)) return false;
  camera.near = planes.nearMm;
  camera.far = planes.farMm;
  camera.updateProjectionMatrix();
  return true;
}

/** The points of a geometry's position attribute that are drawn (its draw range), as a box in its own frame. */
function drawnBox(geometry: BufferGeometry, box: Box3): Box3 {
  box.makeEmpty();
  const position = geometry.getAttribute('position');
  if (position === undefined) return box;
  // An indexed geometry's draw range counts indices: every vertex is taken (the views draw them all).
  const indexed = geometry.getIndex() !== null;
  const first = indexed ? 0 : Math.max(0, geometry.drawRange.start);
  const end = indexed ? position.count : Math.min(position.count, first + geometry.drawRange.count);
  const p = new Vector3();
  for (let i = first; i < end; i++) box.expandByPoint(p.fromBufferAttribute(position, i));
  return box;
}

/**
 * A sphere bounding what `root` draws, in world coordinates: the drawn points (draw ranges only:
 * a line's buffer beyond its range keeps stale points of an earlier state) of every visible object
 * and the anchors of its visible labels (objects with no geometry count as their position). Hidden
 * objects and their children are left out. World matrices are updated first.
 *
 * @param isLabel which geometry-less objects are drawn points (the scene's label anchors)
 * @param out the sphere written (a new one by default)
 * @returns the sphere, or an empty one (radius -1) when nothing is drawn
 */
export function drawnBoundingSphere(
  root: Object3D,
  isLabel: (o: Object3D) => boolean,
  out: Sphere = new Sphere(),
): Sphere {
  root.updateMatrixWorld();
  const all = new Box3();
  const local = new Map<BufferGeometry, Box3>();
  const world = new Box3();
  const anchor = new Vector3();
  const visit = (o: Object3D): void => {
    if (!o.visible) return;
    const geometry = (o as Object3D & { geometry?: BufferGeometry }).geometry;
    if (geometry !== undefined) {
      let box = local.get(geometry);
      if (box === undefined) {
        box = drawnBox(geometry, new Box3());
        local.set(geometry, box);
      }
      if (!box.isEmpty()) all.union(world.copy(box).applyMatrix4(o.matrixWorld));
    } else if (isLabel(o)) all.expandByPoint(anchor.setFromMatrixPosition(o.matrixWorld));
    for (const child of o.children) visit(child);
  };
  visit(root);
  return all.isEmpty() ? out.makeEmpty() : all.getBoundingSphere(out);
}
