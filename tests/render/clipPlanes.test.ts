/**
 * The 3D views' near and far planes from the size of the drawing (src/render/clipPlanes.ts), checked
 * against three.js's own camera transform: every point of the drawing's bounding sphere lies between
 * the planes, from the fitted views of the smallest and the largest tool and from cameras moved
 * anywhere around it (issue 17, item 3).
 */
import {
  BufferAttribute,
  BufferGeometry,
  Group,
  Line,
  LineBasicMaterial,
  Mesh,
  MeshBasicMaterial,
  Object3D,
  PerspectiveCamera,
  Sphere,
  SphereGeometry,
  Vector3,
} from 'three';
import { describe, expect, it } from 'vitest';
import { clipPlanesMm, drawnBoundingSphere, fitClipPlanes, MIN_NEAR_OVER_FAR } from '../../src/render/clipPlanes';

/** Points on a sphere's surface (a Fibonacci lattice), and its centre. */
function spherePoints(sphere: Sphere, n = 400): Vector3[] {
  const out = [sphere.center.clone()];
  const golden = Math.PI * (3 - Math.sqrt(5));
  for (let i = 0; i < n; i++) {
    const z = 1 - (2 * (i + 0.5)) / n;
    const rho = Math.sqrt(1 - z * z);
    const a = golden * i;
    out.push(new Vector3(rho * Math.cos(a), rho * Math.sin(a), z).multiplyScalar(sphere.radius).add(sphere.center));
  }
  return out;
}

/** A camera at `position` looking at `target`, its planes set by fitClipPlanes for `sphere`. */
function camera(position: Vector3, target: Vector3, sphere: Sphere): PerspectiveCamera {
  const c = new PerspectiveCamera(40, 1.2, 0.01, 1000);
  c.up.set(0, 0, 1);
  c.position.copy(position);
  c.lookAt(target);
  fitClipPlanes(c, sphere);
  c.updateMatrixWorld();
  return c;
}

/** Depths of points along the camera's view direction (three.js's camera space: -z ahead). */
function depths(c: PerspectiveCamera, points: readonly Vector3[]): number[] {
  return points.map((p) => -p.clone().applyMatrix4(c.matrixWorldInverse).z);
}

/** The scene's isometric preset for a tool of radius R (scene.ts setCamera). */
function isoCamera(R: number) {
  const target = new Vector3(0, 0, 0.3 * R);
  const d = 4.2 * R;
  return { position: target.clone().add(new Vector3(0.75 * d, -0.85 * d, 0.6 * d)), target };
}

describe('clipPlanesMm', () => {
  it('encloses the sphere from outside it: near before its nearest point, far beyond its farthest', () => {
    for (const [d, r] of [
      [10, 1],
      [5.4e-3, 2.5e-3],
      [5400, 2500],
      [1e6, 1],
    ] as const) {
      const p = clipPlanesMm(d, r);
      if (p === null) throw new Error('planes expected');
      expect(p.nearMm).toBeGreaterThan(0);
      expect(p.nearMm).toBeLessThan(d - r);
      expect(p.farMm).toBeGreaterThan(d + r);
      expect(p.nearMm / p.farMm).toBeGreaterThanOrEqual(MIN_NEAR_OVER_FAR);
      // And close around it: the depth buffer is not spent on empty space (5 % margin).
      expect(p.farMm).toBeLessThanOrEqual(d + 1.05 * r * (1 + 1e-12));
    }
  });

  it('from inside the sphere (zoomed in): far beyond it, near the bounded fraction of far', () => {
    for (const d of [0, 0.3, 0.99, 1]) {
      const p = clipPlanesMm(d, 1);
      if (p === null) throw new Error('planes expected');
      expect(p.farMm).toBeGreaterThan(d + 1);
      expect(p.nearMm).toBeCloseTo(MIN_NEAR_OVER_FAR * p.farMm, 15);
    }
  });

  it('scales with the drawing: the same view of a tool 1e6 times larger has planes 1e6 times farther', () => {
    const small = clipPlanesMm(5.4e-3, 2.5e-3);
    const large = clipPlanesMm(5.4e3, 2.5e3);
    if (small === null || large === null) throw new Error('planes expected');
    expect(large.nearMm / small.nearMm).toBeCloseTo(1e6, 3);
    expect(large.farMm / small.farMm).toBeCloseTo(1e6, 3);
  });

  it('no planes for a distance or a radius outside its range (the old planes are kept)', () => {
    for (const [d, r] of [
      [Number.NaN, 1],
      [-1, 1],
      [Number.POSITIVE_INFINITY, 1],
      [1, 0],
      [1, -1],
      [1, Number.NaN],
      [1, Number.POSITIVE_INFINITY],
    ] as const)
      expect(clipPlanesMm(d, r), `${d}, ${r}`).toBeNull();
  });
});

describe('fitClipPlanes, checked with three.js camera transforms', () => {
  // About the scene's drawing around a tool of radius R: the plane patch 2.8 R by 2 L + 2.4 R, the
  // tool and its axis up to 2.2 R above the tool's centre (scene.ts update), in a sphere of 3 R.
  const drawing = (R: number) => new Sphere(new Vector3(0, 0, R), 3 * R);
  for (const R of [0.001, 0.01, 3, 500, 1000]) {
    it(`the isometric view of a tool of R = ${R} mm has the whole drawing between its planes`, () => {
      const sphere = drawing(R);
      const { position, target } = isoCamera(R);
      const c = camera(position, target, sphere);
      for (const z of depths(c, spherePoints(sphere))) {
        expect(z).toBeGreaterThan(c.near);
        expect(z).toBeLessThan(c.far);
      }
      // Projected by three.js: every point within the clip volume's depth (-1 near, 1 far).
      for (const p of spherePoints(sphere)) {
        const ndc = p.clone().project(c);
        expect(Math.abs(ndc.z)).toBeLessThan(1);
      }
    });
  }

  it('the old fixed planes (0.01 and 1000 mm) clipped the whole drawing at R = 0.001 and R = 500 mm', () => {
    for (const R of [0.001, 500]) {
      const sphere = drawing(R);
      const { position, target } = isoCamera(R);
      const c = new PerspectiveCamera(40, 1.2, 0.01, 1000);
      c.up.set(0, 0, 1);
      c.position.copy(position);
      c.lookAt(target);
      c.updateMatrixWorld();
      const inside = depths(c, spherePoints(sphere)).filter((z) => z > 0.01 && z < 1000);
      expect(inside, `R = ${R}`).toEqual([]);
    }
  });

  it('follows the camera wherever it is moved: turned, zoomed far out, zoomed into the drawing, panned', () => {
    const sphere = new Sphere(new Vector3(0.2, -0.1, 0.5), 2.5);
    const points = spherePoints(sphere);
    const target = new Vector3(0, 0, 0.3);
    for (const position of [
      new Vector3(3, -3.5, 2.5),
      new Vector3(-4, 1, -3),
      new Vector3(3e4, -3.5e4, 2.5e4),
      new Vector3(0.5, 0.2, 0.6),
      new Vector3(0.2, -0.1, 0.5),
    ]) {
      const c = camera(position, target, sphere);
      const outside = position.distanceTo(sphere.center) > sphere.radius * 1.05;
      for (const z of depths(c, points)) {
        expect(z).toBeLessThan(c.far);
        if (outside) expect(z).toBeGreaterThan(c.near);
      }
      expect(c.near / c.far).toBeGreaterThanOrEqual(MIN_NEAR_OVER_FAR * (1 - 1e-12));
    }
  });

  it('changes the planes only when they change, and keeps them for an empty sphere', () => {
    const sphere = new Sphere(new Vector3(), 1);
    const c = new PerspectiveCamera(40, 1, 0.01, 1000);
    c.position.set(0, 0, 10);
    expect(fitClipPlanes(c, sphere)).toBe(true);
    expect(fitClipPlanes(c, sphere)).toBe(false);
    const before = [c.near, c.far];
    expect(fitClipPlanes(c, new Sphere().makeEmpty())).toBe(false);
    expect([c.near, c.far]).toEqual(before);
  });
});

describe('drawnBoundingSphere', () => {
  const line = (points: number[], drawn: number) => {
    const g = new BufferGeometry();
    g.setAttribute('position', new BufferAttribute(new Float32Array(points), 3));
    g.setDrawRange(0, drawn);
    return new Line(g, new LineBasicMaterial());
  };

  it("takes a line's drawn points only: the buffer beyond its draw range keeps an earlier state's", () => {
    const root = new Group();
    // Two points drawn, from (-1, 0, 0) to (1, 0, 0); two stale ones 1000 mm away.
    root.add(line([-1, 0, 0, 1, 0, 0, 1000, 0, 0, 0, 1000, 0], 2));
    const s = drawnBoundingSphere(root, () => false);
    expect(s.center.toArray()).toEqual([0, 0, 0]);
    expect(s.radius).toBeCloseTo(1, 12);
  });

  it('leaves out hidden objects and the children of hidden ones; applies the world matrices', () => {
    const root = new Group();
    const scaled = new Group();
    scaled.scale.setScalar(500);
    scaled.position.set(0, 0, 100);
    const dot = new Mesh(new SphereGeometry(1, 8, 6), new MeshBasicMaterial());
    scaled.add(dot);
    const hidden = new Group();
    hidden.visible = false;
    hidden.add(line([1e6, 0, 0, -1e6, 0, 0], 2));
    const hiddenLine = line([0, 1e6, 0, 0, -1e6, 0], 2);
    hiddenLine.visible = false;
    root.add(scaled, hidden, hiddenLine);
    const s = drawnBoundingSphere(root, () => false);
    expect(s.center.z).toBeCloseTo(100, 9);
    // The box around the scaled unit sphere (500 mm) and its half diagonal.
    expect(s.radius).toBeCloseTo(500 * Math.sqrt(3), 6);
  });

  it("counts a label's anchor (a point with no geometry) when the predicate says it is one", () => {
    const root = new Group();
    root.add(line([0, 0, 0, 1, 0, 0], 2));
    const anchor = new Object3D();
    anchor.position.set(0, 0, 3);
    anchor.userData.label = true;
    root.add(anchor);
    expect(drawnBoundingSphere(root, () => false).radius).toBeCloseTo(0.5, 12);
    const withLabel = drawnBoundingSphere(root, (o) => o.userData.label === true);
    expect(withLabel.radius).toBeCloseTo(Math.hypot(1, 3) / 2, 6);
  });

  it('is empty when nothing is drawn', () => {
    const root = new Group();
    const hidden = line([0, 0, 0, 1, 1, 1], 2);
    hidden.visible = false;
    root.add(hidden, new Object3D());
    expect(drawnBoundingSphere(root, () => false).isEmpty()).toBe(true);
  });
});
