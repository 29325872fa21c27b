/**
 * The teaching views' data beyond a plane or a cylinder (the `teach` job on a page request): for
 * three-axis machining (issue 20) the chart "step against slope"; for a doubly curved point (issue
 * 19) the chart of L against each radius and the cross-feed profile on the curved section. Plain
 * data crossing the worker boundary; lengths mm, angles degrees. Every reply echoes its request, so
 * the views show it only while it answers the inputs on screen (samePageRequest).
 */
import type { ThreeAxisPasses } from '../core/threeAxis/slopedPlane';
import type { CurvedRequest, PageRequest, ThreeAxisRequest } from './pageProtocol';
import type { CylinderCurves, ExactSummary, TeachReply } from './protocol';

/** The chart "step against slope" (core/threeAxis/slopeSweep.ts over 200 slopes). */
export interface SlopeChartData {
  readonly passes: ThreeAxisPasses;
  /** The raster angle psi of the passes charted, degrees (90 for waterline). */
  readonly rasterAngleDeg: number;
  /** Waterline on a surface of revolution (its radii held at every slope); false on a plane. */
  readonly onRevolution: boolean;
  /** The scallop height charted (the answer's), mm. */
  readonly hMm: number;
  /** Slopes, degrees, ascending from 0 to the largest valid one. */
  readonly slopeDeg: readonly number[];
  /** The exact programmed step (Lxy raster, dz waterline) leaving h at each slope, mm; null where refused. */
  readonly stepMm: ReadonlyArray<number | null>;
  /**
   * On a plane, the other strategy's programmed step for the same h at each slope (waterline's dz
   * beside raster, raster's Lxy at psi 0 beside waterline), mm; null where refused or off a plane.
   */
  readonly otherStepMm: ReadonlyArray<number | null>;
  /** The scallop the constant programmed step leaves at each slope, mm; null where that step is refused. */
  readonly cuspAtConstantStepMm: ReadonlyArray<number | null>;
  /** The runs of slopes (degrees) where the constant step leaves no cusp, and the core's reason (errors.ts code). */
  readonly constantStepRefusals: ReadonlyArray<{
    readonly fromDeg: number;
    readonly toDeg: number;
    readonly code: string;
  }>;
  /** The largest slope at which h is valid, degrees. */
  readonly largestSlopeDeg: number;
  /** The flat floor's step-over for h (Lxy0), mm. */
  readonly flatFloorStepMm: number;
  /** The constant programmed step (the flat floor's, or the one typed), mm. */
  readonly constantStepMm: number;
  /** The slope on screen, degrees, and the programmed step answering it, mm (null: waterline at 0). */
  readonly currentSlopeDeg: number;
  readonly currentStepMm: number | null;
  /** At the current slope: the other strategy's step on the plane, and the scallop the constant step leaves (mm; null where none). */
  readonly currentOtherStepMm: number | null;
  readonly currentCuspAtConstantStepMm: number | null;
  /** The raster angle the crossing compares (the current one for raster, 0 for waterline), degrees. */
  readonly crossingRasterAngleDeg: number;
  /** Where raster and waterline program the same step for h on a plane, degrees; null: no crossing. */
  readonly crossingDeg: number | null;
  /** The step both program there, mm (null without a crossing). */
  readonly crossingStepMm: number | null;
}

/** The three-axis teaching reply. */
export type ThreeAxisTeachReply =
  | {
      readonly ok: true;
      readonly request: ThreeAxisRequest;
      readonly slope: SlopeChartData;
      /**
       * On a sloped plane, the teaching data of the plane at the equivalent lead and tilt, one-way, at
       * the answer's cusp (equivalentPlane.ts): what the profile, formulas and step-through draw; null
       * on a surface of revolution or where that plane question is refused.
       */
      readonly plane: Extract<TeachReply, { ok: true }> | null;
    }
  | {
      readonly ok: false;
      readonly request: ThreeAxisRequest;
      /** A valid request with nothing to chart (no scallop), said in words; null for input errors. */
      readonly reason: string | null;
    };

/** Why one radius of the L-against-radius chart has no answer over a range. */
export type RadiusGapReason = 'gouging' | 'above-limit';

/** One radius's range without an answer (|radius| from, to; mm), on one side. */
export interface RadiusGap {
  readonly side: 'convex' | 'concave';
  readonly fromMm: number;
  readonly toMm: number;
  readonly reason: RadiusGapReason;
}

/** L against one principal radius (the other held) at the current posture and h. */
export interface RadiusSweepData {
  /** Which radius varies: `feed` (Rf) or `cross` (Rc). */
  readonly which: 'feed' | 'cross';
  /** The other radius, held, signed mm (Infinity: straight). */
  readonly heldMm: number;
  /** |radius| samples, mm, ascending on a log grid (the current |radius| among them). */
  readonly radiusMm: readonly number[];
  /** L (mm) with the radius convex (+|r|) and concave (-|r|); null where gouging or h too high. */
  readonly convex: ReadonlyArray<number | null>;
  readonly concave: ReadonlyArray<number | null>;
  readonly gaps: readonly RadiusGap[];
  /** L with this radius straight (the other held), mm; null where none. */
  readonly straightMm: number | null;
  /** The current signed radius, mm, and L there (null where none). */
  readonly currentMm: number;
  readonly currentIntervalMm: number | null;
}

/** A comparison row's mark in the profile: where its step-over puts the next pass. */
export interface CurvedMark {
  readonly key: CylinderCurves['comparison'][number]['key'] | 'cylinderAlong' | 'cylinderAcross';
  readonly intervalMm: number | null;
}

/** The cross-feed profile at a doubly curved point: the section across the feed is a circle of radius Rc. */
export interface CurvedSectionData {
  /** The tool radius R, mm (the drawing's scale). */
  readonly toolRadiusMm: number;
  readonly crossRadiusMm: number;
  readonly feedRadiusMm: number;
  /** One pass's profile in surface coordinates (s arc length along the equator, h radial), flat pairs, mm. */
  readonly passProfile: Float64Array;
  /** The exact answer as the drawing reads it (cusps at their reach, radial heights). */
  readonly exact: ExactSummary;
  /** Where the plane's, each cylinder's and the corrected procedures' step-overs put the next pass. */
  readonly comparison: readonly CurvedMark[];
  /** No tilt: the profile is symmetric. */
  readonly untilted: boolean;
}

/** The doubly curved point's teaching reply (in inverse mode, at the solved h). */
export type CurvedTeachReply =
  | {
      readonly ok: true;
      readonly request: CurvedRequest;
      readonly feed: RadiusSweepData;
      readonly cross: RadiusSweepData;
      readonly section: CurvedSectionData;
    }
  | { readonly ok: false; readonly request: CurvedRequest; readonly reason: string | null };

/** Every reply of the `teach` job. */
export type PageTeachReply = TeachReply | CurvedTeachReply | ThreeAxisTeachReply;

/** The `teach` job's question: any page request. */
export type PageTeachRequest = PageRequest;
