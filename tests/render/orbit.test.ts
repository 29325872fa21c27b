/** The 3D views' own orbit controller (src/render/orbit.ts), driven by pointer and wheel events. */
import { PerspectiveCamera, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { OrbitController } from '../../src/render/orbit';

/** A stand-in for the canvas: an event target of a given height that takes pointer capture. */
function element(heightPx = 400) {
  const target = new EventTarget() as EventTarget & { clientHeight: number; setPointerCapture(id: number): void };
  target.clientHeight = heightPx;
  target.setPointerCapture = () => {};
  return target as unknown as HTMLElement;
}

function pointer(type: string, init: Partial<PointerEvent> & { clientX: number; clientY: number }): Event {
  return Object.assign(new Event(type, { cancelable: true }), {
    pointerId: 1,
    pointerType: 'mouse',
    button: 0,
    buttons: 1,
    shiftKey: false,
    ...init,
  });
}

function drag(el: HTMLElement, dx: number, dy: number, init: Partial<PointerEvent> = {}, id = 1) {
  el.dispatchEvent(pointer('pointerdown', { clientX: 100, clientY: 100, pointerId: id, ...init }));
  el.dispatchEvent(pointer('pointermove', { clientX: 100 + dx, clientY: 100 + dy, pointerId: id, ...init }));
  el.dispatchEvent(pointer('pointerup', { clientX: 100 + dx, clientY: 100 + dy, pointerId: id, ...init }));
}

function setUp(position = new Vector3(10, 0, 0), target = new Vector3(0, 0, 0)) {
  const camera = new PerspectiveCamera(35, 1, 0.01, 1000);
  camera.up.set(0, 0, 1);
  camera.position.copy(position);
  const el = element();
  const controls = new OrbitController(camera, el);
  controls.target.copy(target);
  controls.update();
  let changes = 0;
  controls.onChange = () => changes++;
  return { camera, el, controls, changes: () => changes };
}

const close = (a: Vector3, b: Vector3, tol = 1e-9) => expect(a.distanceTo(b)).toBeLessThan(tol);

describe('OrbitController', () => {
  it('a drag across a quarter of the height turns the view a quarter turn about the up axis, keeping the distance', () => {
    const { camera, el, controls, changes } = setUp(new Vector3(10, 0, 2), new Vector3(0, 0, 2));
    drag(el, 100, 0); // 400 px high: 100 px is a quarter of a full turn
    close(camera.position, new Vector3(0, -10, 2));
    close(controls.target, new Vector3(0, 0, 2));
    expect(changes()).toBe(1);
    // The camera looks at the target.
    const dir = new Vector3();
    camera.getWorldDirection(dir);
    close(dir, new Vector3(0, 1, 0), 1e-9);
  });

  it('a vertical drag raises the camera towards the up axis but never over it', () => {
    const { camera, el } = setUp(new Vector3(10, 0, 0));
    drag(el, 0, 50); // an eighth of a turn: 45 degrees up
    expect(camera.position.length()).toBeCloseTo(10, 9);
    expect(Math.atan2(camera.position.z, camera.position.x)).toBeCloseTo(Math.PI / 4, 9);
    drag(el, 0, 1000); // far past the pole
    expect(camera.position.length()).toBeCloseTo(10, 9);
    expect(camera.position.z).toBeLessThan(10);
    expect(camera.position.x).toBeGreaterThan(0); // still on the same side: no flip
    drag(el, 0, -4000); // and past the other pole
    expect(camera.position.z).toBeGreaterThan(-10);
    expect(camera.position.x).toBeGreaterThan(0);
  });

  it('turns about the up axis the camera has (the top view has x up)', () => {
    const { camera, el } = setUp(new Vector3(0, 0, 10));
    camera.up.set(1, 0, 0);
    drag(el, 100, 0);
    expect(camera.position.length()).toBeCloseTo(10, 9);
    expect(Math.abs(camera.position.x)).toBeLessThan(1e-9); // turned about x: stays in the y-z plane
  });

  it('the wheel zooms by a factor per pixel, in and out, and keeps the page from scrolling', () => {
    const { camera, el } = setUp(new Vector3(10, 0, 0));
    const wheel = (deltaY: number) => {
      const e = Object.assign(new Event('wheel', { cancelable: true }), { deltaY, deltaMode: 0 });
      el.dispatchEvent(e);
      return e;
    };
    expect(wheel(100).defaultPrevented).toBe(true);
    expect(camera.position.x).toBeCloseTo(10 * Math.exp(0.1), 9);
    wheel(-200);
    expect(camera.position.x).toBeCloseTo(10 * Math.exp(-0.1), 9);
  });

  it('the right button or Shift pans: camera and target move together, across the view, by the pixels dragged', () => {
    for (const init of [{ buttons: 2, button: 2 }, { shiftKey: true }]) {
      const { camera, el, controls } = setUp(new Vector3(10, 0, 0));
      drag(el, 40, 0, init);
      const moved = controls.target.clone();
      close(camera.position.clone().sub(moved), new Vector3(10, 0, 0)); // same offset
      expect(moved.x).toBeCloseTo(0, 9); // across the view direction
      // 40 px of 400 px at distance 10 with a 35 degree field of view.
      expect(moved.length()).toBeCloseTo((40 * 2 * 10 * Math.tan((17.5 * Math.PI) / 180)) / 400, 9);
    }
  });

  it('two fingers spreading apart zoom in', () => {
    const { camera, el, controls } = setUp(new Vector3(10, 0, 0));
    const touch = (type: string, id: number, x: number) =>
      el.dispatchEvent(pointer(type, { pointerId: id, pointerType: 'touch', clientX: x, clientY: 100 }));
    touch('pointerdown', 1, 100);
    touch('pointerdown', 2, 200);
    touch('pointermove', 2, 300); // the fingers' distance doubles (and their midpoint pans)
    expect(camera.position.distanceTo(controls.target)).toBeCloseTo(5, 9);
  });

  it('does nothing once disposed', () => {
    const { camera, el, controls } = setUp(new Vector3(10, 0, 0));
    controls.dispose();
    drag(el, 100, 0);
    close(camera.position, new Vector3(10, 0, 0));
  });
});
