/**
 * The wide lines' quads (render/fatLines.ts), in Node: each segment two triangles whose corners,
 * pushed across the segment's direction as the vertex shader pushes them, cover a band of the
 * line's width on both sides of it (no twisted or empty quad); a strip joins its points, a loop
 * closes, pairs stay apart; the draw range follows what was written, within the capacity.
 */
import type { BufferAttribute } from 'three';
import { describe, expect, it } from 'vitest';
import { FatLine, FatLineMaterial } from '../../src/render/fatLines';

/** The corners as the shader places them in a plane (z ignored): each end moved by side x half the width across its segment. */
function corners(line: FatLine, widthPx: number): Array<[number, number]> {
  const pos = line.geometry.getAttribute('position') as BufferAttribute;
  const other = line.geometry.getAttribute('other') as BufferAttribute;
  const side = line.geometry.getAttribute('side') as BufferAttribute;
  const out: Array<[number, number]> = [];
  for (let i = 0; i < line.geometry.drawRange.count; i++) {
    const [ax, ay, bx, by] = [pos.getX(i), pos.getY(i), other.getX(i), other.getY(i)];
    const len = Math.hypot(bx - ax, by - ay);
    const [nx, ny] = [-(by - ay) / len, (bx - ax) / len];
    out.push([ax + (nx * side.getX(i) * widthPx) / 2, ay + (ny * side.getX(i) * widthPx) / 2]);
  }
  return out;
}

/** Signed area of each triangle. */
function areas(c: Array<[number, number]>): number[] {
  const out: number[] = [];
  for (let i = 0; i + 2 < c.length; i += 3) {
    const [a, b, d] = [c[i], c[i + 1], c[i + 2]] as [[number, number], [number, number], [number, number]];
    out.push(((b[0] - a[0]) * (d[1] - a[1]) - (d[0] - a[0]) * (b[1] - a[1])) / 2);
  }
  return out;
}

describe('wide lines as quads', () => {
  it('a strip of 3 points: 2 segments, each a band of the width (both triangles the same way round, half the quad each)', () => {
    const line = new FatLine(8, new FatLineMaterial(0x112233, 3));
    line.points.set([0, 0, 0, 10, 0, 0, 10, 20, 0]);
    line.finish(3);
    expect(line.drawnPoints).toBe(3);
    expect(line.geometry.drawRange.count).toBe(12);
    const a = areas(corners(line, 4));
    expect(a).toHaveLength(4);
    // Segment 1 is 10 long, segment 2 20 long; the band 4 wide: quads of 40 and 80, two equal triangles each.
    for (const [i, want] of [20, 20, 40, 40].entries()) expect(Math.abs(a[i] as number)).toBeCloseTo(want, 9);
    expect(Math.sign(a[0] as number)).toBe(Math.sign(a[1] as number));
  });

  it('a loop closes; pairs stay apart; the capacity bounds what is drawn', () => {
    const loop = new FatLine(4, new FatLineMaterial(0x112233, 3), 'loop');
    loop.points.set([0, 0, 0, 1, 0, 0, 1, 1, 0]);
    loop.finish(3);
    expect(loop.geometry.drawRange.count).toBe(18);
    const pairs = new FatLine(4, new FatLineMaterial(0x112233, 3), 'pairs');
    pairs.points.set([0, 0, 0, 1, 0, 0, 5, 5, 0, 5, 6, 0]);
    pairs.finish(4);
    expect(pairs.geometry.drawRange.count).toBe(12);
    const pos = pairs.geometry.getAttribute('position') as BufferAttribute;
    // The second segment starts at (5, 5): no segment joins (1, 0) to (5, 5).
    expect([pos.getX(6), pos.getY(6)]).toEqual([5, 5]);
    for (const a of areas(corners(pairs, 2))) expect(Math.abs(a)).toBeGreaterThan(0.4);
    const full = new FatLine(2, new FatLineMaterial(0x112233, 3));
    full.points.set([0, 0, 0, 1, 0, 0]);
    full.finish(50);
    expect(full.drawnPoints).toBe(2);
    expect(full.geometry.drawRange.count).toBe(6);
  });

  it("the halo's material is wider by the halo each side and shares the background's colour", () => {
    const a = new FatLineMaterial('halo', 3, { overlay: true });
    const b = new FatLineMaterial('halo', 2, { overlay: true });
    expect(a.widthPx).toBe(6);
    expect(a.color).toBe(b.color);
    expect(a.depthTest).toBe(false);
    expect(new FatLineMaterial(0x112233, 3, { overlay: true }).transparent).toBe(true);
  });
});
