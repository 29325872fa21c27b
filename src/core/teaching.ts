/**
 * Data for the teaching views: the cross-feed profiles each procedure assumes, a sweep of
 * L/2 over the lead angle, and the paper's tables recomputed. Pure; lengths mm, angles degrees.
 */
import {
  bediHalfInterval,
  bediModel,
  bediScallopHeight,
  redonnetHalfInterval,
  redonnetModel,
  redonnetScallopHeight,
  sekineHalfInterval,
  sekineModel,
  sekineScallopHeight,
} from './approximations';
import { exactHalfIntervalMm, exactScallopHeightMm } from './exact';
import { PAPER_CONDITIONS, type PaperCondition, type ProcedureValues } from './paper';
import { profileHalfWidthMm, profileHeightMm, profileShape } from './profile';
import type { ForwardInput, InverseInput, ToolInput } from './validate';

const DEG = Math.PI / 180;

/** Cross-feed curves as flat (y, z) arrays, z above the lowest point, y from 0 outwards (mm). */
export interface ProfileCurves {
  /** Exact tool profile (offset ellipse), y from 0 to R. */
  readonly exact: Float64Array;
  /** The ring ellipse it is offset from (semi-axes Rb, Rb sin rho), centred Rcr + Rb sin rho above the lowest point. */
  readonly ringEllipse: Float64Array;
  /** Circle of Sekine's Reff, or null where not applicable. */
  readonly sekine: Float64Array | null;
  /** Circle of Redonnet's Reff, or null. */
  readonly redonnet: Float64Array | null;
  /** Bedi's ellipse (semi-axes Rlong, Rlong sin rho), or null. */
  readonly bedi: Float64Array | null;
}

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
 * @param tool validated tool; @param samples points per curve (>= 16).
 */
export function profileCurves(tool: ToolInput, samples = 400): ProfileCurves {
  const n = Math.max(16, Math.round(samples));
  const R = tool.toolRadiusMm;
  const s = profileShape(R, tool.cornerRadiusMm, tool.leadAngleDeg * DEG);
  const exact = new Float64Array(2 * (n + 1));
  for (let i = 0; i <= n; i++) {
    // Denser near the bottom: theta = (pi/2) u^2.
    const u = i / n;
    const theta = (Math.PI / 2) * u * u;
    exact[2 * i] = i === 0 && s.b > 0 ? 0 : profileHalfWidthMm(s, theta);
    exact[2 * i + 1] = profileHeightMm(s, theta);
  }
  const ring = new Float64Array(2 * (n + 1));
  for (let i = 0; i <= n; i++) {
    const g = ((Math.PI / 2) * i) / n;
    ring[2 * i] = s.a * Math.sin(g);
    ring[2 * i + 1] = s.rcr + s.b * (1 - Math.cos(g));
  }
  const sek = sekineModel(tool);
  const red = redonnetModel(tool);
  const bedi = bediModel(tool);
  return {
    exact,
    ringEllipse: ring,
    sekine: sek.ok ? circleArc(sek.effectiveRadiusMm, 2 * R, n) : null,
    redonnet: red.ok ? circleArc(red.effectiveRadiusMm, 2 * R, n) : null,
    bedi: bedi.ok && bedi.shortRadiusMm > 0 ? ellipseArc(bedi.longRadiusMm, bedi.shortRadiusMm, 2 * R, n) : null,
  };
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
    const limit = (R - Rcr) * Math.sin(rho * DEG) + Rcr;
    if (!(h < limit)) {
      out.exact.push(null);
      out.sekine.push(null);
      out.redonnet.push(null);
      out.bedi.push(null);
      continue;
    }
    const input: ForwardInput = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, scallopHeightMm: h };
    out.exact.push(exactHalfIntervalMm(input));
    const sek = sekineHalfInterval(input);
    const red = redonnetHalfInterval(input);
    const bed = bediHalfInterval(input);
    out.sekine.push(sek.ok ? sek.halfIntervalMm : null);
    out.redonnet.push(red.ok ? red.halfIntervalMm : null);
    out.bedi.push(bed.ok ? bed.halfIntervalMm : null);
  }
  return out;
}

/** One recomputed row of Tables 2-5 beside the printed values. */
export interface PaperTableRow extends Omit<PaperCondition, 'notesExactHalf'> {
  readonly computedHalf: ProcedureValues;
  /** Eqs. 12-13 and the exact inverse, evaluated at the printed 3D L/2 as the paper did. */
  readonly computedHeight: ProcedureValues;
}

function heightsAt(input: InverseInput): ProcedureValues {
  const value = (r: { ok: true; scallopHeightMm: number } | { ok: false }) => (r.ok ? r.scallopHeightMm : 0);
  return {
    threeD: exactScallopHeightMm(input),
    sekine: value(sekineScallopHeight(input)),
    redonnet: value(redonnetScallopHeight(input)),
    bedi: value(bediScallopHeight(input)),
  };
}

/** Tables 2-5 recomputed (the conditions are all valid, so every value exists). */
export function paperTables(): PaperTableRow[] {
  return PAPER_CONDITIONS.map((c) => {
    const input: ForwardInput = { toolRadiusMm: c.R, cornerRadiusMm: c.Rcr, leadAngleDeg: c.rho, scallopHeightMm: c.h };
    const value = (r: { ok: true; halfIntervalMm: number } | { ok: false }) => (r.ok ? r.halfIntervalMm : 0);
    return {
      table: c.table,
      R: c.R,
      Rcr: c.Rcr,
      rho: c.rho,
      h: c.h,
      printedHalf: c.printedHalf,
      computedHalf: {
        threeD: exactHalfIntervalMm(input),
        sekine: value(sekineHalfInterval(input)),
        redonnet: value(redonnetHalfInterval(input)),
        bedi: value(bediHalfInterval(input)),
      },
      printedHeight: c.printedHeight,
      computedHeight: heightsAt({ ...input, halfIntervalMm: c.printedHalf.threeD }),
    };
  });
}
