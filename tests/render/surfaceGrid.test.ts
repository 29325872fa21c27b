/** The simulated surface's mesh geometry (pure part of render/surfaceMesh.ts). */
import { describe, expect, it } from 'vitest';
import { HEIGHT_RAMP, rampColour, surfaceGrid } from '../../src/render/surfaceGrid';

describe('surface mesh', () => {
  it('one vertex per column across, heights exaggerated from the lowest point, coloured by height', () => {
    const across = 5;
    const along = 3;
    const heightsMm = new Float32Array(across * along);
    for (let i = 0; i < along; i++) heightsMm.set([0.5, 0.1, 0, 0.1, 0.5], i * across);
    const g = surfaceGrid(
      { cellsAcross: across, cellsAlong: along, acrossFromMm: -2, acrossToMm: 2, alongLengthMm: 6, heightsMm },
      10,
    );
    expect(g.positions.length).toBe(3 * across * along);
    expect(g.indices.length).toBe((along - 1) * (across - 1) * 6);
    expect(g.minMm).toBe(0);
    expect(g.maxMm).toBe(0.5);
    // Vertex (row 1, column 0): x = 3, y = -2, z = 0.5 * 10; the highest gets the top colour.
    const k = 3 * (1 * across + 0);
    expect([...g.positions.slice(k, k + 3)]).toEqual([3, -2, 5]);
    expect([...g.colours.slice(k, k + 3)].map((c) => Math.fround(c))).toEqual(
      (HEIGHT_RAMP[HEIGHT_RAMP.length - 1] as readonly number[]).map((c) => Math.fround(c)),
    );
    const low = 3 * 2;
    expect([...g.colours.slice(low, low + 3)].map((c) => Math.fround(c))).toEqual(
      (HEIGHT_RAMP[0] as readonly number[]).map((c) => Math.fround(c)),
    );
    for (const v of [...g.positions, ...g.colours]) expect(Number.isFinite(v)).toBe(true);
    for (const i of g.indices) expect(i).toBeLessThan(across * along);
  });

  it('keeps at most maxRows rows along the feed, and the ramp clamps', () => {
    const heightsMm = new Float32Array(16 * 100);
    const g = surfaceGrid(
      { cellsAcross: 16, cellsAlong: 100, acrossFromMm: 0, acrossToMm: 1, alongLengthMm: 1, heightsMm },
      1,
      { maxRows: 10 },
    );
    expect(g.positions.length).toBe(3 * 16 * 10);
    expect(rampColour(-1)).toEqual([...(HEIGHT_RAMP[0] as readonly number[])]);
    expect(rampColour(Number.NaN)).toEqual([...(HEIGHT_RAMP[0] as readonly number[])]);
    expect(rampColour(2)).toEqual([...(HEIGHT_RAMP[HEIGHT_RAMP.length - 1] as readonly number[])]);
  });

  it("a given range: heights from its lowest, the ramp's top at lowest + span (the teeth's exact Sz)", () => {
    const heightsMm = Float32Array.from([0.2, 0.3, 0.2, 0.3]);
    const g = surfaceGrid(
      { cellsAcross: 2, cellsAlong: 2, acrossFromMm: 0, acrossToMm: 1, alongLengthMm: 1, heightsMm },
      10,
      { range: { lowMm: 0.1, spanMm: 0.4 } },
    );
    expect(Math.fround(g.positions[2] as number)).toBe(Math.fround((Math.fround(0.2) - 0.1) * 10));
    expect([...g.colours.slice(3, 6)]).toEqual(rampColour((Math.fround(0.3) - 0.1) / 0.4).map((c) => Math.fround(c)));
  });
});
