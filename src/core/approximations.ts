/**
 * The three published 2-D approximations compared in the paper (Sekine & Kameya 2022,
 * section 2), and their inverses (Eqs. 12-13). Lengths in mm; public angles in degrees.
 *
 * Each returns either a result or `notApplicable` with the reason where its own model
 * has no meaningful answer; never NaN.
 */
import type { ForwardInput, InverseInput, ToolInput } from './validate';

const DEG = Math.PI / 180;

export type Approximation<T> = ({ readonly ok: true } & T) | { readonly ok: false; readonly notApplicable: string };

export type ProcedureName = 'sekine' | 'redonnet' | 'bedi';

/** Sekine et al.'s ellipse (Eqs. 5-7) and effective radius (Eq. 4), mm. */
export interface SekineModel {
  readonly toolCentreHeightMm: number;
  readonly shortRadiusMm: number;
  readonly longRadiusMm: number;
  readonly effectiveRadiusMm: number;
}

/** Redonnet et al.'s effective radius (Eq. 9), mm. */
export interface RedonnetModel {
  readonly effectiveRadiusMm: number;
}

/** Bedi et al.'s projected ellipse (Eq. 10): semi-axes `Rlong` and `Rlong sin(rho)`, mm. */
export interface BediModel {
  readonly longRadiusMm: number;
  readonly shortRadiusMm: number;
}

export interface HalfInterval {
  readonly halfIntervalMm: number;
  readonly intervalMm: number;
}

export interface ScallopHeight {
  readonly scallopHeightMm: number;
}

function notApplicable(reason: string): { ok: false; notApplicable: string } {
  return { ok: false, notApplicable: reason };
}

const RHO_ZERO_ELLIPSE =
  'at rho = 0 the projected ellipse degenerates to a line (its long radius Rshort/sin(rho) is infinite)';

/**
 * Sekine et al.: `Z_tc = |Rb sin rho| + Rcr` (Eq. 7), `Rshort = Z_tc - Rcr cos rho` (Eq. 6),
 * `Rlong = Rshort / |sin rho|` (Eq. 5), `Reff = (Rlong^2 + Rshort^2) / (2 Rshort)` (Eq. 4).
 * Not applicable at rho = 0 (Rshort = 0, Rlong infinite).
 */
export function sekineModel(tool: ToolInput): Approximation<SekineModel> {
  const rho = tool.leadAngleDeg * DEG;
  const sin = Math.abs(Math.sin(rho));
  if (sin === 0) return notApplicable(`Sekine et al.: ${RHO_ZERO_ELLIPSE}.`);
  const rb = tool.toolRadiusMm - tool.cornerRadiusMm;
  const toolCentreHeightMm = Math.abs(rb * Math.sin(rho)) + tool.cornerRadiusMm;
  // Z_tc - Rcr cos(rho) = Rb sin + Rcr (1 - cos), written without cancellation.
  const half = Math.sin(rho / 2);
  const shortRadiusMm = Math.abs(rb * Math.sin(rho)) + 2 * tool.cornerRadiusMm * half * half;
  if (!(shortRadiusMm > 0)) return notApplicable(`Sekine et al.: the ellipse's short radius is 0.`);
  const longRadiusMm = shortRadiusMm / sin;
  const effectiveRadiusMm = (longRadiusMm * longRadiusMm + shortRadiusMm * shortRadiusMm) / (2 * shortRadiusMm);
  return { ok: true, toolCentreHeightMm, shortRadiusMm, longRadiusMm, effectiveRadiusMm };
}

/**
 * Redonnet et al.: `Reff = Rb / sin(rho) + Rcr` (Eq. 9), the osculating circle of the exact
 * profile at its lowest point. For a ball end (Rb = 0) it is `Rcr` at every rho; otherwise
 * not applicable at rho = 0 (infinite radius).
 */
export function redonnetModel(tool: ToolInput): Approximation<RedonnetModel> {
  const rb = tool.toolRadiusMm - tool.cornerRadiusMm;
  if (rb === 0) return { ok: true, effectiveRadiusMm: tool.cornerRadiusMm };
  const sin = Math.sin(tool.leadAngleDeg * DEG);
  if (sin === 0)
    return notApplicable('Redonnet et al.: at rho = 0 the effective radius Rb/sin(rho) + Rcr is infinite.');
  return { ok: true, effectiveRadiusMm: rb / sin + tool.cornerRadiusMm };
}

/**
 * Bedi et al.: `Rlong = Rb + Rcr sin(rho)` (Eq. 10); the tool's section is taken as the
 * ellipse with semi-axes `Rlong` and `Rlong sin(rho)`. Not applicable at rho = 0.
 */
export function bediModel(tool: ToolInput): Approximation<BediModel> {
  const sin = Math.sin(tool.leadAngleDeg * DEG);
  if (sin === 0) {
    return notApplicable(
      'Bedi et al.: at rho = 0 its ellipse (semi-axes Rlong, Rlong sin(rho)) is flat and Eq. 11 divides by 0.',
    );
  }
  const longRadiusMm = tool.toolRadiusMm - tool.cornerRadiusMm + tool.cornerRadiusMm * sin;
  return { ok: true, longRadiusMm, shortRadiusMm: longRadiusMm * sin };
}

/** `L/2 = sqrt(2 Reff h - h^2)` (Eq. 8); not applicable when h exceeds the circle's widest point (h > Reff). */
function circleHalfInterval(who: string, reffMm: number, h: number): Approximation<HalfInterval> {
  if (h > reffMm) {
    return notApplicable(
      `${who}: h = ${h} mm is above the widest point of its circle (Reff = ${Number(reffMm.toPrecision(6))} mm).`,
    );
  }
  const half = Math.sqrt(h * (2 * reffMm - h));
  return { ok: true, halfIntervalMm: half, intervalMm: 2 * half };
}

/** Sekine et al.'s `L/2` (Eqs. 4-8), mm. */
export function sekineHalfInterval(input: ForwardInput): Approximation<HalfInterval & SekineModel> {
  const model = sekineModel(input);
  if (!model.ok) return model;
  const r = circleHalfInterval('Sekine et al.', model.effectiveRadiusMm, input.scallopHeightMm);
  if (!r.ok) return r;
  return {
    ok: true,
    toolCentreHeightMm: model.toolCentreHeightMm,
    shortRadiusMm: model.shortRadiusMm,
    longRadiusMm: model.longRadiusMm,
    effectiveRadiusMm: model.effectiveRadiusMm,
    halfIntervalMm: r.halfIntervalMm,
    intervalMm: r.intervalMm,
  };
}

/** Redonnet et al.'s `L/2` (Eqs. 9, 8), mm. */
export function redonnetHalfInterval(input: ForwardInput): Approximation<HalfInterval & RedonnetModel> {
  const model = redonnetModel(input);
  if (!model.ok) return model;
  const r = circleHalfInterval('Redonnet et al.', model.effectiveRadiusMm, input.scallopHeightMm);
  if (!r.ok) return r;
  return {
    ok: true,
    effectiveRadiusMm: model.effectiveRadiusMm,
    halfIntervalMm: r.halfIntervalMm,
    intervalMm: r.intervalMm,
  };
}

/**
 * Bedi et al.'s `L/2 = Rlong sqrt(1 - ((Rlong sin rho - h)/(Rlong sin rho))^2)` (Eq. 11), mm.
 * Not applicable at rho = 0, or when h is above the ellipse's widest point (h > Rlong sin rho).
 */
export function bediHalfInterval(input: ForwardInput): Approximation<HalfInterval & BediModel> {
  const model = bediModel(input);
  if (!model.ok) return model;
  const h = input.scallopHeightMm;
  const { longRadiusMm, shortRadiusMm } = model;
  if (h > shortRadiusMm) {
    return notApplicable(
      `Bedi et al.: h = ${h} mm is above the widest point of its ellipse (Rlong sin(rho) = ${Number(shortRadiusMm.toPrecision(6))} mm).`,
    );
  }
  // 1 - (1 - u)^2 = u (2 - u) with u = h / (Rlong sin rho): no cancellation for small h.
  const u = h / shortRadiusMm;
  const half = longRadiusMm * Math.sqrt(u * (2 - u));
  return { ok: true, longRadiusMm, shortRadiusMm, halfIntervalMm: half, intervalMm: 2 * half };
}

/** True-circular inverse (Eq. 12): `h = Reff - sqrt(Reff^2 - (L/2)^2)`, not applicable for L/2 > Reff. */
function circleScallop(who: string, reffMm: number, halfMm: number): Approximation<ScallopHeight> {
  if (halfMm > reffMm) {
    return notApplicable(
      `${who}: L/2 = ${halfMm} mm is wider than its circle (Reff = ${Number(reffMm.toPrecision(6))} mm).`,
    );
  }
  return { ok: true, scallopHeightMm: (halfMm * halfMm) / (reffMm + Math.sqrt(reffMm * reffMm - halfMm * halfMm)) };
}

/** Scallop height (mm) Sekine et al.'s circle predicts at a given L/2 (Eq. 12). */
export function sekineScallopHeight(input: InverseInput): Approximation<ScallopHeight> {
  const model = sekineModel(input);
  if (!model.ok) return model;
  return circleScallop('Sekine et al.', model.effectiveRadiusMm, input.halfIntervalMm);
}

/** Scallop height (mm) Redonnet et al.'s circle predicts at a given L/2 (Eq. 12). */
export function redonnetScallopHeight(input: InverseInput): Approximation<ScallopHeight> {
  const model = redonnetModel(input);
  if (!model.ok) return model;
  return circleScallop('Redonnet et al.', model.effectiveRadiusMm, input.halfIntervalMm);
}

/**
 * Scallop height (mm) of the elliptic projection (Eq. 13):
 * `h = Rlong sin(rho) (1 - sqrt(1 - (L/(2 Rlong))^2))`; not applicable for L/2 > Rlong.
 */
export function bediScallopHeight(input: InverseInput): Approximation<ScallopHeight> {
  const model = bediModel(input);
  if (!model.ok) return model;
  const { longRadiusMm, shortRadiusMm } = model;
  const half = input.halfIntervalMm;
  if (half > longRadiusMm) {
    return notApplicable(
      `Bedi et al.: L/2 = ${half} mm is wider than its ellipse (Rlong = ${Number(longRadiusMm.toPrecision(6))} mm).`,
    );
  }
  const q = half / longRadiusMm;
  return { ok: true, scallopHeightMm: (shortRadiusMm * q * q) / (1 + Math.sqrt(1 - q * q)) };
}
