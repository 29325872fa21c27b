/**
 * The exact step-over and its inverse on any registered surface (registry.ts): the solvers' entry
 * for every caller (validation, comparison, roughness, the worker, the command line). Each call
 * goes to the surface's model (models/*), which answers on its own surface; see surface.ts for what
 * a model supplies. Lengths mm.
 */
import type { ForwardInput, InverseInput } from '../domain/pass';
import { modelIntervalMm, type SurfaceDescriptor, surfaceModel } from './registry';
import type { ExactForward, ExactInverse } from './surface';

/**
 * Exact step-over L (mm) for a validated forward input: the fast path (no display geometry). Error
 * below 1e-9 mm over the valid domain.
 */
export function exactIntervalMm(input: ForwardInput<SurfaceDescriptor>): number {
  return modelIntervalMm(input);
}

/**
 * Exact half path interval `L/2` in mm (the paper's quantity; L / 2 for either pattern).
 * @param input validated by validateForward.
 */
export function exactHalfIntervalMm(input: ForwardInput<SurfaceDescriptor>): number {
  return exactIntervalMm(input) / 2;
}

/** Exact forward solution: step-over, flank widths, contact offset and cusp heights (mm). @param input validated. */
export function exactForward(input: ForwardInput<SurfaceDescriptor>): ExactForward {
  return surfaceModel(input.surface).forward(input);
}

/** Exact inverse: the cusp heights (mm) that passes L apart leave. @param input validated by validateInverse. */
export function exactInverse(input: InverseInput<SurfaceDescriptor>): ExactInverse {
  return surfaceModel(input.surface).inverse(input);
}

/**
 * Exact scallop height (mm) left by passes `intervalMm` apart: the highest cusp. 0 when the
 * point lies on a flat bottom lying on the plane (rho = 0 without tilt, L/2 <= R - Rcr).
 */
export function exactScallopHeightMm(input: InverseInput<SurfaceDescriptor>): number {
  return exactInverse(input).cuspHeightMm;
}

/** The answers' types (surface.ts), re-exported with the functions that give them. */
export type { ExactForward, ExactInverse };
