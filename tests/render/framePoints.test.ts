/** The points the camera is fitted to (src/render/framePoints.ts). */
import { BoxGeometry, BufferAttribute, BufferGeometry, Group, Line, LineBasicMaterial, Mesh } from 'three';
import { describe, expect, it } from 'vitest';
import { framed, gatherFramePoints } from '../../src/render/framePoints';

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
});
