/**
 * A simulation of the passes, independent of the projection argument of posture.ts: the real tool
 * surface (torus corner and flat bottom, in its posture; placement.ts) is sampled as points, the
 * tool is swept along several adjacent passes over a height field (z-buffer) of the design plane,
 * and the material left is measured along a trace across the passes.
 *
 * Sweep. A pass moves the tool along X through every cell of the field (one placement per cell
 * along the feed). A surface sample at (x, y, z) then visits every cell of the row its y falls in,
 * so the z-buffer keeps, per row, the minimum z of the samples that fall in that row; the field is
 * that row minimum along X. Passes sit `L` apart in Y; zigzag passes are mirrored (y -> -y) on
 * every other pass.
 *
 * Meshing. The surface is meshed by triangles whose corners lie on it: a uniform grid in its own
 * parameters (ring angle and section angle for the corner's lower outer quarter; the same angles
 * and the radius for the bottom disk, so the two meet without cracks), kept only in blocks that can
 * reach below a height cap (taken from a coarse first run, plus its bound) and into the field. A
 * triangle cut by the plane of a row gives a segment whose lowest end is that triangle's value for
 * the row; the row keeps the lowest. So a small scallop under a big tool costs little. Nothing
 * here uses the exact solver or the projected ellipse.
 *
 * Resolution bound (stated with every result). The tool solid is convex, so a triangle with its
 * corners on the surface lies inside the solid: a row's value is at or above the true envelope E
 * and at most the chord error above it (chordErrorMm: `l^2 / (8 Rcr)` across the corner, capped at
 * `2 Rcr` for a corner smaller than a triangle, plus `l^2 / (8 (Rb + Rcr))` around the axis, for
 * the rim of a flat end too; l the longest triangle edge; the flat bottom itself is exact). A cusp is located between rows by intersecting the lines through the two rows on
 * each side: its error adds at most the measured curvature of the trace times `dy^2`. Roughness is
 * integrated on the piecewise-linear trace through the rows and the refined cusps; its values are
 * within twice the height bound. Lengths mm.
 *
 * The parts: the meshed tool surface (toolMesh.ts), the placement of the passes and the height
 * field (passes.ts), and the measurement (measurement.ts).
 */

import type { PassPattern, ToolInput } from '../domain/tool';
import { placeTool } from '../tool/placement';
import { measure } from './measurement';
import { type Field, passLayout, sweep } from './passes';
import {
  chordErrorMm,
  MAX_SIMULATION_TRIANGLES,
  meshSurface,
  SimulationTooLargeError,
  type Triangles,
} from './toolMesh';

/** The mesh's limit (toolMesh.ts), re-exported for the callers. */
export { MAX_SIMULATION_TRIANGLES, SimulationTooLargeError };

/** What is simulated: a tool in its posture, a pass pattern and a step-over. */
export interface SimulationInput {
  readonly tool: ToolInput;
  readonly pattern: PassPattern;
  /** Step-over L between adjacent cutter-contact paths, mm (> 0). */
  readonly intervalMm: number;
}

export interface SimulationOptions {
  /** Cells across the feed (Y), default 512. */
  readonly cellsAcross?: number;
  /** Cells along the feed (X), default 512. */
  readonly cellsAlong?: number;
  /** Passes: default 5 one-way, 4 zigzag (both cusps). */
  readonly passes?: number;
}

export interface SimulationResult {
  readonly cellsAcross: number;
  readonly cellsAlong: number;
  /** Y of the first and last row centres, and the X length of the field, mm. */
  readonly acrossFromMm: number;
  readonly acrossToMm: number;
  readonly alongLengthMm: number;
  /** Heights of the material left, mm above the design plane: row-major, `cellsAlong` rows of `cellsAcross`. */
  readonly heightsMm: Float32Array;
  /** The profilometer trace across the passes at mid-length: (y, z) pairs, mm. */
  readonly trace: Float64Array;
  /** Measured height of each cusp between adjacent passes, mm (alternating kinds for zigzag). */
  readonly cuspHeightsMm: number[];
  /** The highest measured cusp, mm. */
  readonly cuspHeightMm: number;
  /** Roughness of the trace over whole periods (one-way: L each, zigzag: 2L each), mm. */
  readonly roughness: { readonly rzMm: number; readonly raMm: number; readonly rqMm: number; readonly meanMm: number };
  /** Bound on the cusp-height error (see the module comment), mm; roughness values within twice it plus s dy. */
  readonly resolutionBoundMm: number;
  /** Bound on the roughness values' error, mm. */
  readonly roughnessBoundMm: number;
  /** Cell size across the feed and the largest sample spacing, mm. */
  readonly cellMm: number;
  readonly sampleSpacingMm: number;
  readonly cells: number;
  /** Tool placements: one per cell along the feed, per pass. */
  readonly placements: number;
  /** Triangles of the tool surface used. */
  readonly samples: number;
}

/** A simulation that runs in steps, so a worker can yield between them, report progress and cancel. */
export interface SimulationRun {
  /** Does the next step; true when the result is ready. */
  step(): boolean;
  /** Fraction done, 0 to 1. */
  readonly progress: number;
  /** The result, after step() returned true. */
  result(): SimulationResult;
}

/**
 * Prepares a simulation (see the module comment). Steps: a coarse run to bound the height that
 * matters, then the fine sampling, then the sweep of each pass, then the measurement.
 * @param input a valid tool and posture, pattern and step-over (0 < L, below the wall).
 * A step throws {@link SimulationTooLargeError} when the tool surface needs more triangles than
 * {@link MAX_SIMULATION_TRIANGLES}.
 */
export function startSimulation(input: SimulationInput, options: SimulationOptions = {}): SimulationRun {
  const across = Math.max(16, Math.round(options.cellsAcross ?? 512));
  const along = Math.max(2, Math.round(options.cellsAlong ?? 512));
  const passes = Math.max(2, Math.round(options.passes ?? (input.pattern === 'zigzag' ? 4 : 5)));
  const L = input.intervalMm;
  const p = placeTool(input.tool);
  const layout = passLayout(input, passes);
  // Rows from half a step-over before the first pass to half a step-over after the last one.
  const span = passes * L;
  const dy = span / across;
  const y0 = -0.5 * L + 0.5 * dy;
  const yLo = y0 - 0.5 * dy;
  const yHi = y0 + (across - 0.5) * dy;
  const inRange = (a: number, b: number) =>
    layout.some((pass) => {
      const lo = pass.mirrored ? pass.y - b : pass.y + a;
      const hi = pass.mirrored ? pass.y - a : pass.y + b;
      return hi >= yLo && lo <= yHi;
    });
  const newField = (rows: number, step: number, first: number): Field => ({
    rows,
    y0: first,
    dy: step,
    rowMin: new Float64Array(rows).fill(Number.POSITIVE_INFINITY),
  });
  const fine = newField(across, dy, y0);
  // Triangle edges of half a cell: chord error l^2 / (8 Rcr), far below the cell.
  const edge = dy / 2;
  let stage = 0;
  let tris: Triangles = new Float64Array(0);
  let zCap = Number.POSITIVE_INFINITY;
  let passIndex = 0;
  let retries = 0;
  let done: SimulationResult | null = null;
  const totalSteps = 3 + passes;
  return {
    get progress() {
      // Steps: two coarse runs and the mesh (stages 0, 1), one sweep per pass, the measurement.
      const steps = stage < 2 ? stage : stage === 2 ? 2 + passIndex : 2 + passes;
      return done ? 1 : Math.min(0.99, steps / totalSteps);
    },
    step() {
      if (done) return true;
      if (stage === 0) {
        // Coarse runs (64 rows) bound the height that matters. First a strip of the surface around
        // the plane x = 0: any part of the tool leaves material at or above what the whole tool
        // leaves, so its cusps bound the true ones from above. Then the whole surface below that
        // bound, for a close estimate.
        const coarseRows = 64;
        const cdy = span / coarseRows;
        const coarseCap = (tris: Triangles): number => {
          const coarse = newField(coarseRows, cdy, -0.5 * L + 0.5 * cdy);
          for (const pass of layout) sweep(tris, pass, coarse);
          const m = measure(coarse, input, passes);
          const top = Math.max(0, ...m.cusps.map((c) => c.z).filter(Number.isFinite));
          return top + m.slope * cdy + chordErrorMm(p, cdy / 2);
        };
        const strip = coarseCap(meshSurface(p, cdy / 2, Number.POSITIVE_INFINITY, inRange, 2 * cdy));
        // A quarter more covers what the coarse rows cannot resolve; should a row in the measured
        // span still get no triangle below the cap, the sweep doubles the cap and runs again.
        zCap = 1.25 * Math.min(strip, coarseCap(meshSurface(p, cdy / 2, strip, inRange)));
        stage = 1;
        return false;
      }
      if (stage === 1) {
        tris = meshSurface(p, edge, zCap, inRange);
        stage = 2;
        return false;
      }
      if (stage === 2) {
        const pass = layout[passIndex];
        if (pass) sweep(tris, pass, fine);
        passIndex++;
        if (passIndex >= layout.length) stage = 3;
        return false;
      }
      // Every row between the first and the last contact must have met the surface below the cap.
      const lastContact = (passes - 1) * L;
      let missing = false;
      for (let j = 0; j < across; j++) {
        const y = y0 + j * dy;
        if (y >= 0 && y <= lastContact && !Number.isFinite(fine.rowMin[j] as number)) missing = true;
      }
      if (missing && retries < 20) {
        retries++;
        zCap = 2 * zCap + dy;
        fine.rowMin.fill(Number.POSITIVE_INFINITY);
        passIndex = 0;
        stage = 1;
        return false;
      }
      const m = measure(fine, input, passes);
      // Rows no low triangle reached lie above the cap: show them at the cap.
      for (let j = 0; j < across; j++) if (!Number.isFinite(fine.rowMin[j] as number)) fine.rowMin[j] = zCap;
      const heights = new Float32Array(across * along);
      for (let i = 0; i < along; i++)
        for (let j = 0; j < across; j++) heights[i * across + j] = fine.rowMin[j] as number;
      const trace = new Float64Array(2 * across);
      for (let j = 0; j < across; j++) {
        trace[2 * j] = y0 + j * dy;
        trace[2 * j + 1] = fine.rowMin[j] as number;
      }
      // Longest triangle edge: about sqrt(2) grid steps; chord error l^2 / (8 Rcr) (flat bottom: 0).
      const l = Math.SQRT2 * edge * 1.5;
      const chord = chordErrorMm(p, l);
      const curvature = Math.max(0, ...m.cusps.map((c) => c.curvature));
      const bound = chord + curvature * dy * dy;
      const cuspHeights = m.cusps.map((c) => c.z);
      done = {
        cellsAcross: across,
        cellsAlong: along,
        acrossFromMm: y0,
        acrossToMm: y0 + (across - 1) * dy,
        alongLengthMm: along * dy,
        heightsMm: heights,
        trace,
        cuspHeightsMm: cuspHeights,
        cuspHeightMm: Math.max(...cuspHeights),
        roughness: m.roughness,
        resolutionBoundMm: bound,
        roughnessBoundMm: 2 * bound + (m.slope * dy * dy) / (2 * L),
        cellMm: dy,
        sampleSpacingMm: l,
        cells: across * along,
        placements: passes * along,
        samples: tris.length / 6,
      };
      return true;
    },
    result() {
      if (!done) throw new Error('the simulation has not finished');
      return done;
    },
  };
}

/** Runs a simulation to the end (command line, tests). */
export function simulatePasses(input: SimulationInput, options: SimulationOptions = {}): SimulationResult {
  const run = startSimulation(input, options);
  while (!run.step()) {
    // next step
  }
  return run.result();
}
