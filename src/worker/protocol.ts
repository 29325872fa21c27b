/**
 * Plain data crossing the worker boundary (structured-clone safe; typed arrays are
 * transferred). Lengths in mm, angles in degrees.
 */
import type { FieldName, InputError } from '../core/validate';
import type { Vec3 } from '../core/vec';

export type SolveMode = 'forward' | 'inverse';

export interface SolveRequest {
  /** Increasing per client; replies echo it so stale ones can be dropped. */
  readonly id: number;
  readonly mode: SolveMode;
  readonly R: number;
  readonly Rcr: number;
  readonly rho: number;
  /** Forward: scallop height h (mm). Inverse: path interval L (mm). */
  readonly value: number;
}

export type ProcedureKey = 'exact' | 'sekine' | 'redonnet' | 'bedi';

/** One row of the results table. */
export interface ProcedureRow {
  readonly key: ProcedureKey;
  /** Forward: L/2 of this procedure. Inverse: the scallop height it predicts. */
  readonly valueMm: number | null;
  /** Signed deviation from exact, mm and %, or null for exact / not applicable. */
  readonly deviationMm: number | null;
  readonly deviationPercent: number | null;
  /** Forward only: the scallop the procedure's own L really leaves (exact inverse); null if none. */
  readonly realScallopMm: number | null;
  /** Why there is no value (not applicable), or why there is no real scallop. */
  readonly note: string | null;
  /** Effective radius or ellipse long radius the procedure assumes, mm. */
  readonly modelRadiusMm: number | null;
}

export interface SceneGeometry {
  readonly toolRadiusMm: number;
  readonly scallopHeightMm: number;
  readonly halfIntervalMm: number;
  readonly ringAngleRad: number;
  readonly toolCentre: Vec3;
  readonly toolAxis: Vec3;
  readonly pBase: Vec3;
  readonly pHp: Vec3;
  readonly sectionCentre: Vec3;
  readonly sectionNormal: Vec3;
  readonly sectionRadiusMm: number;
  readonly intersectionLoops: Float64Array[];
  readonly profile: Float64Array;
  readonly toolPositions: Float32Array;
}

export type SolveReply =
  | {
      readonly id: number;
      readonly ok: true;
      readonly mode: SolveMode;
      /** Exact L/2 and h (mm) of the solved state. */
      readonly halfIntervalMm: number;
      readonly scallopHeightMm: number;
      readonly rows: readonly ProcedureRow[];
      /** Null when there is no scallop to draw (flat bottom at rho = 0 in inverse mode). */
      readonly geometry: SceneGeometry | null;
      readonly solveMs: number;
    }
  | { readonly id: number; readonly ok: false; readonly errors: readonly InputError[] };

export type { FieldName, InputError };
