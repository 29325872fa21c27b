/** The points the camera is fitted to (src/render/framePoints.ts). */
import { BoxGeometry, BufferAttribute, BufferGeometry, Group, Line, LineBasicMaterial, Mesh, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { axisBoxCorners, framed, gatherFramePoints } from '../../src/render/framePoints';

describe('gatherFramePoints', () => {
  it("a box's 8 corners in world coordinates, a line's drawn points, a marked point's place; hidden ones left out", () => {
    const root = new Group();
    const tool = framed(new Mesh(new BoxGeometry(2, 2, 4)), 'box');
    tool.position.set(10, 0, 0);
    const lineGeometry = new BufferGeometry();
    lineGeometry.setAttribute('position', new BufferAttribute(new Float32Array([0, 0, 0, 1, 1, 1, 7, 7, 7]), 3));
    lineGeometry.setDrawRange(0, 2); // the third point is stale: not drawn
    const line = framed(new Line(lineGeometry, new LineBasicMaterial()), 'points', true);
    const dot = framed(new Group(), 'origin');
    dot.position.set(0, -5, 0);
    const hidden = framed(new Group(), 'origin');
    hidden.position.set(100, 100, 100);
    hidden.visible = false;
    root.add(tool, line, dot, hidden, new Mesh(new BoxGeometry(50, 50, 50)));
    root.updateMatrixWorld();
    const out: number[] = [];
    expect(gatherFramePoints(root, out, false)).toBe(8 + 2 + 1);
    const xs = out.filter((_, i) => i % 3 === 0);
    expect(Math.max(...xs)).toBe(11);
    expect(out).toEqual(expect.arrayContaining([1, 1, 1, 0, -5, 0]));
    expect(out).not.toContain(7);
    expect(out).not.toContain(100);
    // The close-up: only what is marked for it.
    expect(gatherFramePoints(root, out, true)).toBe(2);
  });

  it('a box about a tilted axis: tight around a tilted cylinder, its corners square to the axis', () => {
    // A cylinder of radius 1 from 0 to 4 along an axis tilted 30 deg (about x, and 20 deg about z).
    const a = [Math.sin(0.35) * Math.sin(0.52), -Math.cos(0.35) * Math.sin(0.52), Math.cos(0.52)] as const;
    const n = Math.hypot(...a);
    const axis = [a[0] / n, a[1] / n, a[2] / n] as const;
    const box = new Group();
    box.lookAt(...axis);
    box.updateMatrixWorld();
    const xyz: number[] = [];
    for (const along of [0, 4])
      for (let k = 0; k < 64; k++) {
        const t = (2 * Math.PI * k) / 64;
        const q = new Vector3(Math.cos(t), Math.sin(t), along).applyMatrix4(box.matrixWorld);
        xyz.push(q.x, q.y, q.z);
      }
    const out: number[] = [];
    axisBoxCorners(xyz, xyz.length / 3, axis, out);
    expect(out.length).toBe(24);
    for (let i = 0; i < 24; i += 3) {
      const [x, y, z] = [out[i] as number, out[i + 1] as number, out[i + 2] as number];
      const w = x * axis[0] + y * axis[1] + z * axis[2];
      // On the cylinder's end planes, within the square around its circle (half side 1: corner at sqrt 2).
      expect(Math.min(Math.abs(w), Math.abs(w - 4))).toBeLessThan(1e-9);
      expect(Math.hypot(x - w * axis[0], y - w * axis[1], z - w * axis[2])).toBeLessThanOrEqual(Math.SQRT2 + 1e-9);
      expect(Math.hypot(x - w * axis[0], y - w * axis[1], z - w * axis[2])).toBeGreaterThan(1);
    }
  });
});
