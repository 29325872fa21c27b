/**
 * Pure solver core: no DOM, no three.js. Runs unchanged in Node, a Web Worker and tests.
 */
import {
  type Approximation,
  type BediModel,
  bediHalfInterval,
  bediScallopHeight,
  type HalfInterval,
  type RedonnetModel,
  redonnetHalfInterval,
  redonnetScallopHeight,
  type ScallopHeight,
  type SekineModel,
  sekineHalfInterval,
  sekineScallopHeight,
} from './approximations';
import { exactHalfIntervalMm, exactScallopHeightMm } from './exact';
import {
  type ForwardInput,
  type InverseInput,
  type RawForwardInput,
  type RawInverseInput,
  type Validation,
  validateForward,
  validateInverse,
} from './validate';

export * from './approximations';
export * from './exact';
export * from './trace';
export * from './validate';

/** Path interval of all four procedures for one case (mm). */
export interface ForwardComparison {
  readonly input: ForwardInput;
  readonly exact: { readonly ok: true } & HalfInterval;
  readonly sekine: Approximation<HalfInterval & SekineModel>;
  readonly redonnet: Approximation<HalfInterval & RedonnetModel>;
  readonly bedi: Approximation<HalfInterval & BediModel>;
}

/** Scallop height of all four procedures at one path interval (mm). */
export interface InverseComparison {
  readonly input: InverseInput;
  readonly exact: { readonly ok: true } & ScallopHeight;
  readonly sekine: Approximation<ScallopHeight>;
  readonly redonnet: Approximation<ScallopHeight>;
  readonly bedi: Approximation<ScallopHeight>;
}

/** The four procedures' L/2 for a validated input. */
export function compareForward(input: ForwardInput): ForwardComparison {
  const half = exactHalfIntervalMm(input);
  return {
    input,
    exact: { ok: true, halfIntervalMm: half, intervalMm: 2 * half },
    sekine: sekineHalfInterval(input),
    redonnet: redonnetHalfInterval(input),
    bedi: bediHalfInterval(input),
  };
}

/** The four procedures' scallop height at a validated L/2. */
export function compareInverse(input: InverseInput): InverseComparison {
  return {
    input,
    exact: { ok: true, scallopHeightMm: exactScallopHeightMm(input) },
    sekine: sekineScallopHeight(input),
    redonnet: redonnetScallopHeight(input),
    bedi: bediScallopHeight(input),
  };
}

/** Validates raw values and compares the four procedures; errors name the fields. */
export function solveForwardRaw(raw: RawForwardInput): Validation<ForwardComparison> {
  const v = validateForward(raw);
  return v.ok ? { ok: true, value: compareForward(v.value) } : v;
}

/** Validates raw values and computes the four procedures' scallop heights. */
export function solveInverseRaw(raw: RawInverseInput): Validation<InverseComparison> {
  const v = validateInverse(raw);
  return v.ok ? { ok: true, value: compareInverse(v.value) } : v;
}
