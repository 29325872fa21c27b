/**
 * The simulated surface's mesh geometry, pure (no DOM, no three.js; tested in Node): positions
 * from the simulation's height field, heights exaggerated from the lowest point, and colours by
 * height along one ramp (the view's legend draws the same ramp).
 */
import type { SimulationResult } from '../core/simulation/simulation';

/** The colour ramp, low to high (dark blue, teal, green, yellow), as 0-1 RGB stops. */
export const HEIGHT_RAMP: readonly (readonly [number, number, number])[] = [
  [0.12, 0.16, 0.42],
  [0.13, 0.48, 0.56],
  [0.35, 0.73, 0.37],
  [0.99, 0.88, 0.25],
];

/** The ramp's colour at `t` in [0, 1] (clamped; a non-finite t is the lowest colour). */
export function rampColour(t: number): [number, number, number] {
  const x = Number.isFinite(t) ? Math.min(1, Math.max(0, t)) : 0;
  const n = HEIGHT_RAMP.length - 1;
  const i = Math.min(n - 1, Math.floor(x * n));
  const f = x * n - i;
  const a = HEIGHT_RAMP[i] as readonly [number, number, number];
  const b = HEIGHT_RAMP[i + 1] as readonly [number, number, number];
  return [a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f];
}

/** A height field as the simulation gives it (mm). */
export type HeightField = Pick<
  SimulationResult,
  'cellsAcross' | 'cellsAlong' | 'acrossFromMm' | 'acrossToMm' | 'alongLengthMm' | 'heightsMm'
>;

export interface SurfaceGrid {
  /** xyz per vertex (x along the feed, y across, z the exaggerated height), mm. */
  readonly positions: Float32Array;
  readonly colours: Float32Array;
  readonly indices: Uint32Array;
  /** Lowest and highest height of the field (mm, not exaggerated). */
  readonly minMm: number;
  readonly maxMm: number;
}

/** How a height field is drawn: rows kept along the feed, and the heights the ramp spans. */
export interface SurfaceGridOptions {
  /** At most this many rows along the feed (the rows of a plane simulation repeat along it). */
  readonly maxRows?: number;
  /** The ramp's lowest height and its span (mm; default the field's own lowest and highest). */
  readonly range?: { readonly lowMm: number; readonly spanMm: number };
}

/**
 * The mesh of a height field: every column across the feed, at most `maxRows` rows along it
 * (48 unless given), heights times `exaggeration` above the ramp's lowest height.
 */
export function surfaceGrid(field: HeightField, exaggeration: number, options: SurfaceGridOptions = {}): SurfaceGrid {
  const nx = field.cellsAcross;
  const rows = Math.max(2, Math.min(field.cellsAlong, options.maxRows ?? 48));
  let lo = Number.POSITIVE_INFINITY;
  let hi = Number.NEGATIVE_INFINITY;
  for (const z of field.heightsMm) {
    if (z < lo) lo = z;
    if (z > hi) hi = z;
  }
  if (!Number.isFinite(lo) || !Number.isFinite(hi)) lo = hi = 0;
  const range = options.range;
  const base = range !== undefined && Number.isFinite(range.lowMm) ? range.lowMm : lo;
  const span = range !== undefined && range.spanMm > 0 ? range.spanMm : hi - lo;
  const positions = new Float32Array(rows * nx * 3);
  const colours = new Float32Array(rows * nx * 3);
  const dy = nx > 1 ? (field.acrossToMm - field.acrossFromMm) / (nx - 1) : 0;
  for (let r = 0; r < rows; r++) {
    const i = Math.min(field.cellsAlong - 1, Math.round((r * (field.cellsAlong - 1)) / (rows - 1)));
    const x = (r / (rows - 1)) * field.alongLengthMm;
    for (let j = 0; j < nx; j++) {
      const z = field.heightsMm[i * nx + j] ?? lo;
      const k = 3 * (r * nx + j);
      positions[k] = x;
      positions[k + 1] = field.acrossFromMm + j * dy;
      positions[k + 2] = (z - base) * exaggeration;
      const [cr, cg, cb] = rampColour(span > 0 ? (z - base) / span : 0);
      colours[k] = cr;
      colours[k + 1] = cg;
      colours[k + 2] = cb;
    }
  }
  const indices = new Uint32Array((rows - 1) * (nx - 1) * 6);
  let n = 0;
  for (let r = 0; r + 1 < rows; r++)
    for (let j = 0; j + 1 < nx; j++) {
      const a = r * nx + j;
      const b = a + nx;
      indices.set([a, b, a + 1, a + 1, b, b + 1], n);
      n += 6;
    }
  return { positions, colours, indices, minMm: lo, maxMm: hi };
}
