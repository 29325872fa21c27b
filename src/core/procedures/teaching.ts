/**
 * Data for the teaching views: the cross-feed profiles each procedure assumes, a sweep of
 * L/2 over the lead angle, and the paper's tables recomputed. Pure; lengths mm, angles degrees.
 */

import type { InverseInput } from '../domain/pass';
import { PLANE, type Surface } from '../domain/surface';
import type { PassPattern, ToolInput } from '../domain/tool';
import { forwardInput, inverseInput } from '../input/validate';
import { surfaceModel } from '../surfaces/registry';
import { exactIntervalMm, exactScallopHeightMm } from '../surfaces/solve';
import { leavesNoScallop, scallopHeightLimits } from '../surfaces/validate';
import { shapeOfTool } from '../tool/posture';
import { profilePolyline } from '../tool/profile';
import { compareForward } from './compare';
import { PAPER_CONDITIONS, type PaperCondition, type ProcedureValues } from './paper';
import {
  APPROXIMATION_KEYS,
  APPROXIMATIONS,
  type ApproximationKey,
  type ModelCurve,
  modelCurve,
  PAPER_PROCEDURE_KEYS,
  type PaperProcedureKey,
  PROCEDURE_KEYS,
  type ProcedureKey,
} from './procedures';
import { noAnswerReason, type SweepGap, sweepGaps } from './sweepGaps';

/** Cross-feed curves as flat (y, z) arrays, z above the contact, y from the contact (mm). */
export interface ProfileCurves extends ApproximationCurves {
  /** Exact tool profile, right flank only: y from 0 outwards (the whole profile without tilt, mirrored). */
  readonly exact: Float64Array;
  /** Exact tool profile, both flanks: y from the left flank's widest point to the right one's. */
  readonly profile: Float64Array;
  /** The ring ellipse it is offset from (semi-axes Rb, Rb cos(beta) sin(rho), turned by the tilt), closed. */
  readonly ringEllipse: Float64Array;
}

/**
 * Each approximation's curve (its model's circle or ellipse: Sekine's and Redonnet's Reff, Bedi's
 * ellipse with semi-axes Rlong and Rlong sin rho, the osculating circle, the corner ball), or null
 * where its model does not apply.
 */
export type ApproximationCurves = { readonly [K in ApproximationKey]: Float64Array | null };

/** Lower arc of a circle of radius r touching z = 0 at y = 0, for y in [0, min(r, yMax)]. */
function circleArc(r: number, yMax: number, n: number): Float64Array {
  const out = new Float64Array(2 * (n + 1));
  const top = Math.min(r, yMax);
  for (let i = 0; i <= n; i++) {
    const y = (top * i) / n;
    out[2 * i] = y;
    out[2 * i + 1] = (y * y) / (r + Math.sqrt(Math.max(0, r * r - y * y)));
  }
  return out;
}

/** Lower arc of the ellipse with semi-axes a (y) and b (z) touching z = 0 at y = 0. */
function ellipseArc(a: number, b: number, yMax: number, n: number): Float64Array {
  const out = new Float64Array(2 * (n + 1));
  const top = Math.min(a, yMax);
  for (let i = 0; i <= n; i++) {
    const y = (top * i) / n;
    const q = y / a;
    out[2 * i] = y;
    out[2 * i + 1] = (b * q * q) / (1 + Math.sqrt(Math.max(0, 1 - q * q)));
  }
  return out;
}

/**
 * Profiles for the cross-feed view.
 * @param tool validated tool and posture; @param samples points per curve (>= 16).
 */
export function profileCurves(tool: ToolInput, samples = 400): ProfileCurves {
  const n = Math.max(16, Math.round(samples));
  const R = tool.toolRadiusMm;
  const s = shapeOfTool(tool);
  const profile = profilePolyline(s, n);
  // The right flank: the points at y >= 0 (the contact itself first).
  const right: number[] = [0, 0];
  for (let i = 0; i < profile.length; i += 2) {
    const y = profile[i] as number;
    if (y > 0) right.push(y, profile[i + 1] as number);
  }
  // Ring ellipse: the ring points relative to the contact (their centre is D0 + Rcr above it).
  const ring = new Float64Array(2 * (n + 1));
  for (let i = 0; i <= n; i++) {
    const t = (2 * Math.PI * i) / n;
    // e(t) - e(t0) in the global frame, lifted by Rcr (the contact lies Rcr below e(t0)).
    const ey = s.a * Math.sin(t) - s.a * s.sinT0;
    const ez = -s.b * Math.cos(t) + s.b * s.cosT0;
    ring[2 * i] = ey * s.cosPhi + ez * s.sinPhi;
    ring[2 * i + 1] = -ey * s.sinPhi + ez * s.cosPhi + s.rcr;
  }
  const curves = {} as { -readonly [K in ApproximationKey]: Float64Array | null };
  for (const key of APPROXIMATION_KEYS) {
    const m = modelCurve(key, tool);
    curves[key] = m.ok ? curveArc(m.curve, 2 * R, n) : null;
  }
  return { exact: Float64Array.from(right), profile, ringEllipse: ring, ...curves };
}

/** The lower arc of a model's curve for y in [0, yMax] (n + 1 points); null for a flat ellipse. */
function curveArc(curve: ModelCurve, yMax: number, n: number): Float64Array | null {
  if (curve.shape === 'circle') return circleArc(curve.radiusMm, yMax, n);
  return curve.shortRadiusMm > 0 ? ellipseArc(curve.longRadiusMm, curve.shortRadiusMm, yMax, n) : null;
}

/** L/2 of the four procedures over the lead angle (NaN-free: null where none). */
export interface RhoSweep {
  readonly rhoDeg: number[];
  readonly exact: Array<number | null>;
  readonly sekine: Array<number | null>;
  readonly redonnet: Array<number | null>;
  readonly bedi: Array<number | null>;
}

/**
 * Sweeps rho from `fromDeg` to `toDeg` (plus `includeDeg`, if given) at fixed R, Rcr and h. The
 * samples are spaced geometrically (0 < fromDeg < toDeg), dense at small rho where L/2 and the
 * approximations' errors change fastest. Where h is at or above the corner height at some rho
 * (small rho, large h) every procedure is null there.
 */
export function rhoSweep(
  R: number,
  Rcr: number,
  h: number,
  fromDeg = 0.5,
  toDeg = 89,
  steps = 120,
  includeDeg: number | null = null,
  tiltDeg = 0,
  pattern: PassPattern = 'one-way',
): RhoSweep {
  const out: RhoSweep = { rhoDeg: [], exact: [], sekine: [], redonnet: [], bedi: [] };
  const angles: number[] = [];
  const ratio = toDeg / fromDeg;
  for (let i = 0; i <= steps; i++) angles.push(i === steps ? toDeg : fromDeg * ratio ** (i / steps));
  // The current angle is one of the samples, so the chart's values there are the solver's.
  if (includeDeg !== null && includeDeg >= fromDeg && includeDeg <= toDeg && !angles.includes(includeDeg)) {
    angles.push(includeDeg);
    angles.sort((a, b) => a - b);
  }
  for (const rho of angles) {
    out.rhoDeg.push(rho);
    const tool: ToolInput = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tiltDeg };
    if (!(h < scallopHeightLimits(tool).limitMm)) {
      for (const key of ['exact', ...PAPER_PROCEDURE_KEYS] as const) out[key].push(null);
      continue;
    }
    const input = forwardInput(tool, pattern, h);
    out.exact.push(exactIntervalMm(input) / 2);
    for (const key of PAPER_PROCEDURE_KEYS) {
      const r = APPROXIMATIONS[key].halfInterval(input);
      out[key].push(r.ok ? r.halfIntervalMm : null);
    }
  }
  return out;
}

/** One recomputed row of Tables 2-5 beside the printed values. */
export interface PaperTableRow extends Omit<PaperCondition, 'notesExactHalf'> {
  readonly computedHalf: ProcedureValues;
  /** Eqs. 12-13 and the exact inverse, evaluated at the printed 3D L/2 as the paper did. */
  readonly computedHeight: ProcedureValues;
}

/** The paper's procedures' values beside the 3D one (0 where a procedure has none). */
function paperValues(
  threeD: number,
  value: (key: PaperProcedureKey) => { ok: true; value: number } | { ok: false },
): ProcedureValues {
  const out: { -readonly [K in keyof ProcedureValues]: number } = { threeD, sekine: 0, redonnet: 0, bedi: 0 };
  for (const key of PAPER_PROCEDURE_KEYS) {
    const r = value(key);
    out[key] = r.ok ? r.value : 0;
  }
  return out;
}

function heightsAt(input: InverseInput): ProcedureValues {
  return paperValues(exactScallopHeightMm(input), (key) => {
    const r = APPROXIMATIONS[key].scallopHeight(input);
    return r.ok ? { ok: true, value: r.scallopHeightMm } : r;
  });
}

/** Tables 2-5 recomputed (the conditions are all valid, so every value exists). */
export function paperTables(): PaperTableRow[] {
  return PAPER_CONDITIONS.map((c) => {
    const input = forwardInput(
      { toolRadiusMm: c.R, cornerRadiusMm: c.Rcr, leadAngleDeg: c.rho, tiltAngleDeg: 0 },
      'one-way',
      c.h,
    );
    return {
      table: c.table,
      R: c.R,
      Rcr: c.Rcr,
      rho: c.rho,
      h: c.h,
      printedHalf: c.printedHalf,
      computedHalf: paperValues(exactIntervalMm(input) / 2, (key) => {
        const r = APPROXIMATIONS[key].halfInterval(input);
        return r.ok ? { ok: true, value: r.halfIntervalMm } : r;
      }),
      printedHeight: c.printedHeight,
      computedHeight: heightsAt(inverseInput(input, 'one-way', 2 * c.printedHalf.threeD)),
    };
  });
}

/** Step-over L of every procedure along one posture angle (mm; null where a procedure has none). */
export interface StepOverSweep {
  /** Which angle varies: the lead rho or the tilt beta (degrees). */
  readonly axis: 'lead' | 'tilt';
  readonly angleDeg: number[];
  readonly values: { readonly [K in ProcedureKey]: Array<number | null> };
  /** Per procedure, the runs of angles without an answer and why (empty where it always answers). */
  readonly gaps: { readonly [K in ProcedureKey]: SweepGap[] };
}

/**
 * Sweeps the lead (geometrically from `fromDeg` to `toDeg`, dense at small angles) or the tilt
 * (linearly from `fromDeg` to `toDeg`) at a fixed tool, the other angle, pattern and h, always
 * including `includeDeg` when given. Every procedure's step-over L; null where h is at or above
 * the posture's limit, or where a procedure has no answer (with the reason in `gaps`). On a
 * cylinder the exact step-over is the cylinder's (null where the posture gouges a concave one or h
 * is beyond its limit there), and the approximations are as on a plane (they ignore the
 * curvature), as in the results table.
 * @param tool validated tool (the swept angle's value in it is ignored).
 */
export function stepOverSweep(
  tool: ToolInput,
  pattern: PassPattern,
  h: number,
  axis: 'lead' | 'tilt',
  fromDeg: number,
  toDeg: number,
  steps = 120,
  includeDeg: number | null = null,
  surface: Surface = PLANE,
): StepOverSweep {
  const angles: number[] = [];
  for (let i = 0; i <= steps; i++) {
    const u = i / steps;
    angles.push(
      i === steps
        ? toDeg
        : axis === 'lead' && fromDeg > 0
          ? fromDeg * (toDeg / fromDeg) ** u
          : fromDeg + (toDeg - fromDeg) * u,
    );
  }
  if (includeDeg !== null && includeDeg >= fromDeg && includeDeg <= toDeg && !angles.includes(includeDeg)) {
    angles.push(includeDeg);
    angles.sort((a, b) => a - b);
  }
  const values = Object.fromEntries(PROCEDURE_KEYS.map((k) => [k, [] as Array<number | null>])) as {
    [K in ProcedureKey]: Array<number | null>;
  };
  const reasons = Object.fromEntries(PROCEDURE_KEYS.map((k) => [k, [] as Array<string | null>])) as {
    [K in ProcedureKey]: Array<string | null>;
  };
  for (const angle of angles) {
    const t: ToolInput = {
      toolRadiusMm: tool.toolRadiusMm,
      cornerRadiusMm: tool.cornerRadiusMm,
      leadAngleDeg: axis === 'lead' ? angle : tool.leadAngleDeg,
      tiltAngleDeg: axis === 'tilt' ? angle : tool.tiltAngleDeg,
    };
    const ok = h < scallopHeightLimits(t).limitMm || leavesNoScallop(t);
    const c = ok ? compareForward(forwardInput(t, pattern, h)) : null;
    if (surface.kind === 'cylinder') {
      const fits = !surfaceModel(surface).fit(t, surface).gouges;
      const valid = fits && h < scallopHeightLimits(t, surface).limitMm;
      values.exact.push(valid ? exactIntervalMm(forwardInput(t, pattern, h, surface)) : null);
    }
    for (const key of PROCEDURE_KEYS) {
      if (key === 'exact' && surface.kind === 'cylinder') continue;
      if (c === null) values[key].push(null);
      else if (key === 'exact') values[key].push(c.exact.intervalMm);
      else {
        const r = c.approximations[key];
        values[key].push(r.ok ? r.intervalMm : null);
      }
      // Without an exact answer every procedure is blank there, for the exact solver's reason.
      reasons[key].push(values[key].at(-1) !== null ? null : noAnswerReason(c === null ? 'exact' : key, t));
    }
  }
  const gaps = Object.fromEntries(PROCEDURE_KEYS.map((k) => [k, sweepGaps(angles, reasons[k])])) as {
    [K in ProcedureKey]: SweepGap[];
  };
  return { axis, angleDeg: angles, values, gaps };
}
