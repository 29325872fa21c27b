/**
 * The areal height map of the surface the teeth leave, for the x3p export (shared/notes/
 * surface-finish.md, "Exchange with metrology software"): `nx` by `ny` heights over whole period
 * cells, sample (i, j) at x = (i + 1/2) dx, y = (j + 1/2) dy, so that a reader computing Sa on it
 * without levelling or filtering gets the sampled value of the definition. Lengths mm.
 */
import { RowEnvelope } from './rowEnvelope';
import { RunoutRow } from './runout';
import type { ToothModel } from './toothModel';

/** A height map on a regular grid (row-major: index i + nx j), heights in mm above the design plane. */
export interface ArealMap {
  readonly nx: number;
  readonly ny: number;
  /** Increments along x (the feed) and y (across), mm. */
  readonly dxMm: number;
  readonly dyMm: number;
  /** The cells covered along x and y. */
  readonly cellsX: number;
  readonly cellsY: number;
  readonly heightsMm: Float64Array;
}

/**
 * The map of `cellsX` by `cellsY` period cells (feed period by cross period, toothModel.ts) sampled
 * `nx` by `ny` (integers >= 1; cells integers >= 1). One row's passes are prepared once (RowEnvelope).
 */
export function arealMap(m: ToothModel, nx: number, ny: number, cellsX = 1, cellsY = 1): ArealMap {
  const widthMm = cellsX * m.feedPeriodMm;
  const heightMm = cellsY * m.crossPeriodMm;
  const dx = widthMm / nx;
  const dy = heightMm / ny;
  const heights = new Float64Array(nx * ny);
  for (let j = 0; j < ny; j++) {
    const y = (j + 0.5) * dy;
    const row = m.input.finish.runoutMm > 0 ? new RunoutRow(m, y) : new RowEnvelope(m, y);
    for (let i = 0; i < nx; i++) heights[i + nx * j] = row.heightAt((i + 0.5) * dx);
  }
  return { nx, ny, dxMm: dx, dyMm: dy, cellsX, cellsY, heightsMm: heights };
}
