/**
 * The solver API that runs inside the Web Worker. Pure functions of plain data, so it is
 * tested in Node directly and exposed unchanged through Comlink in solver.worker.ts.
 */
import {
  bediHalfInterval,
  bediModel,
  redonnetHalfInterval,
  redonnetModel,
  sekineHalfInterval,
  sekineModel,
} from '../core/approximations';
import { passGeometry } from '../core/geometry';
import { compareForward, compareInverse, exactIntervalMm, type ForwardInput, traceProcedure } from '../core/index';
import { placeTool, ringTangent, sectionCentre } from '../core/placement';
import { flankAtHeight, shapeOfTool } from '../core/posture';
import { type PaperTableRow, paperTables, profileCurves, rhoSweep } from '../core/teaching';
import { toolMesh } from '../core/toolMesh';
import { forwardInput, validateForward, validateInverse } from '../core/validate';
import type {
  ProcedureKey,
  ProcedureRow,
  SceneGeometry,
  SolveReply,
  SolveRequest,
  TeachingData,
  TraceFrame,
} from './protocol';

const PROCEDURES = ['sekine', 'redonnet', 'bedi'] as const;

function toolOf(R: number, Rcr: number, rho: number) {
  return { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: 0 };
}

function sceneGeometry(R: number, Rcr: number, rho: number, h: number): SceneGeometry {
  const tool = toolOf(R, Rcr, rho);
  const g = passGeometry(tool, h, h, 96);
  const mesh = toolMesh(tool, 0.4 * R);
  return {
    toolRadiusMm: R,
    scallopHeightMm: h,
    halfIntervalMm: exactIntervalMm(forwardInput(tool, 'one-way', h)) / 2,
    ringAngleRad: g.right.ringAngleRad,
    toolCentre: g.toolCentre,
    toolAxis: g.toolAxis,
    pBase: [0, 0, 0],
    pHp: g.right.pHp,
    sectionCentre: g.right.sectionCentre,
    sectionNormal: g.right.sectionNormal,
    sectionRadiusMm: g.right.sectionRadiusMm,
    intersectionLoops: g.loopsRight,
    profile: g.profile,
    toolPositions: mesh.positions,
  };
}

function deg(rad: number): string {
  return `${((rad * 180) / Math.PI).toFixed(2)} deg`;
}

/** The trace of the paper's procedure as frames for the 3D step-through (right flank; interim). */
export function traceFrames(input: ForwardInput): TraceFrame[] {
  const rcr = input.cornerRadiusMm;
  const trace = traceProcedure(input);
  const p = trace.placement;
  const section = (g: number) => ({ sectionCentre: sectionCentre(p, g), sectionNormal: ringTangent(p, g) });
  const frames: TraceFrame[] = [];
  let approach = 0;
  for (const step of trace.steps) {
    if (step.flank !== 'right') continue;
    if (step.phase === 'approach') {
      approach++;
      const first = approach === 1;
      frames.push({
        phase: 'approach',
        caption: first
          ? `Step 2 (Eq. 1): start at the section at ring angle gamma = ${deg(step.ringAngleRad)}, where the ring is h/2 above its lowest point; d_s = ${step.dsMm.toFixed(4)} mm against Rcr = ${rcr} mm.`
          : `Steps 6-11: move along the ring towards d_s = Rcr. Section at gamma = ${deg(step.ringAngleRad)}: d_s = ${step.dsMm.toFixed(4)} mm (Rcr - d_s = ${(rcr - step.dsMm).toExponential(2)} mm).`,
        ringAngleRad: step.ringAngleRad,
        dsMm: step.dsMm,
        ...section(step.ringAngleRad),
        candidates: [],
        point: null,
        bestY: null,
      });
    } else if (step.phase === 'single-contact') {
      frames.push({
        phase: 'single-contact',
        caption: step.found
          ? `Steps 12-14: the section at gamma_scp = ${deg(step.ringAngleRad)} touches the h pseudo plane at a single point (d_s = Rcr). It bounds the search range.`
          : 'Every section meets the h pseudo plane (no single contact): the search runs over the whole half ring.',
        ringAngleRad: step.ringAngleRad,
        dsMm: step.dsMm,
        ...section(step.ringAngleRad),
        candidates: [],
        point: step.found ? step.pHp : null,
        bestY: null,
      });
    } else {
      const best = step.ringAnglesRad[step.bestIndex] ?? 0;
      frames.push({
        phase: 'search',
        caption: `Steps 16-25: ${step.ringAnglesRad.length} sections from gamma = ${deg(step.rangeRad[0])} to ${deg(step.rangeRad[1])}; their farthest crossings P_hp[i] with the plane. Best: gamma = ${deg(best)}, Y = ${step.pHp[1].toFixed(6)} mm; the range narrows to its neighbours.`,
        ringAngleRad: best,
        dsMm: null,
        ...section(best),
        candidates: [...step.candidates],
        point: step.pHp,
        bestY: step.pHp[1],
      });
    }
  }
  frames.push({
    phase: 'converged',
    caption: `Step 26: converged. L/2 = ${trace.right.widthMm.toFixed(6)} mm at gamma* = ${deg(trace.right.ringAngleRad)}; the exact solver gives ${(exactIntervalMm(input) / 2).toFixed(6)} mm.`,
    ringAngleRad: trace.right.ringAngleRad,
    dsMm: null,
    ...section(trace.right.ringAngleRad),
    candidates: [],
    point: trace.right.pHp,
    bestY: trace.right.widthMm,
  });
  return frames;
}

/** Fixed conditions: computed once per worker. */
const PAPER_TABLES: readonly PaperTableRow[] = paperTables();

function teachingData(input: ForwardInput): TeachingData {
  // Only the two angles are needed: solve for them, not for the whole viewer geometry.
  const flank = flankAtHeight(shapeOfTool(input), 'right', input.scallopHeightMm);
  const theta = flank.normalAngleRad;
  const gamma = placeTool(input).contactRingAngleRad + flank.ringOffsetRad;
  const sek = sekineModel(input);
  const red = redonnetModel(input);
  const bedi = bediModel(input);
  // The approximations' L/2 at this h, in either mode (in inverse mode the rows hold heights).
  const halfOf = (r: { ok: true; halfIntervalMm: number } | { ok: false }) => (r.ok ? r.halfIntervalMm : null);
  return {
    curves: profileCurves(input),
    sweep: rhoSweep(
      input.toolRadiusMm,
      input.cornerRadiusMm,
      input.scallopHeightMm,
      0.5,
      89,
      120,
      input.leadAngleDeg,
      input.tiltAngleDeg,
      input.pattern,
    ),
    frames: traceFrames(input),
    tables: PAPER_TABLES,
    models: {
      sekine: sek.ok
        ? {
            toolCentreHeightMm: sek.toolCentreHeightMm,
            shortRadiusMm: sek.shortRadiusMm,
            longRadiusMm: sek.longRadiusMm,
            effectiveRadiusMm: sek.effectiveRadiusMm,
            halfIntervalMm: halfOf(sekineHalfInterval(input)),
          }
        : null,
      redonnet: red.ok
        ? { effectiveRadiusMm: red.effectiveRadiusMm, halfIntervalMm: halfOf(redonnetHalfInterval(input)) }
        : null,
      bedi: bedi.ok
        ? {
            longRadiusMm: bedi.longRadiusMm,
            shortRadiusMm: bedi.shortRadiusMm,
            halfIntervalMm: halfOf(bediHalfInterval(input)),
          }
        : null,
      exactNormalAngleRad: theta,
      exactRingAngleRad: gamma,
    },
  };
}

/** A results row: every field not given is null. */
function row(key: ProcedureKey, values: Partial<Omit<ProcedureRow, 'key'>>): ProcedureRow {
  return {
    key,
    valueMm: null,
    deviationMm: null,
    deviationPercent: null,
    realScallopMm: null,
    note: null,
    modelRadiusMm: null,
    ...values,
  };
}

/** The effective radius (Sekine, Redonnet) or ellipse long radius (Bedi) a procedure assumes, mm. */
function modelRadius(c: ReturnType<typeof compareForward>, key: (typeof PROCEDURES)[number]): number | null {
  if (key === 'bedi') {
    const b = c.approximations.bedi;
    return b.ok ? b.longRadiusMm : null;
  }
  const r = c.approximations[key];
  return r.ok ? r.effectiveRadiusMm : null;
}

/** Solves one request; never throws for any numeric input. */
export function solve(req: SolveRequest): SolveReply {
  const t0 = performance.now();
  const { R, Rcr, rho } = req;
  if (req.mode === 'forward') {
    const v = validateForward({ R, Rcr, rho, h: req.value });
    if (!v.ok) return { id: req.id, ok: false, errors: v.errors };
    const c = compareForward(v.value);
    const exact = c.exact.halfIntervalMm;
    const rows: ProcedureRow[] = [row('exact', { valueMm: exact, realScallopMm: c.exact.cuspHeightMm })];
    for (const key of PROCEDURES) {
      const r = c.approximations[key];
      if (!r.ok) {
        rows.push(row(key, { note: r.notApplicable }));
        continue;
      }
      rows.push(
        row(key, {
          valueMm: r.halfIntervalMm,
          deviationMm: r.halfIntervalMm - exact,
          deviationPercent: r.deviationPercent,
          realScallopMm: r.realScallopMm,
          note: r.warning,
          modelRadiusMm: modelRadius(c, key),
        }),
      );
    }
    const h = c.exact.cuspHeightMm;
    return {
      id: req.id,
      ok: true,
      mode: 'forward',
      halfIntervalMm: exact,
      scallopHeightMm: req.value,
      rows,
      geometry: h >= 1e-9 ? sceneGeometry(R, Rcr, rho, req.value) : null,
      teaching: req.withViews && h >= 1e-9 ? teachingData(v.value) : null,
      solveMs: performance.now() - t0,
    };
  }
  const v = validateInverse({ R, Rcr, rho, interval: req.value });
  if (!v.ok) return { id: req.id, ok: false, errors: v.errors };
  const c = compareInverse(v.value);
  const exactH = c.exact.cuspHeightMm;
  const rows: ProcedureRow[] = [row('exact', { valueMm: exactH, realScallopMm: exactH })];
  for (const key of PROCEDURES) {
    const r = c.approximations[key];
    if (!r.ok) {
      rows.push(row(key, { note: r.notApplicable }));
      continue;
    }
    rows.push(
      row(key, {
        valueMm: r.scallopHeightMm,
        deviationMm: r.deviationMm,
        deviationPercent: r.deviationPercent,
        realScallopMm: exactH,
      }),
    );
  }
  return {
    id: req.id,
    ok: true,
    mode: 'inverse',
    halfIntervalMm: req.value / 2,
    scallopHeightMm: exactH,
    rows,
    geometry: exactH >= 1e-9 ? sceneGeometry(R, Rcr, rho, exactH) : null,
    teaching:
      req.withViews && exactH >= 1e-9 ? teachingData(forwardInput(toolOf(R, Rcr, rho), 'one-way', exactH)) : null,
    solveMs: performance.now() - t0,
  };
}

/** Buffers of a reply that can be transferred instead of copied. */
export function transferables(reply: SolveReply): ArrayBuffer[] {
  if (!reply.ok || reply.geometry === null) return [];
  const g = reply.geometry;
  const out = [g.profile.buffer, g.toolPositions.buffer, ...g.intersectionLoops.map((l) => l.buffer)] as ArrayBuffer[];
  if (reply.teaching) {
    const c = reply.teaching.curves;
    for (const curve of [c.exact, c.ringEllipse, c.sekine, c.redonnet, c.bedi])
      if (curve) out.push(curve.buffer as ArrayBuffer);
  }
  return out;
}

/** The worker's API object; its type is what the page sees through Comlink. */
export const solverApi = {
  solve,
  /** Test hook: makes the worker die, as a crash would. */
  crash(): void {
    (globalThis as unknown as { close: () => void }).close();
  },
};

export type SolverApi = typeof solverApi;
