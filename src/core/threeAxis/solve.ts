/**
 * The one entry that solves a validated three-axis problem (validate.ts's validateThreeAxis): a
 * sloped plane (slopedPlane.ts) or a surface of revolution (waterlineRevolution.ts), forward or
 * inverse. Apart from the validation, so that a caller that only validates (the page, before it
 * asks its worker) loads no solver.
 */
import type { ThreeAxisError } from './errors';
import { slopedPlaneForward, slopedPlaneInverse } from './slopedPlane';
import type { ThreeAxisAnswer, ThreeAxisInputError, ThreeAxisProblem } from './validate';
import { waterlineForward, waterlineInverse } from './waterlineRevolution';

/** The solvers' errors as input errors (same fields, codes and messages). */
export function fromSolver(errors: readonly ThreeAxisError[]): ThreeAxisInputError[] {
  return errors.map((e) => ({ field: e.field, code: e.code, got: e.got, limit: e.limit, message: e.message }));
}

/**
 * Solves a validated three-axis problem: forward (h to L, Lxy, dz) or inverse (a step to the cusp
 * height it leaves), with the equivalent lead and tilt. Errors are the solvers' (ranges, the
 * vertical wall, the shank and flank limits with the height, the surface's end, gouging).
 */
export function solveThreeAxis(
  p: ThreeAxisProblem,
): { ok: true; value: ThreeAxisAnswer } | { ok: false; errors: readonly ThreeAxisInputError[] } {
  if (p.surface === 'plane') {
    const r =
      p.quantity === 'h'
        ? slopedPlaneForward(p.case, p.mm)
        : slopedPlaneInverse(p.case, { field: p.quantity, mm: p.mm });
    if (!r.ok) return { ok: false, errors: fromSolver(r.errors) };
    const a = r.value;
    return {
      ok: true,
      value: {
        passes: p.case.passes,
        intervalMm: a.intervalMm,
        horizontalStepMm: a.horizontalStepMm,
        stepDownMm: a.stepDownMm,
        cuspHeightMm: a.cuspHeightMm,
        leadDeg: a.leadDeg,
        tiltDeg: a.tiltDeg,
        noScallop: a.noScallop,
      },
    };
  }
  if (p.quantity === 'horizontalStep') throw new Error('validateThreeAxis refuses a horizontal step with waterline');
  const r =
    p.quantity === 'h' ? waterlineForward(p.case, p.mm) : waterlineInverse(p.case, { field: p.quantity, mm: p.mm });
  if (!r.ok) return { ok: false, errors: fromSolver(r.errors) };
  const a = r.value;
  return {
    ok: true,
    value: {
      passes: 'waterline',
      intervalMm: a.intervalMm,
      horizontalStepMm: a.radialStepMm,
      stepDownMm: a.stepDownMm,
      cuspHeightMm: a.cuspHeightMm,
      leadDeg: a.leadDeg,
      tiltDeg: a.tiltDeg,
      noScallop: false,
    },
  };
}
