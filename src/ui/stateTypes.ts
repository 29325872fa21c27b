/**
 * The calculator state's types, a leaf: state.ts (parsing, links), machineState.ts (the machine's
 * part) and toolPresets.ts all read them, so none of them imports another for a type. Pure.
 */
import type { PageFieldKey } from '../core/input/fields';
import type { LengthUnit } from '../core/input/units';
import type { PassPattern } from '../core/input/validate';
import type { SurfaceAxis } from '../core/surfaces/cylinder';
import type { ThreeAxisPasses } from '../core/threeAxis/slopedPlane';
import type { SolveMode } from '../worker/protocol';
import type { CurvedFields, RadiusSide } from './surfaceState';

export type Unit = LengthUnit;
/** The page's text fields: R (or D), Rcr, rho, tilt, Rs, h, ra, L (the field registry's page keys). */
export type FieldKey = PageFieldKey;
/**
 * What the forward problem is given: a scallop height h, a roughness Ra (h then follows), or a
 * target Sa (the teeth's areal roughness: the best pair of step-over and feed per tooth; a plane only).
 */
export type Target = 'h' | 'ra' | 'sa';
/** How the tool size field is given: the radius R, or the diameter D = 2R, as catalogues give it. */
export type ToolSize = 'R' | 'D';
/**
 * The design surface as the page offers it: a plane, a cylinder (its radius the field Rs, a
 * magnitude), or a doubly curved point (`curved`: the fields Rf and Rc, magnitudes, with their sides).
 */
export type SurfaceKind = 'plane' | 'convex' | 'concave' | 'curved';
/** The machine: five-axis (lead and tilt given) or three-axis (the tool upright). */
export type Machine = '5axis' | '3axis';
/** Three-axis pass strategy: raster (parallel passes) or waterline (Z-level). */
export type Passes = ThreeAxisPasses;

/** A length field's text as typed in `unit`, and the text a unit switch made of it (`shown`). */
export interface TypedText {
  readonly unit: Unit;
  readonly text: string;
  readonly shown: string;
}

export interface CalculatorState extends CurvedFields {
  readonly unit: Unit;
  readonly mode: SolveMode;
  readonly pattern: PassPattern;
  /** Forward mode's given value: h or Ra. */
  readonly target: Target;
  /** The design surface, and a cylinder's axis (kept while a plane is chosen, for the next cylinder). */
  readonly surface: SurfaceKind;
  readonly surfaceAxis: SurfaceAxis;
  /** The sides of the doubly curved point's radii (kept while another surface is chosen). */
  readonly feedSide: RadiusSide;
  readonly crossSide: RadiusSide;
  /** Five-axis (lead and tilt given) or three-axis (the tool upright: the slope sets them). */
  readonly machine: Machine;
  /** Three-axis passes: raster (parallel, at the raster angle) or waterline (Z-level). */
  readonly passes: Passes;
  /** Text of each field in the current unit (angles in degrees); `R` holds D when `size` is 'D'. */
  readonly fields: Readonly<Record<FieldKey, string>>;
  /** The tool size field: radius R (default, also when missing) or diameter D. */
  readonly size?: ToolSize;
  /**
   * The fields the user set on this page (typed, a preset, a tool): a unit switch converts them
   * without loss, while the others, still at their defaults, become the new unit's defaults.
   */
  readonly edited?: readonly FieldKey[];
  /** What each length field converted by a unit switch was typed as (a switch back restores it exactly). */
  readonly typed?: Readonly<Partial<Record<FieldKey, TypedText>>>;
  /** The name of the tool the tool fields hold (a saved or library tool), plain text; dropped when D or Rcr is edited. */
  readonly toolName?: string;
}
