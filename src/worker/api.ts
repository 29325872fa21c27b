/**
 * The solver API that runs inside the Web Worker. Pure functions of plain data, so it is
 * tested in Node directly and exposed unchanged through Comlink in solver.worker.ts.
 */
import {
  compareForward,
  compareInverse,
  exactScallopHeightMm,
  type ForwardComparison,
  solveExact,
} from '../core/index';
import { toolMesh } from '../core/toolMesh';
import { validateForward, validateInverse } from '../core/validate';
import type { ProcedureKey, ProcedureRow, SceneGeometry, SolveReply, SolveRequest } from './protocol';

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
    solveMs: performance.now() - t0,
  };
}

/** Buffers of a reply that can be transferred instead of copied. */
export function transferables(reply: SolveReply): ArrayBuffer[] {
  if (!reply.ok || reply.geometry === null) return [];
  const g = reply.geometry;
  return [g.profile.buffer, g.toolPositions.buffer, ...g.intersectionLoops.map((l) => l.buffer)] as ArrayBuffer[];
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
