/**
 * The solver core as a library: the documented entry that other CAM and web tools import
 * (`import { stepOver } from 'path-interval'`, built by `npm run build:lib` into `dist-lib/`).
 * Pure functions, no DOM, no three.js, no I/O: it runs in Node, a browser or a Web Worker.
 *
 * Units at this edge: lengths in mm, angles in degrees. Raw inputs (`Raw*Input`) take what a
 * form, URL or CSV cell gives (numbers or number text) and are validated; every invalid input is
 * an `{ ok: false, error }` value naming the field and its limit (`describeInputError` words it
 * in mm or inches), never an exception, `NaN` or `Infinity`. Validated inputs (`ForwardInput`,
 * `InverseInput`) go straight to the solvers.
 *
 * Source: the exact solution and the three published approximations of Sekine & Kameya (2022),
 * "Path interval of a filleted end mill", extended to tilt, zigzag passes and cylinders as the
 * README's "What it computes" says.
 */

export type { LengthUnit } from './input/units';
export type {
  AnyInputError,
  ForwardInput,
  InputError,
  InverseInput,
  PassInput,
  PassPattern,
  RawForwardInput,
  RawInverseInput,
  RawToolInput,
  ToolInput,
  Validation,
} from './input/validate';
export { describeInputError, forwardInput, inverseInput } from './input/validate';
export type { ForwardComparison, InverseComparison } from './procedures/compare';
export { compareForward, compareInverse, solveForwardRaw, solveInverseRaw } from './procedures/compare';
export type { ApproximationKey, ProcedureInfo, ProcedureKey } from './procedures/procedures';
export { PROCEDURE_KEYS, PROCEDURES } from './procedures/procedures';
export type { RawTargetRaInput, Roughness, TargetRaInput } from './roughness/roughness';
export {
  exactRoughness,
  exactRoughnessAtInterval,
  scallopHeightForRaMm,
  validateTargetRa,
} from './roughness/roughness';
export type { CylinderSurface, Surface, SurfaceAxis } from './surfaces/cylinder';
export type { ExactForward, ExactInverse } from './surfaces/solve';
export { exactForward, exactInverse } from './surfaces/solve';
export { maxIntervalMm, scallopHeightLimits, validateForward, validateInverse } from './surfaces/validate';
