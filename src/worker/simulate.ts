/**
 * The `simulate` job: the passes simulated on a height field (core/simulation/simulation.ts) at the exact
 * step-over of a request, beside the exact cusp and roughness it checks. Plain data in and out,
 * tested in Node; the worker (solver.worker.ts) runs it with a stop signal so that the next
 * input cancels it (latest wins). It yields between the simulation's steps, so a cancel message
 * gets through, and reports progress once it has run longer than a frame.
 * The reply echoes its request (the page's SolveRequest); its arrays are transferred.
 */
import { compareForward, compareInverse } from '../core/procedures/compare';
import { forwardOfRaTarget } from '../core/roughness/raTarget';
import { exactRoughness, exactRoughnessAtInterval, type Roughness } from '../core/roughness/roughness';
import { type SimulationResult, startSimulation } from '../core/simulation/simulation';
import { revalidate } from './jobs/revalidate';
import type { InputError, SolveRequest } from './protocol';

/** Cells of the page's simulation across and along the feed (the default, 512 x 512). */
export const PAGE_SIMULATION_CELLS = 512;

/**
 * What the simulation measured (mm; core/simulation/simulation.ts), beside the exact values it checks:
 * `heightsMm` and `trace` are transferred.
 */
export type SimulationSummary = Pick<
  SimulationResult,
  | 'cellsAcross'
  | 'cellsAlong'
  | 'acrossFromMm'
  | 'acrossToMm'
  | 'alongLengthMm'
  | 'heightsMm'
  | 'trace'
  | 'cuspHeightsMm'
  | 'cuspHeightMm'
  | 'roughness'
  | 'resolutionBoundMm'
  | 'roughnessBoundMm'
  | 'cells'
  | 'placements'
> & { readonly passes: number };

export type SimulateReply =
  | {
      readonly ok: true;
      readonly request: SolveRequest;
      /** The exact step-over simulated, the exact highest cusp and the exact roughness. */
      readonly exact: { readonly intervalMm: number; readonly cuspHeightMm: number; readonly roughness: Roughness };
      readonly simulation: SimulationSummary;
      readonly ms: number;
    }
  | {
      readonly ok: false;
      readonly request: SolveRequest;
      /** Input errors (a request the page should not have sent). */
      readonly errors: readonly InputError[];
      /** A valid request with nothing to simulate, said in words; null otherwise. */
      readonly reason: string | null;
      /** That reason as a code (a page words it in its language): not a plane, or no scallop; absent else. */
      readonly reasonCode?: 'planes-only' | 'no-scallop';
      /** Stopped because a newer request came. */
      readonly cancelled: boolean;
    };

export interface SimulateOptions {
  /** Cells across and along the feed (default PAGE_SIMULATION_CELLS). */
  readonly cells?: number;
  /** Called with the fraction done after each step once the run has taken longer than `frameMs`. */
  readonly onProgress?: (fraction: number) => void;
  /** Asked between steps: true stops the run (a newer request came). */
  readonly shouldStop?: () => boolean;
  /** Lets other messages through between steps (default: one macrotask). */
  readonly pause?: () => Promise<void>;
  /** Runs shorter than this report no progress (ms, default 16: one frame). */
  readonly frameMs?: number;
}

/** One macrotask: a cancel waiting in the worker's queue runs before the next step. */
function nextTask(): Promise<void> {
  return new Promise((resolve) => setTimeout(resolve, 0));
}

const PLANES_ONLY =
  'The simulation covers planes only: on a cylinder the exact values above still hold, but there is no simulated surface to compare them with.';
const NO_SCALLOP =
  'No scallop: the flat bottom lying on the plane leaves a flat surface, so there is nothing to simulate.';

/** The exact step-over, highest cusp and roughness a request comes to; or why none. */
function exactOf(
  request: SolveRequest,
): { intervalMm: number; cuspHeightMm: number; roughness: Roughness } | { reason: string } {
  if (request.mode === 'inverse') {
    const c = compareInverse(request.input);
    const e = c.exact;
    if (!(e.cuspHeightMm > 0)) return { reason: NO_SCALLOP };
    const roughness = exactRoughnessAtInterval(request.input, request.input.pattern, e, request.input.surface);
    return { intervalMm: e.intervalMm, cuspHeightMm: e.cuspHeightMm, roughness };
  }
  const input = request.mode === 'ra' ? forwardOfRaTarget(request.input) : request.input;
  const e = compareForward(input).exact;
  if (e.noScallop) return { reason: NO_SCALLOP };
  return { intervalMm: e.intervalMm, cuspHeightMm: e.cuspHeightMm, roughness: exactRoughness(input, e) };
}

/**
 * Simulates the passes a request leaves (plane only) at its exact step-over. Never throws for a
 * request the page can send; a cylinder or a flat surface gets a reason, a newer request a
 * cancelled reply.
 */
export async function simulate(request: SolveRequest, options: SimulateOptions = {}): Promise<SimulateReply> {
  const t0 = performance.now();
  const fail = (errors: readonly InputError[], reason: string | null, cancelled = false): SimulateReply => {
    const reasonCode = reason === PLANES_ONLY ? 'planes-only' : reason === NO_SCALLOP ? 'no-scallop' : undefined;
    return { ok: false, request, errors, reason, ...(reasonCode === undefined ? {} : { reasonCode }), cancelled };
  };
  const errors = revalidate(request);
  if (errors !== null) return fail(errors, null);
  if (request.input.surface.kind !== 'plane') return fail([], PLANES_ONLY);
  let exact: ReturnType<typeof exactOf>;
  try {
    exact = exactOf(request);
  } catch (e) {
    // forwardOfRaTarget on an Ra the page should have rejected.
    return fail([], `No simulation: ${String(e)}`);
  }
  if ('reason' in exact) return fail([], exact.reason);
  const cells = options.cells ?? PAGE_SIMULATION_CELLS;
  const run = startSimulation(
    { tool: request.input, pattern: request.input.pattern, intervalMm: exact.intervalMm },
    { cellsAcross: cells, cellsAlong: cells },
  );
  const pause = options.pause ?? nextTask;
  const frameMs = options.frameMs ?? 16;
  for (;;) {
    if (options.shouldStop?.()) return fail([], null, true);
    const finished = run.step();
    if (finished) break;
    if (performance.now() - t0 > frameMs) options.onProgress?.(run.progress);
    await pause();
  }
  const r = run.result();
  return {
    ok: true,
    request,
    exact,
    simulation: {
      cellsAcross: r.cellsAcross,
      cellsAlong: r.cellsAlong,
      passes: r.placements / r.cellsAlong,
      acrossFromMm: r.acrossFromMm,
      acrossToMm: r.acrossToMm,
      alongLengthMm: r.alongLengthMm,
      heightsMm: r.heightsMm,
      trace: r.trace,
      cuspHeightsMm: r.cuspHeightsMm,
      cuspHeightMm: r.cuspHeightMm,
      roughness: r.roughness,
      resolutionBoundMm: r.resolutionBoundMm,
      roughnessBoundMm: r.roughnessBoundMm,
      cells: r.cells,
      placements: r.placements,
    },
    ms: performance.now() - t0,
  };
}

/**
 * The worker's simulations, latest wins: starting one, or `cancel`, stops the one running at its
 * next step (it replies cancelled).
 */
export class SimulationRunner {
  private generation = 0;

  constructor(private readonly options: Pick<SimulateOptions, 'cells' | 'pause' | 'frameMs'> = {}) {}

  run(request: SolveRequest, onProgress?: (fraction: number) => void): Promise<SimulateReply> {
    const mine = ++this.generation;
    return simulate(request, { ...this.options, onProgress, shouldStop: () => this.generation !== mine });
  }

  cancel(): void {
    this.generation++;
  }
}

/** The buffers a simulate reply transfers instead of copying. */
export function simulationTransferables(reply: SimulateReply): ArrayBuffer[] {
  if (!reply.ok) return [];
  return [reply.simulation.heightsMm.buffer as ArrayBuffer, reply.simulation.trace.buffer as ArrayBuffer];
}
