/** Height exaggeration of the 3D scene (pure part of render/scene.ts). */
import { describe, expect, it } from 'vitest';
import {
  drawHeightsInPlace,
  drawnHeightMm,
  drawnPoints,
  heightMapFor,
  sceneHeightExaggeration,
} from '../../src/render/heightExaggeration';

describe('scene height exaggeration', () => {
  it('the largest 1-2-5 factor that draws the scallop at most 0.12 R; true scale for a tall scallop', () => {
    expect(sceneHeightExaggeration(3, 0.05)).toBe(5); // 0.36 mm / 0.05 mm = 7.2
    expect(sceneHeightExaggeration(3, 0.001)).toBe(200);
    expect(sceneHeightExaggeration(3, 0.5)).toBe(1);
    expect(sceneHeightExaggeration(3, 0)).toBe(1);
    expect(sceneHeightExaggeration(Number.NaN, 0.05)).toBe(1);
  });

  it('heights in the band x N, continued at true scale above it, unchanged below the plane and at x1', () => {
    const map = heightMapFor(5, 0.05);
    expect(map.bandMm).toBe(0.1);
    expect(drawnHeightMm(map, 0.05)).toBeCloseTo(0.25, 15);
    expect(drawnHeightMm(map, 0.1)).toBeCloseTo(0.5, 15);
    expect(drawnHeightMm(map, 1.1)).toBeCloseTo(1.5, 15);
    expect(drawnHeightMm(map, -0.2)).toBe(-0.2);
    expect(drawnHeightMm(heightMapFor(1, 0.05), 0.05)).toBe(0.05);
    // Increasing: nothing folds over.
    let last = Number.NEGATIVE_INFINITY;
    for (let z = -1; z <= 2; z += 0.01) {
      const d = drawnHeightMm(map, z);
      expect(d).toBeGreaterThan(last);
      last = d;
    }
    expect(Array.from(drawnPoints(map, [1, 2, 0.05, 3, 4, 2]))).toEqual([
      1,
      2,
      Math.fround(0.25),
      3,
      4,
      Math.fround(2.4),
    ]);
  });

  it("draws a buffer's heights in place, only its first points, and leaves x and y", () => {
    const map = heightMapFor(5, 0.05);
    const buffer = Float32Array.from([1, 2, 0.05, 3, 4, 2, 5, 6, 0.05]);
    drawHeightsInPlace(map, buffer, 2);
    expect([...buffer]).toEqual([...drawnPoints(map, [1, 2, 0.05, 3, 4, 2]), 5, 6, Math.fround(0.05)]);
    const trueScale = Float32Array.from([1, 2, 0.05]);
    drawHeightsInPlace(heightMapFor(1, 0.05), trueScale, 1);
    expect([...trueScale]).toEqual([1, 2, Math.fround(0.05)]);
  });
});
