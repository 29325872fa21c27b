/**
 * Analytic height grids for the x3p tests: a constant plus a sum of cosines over whole periods of
 * the grid, sampled on the notes' grid (sample `i` at `x = (i + 1/2) dx`). Over whole periods the
 * samples' mean is the constant, and, when no two waves alias (no wave vector is another's or its
 * negative's modulo the grid, none is half the grid), the samples' Sq is `sqrt(sum a^2 / 2)`:
 * values known without computing a mean.
 */
import type { HeightGrid } from '../../../src/core/output/x3p';

/** One wave: `amplitudeMm cos(2 pi (p x / (nx dx) + q y / (ny dy)) + phase)`. */
export interface Wave {
  amplitudeMm: number;
  /** Whole periods along x over the grid. */
  p: number;
  /** Whole periods along y over the grid. */
  q: number;
  phase: number;
}

/** A grid case: the grid's shape and the surface on it. */
export interface GridCase {
  name: string;
  nx: number;
  ny: number;
  dxMm: number;
  dyMm: number;
  constantMm: number;
  waves: Wave[];
}

/** The heights of `c` on its grid, row-major with x fastest, with the notes' origin (dx/2, dy/2). */
export function gridOf(c: GridCase): HeightGrid & { xOriginMm: number; yOriginMm: number } {
  const heightsMm = new Float64Array(c.nx * c.ny);
  for (let j = 0; j < c.ny; j++) {
    for (let i = 0; i < c.nx; i++) {
      let h = c.constantMm;
      for (const w of c.waves)
        h += w.amplitudeMm * Math.cos(2 * Math.PI * ((w.p * (i + 0.5)) / c.nx + (w.q * (j + 0.5)) / c.ny) + w.phase);
      heightsMm[j * c.nx + i] = h;
    }
  }
  return { nx: c.nx, ny: c.ny, dxMm: c.dxMm, dyMm: c.dyMm, heightsMm, xOriginMm: c.dxMm / 2, yOriginMm: c.dyMm / 2 };
}

/** The samples' exact Sq of `c` (the waves must not alias: see the file's comment). */
export function analyticSqMm(c: GridCase): number {
  return Math.sqrt(c.waves.reduce((sum, w) => sum + w.amplitudeMm ** 2 / 2, 0));
}

/** The grids of the tests: odd and even sizes, square and not, tiny and large heights. */
export const GRID_CASES: GridCase[] = [
  {
    name: 'even 64 x 48, dx != dy, micrometre heights',
    nx: 64,
    ny: 48,
    dxMm: 0.002,
    dyMm: 0.0035,
    constantMm: 0.001,
    waves: [
      { amplitudeMm: 0.004, p: 1, q: 0, phase: 0.3 },
      { amplitudeMm: 0.0015, p: 3, q: 2, phase: -1.1 },
      { amplitudeMm: 0.0007, p: 0, q: 5, phase: 2.2 },
    ],
  },
  {
    name: 'odd 33 x 17, sub-nanometre heights',
    nx: 33,
    ny: 17,
    dxMm: 0.01,
    dyMm: 0.007,
    constantMm: -3e-7,
    waves: [
      { amplitudeMm: 4e-7, p: 2, q: 1, phase: 0.5 },
      { amplitudeMm: 1e-7, p: 7, q: -3, phase: 1.9 },
    ],
  },
  {
    name: 'odd x even 41 x 10, millimetre heights far from zero',
    nx: 41,
    ny: 10,
    dxMm: 0.125,
    dyMm: 0.05,
    constantMm: 37.5,
    waves: [
      { amplitudeMm: 2.5, p: 1, q: 1, phase: 0 },
      { amplitudeMm: 0.8, p: 4, q: 0, phase: -0.4 },
    ],
  },
  {
    name: 'a single row, 9 x 1',
    nx: 9,
    ny: 1,
    dxMm: 0.3,
    dyMm: 0.3,
    constantMm: 0,
    waves: [{ amplitudeMm: 0.01, p: 2, q: 0, phase: 0.7 }],
  },
  {
    name: 'the default export size 1024 x 1024 (8 MB of heights)',
    nx: 1024,
    ny: 1024,
    dxMm: 0.0009765625,
    dyMm: 0.0015,
    constantMm: 0.0002,
    waves: [
      { amplitudeMm: 0.003, p: 5, q: 0, phase: 0.2 },
      { amplitudeMm: 0.0012, p: 17, q: 3, phase: 1.3 },
      { amplitudeMm: 0.0004, p: -40, q: 61, phase: -2.5 },
    ],
  },
];
