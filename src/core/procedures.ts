/**
 * The one registry of procedures: key, labels, equations, colour and what each assumes.
 * Every view, table, chart and the command line read their names and colours from here.
 */

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

/**
 * The rows a cylinder adds beside the exact answer (compare.ts, CurvatureComparison): the plane's
 * exact answer, which ignores the curvature, and the usual correction `1/rho = 1/Reff + 1/Rs`
 * applied to each procedure that has an effective radius. Labels as the command line prints them.
 */
export const CURVATURE_ROW_KEYS = [
  'plane',
  'sekineCorrected',
  'redonnetCorrected',
  'osculatingCorrected',
  'cornerBallCorrected',
] as const;

export type CurvatureRowKey = (typeof CURVATURE_ROW_KEYS)[number];

export interface CurvatureRowInfo {
  readonly key: CurvatureRowKey;
  /** The procedure whose effective radius is corrected; null for the plane's answer. */
  readonly corrects: 'sekine' | 'redonnet' | 'osculating' | 'cornerBall' | null;
  readonly label: string;
  readonly shortLabel: string;
  /** Colour in every view (hex): the corrected procedure's own hue, darker; slate for the plane. */
  readonly colour: string;
  readonly assumes: string;
}

const corrected = (
  key: CurvatureRowKey,
  base: 'sekine' | 'redonnet' | 'osculating' | 'cornerBall',
  colour: string,
): CurvatureRowInfo => ({
  key,
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
  sekineCorrected: corrected('sekineCorrected', 'sekine', '#78350f'),
  redonnetCorrected: corrected('redonnetCorrected', 'redonnet', '#4c1d95'),
  osculatingCorrected: corrected('osculatingCorrected', 'osculating', '#14532d'),
  cornerBallCorrected: corrected('cornerBallCorrected', 'cornerBall', '#831843'),
};
