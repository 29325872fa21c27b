/**
 * Plain data crossing the worker boundary (structured-clone safe; typed arrays are
 * transferred). Lengths in mm, angles in degrees.
 */
import type { PaperTableRow } from '../core/teaching';
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
  /** Also compute the teaching views' data. */
  readonly withViews?: boolean;
}

/** One frame of the step-through of the paper's 3D procedure (Figure 1). */
export interface TraceFrame {
  readonly phase: 'approach' | 'single-contact' | 'search' | 'converged';
  readonly caption: string;
  readonly ringAngleRad: number;
  /** In-plane distance of the section centre from the h pseudo plane (mm), null in search frames. */
  readonly dsMm: number | null;
  readonly sectionCentre: Vec3;
  readonly sectionNormal: Vec3;
  /** Candidate points P_hp[i] of a search pass (flat xyz, mm); empty otherwise. */
  readonly candidates: number[];
  /** The point this frame shows (touching point, best candidate, converged P_hp), or null. */
  readonly point: Vec3 | null;
  readonly bestY: number | null;
}

export interface TeachingData {
  readonly curves: {
    readonly exact: Float64Array;
    readonly ringEllipse: Float64Array;
    readonly sekine: Float64Array | null;
    readonly redonnet: Float64Array | null;
    readonly bedi: Float64Array | null;
  };
  readonly sweep: {
    readonly rhoDeg: number[];
    readonly exact: Array<number | null>;
    readonly sekine: Array<number | null>;
    readonly redonnet: Array<number | null>;
    readonly bedi: Array<number | null>;
  };
  readonly frames: readonly TraceFrame[];
  /** Tables 2-5 recomputed beside the printed values. */
  readonly tables: readonly PaperTableRow[];
  /**
   * Model quantities for the formulas (mm), null where the model does not apply. Each
   * `halfIntervalMm` is that procedure's L/2 at this state's h (null: no answer at this h).
   */
  readonly models: {
    readonly sekine: {
      toolCentreHeightMm: number;
      shortRadiusMm: number;
      longRadiusMm: number;
      effectiveRadiusMm: number;
      halfIntervalMm: number | null;
    } | null;
    readonly redonnet: { effectiveRadiusMm: number; halfIntervalMm: number | null } | null;
    readonly bedi: { longRadiusMm: number; shortRadiusMm: number; halfIntervalMm: number | null } | null;
    readonly exactNormalAngleRad: number;
    readonly exactRingAngleRad: number;
  };
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
      /** Present when requested and there is a scallop. */
      readonly teaching: TeachingData | null;
      readonly solveMs: number;
    }
  | { readonly id: number; readonly ok: false; readonly errors: readonly InputError[] };

export type { FieldName, InputError };
