/**
 * The approximations: the three published 2-D procedures compared in the paper (Sekine &
 * Kameya 2022, section 2) with their inverses (Eqs. 12-13), and two more circles: the
 * osculating circle of the exact profile at the contact (Redonnet's idea for any posture) and
 * the ball of the corner radius. Lengths in mm; public angles in degrees.
 *
 * The paper's procedures are lead-only models: with tilt they are applied as a user would,
 * with the lead angle alone (tilt ignored). Every model here is symmetric, so its step-over is
 * twice its L/2 for either pass pattern. Each returns a result or `notApplicable` with the
 * reason where its own model has no meaningful answer (never NaN, never Infinity).
 */

import { formatSignificant, RAD_PER_DEG } from '../input/units';
import { contactCurvatureRadiusMm, shapeOfTool } from '../tool/posture';

/** A length for a message: 6 significant digits, trailing zeros dropped, with its unit. */
function mm(lengthMm: number): string {
  return `${formatSignificant(lengthMm, { digits: 6, trimZeros: true })} mm`;
}

import type { ForwardInput, InverseInput } from '../domain/pass';
import type { CylinderSurface } from '../domain/surface';
import type { ToolInput } from '../domain/tool';

const DEG = RAD_PER_DEG;

export type Approximation<T> = ({ readonly ok: true } & T) | { readonly ok: false; readonly notApplicable: string };

/** An effective radius must be a finite number: a subnormal lead angle can overflow it. */
function overflow(who: string): { ok: false; notApplicable: string } {
  return notApplicable(
    `${who}: its effective radius overflows (rho is too close to 0 for its 1/sin(rho)); the model has no answer here.`,
  );
}

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
  // (Rlong^2 + Rshort^2) / (2 Rshort), written so that a huge Rlong does not overflow its square.
  const effectiveRadiusMm = 0.5 * longRadiusMm * (longRadiusMm / shortRadiusMm) + 0.5 * shortRadiusMm;
  if (!Number.isFinite(effectiveRadiusMm) || !Number.isFinite(longRadiusMm)) return overflow('Sekine et al.');
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
  const effectiveRadiusMm = rb / sin + tool.cornerRadiusMm;
  if (!Number.isFinite(effectiveRadiusMm)) return overflow('Redonnet et al.');
  return { ok: true, effectiveRadiusMm };
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
    return notApplicable(`${who}: h = ${mm(h)} is above the widest point of its circle (Reff = ${mm(reffMm)}).`);
  }
  // sqrt(h) sqrt(2 Reff - h): no overflow of the product for a huge Reff.
  const half = Math.sqrt(h) * Math.sqrt(2 * reffMm - h);
  return { ok: true, halfIntervalMm: half, intervalMm: 2 * half };
}

/** A model that stands in for the tool's profile with a circle of radius Reff (mm). */
type CircleModel = Approximation<{ readonly effectiveRadiusMm: number }>;

/**
 * A circle model's L/2 (Eq. 8) with its radius, or why it has none; built property by property in
 * a spread's key order (an object made by spreading is slow to make and to read in V8).
 */
function circleModelHalfInterval(
  who: string,
  model: CircleModel,
  h: number,
): Approximation<HalfInterval & { readonly effectiveRadiusMm: number }> {
  if (!model.ok) return model;
  const effectiveRadiusMm = model.effectiveRadiusMm;
  const r = circleHalfInterval(who, effectiveRadiusMm, h);
  if (!r.ok) return r;
  return { ok: true, halfIntervalMm: r.halfIntervalMm, intervalMm: r.intervalMm, effectiveRadiusMm };
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
  return circleModelHalfInterval('Redonnet et al.', redonnetModel(input), input.scallopHeightMm);
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
      `Bedi et al.: h = ${mm(h)} is above the widest point of its ellipse (Rlong sin(rho) = ${mm(shortRadiusMm)}).`,
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
    return notApplicable(`${who}: L/2 = ${mm(halfMm)} is wider than its circle (Reff = ${mm(reffMm)}).`);
  }
  return { ok: true, scallopHeightMm: (halfMm * halfMm) / (reffMm + Math.sqrt(reffMm * reffMm - halfMm * halfMm)) };
}

/** A circle model's scallop height at a step-over L (Eq. 12 at L/2), or why it has none. */
function circleModelScallop(who: string, model: CircleModel, intervalMm: number): Approximation<ScallopHeight> {
  if (!model.ok) return model;
  return circleScallop(who, model.effectiveRadiusMm, intervalMm / 2);
}

/** Scallop height (mm) Sekine et al.'s circle predicts at a given step-over L (Eq. 12 at L/2). */
export function sekineScallopHeight(input: InverseInput): Approximation<ScallopHeight> {
  return circleModelScallop('Sekine et al.', sekineModel(input), input.intervalMm);
}

/** Scallop height (mm) Redonnet et al.'s circle predicts at a given step-over L (Eq. 12 at L/2). */
export function redonnetScallopHeight(input: InverseInput): Approximation<ScallopHeight> {
  return circleModelScallop('Redonnet et al.', redonnetModel(input), input.intervalMm);
}

/**
 * Scallop height (mm) of the elliptic projection (Eq. 13):
 * `h = Rlong sin(rho) (1 - sqrt(1 - (L/(2 Rlong))^2))`; not applicable for L/2 > Rlong.
 */
export function bediScallopHeight(input: InverseInput): Approximation<ScallopHeight> {
  const model = bediModel(input);
  if (!model.ok) return model;
  const { longRadiusMm, shortRadiusMm } = model;
  const half = input.intervalMm / 2;
  if (half > longRadiusMm) {
    return notApplicable(`Bedi et al.: L/2 = ${mm(half)} is wider than its ellipse (Rlong = ${mm(longRadiusMm)}).`);
  }
  const q = half / longRadiusMm;
  return { ok: true, scallopHeightMm: (shortRadiusMm * q * q) / (1 + Math.sqrt(1 - q * q)) };
}

/** The osculating circle of the exact profile at the contact point (mm). */
export interface OsculatingModel {
  readonly effectiveRadiusMm: number;
}

/**
 * Redonnet's idea for any posture: the circle that osculates the exact profile at its contact
 * point, `Reff = Rcr + a^2 b^2 / D0^3` with `a = Rb`, `b = Rb cos(beta) sin(rho)` and
 * `D0 = sqrt(a^2 sin^2 phi + b^2 cos^2 phi)` (posture.ts). Without tilt it is Eq. 9. Not
 * applicable when the tool's flat bottom lies on the plane (rho = 0, no tilt: infinite radius).
 */
export function osculatingModel(tool: ToolInput): Approximation<OsculatingModel> {
  const r = contactCurvatureRadiusMm(shapeOfTool(tool));
  if (r === null) {
    return notApplicable(
      'Osculating circle: the flat bottom lies on the plane (rho = 0 without tilt, or lead and tilt too small to count), so the radius of curvature at the contact is infinite.',
    );
  }
  if (!Number.isFinite(r)) return overflow('Osculating circle');
  if (!(r > 0)) {
    return notApplicable('Osculating circle: the contact is a sharp edge (Rcr = 0), a circle of radius 0.');
  }
  return { ok: true, effectiveRadiusMm: r };
}

/** `L/2 = sqrt(2 Reff h - h^2)` with the osculating radius at the contact, mm. */
export function osculatingHalfInterval(input: ForwardInput): Approximation<HalfInterval & OsculatingModel> {
  return circleModelHalfInterval('Osculating circle', osculatingModel(input), input.scallopHeightMm);
}

/** Scallop height (mm) the osculating circle predicts at a step-over L: `Reff - sqrt(Reff^2 - (L/2)^2)`. */
export function osculatingScallopHeight(input: InverseInput): Approximation<ScallopHeight> {
  return circleModelScallop('Osculating circle', osculatingModel(input), input.intervalMm);
}

/** The ball of the corner radius (mm). */
export interface CornerBallModel {
  readonly effectiveRadiusMm: number;
}

/**
 * The bull-nose tool taken as a ball end of radius `Rcr` (what some online calculators do):
 * `L/2 = sqrt(2 Rcr h - h^2)`. Exact only for a ball end (Rcr = R). Not applicable for a flat end.
 */
export function cornerBallModel(tool: ToolInput): Approximation<CornerBallModel> {
  if (!(tool.cornerRadiusMm > 0)) return notApplicable('Corner ball: a flat end (Rcr = 0) has no corner ball.');
  return { ok: true, effectiveRadiusMm: tool.cornerRadiusMm };
}

/** `L/2 = sqrt(2 Rcr h - h^2)`, mm; not applicable for h > Rcr. */
export function cornerBallHalfInterval(input: ForwardInput): Approximation<HalfInterval & CornerBallModel> {
  return circleModelHalfInterval('Corner ball', cornerBallModel(input), input.scallopHeightMm);
}

/** Scallop height (mm) the corner ball predicts at a step-over L: `Rcr - sqrt(Rcr^2 - (L/2)^2)`. */
export function cornerBallScallopHeight(input: InverseInput): Approximation<ScallopHeight> {
  return circleModelScallop('Corner ball', cornerBallModel(input), input.intervalMm);
}

/**
 * The usual second-order curvature correction of a circle on a cylinder: the combined radius rho
 * with `1/rho = 1/Reff + 1/Rs`, Rs the surface's signed radius across the feed (> 0 convex, < 0
 * concave): the cylinder's own with the axis along the feed; across it the surface is straight
 * across the feed (Rs infinite), so rho = Reff. Returns rho in mm (Reff > 0 in mm); it is not
 * positive, or not finite, where a concave surface is as tight as the circle or tighter (|Rs| <= Reff).
 */
export function combinedRadiusMm(effectiveRadiusMm: number, surface: CylinderSurface): number {
  const across = surface.axis === 'feed' ? surface.radiusMm : Number.POSITIVE_INFINITY;
  return Number.isFinite(across) ? (effectiveRadiusMm * across) / (effectiveRadiusMm + across) : effectiveRadiusMm;
}
