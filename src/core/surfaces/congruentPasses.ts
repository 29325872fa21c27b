/**
 * The adapter from congruent passes to a surface model (surface.ts): a surface whose adjacent passes
 * are one pass moved by a rigid motion only says how far each flank reaches (CongruentPasses) and
 * whether the tool fits; the step-over rule (tool/stepOverRule.ts) and the forward and inverse
 * solutions of exact.ts do the rest. Lengths mm.
 */
import type { SurfaceDescriptorBase } from '../domain/surface';
import type { PassPattern, ToolInput } from '../domain/tool';
import { stepOverFromReaches } from '../tool/stepOverRule';
import { congruentForward, congruentIntervalMm, congruentInverse } from './exact';
import type { CongruentPasses, SurfaceFit, SurfaceModel } from './surface';

/** What a surface with congruent passes supplies. */
export interface CongruentSurface<S extends SurfaceDescriptorBase> {
  readonly kind: S['kind'];
  /** Its passes prepared for one tool and posture. */
  passes(tool: ToolInput, surface: S): CongruentPasses;
  /** Gouging (surface.ts's SurfaceFit). */
  fit(tool: ToolInput, surface: S): SurfaceFit;
}

/**
 * The widest step-over (mm) that still leaves a scallop with these passes: the flanks' reaches at the
 * height limit, combined by the pattern's step-over rule.
 */
export function congruentMaxIntervalMm(c: CongruentPasses, pattern: PassPattern): number {
  const h = c.limits().limitMm;
  const right = c.reach('right', h);
  const left = c.reach('left', h);
  return c.intervalFromReach(stepOverFromReaches(pattern, right, left));
}

/**
 * The surface model of a surface whose passes are congruent: every answer from its prepared passes
 * (exact.ts's congruentForward, congruentInverse). No flat face lies on such a surface's scallops
 * here (`leavesNoScallop` false): a model that has one says so itself.
 */
export function congruentSurfaceModel<S extends SurfaceDescriptorBase>(surface: CongruentSurface<S>): SurfaceModel<S> {
  return {
    kind: surface.kind,
    intervalMm: (input) => congruentIntervalMm(input, surface.passes(input, input.surface)),
    forward: (input) => congruentForward(input, surface.passes(input, input.surface)),
    inverse: (input) => congruentInverse(input, surface.passes(input, input.surface)),
    limits: (tool, s) => surface.passes(tool, s).limits(),
    maxIntervalMm: (tool, pattern, s) => congruentMaxIntervalMm(surface.passes(tool, s), pattern),
    flankWidths: (tool, s) => {
      const c = surface.passes(tool, s);
      return (flank, h) => c.intervalFromReach(c.reach(flank, h));
    },
    fit: (tool, s) => surface.fit(tool, s),
    leavesNoScallop: () => false,
  };
}
