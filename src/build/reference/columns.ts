/**
 * The reference data set's columns (public/reference/scallop-reference.csv), each with its unit and meaning:
 * the one list that the generator writes, the JSON description states and the check reads. Inputs
 * carry the command line's batch names (src/core/input/fields.ts), so a row reads as a batch row;
 * an empty cell is an input not given (its default: tilt 0, one-way, plane, feed, straight).
 */

/** A column of the data set. */
export interface ReferenceColumn {
  readonly name: string;
  /** `mm`, `deg`, or `-` (text, or a count). */
  readonly unit: 'mm' | 'deg' | '-';
  readonly description: string;
}

/** The data set's version (semantic: a new major when a column changes meaning). */
export const REFERENCE_VERSION = '1.0.0';

/** The seed of the stratified random cases (each stratum draws from its own seed, this plus its index). */
export const REFERENCE_SEED = 2027;

/** File names, inside the package's `reference/` folder. */
export const REFERENCE_CSV = 'scallop-reference.csv';
export const REFERENCE_JSON = 'scallop-reference.json';

/** The calculator's stated accuracy, added to each reference's own uncertainty to give a row's bound: mm per mm of R (at least 1 mm). */
export const CALCULATOR_ACCURACY_MM = 1e-9;

/** The columns, in file order. */
export const REFERENCE_COLUMNS: readonly ReferenceColumn[] = [
  { name: 'id', unit: '-', description: 'Row number, from 1.' },
  {
    name: 'stratum',
    unit: '-',
    description:
      'The surface and mode the row samples (plane-lead, plane-posture-one-way, plane-zigzag, plane-inverse, cylinder-feed-convex, cylinder-feed-concave, cylinder-cross-convex, cylinder-cross-concave, doubly-curved, three-axis-raster, three-axis-waterline-plane, three-axis-waterline-revolution, roughness, invalid-...).',
  },
  {
    name: 'mode',
    unit: '-',
    description:
      'forward: h given, the step-over L answered; inverse: L given, the scallop height answered; roughness: h given, Rz, Ra or Rq answered; target-ra: a target Ra given, the scallop height that leaves it answered; slope rows (three-axis) are forward or inverse likewise.',
  },
  { name: 'R', unit: 'mm', description: 'Tool radius (half the diameter).' },
  { name: 'Rcr', unit: 'mm', description: 'Corner radius: R a ball end, 0 a flat end.' },
  {
    name: 'rho',
    unit: 'deg',
    description: 'Lead along the feed (empty on slope rows: the slope sets the posture).',
  },
  { name: 'tilt', unit: 'deg', description: 'Tilt across the feed, + leans the shank to +Y (empty: 0).' },
  { name: 'pattern', unit: '-', description: 'one-way or zigzag (empty: one-way).' },
  {
    name: 'surfaceRadius',
    unit: 'mm',
    description: 'A cylinder: signed radius, > 0 convex, < 0 concave (empty: a plane).',
  },
  { name: 'surfaceAxis', unit: '-', description: 'The cylinder axis: feed (along the passes) or cross (around it).' },
  {
    name: 'feedRadius',
    unit: 'mm',
    description:
      'Without slope: a doubly curved point, signed principal radius along the feed. With slope (waterline): the surface of revolution, signed normal radius along the feed (empty: straight).',
  },
  {
    name: 'crossRadius',
    unit: 'mm',
    description:
      'Without slope: a doubly curved point, signed principal radius across the feed. With slope (waterline): the signed meridian radius (empty: straight).',
  },
  {
    name: 'slope',
    unit: 'deg',
    description:
      'Three-axis machining: the slope at the contact, the tool upright (empty: five-axis posture rho, tilt).',
  },
  { name: 'passes', unit: '-', description: 'Three-axis: raster or waterline.' },
  { name: 'rasterAngle', unit: 'deg', description: 'Three-axis raster: the passes plan angle to the fall line.' },
  {
    name: 'h',
    unit: 'mm',
    description: 'Given scallop height (forward and roughness rows), along the surface normal.',
  },
  {
    name: 'interval',
    unit: 'mm',
    description: 'Given step-over L between cutter-contact paths (inverse rows), arc length on a curved surface.',
  },
  {
    name: 'Ra',
    unit: 'mm',
    description: 'Given target roughness Ra (target-ra rows), across the feed over one period.',
  },
  {
    name: 'quantity',
    unit: '-',
    description:
      'What answer is: interval (step-over L), scallopHeight (the highest cusp), Rz, Ra, Rq (across the feed over one period), or errorLimit (the limit the refused input broke, mm or deg as errorField).',
  },
  {
    name: 'answer',
    unit: 'mm',
    description: "The calculator's answer (degrees for an errorLimit on an angle; empty when the error has no limit).",
  },
  {
    name: 'errorCode',
    unit: '-',
    description: "The refused input's error code (as the command line's JSON errors give it); empty when answered.",
  },
  { name: 'errorField', unit: '-', description: 'The field the first error names (batch name).' },
  {
    name: 'reference',
    unit: 'mm',
    description:
      'The independent reference value of the same quantity (empty where none applies: an error without a limit).',
  },
  {
    name: 'referenceUncertainty',
    unit: 'mm',
    description: "The reference method's own stated uncertainty for this row.",
  },
  {
    name: 'bound',
    unit: 'mm',
    description:
      "Largest |answer - reference| accepted: referenceUncertainty plus the calculator's stated accuracy, 1e-9 mm times max(1, R / 1 mm).",
  },
  { name: 'method', unit: '-', description: "The reference method (the JSON's methods describe each)." },
  {
    name: 'sampled',
    unit: 'mm',
    description:
      "Sampled brute force's value, for the methods that polish from a sampled start (empty otherwise); it lies within sampledBound of reference.",
  },
  { name: 'sampledBound', unit: 'mm', description: "The sampled brute force's stated resolution bound." },
];

/** The column names, in file order. */
export const COLUMN_NAMES: readonly string[] = REFERENCE_COLUMNS.map((c) => c.name);

/** A row as text cells by column name (an absent cell is empty). */
export type ReferenceRow = Readonly<Record<string, string>>;

/** The tolerance added for the calculator (mm): 1e-9 mm per mm of R, at least 1e-9 mm. */
export function calculatorToleranceMm(toolRadiusMm: number): number {
  return CALCULATOR_ACCURACY_MM * Math.max(1, toolRadiusMm);
}

/** The reference methods, by the key the `method` column gives (their code: src/build/reference/). */
export const REFERENCE_METHODS: Readonly<Record<string, string>> = {
  'high-precision-profile':
    'Plane: the cross-feed profile of the tool end (a disk grown by a ball, projected along the feed) and its shank from its support function in 64-digit decimal arithmetic (decimal.js), sharing no code with the solver; the step-over is the flank widths at h added (one-way) or twice the smaller (zigzag), the inverse the profile height at L/2 (zigzag, or one-way without tilt). At least 40 correct digits, rounded to doubles.',
  'cylinder-reach':
    'Cylinder: the real tool surface (torus corner, bottom disk, shank) in its posture searched for the farthest point at or below the radial height h, as polar angle about the axis (axis along the feed) or distance along it (across), by sampling and golden-section and bisection polishing; the step-over is the two reaches added (one-way) or twice the smaller (zigzag), times |Rs| along the feed.',
  'doubly-curved-polished':
    'Doubly curved point: the real tool (corner, bottom, shank) carried along two adjacent passes about the feed circle, the second turned about the cross circle by L/|Rc| (mirrored for zigzag); the material left in the plane X = 0 sampled on bins (sampled, with its resolution bound sampledBound), then the crossing of the two passes columns polished by bisection over the tool surface parameters. Zigzag: the higher of its two cusps.',
  'three-axis-raster-brute':
    'Three-axis raster on a sloped plane: the upright tool as horizontal disks (corner and shank) placed by its support point in the machine frame, translated along the CC path; the material left in the cross-section sampled on columns (sampled, sampledBound), then the crossing of the two tools lowest points polished by bisection.',
  'three-axis-waterline-brute':
    'Three-axis waterline: the upright tool as horizontal disks turned about the vertical axis of revolution (translated along the contour on a sloped plane), the next pass L further down the meridian; the material left in the meridian half-plane sampled (sampled, sampledBound), then polished by bisection; heights radial from the meridian centre (above the line when straight).',
  'brute-force-layer-cake':
    'Plane roughness: the tool surface sampled and polished in 3D (independent of the solver and of the 64-digit profile), its flank widths w(s) at each level s integrated by the layer-cake formulas m = (1/P) int (P - mu) ds, Ra = (2/P) int_m^H (P - mu) ds, Rq^2 = (1/P) [int_0^m 2(m - s) mu ds + int_m^H 2(s - m)(P - mu) ds], mu(s) the length of the period below s, by 16-point Gauss-Legendre in sqrt(s) on one and two panels (their difference the quadrature uncertainty, plus the widths 1e-9 R).',
  'brute-force-layer-cake-inverse':
    'Target Ra on a plane: the scallop height at which the brute-force-layer-cake Ra equals the target, by Illinois regula falsi over [2 Ra, the lower flank top] to 1e-13 h; uncertainty the Ra uncertainty over dRa/dh.',
  'roughness-definition':
    'Rz over one period: the highest cusp minus the contacts, the scallop height h itself (one-way) or the higher cusp (zigzag).',
  'stated-limit':
    'Refused inputs: the limit stated by the valid domain (README, Valid inputs: R from 0.001 to 1000 mm, 0 <= Rcr <= R, rho below 90 degrees, |tilt| below 90 degrees, h and L/2 at least 1e-9 mm, |Rs| from 0.001 to 1e6 mm, slope below 90 degrees).',
  'closed-form-limit':
    'Refused scallop heights of waterline passes on a sloped plane: Rcr (1 - sin(slope)), where the shank starts to form the cusp (README, Three-axis machining).',
  'high-precision-limit':
    "Refused scallop heights on a plane: the 64-digit profile's flank top (its widest point) or the height where the shank starts to form the flank, whichever is lower.",
};
