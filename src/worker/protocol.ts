/**
 * Plain data crossing the worker boundary (structured-clone safe; typed arrays are
 * transferred). Lengths in mm, angles in degrees unless a name says radians.
 *
 * A request is a validated core input; every reply echoes the request it answers, so the page
 * can show a reply only when it answers the inputs on screen (sameRequest).
 */

import { type FieldName, PASS_FIELDS } from '../core/input/fields';
import { sameFields } from '../core/input/raw';
import type { LengthUnit } from '../core/input/units';
import type { ForwardInput, InputError, InverseInput, PassPattern } from '../core/input/validate';
import type { Vec3 } from '../core/math/vec';
import type { LookupGrid, LookupTable, LookupTool } from '../core/output/lookupTable';
import type { DrawnSurface } from '../core/output/surfaceGeometry';
import type { ThreeAxisLookupCase } from '../core/output/threeAxisLookup';
import type { ApproximationKey, CurvatureRowKey, ForwardModels, ProcedureKey } from '../core/procedures/procedures';
import type { SweepGap } from '../core/procedures/sweepGaps';
import type { PaperTableRow } from '../core/procedures/teaching';
import type { RaTargetInput, RoughnessSummary } from '../core/roughness/raTarget';
import type { CylinderSurface } from '../core/surfaces/cylinder';
import type { PrincipalRadii } from '../core/surfaces/doublyCurved/types';

/**
 * One question: a scallop height to a step-over, a step-over to the cusp heights, or a target
 * roughness Ra to a step-over (through the h that leaves it).
 */
export type SolveRequest =
  | { readonly mode: 'forward'; readonly input: ForwardInput }
  | { readonly mode: 'inverse'; readonly input: InverseInput }
  | { readonly mode: 'ra'; readonly input: RaTargetInput };

/** The page's two directions (a target Ra is a forward question). */
export type SolveMode = 'forward' | 'inverse';

/** The field each mode's question gives (the field registry's): a scallop height, a target Ra, a step-over. */
export const QUESTION_FIELD = { forward: 'h', ra: 'ra', inverse: 'interval' } as const satisfies Readonly<
  Record<SolveRequest['mode'], FieldName>
>;

/** True when both requests ask the same question (every input equal); null equals nothing. */
export function sameRequest(a: SolveRequest | null, b: SolveRequest | null): boolean {
  if (a === null || b === null || a.mode !== b.mode) return false;
  return sameFields(a.input, b.input, PASS_FIELDS) && sameFields(a.input, b.input, [QUESTION_FIELD[a.mode]]);
}

/** Where one cusp stands: across the feed from this pass's contact, and its height above it (mm). */
export interface Cusp {
  readonly yMm: number;
  readonly heightMm: number;
}

/** The exact answer of a request (mm). */
export interface ExactSummary {
  readonly pattern: PassPattern;
  /** Step-over L between adjacent cutter-contact paths, and L/2. */
  readonly intervalMm: number;
  readonly halfIntervalMm: number;
  /** Flank widths wR, wL from the contact: at the scallop height (forward) or at the cusps (inverse). */
  readonly widthRightMm: number;
  readonly widthLeftMm: number;
  /** Contact offset y0: Y of the contact minus Y of the tool centre point O. */
  readonly contactOffsetMm: number;
  /** The highest cusp (the scallop height) and, for zigzag, the other one. */
  readonly cuspHeightMm: number;
  readonly otherCuspHeightMm: number | null;
  /** The cusp on the right (+Y) and on the left of this pass. */
  readonly right: Cusp;
  readonly left: Cusp;
  /** No scallop at any step-over up to 2R (a flat end lying flat). */
  readonly noScallop: boolean;
  /** The widest step-over that still leaves a scallop. */
  readonly maxIntervalMm: number;
}

/**
 * Why a procedure has no value or no real scallop, as data so that the page words it in the
 * user's unit: a reason with no numbers in it, a scallop beyond the model's own widest point, or
 * a step-over so wide that the passes leave a wall.
 */
export type ProcedureNote =
  | { readonly kind: 'reason'; readonly text: string }
  | {
      readonly kind: 'beyond-model';
      /** The model's shape and the quantity that exceeds it (h or L/2), mm. */
      readonly shape: 'circle' | 'ellipse';
      readonly quantity: 'h' | 'half';
      readonly valueMm: number;
      /** Reff of a circle; Rlong sin(rho) (for h) or Rlong (for L/2) of Bedi's ellipse. */
      readonly limitMm: number;
    }
  | { readonly kind: 'wall'; readonly intervalMm: number; readonly maxIntervalMm: number };

/** One row of the results table, of a procedure (K: ProcedureKey) or of a cylinder's comparison (CurvatureRowKey). */
export interface ResultRow<K extends string> {
  readonly key: K;
  /** Forward: L/2 of this procedure. Inverse: the scallop height it predicts. */
  readonly valueMm: number | null;
  /** Signed deviation from exact (of L/2 forward, of h inverse), mm and %; null for exact or no value. */
  readonly deviationMm: number | null;
  readonly deviationPercent: number | null;
  /** Forward only: the scallop the procedure's own L really leaves (exact inverse); null if none. */
  readonly realScallopMm: number | null;
  readonly note: ProcedureNote | null;
}

/** One row of the results table. */
export type ProcedureRow = ResultRow<ProcedureKey>;

/**
 * One row a cylinder adds to the results table (the plane's exact answer, or a procedure corrected
 * for the curvature), with the same fields as a procedure's row: forward L/2 and its deviation from
 * exact, the scallop its own L really leaves on the cylinder; inverse the scallop height it predicts.
 */
export type CurvatureRow = ResultRow<CurvatureRowKey>;

/** Segments around the tool axis of the tool mesh the worker sends (the scene builds the same indices). */
export const TOOL_RADIAL_SEGMENTS = 64;
/** Samples per branch of the torus / plane curves. */
export const LOOP_SAMPLES = 96;
/** Most points of one torus / plane curve (intersectionLoops: at most 2 samples + 1 per branch, plus the cusps). */
export const LOOP_MAX_POINTS = 4 * LOOP_SAMPLES + 16;

/** Closed curves where the torus meets a plane: none, one or two (flat xyz, mm). */
export type Loops = readonly [] | readonly [Float64Array] | readonly [Float64Array, Float64Array];

/** The section through one cusp point P_hp and the curve at the cusp height. */
export interface CuspGeometry {
  readonly flank: 'right' | 'left';
  readonly heightMm: number;
  readonly pHp: Vec3;
  readonly sectionCentre: Vec3;
  readonly sectionNormal: Vec3;
  readonly sectionRadiusMm: number;
  readonly loops: Loops;
}

/** What the 3D scene draws for one solved state (mm; contact of this pass at the origin, X feed, Z up). */
export interface SceneGeometry {
  readonly toolRadiusMm: number;
  readonly cornerRadiusMm: number;
  readonly pattern: PassPattern;
  readonly intervalMm: number;
  /** Height of the highest cusp (the h pseudo plane). */
  readonly scallopHeightMm: number;
  readonly toolCentre: Vec3;
  readonly toolAxis: Vec3;
  /** Tool surface, TOOL_RADIAL_SEGMENTS around the axis (indices: core toolMeshIndices). */
  readonly toolPositions: Float32Array;
  /** The cusp on each side; null where it has no height (a flat bottom covers it), and on a cylinder. */
  readonly right: CuspGeometry | null;
  readonly left: CuspGeometry | null;
  /**
   * The design surface: a plane, a cylinder, the torus patch of a doubly curved point or a surface
   * of revolution under waterline passes (surfaceGeometry.ts draws it).
   */
  readonly surface: DrawnSurface;
  /**
   * On a cylinder, the cusp points on the h pseudo surface (where the neighbouring passes' profiles
   * meet, in the section through the contact); null on a plane (the cusp sections say it there).
   * On a doubly curved patch likewise, in the cross-feed plane through the CC point.
   */
  readonly cuspPoints: { readonly right: Vec3 | null; readonly left: Vec3 | null } | null;
  /** Three-axis machining: the machine frame and the programmed step; null on a five-axis machine. */
  readonly machine: MachineView | null;
}

/**
 * How a three-axis scene sits in the machine (z up, the tool axis): everything else of the scene is
 * in the CC point's local frame, turned by `frameMatrix`; the passes drawn beside this one, and the
 * step the CAM system programs as a dimension line (mm, local frame).
 */
export interface MachineView {
  /** Local -> machine rotation, column-major 4 x 4 (core machineGeometry.ts frameMatrix). */
  readonly frameMatrix: readonly number[];
  /** Rigid motions (column-major 4 x 4, local frame) carrying this pass's tool to the other passes drawn. */
  readonly passMatrices: readonly (readonly number[])[];
  /** Cross offsets (along the surface) of the CC paths drawn, this pass's (0) included. */
  readonly pathOffsetsMm: readonly number[];
  /** The programmed step: `Lxy` horizontal (raster) or `dz` vertical (waterline). */
  readonly step: {
    readonly kind: 'horizontal' | 'vertical';
    readonly points: Float64Array;
    readonly labelAt: Vec3;
  };
}

/**
 * How far the page's sliders reach for the question a reply answers or refuses (issue 27 point 4:
 * the page solves nothing, so the worker's reply carries what its sliders need), mm: h below
 * `hMm`, L below `intervalMm` (null: the sliders' own range), Ra below `raMm` (null: Ra is not the
 * target), a concave cylinder's radius from `concaveMinMm` (Infinity: no concave radius fits; 0: no
 * concave cylinder asked). Null in a reply whose tool, posture or surface make no such question.
 */
export interface SliderLimits {
  readonly hMm: number;
  readonly intervalMm: number | null;
  readonly raMm: number | null;
  readonly concaveMinMm: number;
}

/** The answer to `solve`. */
export type SolveReply =
  | {
      readonly ok: true;
      readonly request: SolveRequest;
      readonly limits: SliderLimits | null;
      readonly exact: ExactSummary;
      readonly rows: readonly ProcedureRow[];
      /** On a cylinder: the plane's answer and the corrected procedures (CURVATURE_ROW_KEYS order); null on a plane. */
      readonly curvature: readonly CurvatureRow[] | null;
      readonly scene: SceneGeometry;
      /** Rz, Ra, Rq of the surface left at the exact step-over, and the rule of thumb Ra ~ h/4. */
      readonly roughness: RoughnessSummary;
      readonly solveMs: number;
    }
  | {
      readonly ok: false;
      readonly request: SolveRequest;
      readonly errors: readonly InputError[];
      readonly limits: SliderLimits | null;
    };

/** One frame of the step-through of the paper's 3D procedure (Figure 1), on one flank or both. */
export interface TraceFrame {
  readonly phase: 'approach' | 'single-contact' | 'search' | 'converged';
  /** The flank this step works on; null for the closing frame (both flanks). */
  readonly flank: 'right' | 'left' | null;
  /** Index of this step among the approach steps of its flank (0: Eq. 1's starting section). */
  readonly approachIndex: number;
  readonly ringAngleRad: number;
  /** In-plane distance of the section centre from the h pseudo plane (mm), null in search frames. */
  readonly dsMm: number | null;
  readonly sectionCentre: Vec3;
  readonly sectionNormal: Vec3;
  /** Single contact: false when every section meets the plane. */
  readonly found: boolean;
  /** Search: the ring-angle range and the sections tried in it. */
  readonly rangeRad: readonly [number, number] | null;
  readonly sectionCount: number;
  /** Candidate points P_hp[i] of a search pass (flat xyz, mm); empty otherwise. */
  readonly candidates: readonly number[];
  /** The point this frame shows (touching point, best candidate, converged P_hp), or null. */
  readonly point: Vec3 | null;
  /** Search: how far out the best crossing lies; converged: the flank's width (mm). */
  readonly outMm: number | null;
}

/** The procedure's result beside the exact solver, for the closing caption (mm). */
export interface TraceResult {
  readonly widthRightMm: number;
  readonly widthLeftMm: number;
  readonly exactWidthRightMm: number;
  readonly exactWidthLeftMm: number;
}

/** One approximation's model for the formulas (mm) and its L/2 at h (null where it has none). */
export type FormulaModel<K extends ApproximationKey> = ForwardModels[K] & { readonly halfIntervalMm: number | null };

/** Model quantities for the formulas (mm, radians), null where a model does not apply. */
export type FormulaModels = FormulaShape & { readonly [K in ApproximationKey]: FormulaModel<K> | null };

/** The exact profile's quantities for the formulas (mm, radians). */
export interface FormulaShape {
  readonly shape: {
    readonly a: number;
    readonly b: number;
    readonly phiRad: number;
    readonly d0: number;
    readonly t0Rad: number;
    readonly contactOffsetMm: number;
  };
  /** Ring-angle offsets of the sections carrying each flank's cusp point. */
  readonly rightOffsetRad: number;
  readonly leftOffsetRad: number;
}

/** Step-over L of every procedure along one posture angle (mm; null where none). */
export interface Sweep {
  readonly angleDeg: readonly number[];
  readonly values: { readonly [K in ProcedureKey]: ReadonlyArray<number | null> };
  /** Per procedure, the angle ranges without an answer and why (words with no numbers). */
  readonly gaps: { readonly [K in ProcedureKey]: readonly SweepGap[] };
}

/** Cross-feed curves (flat y, z from the contact, mm). */
export interface ProfileCurveSet {
  /** The exact profile, both flanks (left widest point to right widest point). */
  readonly profile: Float64Array;
  /** The ring ellipse it is offset from, closed. */
  readonly ringEllipse: Float64Array;
  /** Each approximation's right half (symmetric models), null where it does not apply. */
  readonly approximations: { readonly [K in ApproximationKey]: Float64Array | null };
}

/**
 * What the cross-feed profile view draws on a cylinder, in surface coordinates: (the arc length
 * across the feed from the contact, the radial height above the surface), mm.
 */
export interface CylinderCurves {
  readonly surface: CylinderSurface;
  /**
   * One pass's exact profile from the left flank's widest point to the right one's: with the axis
   * along the feed the plane profile (turned about the axis for the next pass), across it the tool
   * revolved about the axis (cylinder.ts revolvedProfile).
   */
  readonly passProfile: Float64Array;
  /** The ring ellipse (curves.ringEllipse) in the same coordinates. */
  readonly ringEllipse: Float64Array;
  /** Where each comparison row puts the next pass: its step-over L on this cylinder (null where none). */
  readonly comparison: ReadonlyArray<{ readonly key: CurvatureRowKey; readonly intervalMm: number | null }>;
}

/** Everything the teaching views draw, for the forward state the request comes to. */
export interface TeachData {
  /** The forward input the views show: the request's own, or in inverse mode the solved h. */
  readonly forward: ForwardInput;
  readonly exact: ExactSummary;
  readonly curves: ProfileCurveSet;
  readonly sweeps: { readonly lead: Sweep; readonly tilt: Sweep };
  readonly frames: readonly TraceFrame[];
  readonly traceResult: TraceResult;
  readonly models: FormulaModels;
  /** Tables 2-5 recomputed beside the printed values. */
  readonly tables: readonly PaperTableRow[];
  /** On a cylinder, the profile view's curves in surface coordinates; null on a plane. */
  readonly cylinder: CylinderCurves | null;
}

/** The answer to `teach`. */
export type TeachReply =
  | ({ readonly ok: true; readonly request: SolveRequest } & TeachData)
  | {
      readonly ok: false;
      readonly request: SolveRequest;
      readonly errors: readonly InputError[];
      /** A valid request with nothing to teach (no scallop), said in words; null for input errors. */
      readonly reason: string | null;
    };

export type { ApproximationKey, InputError, ProcedureKey, RaTargetInput, RoughnessSummary, SweepGap };

/**
 * The `table` job: the lookup table of one validated tool, pattern and surface (mm) over a grid
 * of scallop heights, lead angles and tilts (core/lookupTable.ts).
 */
export interface TableRequest {
  readonly tool: LookupTool;
  readonly grid: LookupGrid;
  /**
   * A doubly curved point's two signed radii (mm; issue 19): the table is then that point's
   * (worker/data/curvedTable.ts), the tool's surface a plane placeholder. Absent for a plane or a
   * cylinder.
   */
  readonly radii?: PrincipalRadii;
  /**
   * The file's unit (issue 21): its lengths in it, every dimensioned column's header naming its
   * unit (`R_in`, `rho_deg`), the reasons worded in it. Absent: the batch layout as the command
   * line writes it (mm and degrees, plain column names).
   */
  readonly unit?: LengthUnit;
  /**
   * Three-axis machining (issue 28): the table is the programmed step over slopes x the grid's
   * scallop heights (core/output/threeAxisLookup.ts) for this tool and strategy; the tool's pattern
   * and surface and the grid's leads and tilts are then placeholders (one-way, a plane, none).
   */
  readonly threeAxis?: { readonly case: ThreeAxisLookupCase; readonly slopesDeg: readonly number[] };
}

/** The answer to `table`, echoing its request: the CSV and its counts, or why there is none. */
export type TableReply =
  | ({ readonly ok: true; readonly request: TableRequest } & LookupTable)
  | { readonly ok: false; readonly request: TableRequest; readonly reason: string };

/** True when both ask the same table (the same tool, pattern, surface and grid). */
export function sameTableRequest(a: TableRequest | null, b: TableRequest | null): boolean {
  if (a === null || b === null) return false;
  const same = (x: readonly number[], y: readonly number[]) => x.length === y.length && x.every((v, i) => v === y[i]);
  return (
    // The tool's fields (a table's tool has no posture: the grid gives it).
    sameFields(a.tool, b.tool, PASS_FIELDS) &&
    a.radii?.feedRadiusMm === b.radii?.feedRadiusMm &&
    a.radii?.crossRadiusMm === b.radii?.crossRadiusMm &&
    a.unit === b.unit &&
    JSON.stringify(a.threeAxis ?? null) === JSON.stringify(b.threeAxis ?? null) &&
    same(a.grid.scallopHeightsMm, b.grid.scallopHeightsMm) &&
    same(a.grid.leadAnglesDeg, b.grid.leadAnglesDeg) &&
    same(a.grid.tiltAnglesDeg, b.grid.tiltAnglesDeg)
  );
}
