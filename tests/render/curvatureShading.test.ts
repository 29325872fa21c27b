/**
 * The colours of a doubly curved patch (render/curvatureShading.ts): a dome falls away from its
 * tangent plane everywhere (blue only), a bowl rises everywhere (orange only), a saddle does both in
 * alternate quadrants; a plane stays white (the material's own colour, as before).
 */
import { describe, expect, it } from 'vitest';
import type { DrawnSurface } from '../../src/core/output/surfaceGeometry';
import { patchIndices, surfacePatch } from '../../src/core/output/surfaceGeometry';
import {
  BAND_TEXELS,
  bandColourInto,
  curvatureBandsInto,
  FALLING_RGB,
  RISING_RGB,
  SHADING_BANDS,
} from '../../src/render/curvatureShading';

/**
 * What the patch shows at its vertices, RGB: the band strip at each vertex's coordinate (as
 * bandMaterial.ts reads it), times its shade.
 */
function coloursOf(positions: ArrayLike<number>, rows: number, columns: number, flatMm: number): Float32Array {
  const n = rows * columns;
  const out = new Float32Array(3 * n);
  const uv = new Float32Array(2 * n);
  if (!(curvatureBandsInto(uv, out, positions, rows, columns, flatMm) > flatMm)) return out;
  const rgb = new Float32Array(3);
  for (let i = 0; i < n; i++) {
    const texel = Math.min(BAND_TEXELS - 1, Math.floor((uv[2 * i] as number) * BAND_TEXELS));
    const falling = texel < SHADING_BANDS;
    bandColourInto(rgb, 0, falling, falling ? SHADING_BANDS - 1 - texel : texel - SHADING_BANDS);
    for (let k = 0; k < 3; k++) out[3 * i + k] = (out[3 * i + k] as number) * (rgb[k] as number);
  }
  return out;
}

const ROWS = 13;
const COLUMNS = 17;

/** Counts of bluish and orangish vertices of a patch 6 mm square around the CC point. */
function hues(surface: DrawnSurface): { falling: number; rising: number; white: number } {
  const points = surfacePatch(surface, 0, 3, 3, ROWS - 1, COLUMNS - 1);
  const colours = coloursOf(points, ROWS, COLUMNS, 1e-9);
  let falling = 0;
  let rising = 0;
  let white = 0;
  for (let i = 0; i < colours.length; i += 3) {
    const [r, , b] = [colours[i] as number, colours[i + 1] as number, colours[i + 2] as number];
    if (r === 1 && b === 1) white++;
    else if (b > r) falling++;
    else rising++;
  }
  return { falling, rising, white };
}

describe('curvature shading', () => {
  it('dome: all falling; bowl: all rising; saddle: both; plane: white', () => {
    const n = ROWS * COLUMNS;
    // The CC point itself lies on the tangent plane: counted with the rising side (z = 0).
    expect(hues({ kind: 'torus', feedRadiusMm: 20, crossRadiusMm: 30 }).falling).toBe(n - 1);
    expect(hues({ kind: 'torus', feedRadiusMm: -20, crossRadiusMm: -30 }).rising).toBe(n);
    const saddle = hues({ kind: 'torus', feedRadiusMm: 20, crossRadiusMm: -20 });
    expect(saddle.falling).toBeGreaterThan(0.3 * n);
    expect(saddle.rising).toBeGreaterThan(0.3 * n);
    expect(hues({ kind: 'plane' }).white).toBe(n);
    expect(FALLING_RGB[2]).toBeGreaterThan(FALLING_RGB[0]);
    expect(RISING_RGB[0]).toBeGreaterThan(RISING_RGB[2]);
    expect(patchIndices(ROWS - 1, COLUMNS - 1).length).toBe((ROWS - 1) * (COLUMNS - 1) * 6);
  });
});

describe('the colours at the vertices on a cylinder', () => {
  it('a convex cylinder (heights 0 along its tangent line, below it elsewhere): every colour finite, the tangent line pale', () => {
    const rows = 5;
    const columns = 7;
    const positions: number[] = [];
    for (let r = 0; r < rows; r++)
      for (let c = 0; c < columns; c++) {
        const y = c - 3;
        positions.push(r, y, -(y * y) / 10);
      }
    const out = coloursOf(positions, rows, columns, 0);
    expect(out.every(Number.isFinite)).toBe(true);
    // The tangent line (y = 0) in the palest band, lighter than the edges.
    expect(out[3 * 3]).toBeGreaterThan(out[0] as number);
  });
});
