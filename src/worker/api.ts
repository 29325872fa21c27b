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
import {
  compareForward,
  compareInverse,
  exactHalfIntervalMm,
  exactScallopHeightMm,
  type ForwardComparison,
  type ForwardInput,
  farthestCrossing,
  solveExact,
  traceProcedure,
} from '../core/index';
import { normalAngleAtHeight, profileShape, ringAngleRad } from '../core/profile';
import { type PaperTableRow, paperTables, profileCurves, rhoSweep } from '../core/teaching';
import { toolMesh } from '../core/toolMesh';
import { ringTangent, sectionCentre, torusFrame } from '../core/torus';
import { validateForward, validateInverse } from '../core/validate';
import type {
  ProcedureKey,
  ProcedureRow,
  SceneGeometry,
  SolveReply,
  SolveRequest,
  TeachingData,
  TraceFrame,
} from './protocol';

const DEG = Math.PI / 180;

const PROCEDURES = ['sekine', 'redonnet', 'bedi'] as const;

function sceneGeometry(R: number, Rcr: number, rho: number, h: number): SceneGeometry {
  const sol = solveExact({ toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, scallopHeightMm: h }, 96);
  const mesh = toolMesh(R, Rcr, rho * DEG, 0.4 * R);
  return {
    toolRadiusMm: R,
    scallopHeightMm: h,
    halfIntervalMm: sol.halfIntervalMm,
    ringAngleRad: sol.ringAngleRad,
    toolCentre: sol.toolCentre,
    toolAxis: sol.toolAxis,
    pBase: sol.pBase,
    pHp: sol.pHp,
    sectionCentre: sol.sectionCircle.centre,
    sectionNormal: sol.sectionCircle.normal,
    sectionRadiusMm: sol.sectionCircle.radiusMm,
    intersectionLoops: sol.intersectionLoops,
    profile: sol.profile,
    toolPositions: mesh.positions,
  };
}

function deg(rad: number): string {
  return `${((rad * 180) / Math.PI).toFixed(2)} deg`;
}

/** The trace of the paper's procedure as frames for the 3D step-through. */
export function traceFrames(input: ForwardInput): TraceFrame[] {
  const frame = torusFrame(input.toolRadiusMm, input.cornerRadiusMm, input.leadAngleDeg * DEG);
  const rcr = input.cornerRadiusMm;
  const trace = traceProcedure(input);
  const section = (g: number) => ({ sectionCentre: sectionCentre(frame, g), sectionNormal: ringTangent(frame, g) });
  const frames: TraceFrame[] = [];
  let approach = 0;
  for (const step of trace.steps) {
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
      const candidates: number[] = [];
      step.ringAnglesRad.forEach((g, i) => {
        const y = step.crossingYMm[i];
        if (y === undefined || !Number.isFinite(y)) return;
        const p = farthestCrossing(frame, g, input.scallopHeightMm);
        if (p) candidates.push(p[0], p[1], p[2]);
      });
      frames.push({
        phase: 'search',
        caption: `Steps 16-25: ${step.ringAnglesRad.length} sections from gamma = ${deg(step.rangeRad[0])} to ${deg(step.rangeRad[1])}; their farthest crossings P_hp[i] with the plane. Best: gamma = ${deg(best)}, Y = ${step.pHp[1].toFixed(6)} mm; the range narrows to its neighbours.`,
        ringAngleRad: best,
        dsMm: null,
        ...section(best),
        candidates,
        point: step.pHp,
        bestY: step.pHp[1],
      });
    }
  }
  frames.push({
    phase: 'converged',
    caption: `Step 26: converged. L/2 = ${trace.halfIntervalMm.toFixed(6)} mm at gamma* = ${deg(trace.ringAngleRad)}; the exact solver gives ${exactHalfIntervalMm(input).toFixed(6)} mm.`,
    ringAngleRad: trace.ringAngleRad,
    dsMm: null,
    ...section(trace.ringAngleRad),
    candidates: [],
    point: trace.pHp,
    bestY: trace.halfIntervalMm,
  });
  return frames;
}

/** Fixed conditions: computed once per worker. */
const PAPER_TABLES: readonly PaperTableRow[] = paperTables();

function teachingData(input: ForwardInput): TeachingData {
  // Only the two angles are needed: solve for them, not for the whole viewer geometry.
  const shape = profileShape(input.toolRadiusMm, input.cornerRadiusMm, input.leadAngleDeg * DEG);
  const theta = normalAngleAtHeight(shape, input.scallopHeightMm);
  const sek = sekineModel(input);
  const red = redonnetModel(input);
  const bedi = bediModel(input);
  // The approximations' L/2 at this h, in either mode (in inverse mode the rows hold heights).
  const halfOf = (r: { ok: true; halfIntervalMm: number } | { ok: false }) => (r.ok ? r.halfIntervalMm : null);
  return {
    curves: profileCurves(input),
    sweep: rhoSweep(input.toolRadiusMm, input.cornerRadiusMm, input.scallopHeightMm, 0.5, 89, 120, input.leadAngleDeg),
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
      exactRingAngleRad: ringAngleRad(shape, theta),
    },
  };
}

/** Scallop (mm) that passes 2 * halfIntervalMm apart really leave, or a reason when none. */
function realScallop(
  R: number,
  Rcr: number,
  rho: number,
  halfIntervalMm: number,
): { mm: number | null; note: string | null } {
  if (halfIntervalMm >= R) return { mm: null, note: `its L/2 reaches the tool radius R: passes leave a wall` };
  return {
    mm: exactScallopHeightMm({ toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, halfIntervalMm }),
    note: null,
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
function modelRadius(c: ForwardComparison, key: (typeof PROCEDURES)[number]): number | null {
  if (key === 'bedi') return c.bedi.ok ? c.bedi.longRadiusMm : null;
  const r = c[key];
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
    const rows: ProcedureRow[] = [row('exact', { valueMm: exact, realScallopMm: req.value })];
    for (const key of PROCEDURES) {
      const r = c[key];
      if (!r.ok) {
        rows.push(row(key, { note: r.notApplicable }));
        continue;
      }
      const real = realScallop(R, Rcr, rho, r.halfIntervalMm);
      rows.push(
        row(key, {
          valueMm: r.halfIntervalMm,
          deviationMm: r.halfIntervalMm - exact,
          deviationPercent: (100 * (r.halfIntervalMm - exact)) / exact,
          realScallopMm: real.mm,
          note: real.note,
          modelRadiusMm: modelRadius(c, key),
        }),
      );
    }
    return {
      id: req.id,
      ok: true,
      mode: 'forward',
      halfIntervalMm: exact,
      scallopHeightMm: req.value,
      rows,
      geometry: sceneGeometry(R, Rcr, rho, req.value),
      teaching: req.withViews ? teachingData(v.value) : null,
      solveMs: performance.now() - t0,
    };
  }
  const half = req.value / 2;
  const v = validateInverse({ R, Rcr, rho, halfInterval: half });
  if (!v.ok) return { id: req.id, ok: false, errors: v.errors };
  const c = compareInverse(v.value);
  const exactH = c.exact.scallopHeightMm;
  const rows: ProcedureRow[] = [row('exact', { valueMm: exactH, realScallopMm: exactH })];
  for (const key of PROCEDURES) {
    const r = c[key];
    if (!r.ok) {
      rows.push(row(key, { note: r.notApplicable }));
      continue;
    }
    const dev = r.scallopHeightMm - exactH;
    rows.push(
      row(key, {
        valueMm: r.scallopHeightMm,
        deviationMm: dev,
        deviationPercent: exactH > 0 ? (100 * dev) / exactH : null,
        realScallopMm: exactH,
      }),
    );
  }
  return {
    id: req.id,
    ok: true,
    mode: 'inverse',
    halfIntervalMm: half,
    scallopHeightMm: exactH,
    rows,
    geometry: exactH >= 1e-9 ? sceneGeometry(R, Rcr, rho, exactH) : null,
    teaching:
      req.withViews && exactH >= 1e-9
        ? teachingData({ toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, scallopHeightMm: exactH })
        : null,
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
