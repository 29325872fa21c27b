/**
 * Printed values of the paper's Tables 2-5 (Sekine & Kameya 2022) and the exact column
 * of shared/notes/geometry.md. Conditions are the same in every table.
 */
/** One value per procedure as the paper's tables list them (3D computation first), mm. */
export interface ProcedureValues {
  readonly threeD: number;
  readonly sekine: number;
  readonly redonnet: number;
  readonly bedi: number;
}

export interface PaperCondition {
  readonly table: 2 | 3;
  readonly R: number;
  readonly Rcr: number;
  readonly rho: number;
  readonly h: number;
  /** Printed L/2 (mm, 3 decimals), Tables 2-3. */
  readonly printedHalf: ProcedureValues;
  /** Printed scallop height (mm, 3 decimals) at the printed 3D L/2, Tables 4-5. */
  readonly printedHeight: ProcedureValues;
  /** Exact L/2 from the notes (checked there by sampling and Open CASCADE), 12 decimals. */
  readonly notesExactHalf: number;
}

const c = (
  table: 2 | 3,
  R: number,
  Rcr: number,
  rho: number,
  h: number,
  half: [number, number, number, number],
  height: [number, number, number, number],
  notesExactHalf: number,
): PaperCondition => ({
  table,
  R,
  Rcr,
  rho,
  h,
  printedHalf: { threeD: half[0], sekine: half[1], redonnet: half[2], bedi: half[3] },
  printedHeight: { threeD: height[0], sekine: height[1], redonnet: height[2], bedi: height[3] },
  notesExactHalf,
});

export const PAPER_CONDITIONS: readonly PaperCondition[] = [
  // biome-ignore lint/suspicious/noApproximativeNumericConstant: 1.442 is a printed table value, not log2(e).
  c(2, 3, 1, 5, 0.05, [1.442, 1.086, 1.547, 1.437], [0.05, 0.088, 0.043, 0.05], 1.443592412967),
  c(2, 3, 1, 5, 0.1, [1.879, 1.534, 2.186, 1.864], [0.1, 0.15, 0.074, 0.103], 1.892088335855),
  c(2, 3, 1, 10, 0.05, [1.083, 0.785, 1.118, 1.081], [0.05, 0.096, 0.047, 0.05], 1.08448834717),
  c(2, 3, 1, 10, 0.1, [1.479, 1.108, 1.579, 1.474], [0.1, 0.179, 0.088, 0.101], 1.484975306771),
  c(3, 6, 2, 5, 0.05, [2.115, 1.536, 2.188, 2.112], [0.05, 0.095, 0.047, 0.05], 2.115665155692),
  c(3, 6, 2, 5, 0.1, [2.883, 2.171, 3.093, 2.874], [0.1, 0.177, 0.087, 0.101], 2.887184825934),
  c(3, 6, 2, 10, 0.05, [1.558, 1.112, 1.581, 1.556], [0.05, 0.098, 0.049, 0.05], 1.558019138503),
  c(3, 6, 2, 10, 0.1, [2.167, 1.571, 2.235, 2.162], [0.1, 0.191, 0.094, 0.1], 2.16897669434),
];
