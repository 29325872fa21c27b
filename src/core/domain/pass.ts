/**
 * A pass problem: the tool and posture, the pass pattern and the design surface, with the forward
 * problem's scallop height or the inverse problem's step-over. Types only (see tool.ts). The surface
 * type is a parameter so that the solvers (surfaces/solve.ts) take any registered surface while the
 * page's inputs stay a plane or a cylinder (the default).
 */
import type { Surface, SurfaceDescriptorBase } from './surface';
import type { PassPattern, ToolInput } from './tool';

/** Tool, posture, pass pattern and the design surface (a plane or a cylinder unless `S` says more). */
export interface PassInput<S extends SurfaceDescriptorBase = Surface> extends ToolInput {
  readonly pattern: PassPattern;
  readonly surface: S;
}

/** Input of the forward problem: scallop height to path interval. */
export interface ForwardInput<S extends SurfaceDescriptorBase = Surface> extends PassInput<S> {
  /** Scallop height `h` in mm: at least 1e-9 mm (MIN_LENGTH_MM), below the flank and shank limits. */
  readonly scallopHeightMm: number;
}

/** Input of the inverse problem: path interval (step-over) to scallop height. */
export interface InverseInput<S extends SurfaceDescriptorBase = Surface> extends PassInput<S> {
  /** Step-over `L` in mm (between cutter-contact paths): 0 < L below the widest step-over without a wall. */
  readonly intervalMm: number;
}
