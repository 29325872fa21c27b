/**
 * What a solver needs from a design surface (issue 18, "A surface interface"): one `SurfaceModel`
 * per kind of surface descriptor (domain/surface.ts), found by surfaces/registry.ts, so that the
 * callers (validation, the comparison, the worker, the command line) never switch on the kind.
 *
 * A model answers, for a tool in its posture and a pass pattern:
 * - where and how the scallop is measured: `limits` (the heights a scallop can have, measured as the
 *   surface measures them: along the normal on a plane, radially on a cylinder or a doubly curved
 *   point), `leavesNoScallop` (a flat face lying on the surface);
 * - the pass motion and the next pass, folded into the general `forward` (scallop height to
 *   step-over) and `inverse` (step-over to cusp heights), with the fast `intervalMm` and the widest
 *   step-over `maxIntervalMm`: a surface whose adjacent passes are not congruent (upright
 *   waterline passes on a surface of revolution) implements these directly;
 * - gouging: `fit`, whether the tool reaches below the surface away from the contact.
 *
 * Surfaces whose passes are congruent (each pass the previous one moved by a rigid motion: a
 * translation on the plane and across a cylinder's axis, a turn about the axis along it) need only
 * `CongruentPasses`, the flanks' reach and its conversion to a step-over; congruentPasses.ts builds
 * the model from it. Lengths mm.
 *
 * Registered: the plane, the cylinders and the doubly curved point (models/*). A machine mode is
 * not a surface: it supplies the tool's posture over these models (mode.ts, modes.ts; the sloped
 * plane is the plane under the upright tool's mode), and question.ts answers any registered mode over
 * any registered surface it has a posture on. Not yet a model: the upright tool's waterline passes on a
 * surface of revolution (its mode's waterlineRevolution.ts), whose two adjacent passes are not
 * congruent. Its step-over, cusp height and height limit fit `intervalMm`, `forward`, `inverse` and
 * `limits().limitMm` as they are (waterlineIntervalMm, waterlineForward, waterlineInverse,
 * waterlineHeightLimitMm); what does not is the per-flank part of the answers (ExactForward's flank
 * widths and points, FlankLimits' per-side tops and `flankWidths`), which only congruent passes
 * define. Registering it means making those parts optional (or per model) rather than inventing
 * them; its programmed steps (dz) stay its own, as the sloped plane's do.
 */
import type { ForwardInput, InverseInput } from '../domain/pass';
import type { SurfaceAxis, SurfaceDescriptorBase } from '../domain/surface';
import type { PassPattern, ToolInput } from '../domain/tool';
import type { Flank, FlankLimits, FlankPoint } from '../tool/posture';
import type { QuestionParameter } from './mode';

/**
 * The forward answer (scallop height to step-over) every surface gives, mm. Widths and the
 * step-over are measured along the surface as the pass motion is: a width on the plane, an arc
 * length about the axis on a cylinder or along the equator at a doubly curved point.
 */
export interface ForwardAnswer {
  /** Step-over L between adjacent cutter-contact paths. */
  readonly intervalMm: number;
  /**
   * How far the right (+Y) and left flank reach at the scallop height, from the contact (wR, wL).
   * One-way `L = wR + wL`, zigzag `L = 2 min(wR, wL)`.
   */
  readonly halfWidthRightMm: number;
  readonly halfWidthLeftMm: number;
  /** Contact offset y0: Y of the contact point minus Y of the tool centre point O. */
  readonly contactOffsetMm: number;
  /** Height of the highest cusp the passes leave: h (0 when no scallop forms at all). */
  readonly cuspHeightMm: number;
  /** Zigzag: the height of the other, lower (or equal) cusp; null for one-way passes. */
  readonly otherCuspHeightMm: number | null;
}

/** The inverse answer (step-over to scallop height) every surface gives, mm; measured as ForwardAnswer. */
export interface InverseAnswer {
  readonly intervalMm: number;
  /** Height of the highest cusp the passes leave (the scallop height); 0 on a flat bottom. */
  readonly cuspHeightMm: number;
  /** Zigzag: the height of the other, lower cusp; null for one-way passes. */
  readonly otherCuspHeightMm: number | null;
  /** Heights of the cusps formed by right flanks and by left flanks (equal for one-way). */
  readonly rightCuspHeightMm: number;
  readonly leftCuspHeightMm: number;
  /** Reaches of the right and left flank at their cusps, from the contact. */
  readonly halfWidthRightMm: number;
  readonly halfWidthLeftMm: number;
  readonly contactOffsetMm: number;
}

/** The exact answer of the forward problem (scallop height to step-over) of a surface model, mm. */
export interface ExactForward extends ForwardAnswer {
  /** L / 2. */
  readonly halfIntervalMm: number;
  /**
   * True when the tool leaves no scallop at any step-over up to `intervalMm`: a flat end with
   * neither lead nor tilt (its bottom face lies on the plane and has no corner to curve up).
   */
  readonly noScallop: boolean;
  /**
   * The flank points of the plane profile at the cusps (geometry and teaching). On a cylinder they
   * are the plane profile's points at the same height, for drawing only: the cylinder's flanks are
   * measured radially.
   */
  readonly right: FlankPoint;
  readonly left: FlankPoint;
}

/** The exact answer of the inverse problem (step-over to scallop height) of a surface model, mm. */
export interface ExactInverse extends InverseAnswer {
  readonly right: FlankPoint;
  readonly left: FlankPoint;
}

/** Whether a surface takes the tool in its posture without gouging, and if not, what would. */
export type SurfaceFit =
  | { readonly gouges: false }
  | {
      readonly gouges: true;
      /** What reaches below the surface: the head (corner and bottom), or the shank. */
      readonly by: 'head' | 'shank';
      /** The admissible signed radius nearest the given one (mm), or null when no radius takes the tool. */
      readonly limitRadiusMm: number | null;
      /** For the shank on a cylinder: the cylinder's axis and the shank's lean seen along it (degrees). */
      readonly shankLean?: { readonly axis: SurfaceAxis; readonly leanDeg: number };
    };

/** The answer of a surface that no tool gouges (the plane, convex surfaces). */
export const FITS: SurfaceFit = { gouges: false };

/**
 * A surface's model: everything the solvers' callers ask of it, for one kind of descriptor `S`.
 * Methods (not function properties) so that a model of one kind is a model of the union.
 */
export interface SurfaceModel<S extends SurfaceDescriptorBase> {
  /** The descriptor kind it answers (the registry's key). */
  readonly kind: S['kind'];
  /**
   * The numbers its descriptor takes from the user (mode.ts's QuestionParameter), for the builders
   * of a question over the registries; the product's surfaces are built by the page's own switches.
   */
  readonly parameters?: readonly QuestionParameter[];
  /** Exact step-over L (mm) for a scallop height: the fast path of `forward`. @param input validated. */
  intervalMm(input: ForwardInput<S>): number;
  /** Exact forward answer: step-over, flank widths, contact offset and cusp heights (mm). @param input validated. */
  forward(input: ForwardInput<S>): ExactForward;
  /** Exact inverse answer: the cusp heights (mm) that passes L apart leave. @param input validated. */
  inverse(input: InverseInput<S>): ExactInverse;
  /** The scallop heights the tool can leave here: below `limitMm` (flank walls and shank), mm. */
  limits(tool: ToolInput, surface: S): FlankLimits;
  /** The widest step-over (mm) that still leaves a scallop: the flanks' reach at the height limit. */
  maxIntervalMm(tool: ToolInput, pattern: PassPattern, surface: S): number;
  /**
   * How far each flank reaches at a height (both mm), measured as the step-over is (along the
   * surface: arc length about an axis, or a width): the profile the roughness integrates.
   */
  flankWidths(tool: ToolInput, surface: S): (flank: Flank, heightMm: number) => number;
  /** Gouging: whether the tool, away from the contact, reaches below the surface. */
  fit(tool: ToolInput, surface: S): SurfaceFit;
  /**
   * True when the tool leaves no scallop at any step-over up to the widest (a flat face lying on the
   * surface): every scallop height is then a valid question, answered by that widest step-over.
   */
  leavesNoScallop(tool: ToolInput, surface: S): boolean;
}

/**
 * The passes of a surface whose adjacent passes are congruent, prepared for one tool and posture
 * (cylinder.ts's CylinderSolver has this shape): the reach of each flank, in the unit the pass motion
 * is measured in, and its conversion to the step-over along the surface.
 */
export interface CongruentPasses {
  /** Height limits, measured as the surface measures scallops (mm). */
  limits(): FlankLimits;
  /** How far a flank reaches at height h: a width (mm) or an angle about an axis (radians). */
  reach(flank: Flank, heightMm: number): number;
  /** The inverse: the flank's height (mm) at that reach. */
  heightAt(flank: Flank, reach: number): number;
  /** Step-over along the surface (mm) from a reach (the next pass is this pass moved by it). */
  intervalFromReach(reach: number): number;
  /** The reach a step-over corresponds to. */
  reachFromInterval(intervalMm: number): number;
}
