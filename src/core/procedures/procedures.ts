/**
 * The one registry of procedures: key, labels, equations, colour and what each assumes, and each
 * approximation's functions (its model of the tool, the step-over at h, the scallop height at L).
 * Every view, table, chart and the command line read their names and colours from here; the
 * comparison, the sweeps, the CSV and the worker iterate the same list.
 */

import type { ForwardInput, InverseInput } from '../domain/pass';
import type { ToolInput } from '../domain/tool';
import {
  type Approximation,
  type BediModel,
  bediHalfInterval,
  bediModel,
  bediScallopHeight,
  type CornerBallModel,
  cornerBallHalfInterval,
  cornerBallModel,
  cornerBallScallopHeight,
  type HalfInterval,
  type OsculatingModel,
  osculatingHalfInterval,
  osculatingModel,
  osculatingScallopHeight,
  type RedonnetModel,
  redonnetHalfInterval,
  redonnetModel,
  redonnetScallopHeight,
  type ScallopHeight,
  type SekineModel,
  sekineHalfInterval,
  sekineModel,
  sekineScallopHeight,
} from './approximations';

/** Every procedure the calculator reports, exact first. */
export const PROCEDURE_KEYS = ['exact', 'sekine', 'redonnet', 'bedi', 'osculating', 'cornerBall'] as const;

export type ProcedureKey = (typeof PROCEDURE_KEYS)[number];

/** The approximations (every procedure but the exact one). */
export type ApproximationKey = Exclude<ProcedureKey, 'exact'>;

export const APPROXIMATION_KEYS: readonly ApproximationKey[] = PROCEDURE_KEYS.filter(
  (k): k is ApproximationKey => k !== 'exact',
);

/** The paper's three published procedures: lead-only models. */
export const PAPER_PROCEDURE_KEYS = ['sekine', 'redonnet', 'bedi'] as const;

export type PaperProcedureKey = (typeof PAPER_PROCEDURE_KEYS)[number];

export interface ProcedureInfo {
  readonly key: ProcedureKey;
  /** Full label with its equations, as in the results table and the command line. */
  readonly label: string;
  /** Short label for legends and charts. */
  readonly shortLabel: string;
  /** Equations of the forward problem (scallop height to path interval). */
  readonly forwardEquations: string;
  /** Equations of the inverse problem (path interval to scallop height). */
  readonly inverseEquations: string;
  /** Colour in every view on the light theme (hex), at least 4.5:1 against white. */
  readonly colour: string;
  /** Colour on the dark theme (hex), at least 4.5:1 against the dark background #12161f. */
  readonly colourDark: string;
  /** One sentence: the model and where it holds. */
  readonly assumes: string;
  /** True for a model built on the lead angle alone (tilt ignored). */
  readonly leadOnly: boolean;
}

/** The registry of procedures: each one's name, source (the paper's reference), colour and scope. */
export const PROCEDURES: Readonly<Record<ProcedureKey, ProcedureInfo>> = {
  exact: {
    key: 'exact',
    label: 'Exact (3D geometry)',
    shortLabel: 'Exact (3D)',
    forwardEquations: 'projection of the tool along the feed',
    inverseEquations: 'projection of the tool along the feed',
    colour: '#111827',
    colourDark: '#f3f4f6',
    assumes:
      'True 3D: the tool moves along X, so the surface it leaves is its projection along X, the ring ellipse offset by Rcr (rotated by the tilt). Valid for every posture, ball and flat ends included.',
    leadOnly: false,
  },
  sekine: {
    key: 'sekine',
    label: 'Sekine et al. (Eqs. 4-8)',
    shortLabel: 'Sekine et al.',
    forwardEquations: 'Eqs. 4-8',
    inverseEquations: 'Eq. 12',
    colour: '#b45309',
    colourDark: '#fbbf24',
    assumes:
      "True-circular approximation: an ellipse from the tool centre height replaced by one circle of radius Reff. It ignores where the real profile's curvature changes, so it is far off at small lead.",
    leadOnly: true,
  },
  redonnet: {
    key: 'redonnet',
    label: 'Redonnet et al. (Eqs. 9, 8)',
    shortLabel: 'Redonnet et al.',
    forwardEquations: 'Eqs. 9, 8',
    inverseEquations: 'Eq. 12',
    colour: '#7c3aed',
    colourDark: '#c4b5fd',
    assumes:
      'Osculating circle at the lowest point without tilt: exact as h tends to 0, then it overestimates L because the real profile curves up faster.',
    leadOnly: true,
  },
  bedi: {
    key: 'bedi',
    label: 'Bedi et al. (Eqs. 10-11)',
    shortLabel: 'Bedi et al.',
    forwardEquations: 'Eqs. 10-11',
    inverseEquations: 'Eq. 13',
    colour: '#0e7490',
    colourDark: '#22d3ee',
    assumes:
      'Elliptic projection: one ellipse with semi-axes Rlong and Rlong sin(rho) stands for the offset ellipse. Close without tilt, but an offset ellipse is not an ellipse; it breaks down at rho = 0.',
    leadOnly: true,
  },
  osculating: {
    key: 'osculating',
    label: 'Osculating circle at the contact',
    shortLabel: 'Osculating circle',
    forwardEquations: 'Reff = Rcr + a^2 b^2 / D0^3',
    inverseEquations: 'h = Reff - sqrt(Reff^2 - (L/2)^2)',
    colour: '#15803d',
    colourDark: '#4ade80',
    assumes:
      "Redonnet's idea for any posture: the circle that osculates the exact profile at the contact point. Exact as h tends to 0; symmetric, so it misses the asymmetry that tilt brings.",
    leadOnly: false,
  },
  cornerBall: {
    key: 'cornerBall',
    label: 'Ball of the corner radius',
    shortLabel: 'Corner ball',
    forwardEquations: 'L/2 = sqrt(2 Rcr h - h^2)',
    inverseEquations: 'h = Rcr - sqrt(Rcr^2 - (L/2)^2)',
    colour: '#be185d',
    colourDark: '#f9a8d4',
    assumes:
      'Treats the bull-nose tool as a ball end of radius Rcr, as some online calculators do: exact only for a ball end, and far too small a step-over when the lead or tilt brings the flat bottom into play.',
    leadOnly: false,
  },
};

/** Each approximation's model of the tool in its posture (mm). */
export interface ForwardModels {
  readonly sekine: SekineModel;
  readonly redonnet: RedonnetModel;
  readonly bedi: BediModel;
  readonly osculating: OsculatingModel;
  readonly cornerBall: CornerBallModel;
}

/**
 * The curve a model stands in for the tool's cross-feed profile with (mm): a circle touching the
 * surface at the contact, or an ellipse (semi-axes along and across the surface).
 */
export type ModelCurve =
  | { readonly shape: 'circle'; readonly radiusMm: number }
  | { readonly shape: 'ellipse'; readonly longRadiusMm: number; readonly shortRadiusMm: number };

/** What an approximation computes (approximations.ts): `M` is its model of the tool. */
export interface ApproximationFunctions<M> {
  /** Its model of the tool in its posture (mm), or why it has none there. */
  model(tool: ToolInput): Approximation<M>;
  /** Forward: `L/2` (mm) at the scallop height h, with its model; or why none. */
  halfInterval(input: ForwardInput): Approximation<HalfInterval & M>;
  /** Inverse: the scallop height (mm) at the step-over L; or why none. */
  scallopHeight(input: InverseInput): Approximation<ScallopHeight>;
  /** The curve of a model (mm). */
  curve(model: M): ModelCurve;
  /**
   * The symbol texts give the height of the curve's widest point, above which h has no answer:
   * `Reff` (a circle's radius), `Rcr` (the corner ball's), `Rlong sin(rho)` (Bedi's ellipse).
   */
  readonly widestSymbol: string;
}

const circle = (radiusMm: number): ModelCurve => ({ shape: 'circle', radiusMm });

/** The approximations' functions, in the registry's order (APPROXIMATION_KEYS). */
export const APPROXIMATIONS: { readonly [K in ApproximationKey]: ApproximationFunctions<ForwardModels[K]> } = {
  sekine: {
    model: sekineModel,
    halfInterval: sekineHalfInterval,
    scallopHeight: sekineScallopHeight,
    curve: (m) => circle(m.effectiveRadiusMm),
    widestSymbol: 'Reff',
  },
  redonnet: {
    model: redonnetModel,
    halfInterval: redonnetHalfInterval,
    scallopHeight: redonnetScallopHeight,
    curve: (m) => circle(m.effectiveRadiusMm),
    widestSymbol: 'Reff',
  },
  bedi: {
    model: bediModel,
    halfInterval: bediHalfInterval,
    scallopHeight: bediScallopHeight,
    curve: (m) => ({ shape: 'ellipse', longRadiusMm: m.longRadiusMm, shortRadiusMm: m.shortRadiusMm }),
    widestSymbol: 'Rlong sin(rho)',
  },
  osculating: {
    model: osculatingModel,
    halfInterval: osculatingHalfInterval,
    scallopHeight: osculatingScallopHeight,
    curve: (m) => circle(m.effectiveRadiusMm),
    widestSymbol: 'Reff',
  },
  cornerBall: {
    model: cornerBallModel,
    halfInterval: cornerBallHalfInterval,
    scallopHeight: cornerBallScallopHeight,
    curve: (m) => circle(m.effectiveRadiusMm),
    widestSymbol: 'Rcr',
  },
};

/** An approximation's curve for a tool (mm), or why its model has none. */
export function modelCurve<K extends ApproximationKey>(key: K, tool: ToolInput): Approximation<{ curve: ModelCurve }> {
  const procedure: ApproximationFunctions<ForwardModels[K]> = APPROXIMATIONS[key];
  const m = procedure.model(tool);
  return m.ok ? { ok: true, curve: procedure.curve(m) } : m;
}

/**
 * The procedures whose model is a circle of effective radius Reff, which the usual curvature
 * correction applies to (a circle's curve in APPROXIMATIONS).
 */
export const CORRECTED_KEYS = [
  'sekine',
  'redonnet',
  'osculating',
  'cornerBall',
] as const satisfies readonly ApproximationKey[];
export type CorrectedKey = (typeof CORRECTED_KEYS)[number];

/** The row key of a corrected procedure. */
export function correctedRowKey<K extends CorrectedKey>(key: K): `${K}Corrected` {
  return `${key}Corrected`;
}

/**
 * The rows a cylinder adds beside the exact answer (compare.ts, CurvatureComparison): the plane's
 * exact answer, which ignores the curvature, and the usual correction `1/rho = 1/Reff + 1/Rs`
 * applied to each procedure that has an effective radius. Labels as the command line prints them.
 */
export const CURVATURE_ROW_KEYS = ['plane', ...CORRECTED_KEYS.map(correctedRowKey)] as const;

export type CurvatureRowKey = 'plane' | `${CorrectedKey}Corrected`;

export interface CurvatureRowInfo {
  readonly key: CurvatureRowKey;
  /** The procedure whose effective radius is corrected; null for the plane's answer. */
  readonly corrects: CorrectedKey | null;
  readonly label: string;
  readonly shortLabel: string;
  /** Colour in every view (hex): the corrected procedure's own hue, darker; slate for the plane. */
  readonly colour: string;
  readonly assumes: string;
}

const corrected = (base: CorrectedKey, colour: string): CurvatureRowInfo => ({
  key: correctedRowKey(base),
  corrects: base,
  label: `${PROCEDURES[base].shortLabel}, corrected (1/rho = 1/Reff + 1/Rs)`,
  shortLabel: `${PROCEDURES[base].shortLabel}, corrected`,
  colour,
  assumes: `${PROCEDURES[base].shortLabel}'s circle of radius Reff with the usual second-order curvature correction: the combined radius 1/rho = 1/Reff + 1/Rs (Rs signed; across the axis the surface is straight across the feed, so rho = Reff) in L = 2 sqrt(2 rho h - h^2).`,
});

export const CURVATURE_ROWS: Readonly<Record<CurvatureRowKey, CurvatureRowInfo>> = {
  plane: {
    key: 'plane',
    corrects: null,
    label: 'Plane, exact (curvature ignored)',
    shortLabel: 'Plane (curvature ignored)',
    colour: '#475569',
    assumes:
      "The exact answer for a plane at the same h: what a calculator that ignores the surface's curvature gives.",
  },
  sekineCorrected: corrected('sekine', '#78350f'),
  redonnetCorrected: corrected('redonnet', '#4c1d95'),
  osculatingCorrected: corrected('osculating', '#14532d'),
  cornerBallCorrected: corrected('cornerBall', '#831843'),
};
