/**
 * The placement of the passes and the height field they leave (simulation.ts): each pass's triangles
 * rasterised into the rows across the feed, each row keeping the lowest cut.
 */
import type { PassPattern } from '../domain/tool';
import type { Triangles } from './toolMesh';

/** Y offsets of the passes' contact paths and whether each pass is mirrored. */
export function passLayout(
  input: { readonly intervalMm: number; readonly pattern: PassPattern },
  passes: number,
): Array<{ y: number; mirrored: boolean }> {
  const out: Array<{ y: number; mirrored: boolean }> = [];
  for (let k = 0; k < passes; k++)
    out.push({ y: k * input.intervalMm, mirrored: input.pattern === 'zigzag' && k % 2 === 1 });
  return out;
}

/** The height field across the feed: `rows` rows from y0, dy apart, each with its lowest cut, mm. */
export interface Field {
  readonly rows: number;
  readonly y0: number;
  readonly dy: number;
  readonly rowMin: Float64Array;
}

/** Rasterises the triangles of one pass into the rows: each row keeps the lowest cut. */
export function sweep(tris: Triangles, pass: { y: number; mirrored: boolean }, field: Field): void {
  const { rows, y0, dy, rowMin } = field;
  const sign = pass.mirrored ? -1 : 1;
  const v = [0, 0, 0, 0, 0, 0];
  for (let k = 0; k < tris.length; k += 6) {
    for (let m = 0; m < 3; m++) {
      v[2 * m] = pass.y + sign * (tris[k + 2 * m] as number);
      v[2 * m + 1] = tris[k + 2 * m + 1] as number;
    }
    const yMin = Math.min(v[0] as number, v[2] as number, v[4] as number);
    const yMax = Math.max(v[0] as number, v[2] as number, v[4] as number);
    const j0 = Math.max(0, Math.ceil((yMin - y0) / dy));
    const j1 = Math.min(rows - 1, Math.floor((yMax - y0) / dy));
    for (let j = j0; j <= j1; j++) {
      const y = y0 + j * dy;
      let low = Number.POSITIVE_INFINITY;
      // The row's plane cuts the triangle along a segment whose lowest end lies on an edge.
      for (let e = 0; e < 3; e++) {
        const ya = v[2 * e] as number;
        const za = v[2 * e + 1] as number;
        const yb = v[(2 * e + 2) % 6] as number;
        const zb = v[(2 * e + 3) % 6] as number;
        if ((ya - y) * (yb - y) > 0) continue;
        const z = ya === yb ? Math.min(za, zb) : za + ((zb - za) * (y - ya)) / (yb - ya);
        if (z < low) low = z;
      }
      if (low < (rowMin[j] as number)) rowMin[j] = low;
    }
  }
}
