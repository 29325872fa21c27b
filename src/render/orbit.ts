/**
 * Turns, zooms and pans a camera about a target with the pointer, for the page's two 3D views:
 * the left button or one finger turns the view about the camera's up axis, the wheel or two
 * fingers (pinch) zoom, the right button, Shift with the left, or two fingers moved together pan.
 * A small stand-in for three.js's OrbitControls (4.4 kB gzip alone), which the page's JavaScript
 * budget (200 kB gzip in all) cannot afford beside three.js's renderer; the same gestures, without
 * damping, keys or inertia, which the views do not use.
 *
 * The element's `touch-action` is left to the page: with `pan-y`, a vertical swipe scrolls the
 * page and the browser cancels the gesture (`pointercancel`), so only a deliberate horizontal
 * drag or a pinch reaches the view.
 */
import { type PerspectiveCamera, Quaternion, Vector3 } from 'three';
import { degToRad } from '../core/input/units';

/** Radians turned per pixel dragged, as a fraction of the element's height (a full turn per height). */
const TURN_PER_HEIGHT_RAD = 2 * Math.PI;
/** Distance factor per wheel pixel (deltaY 100, one notch, zooms by about 10 %). */
const ZOOM_PER_WHEEL_PX = 0.001;
/** The polar angle is kept this far from the up axis, so the view never flips over it (rad). */
const POLAR_MARGIN_RAD = 1e-4;

const Z = new Vector3(0, 0, 1);

export class OrbitController {
  /** The point the camera looks at and turns about (world units). */
  readonly target = new Vector3();
  /** Called after each change the user makes (the view redraws). */
  onChange: (() => void) | null = null;
  /** Called when the user zooms or pans (the view stops fitting its camera to what it draws). */
  onZoomOrPan: (() => void) | null = null;

  private readonly pointers = new Map<number, { x: number; y: number }>();
  private readonly offset = new Vector3();
  private readonly toZ = new Quaternion();
  private readonly fromZ = new Quaternion();
  private readonly right = new Vector3();
  private readonly upOnScreen = new Vector3();

  constructor(
    private readonly camera: PerspectiveCamera,
    private readonly element: HTMLElement,
  ) {
    element.addEventListener('pointerdown', this.onPointerDown);
    element.addEventListener('pointermove', this.onPointerMove);
    element.addEventListener('pointerup', this.onPointerUp);
    element.addEventListener('pointercancel', this.onPointerUp);
    element.addEventListener('wheel', this.onWheel, { passive: false });
    element.addEventListener('contextmenu', this.onContextMenu);
  }

  /** Points the camera at the target (after the camera or the target was moved by code). */
  update(): void {
    this.camera.lookAt(this.target);
  }

  /** Removes the listeners. */
  dispose(): void {
    const e = this.element;
    e.removeEventListener('pointerdown', this.onPointerDown);
    e.removeEventListener('pointermove', this.onPointerMove);
    e.removeEventListener('pointerup', this.onPointerUp);
    e.removeEventListener('pointercancel', this.onPointerUp);
    e.removeEventListener('wheel', this.onWheel);
    e.removeEventListener('contextmenu', this.onContextMenu);
    this.pointers.clear();
    this.onChange = null;
    this.onZoomOrPan = null;
  }

  /**
   * Turns the camera about the target: `azimuthRad` about the up axis, `polarRad` towards it
   * (positive: the camera rises), the distance kept.
   */
  turn(azimuthRad: number, polarRad: number): void {
    this.toZ.setFromUnitVectors(this.camera.up, Z);
    this.fromZ.copy(this.toZ).invert();
    const o = this.offset.copy(this.camera.position).sub(this.target).applyQuaternion(this.toZ);
    const r = o.length();
    if (r === 0) return;
    const azimuth = Math.atan2(o.y, o.x) + azimuthRad;
    const polar = Math.min(
      Math.PI - POLAR_MARGIN_RAD,
      Math.max(POLAR_MARGIN_RAD, Math.acos(Math.min(1, Math.max(-1, o.z / r))) - polarRad),
    );
    o.set(r * Math.sin(polar) * Math.cos(azimuth), r * Math.sin(polar) * Math.sin(azimuth), r * Math.cos(polar));
    this.camera.position.copy(this.target).add(o.applyQuaternion(this.fromZ));
    this.changed();
  }

  /** Moves the camera towards the target (factor < 1) or away from it (> 1). */
  zoom(factor: number): void {
    if (!(factor > 0) || !Number.isFinite(factor)) return;
    this.offset.copy(this.camera.position).sub(this.target).multiplyScalar(factor);
    this.camera.position.copy(this.target).add(this.offset);
    this.onZoomOrPan?.();
    this.changed();
  }

  /** Moves camera and target together by a drag of (dx, dy) pixels on an element `heightPx` high. */
  pan(dxPx: number, dyPx: number, heightPx: number): void {
    const distance = this.camera.position.distanceTo(this.target);
    const unitsPerPx = (2 * distance * Math.tan(degToRad(this.camera.fov / 2))) / Math.max(1, heightPx);
    this.camera.updateMatrixWorld();
    this.right.setFromMatrixColumn(this.camera.matrixWorld, 0).multiplyScalar(-dxPx * unitsPerPx);
    this.upOnScreen.setFromMatrixColumn(this.camera.matrixWorld, 1).multiplyScalar(dyPx * unitsPerPx);
    this.right.add(this.upOnScreen);
    this.target.add(this.right);
    this.camera.position.add(this.right);
    this.onZoomOrPan?.();
    this.changed();
  }

  private changed(): void {
    this.camera.lookAt(this.target);
    this.onChange?.();
  }

  private readonly onPointerDown = (event: PointerEvent): void => {
    if (event.pointerType === 'mouse' && event.button !== 0 && event.button !== 2) return;
    this.element.setPointerCapture?.(event.pointerId);
    this.pointers.set(event.pointerId, { x: event.clientX, y: event.clientY });
  };

  private readonly onPointerMove = (event: PointerEvent): void => {
    const last = this.pointers.get(event.pointerId);
    if (last === undefined) return;
    const heightPx = this.element.clientHeight || 1;
    const dx = event.clientX - last.x;
    const dy = event.clientY - last.y;
    if (this.pointers.size >= 2) {
      // Two fingers: the change of their distance zooms, the move of their midpoint pans.
      const [a, b] = [...this.pointers.values()] as [{ x: number; y: number }, { x: number; y: number }];
      const before = Math.hypot(a.x - b.x, a.y - b.y);
      last.x = event.clientX;
      last.y = event.clientY;
      const after = Math.hypot(a.x - b.x, a.y - b.y);
      if (before > 0 && after > 0) this.zoom(before / after);
      this.pan(dx / 2, dy / 2, heightPx);
      return;
    }
    last.x = event.clientX;
    last.y = event.clientY;
    if ((event.buttons & 2) !== 0 || event.shiftKey) this.pan(dx, dy, heightPx);
    else this.turn((-TURN_PER_HEIGHT_RAD * dx) / heightPx, (TURN_PER_HEIGHT_RAD * dy) / heightPx);
  };

  private readonly onPointerUp = (event: PointerEvent): void => {
    this.pointers.delete(event.pointerId);
  };

  private readonly onWheel = (event: WheelEvent): void => {
    event.preventDefault();
    const px = event.deltaMode === 1 ? event.deltaY * 16 : event.deltaMode === 2 ? event.deltaY * 400 : event.deltaY;
    this.zoom(Math.exp(px * ZOOM_PER_WHEEL_PX));
  };

  private readonly onContextMenu = (event: Event): void => event.preventDefault();
}
