/**
 * A doubly curved point's question without its target, answered through the two registries (issue
 * 27 point 3): the surface registry's doubly curved model (models/doublyCurved.ts, which answers a
 * straight radius by the cylinder's or the plane's model) at the posture the five-axis mode supplies
 * (question.ts posturedModel: lead and tilt as given). Every number the page, the worker and the
 * command line show for the point's exact answer (step-over, cusps, limits, widest step-over, the
 * flanks the roughness and the profile integrate) comes from here, so there is one exact answer.
 * The model loads on first use in the site: a caller there awaits loadSurfaceModel('doublyCurved')
 * first (the worker's page job does). Lengths mm, angles degrees.
 */
import type { DoublyCurvedSurface } from '../domain/surface';
import type { PassPattern, ToolInput } from '../domain/tool';
import type { Flank, FlankLimits } from '../tool/posture';
import type { DoublyCurvedPass, PrincipalRadii } from './doublyCurved/types';
import type { FiveAxisMode } from './modes/fiveAxis';
import { posturedModel } from './question';
import type { ExactForward, ExactInverse, SurfaceModel } from './surface';

/** The point's model, the tool at the five-axis posture, the point as a surface and the pattern its passes make. */
export interface CurvedPoint {
  readonly model: SurfaceModel<DoublyCurvedSurface>;
  readonly tool: ToolInput;
  readonly surface: DoublyCurvedSurface;
  readonly pattern: PassPattern;
}

/** The point as the surface descriptor the registry's model takes. */
export function curvedSurface(radii: PrincipalRadii): DoublyCurvedSurface {
  return { kind: 'doublyCurved', feedRadiusMm: radii.feedRadiusMm, crossRadiusMm: radii.crossRadiusMm };
}

/** The registry's model of a doubly curved point and the tool at the five-axis mode's posture. */
export function curvedPoint(tool: ToolInput, radii: PrincipalRadii, pattern: PassPattern): CurvedPoint {
  const surface = curvedSurface(radii);
  const mode: FiveAxisMode = { kind: 'fiveAxis', leadAngleDeg: tool.leadAngleDeg, tiltAngleDeg: tool.tiltAngleDeg };
  const p = posturedModel({ tool, mode, surface, pattern });
  return { model: p.model as SurfaceModel<DoublyCurvedSurface>, tool: p.tool, surface, pattern: p.posture.pattern };
}

/** curvedPoint of a doubly curved pass (the tool, the posture, the pattern and the radii in one). */
export function curvedPointOf(p: DoublyCurvedPass): CurvedPoint {
  return curvedPoint(p, p, p.pattern);
}

/** The exact forward answer at the point: the step-over that leaves the scallop height h (mm). */
export function curvedForward(c: CurvedPoint, scallopHeightMm: number): ExactForward {
  return c.model.forward({ ...c.tool, pattern: c.pattern, surface: c.surface, scallopHeightMm });
}

/** The exact inverse answer at the point: the cusps passes L (mm) apart leave. */
export function curvedInverse(c: CurvedPoint, intervalMm: number): ExactInverse {
  return c.model.inverse({ ...c.tool, pattern: c.pattern, surface: c.surface, intervalMm });
}

/** The scallop heights the point takes (flank tops and shank, radial, mm). */
export function curvedLimits(c: CurvedPoint): FlankLimits {
  return c.model.limits(c.tool, c.surface);
}

/** The widest step-over (mm) that still leaves a scallop at the point. */
export function curvedMaxIntervalMm(c: CurvedPoint): number {
  return c.model.maxIntervalMm(c.tool, c.pattern, c.surface);
}

/** Each flank's reach (mm, along the surface) at a radial height (mm): what the roughness and the profile integrate. */
export function curvedFlankWidths(c: CurvedPoint): (flank: Flank, heightMm: number) => number {
  return c.model.flankWidths(c.tool, c.surface);
}
