/**
 * --slope-sweep (issue 20): the options to a validated slope sweep (core/threeAxis/slopeSweep.ts),
 * or the input errors. The fields are parsed as --slope parses them (threeAxis/validate.ts, with
 * the swept slope held at a placeholder), their fixed ranges checked by the three-axis solver at a
 * slope where no h limit applies, and the sweep's own errors (core slopeSweep: h and the step at
 * least 1e-9 mm, h valid at some slope: gouging at every slope is the gouging error). Lengths mm,
 * angles degrees.
 */
import { FIELDS } from '../core/input/fields';
import { type SlopeSweep, type SlopeSweepInput, slopeSweep } from '../core/threeAxis/slopeSweep';
import { solveThreeAxis } from '../core/threeAxis/solve';
import { type ThreeAxisInputError, validateThreeAxis } from '../core/threeAxis/validate';
import type { ValueOption } from './args';

/** Slopes in a sweep on the command line: 0 to the largest valid, 31 of them (3 degrees apart up to 90). */
export const SLOPE_SWEEP_COUNT = 31;

type Values = Readonly<Partial<Record<ValueOption, string>>>;

/** Fields whose range does not depend on the slope (the others are the sweep's to judge). */
const FIXED_RANGE_FIELDS: readonly string[] = ['R', 'Rcr', 'rasterAngle', 'feedRadius', 'crossRadius'];

/**
 * The sweep the options ask for, with whether the constant step was typed; or the input errors.
 * @param values the options as typed (args.ts has refused the combinations that do not exist).
 */
export function sweepSlopes(
  values: Values,
):
  | { ok: true; input: SlopeSweepInput; sweep: SlopeSweep; typed: boolean }
  | { ok: false; errors: readonly ThreeAxisInputError[] } {
  const raw = Object.fromEntries(
    (['R', 'Rcr', 'passes', 'rasterAngle', 'feedRadius', 'crossRadius'] as const).map((id) => [
      id,
      values[FIELDS[id].cli],
    ]),
  );
  const stepField =
    values[FIELDS.horizontalStep.cli] !== undefined
      ? 'horizontalStep'
      : values[FIELDS.stepDown.cli] !== undefined
        ? 'stepDown'
        : null;
  // A placeholder slope: the sweep sets it; 45 degrees is valid for both strategies.
  const v = validateThreeAxis({ ...raw, slope: '45' }, 'h', values[FIELDS.h.cli]);
  const errors: ThreeAxisInputError[] = v.ok ? [] : [...v.errors];
  let stepMm: number | undefined;
  if (stepField !== null) {
    const s = validateThreeAxis({ ...raw, slope: '45' }, stepField, values[FIELDS[stepField].cli]);
    if (!s.ok) errors.push(...s.errors.filter((e) => e.field === stepField));
    else stepMm = s.value.mm;
  }
  if (!v.ok || errors.length > 0) return { ok: false, errors };
  const p = v.value;
  // Fixed ranges (R, Rcr, psi, the radii) from the solver; h and the slope are judged by the sweep.
  const fixed = solveThreeAxis(p);
  if (!fixed.ok) {
    const ranges = fixed.errors.filter((e) => FIXED_RANGE_FIELDS.includes(e.field) && e.code !== 'gouging');
    if (ranges.length > 0) return { ok: false, errors: ranges };
  }
  const h = p.mm;
  const input: SlopeSweepInput =
    p.surface === 'plane'
      ? {
          toolRadiusMm: p.case.toolRadiusMm,
          cornerRadiusMm: p.case.cornerRadiusMm,
          hMm: h,
          passes: p.case.passes,
          rasterAngleDeg: p.case.rasterAngleDeg,
          count: SLOPE_SWEEP_COUNT,
          ...(stepMm === undefined ? {} : { programmedStepMm: stepMm }),
        }
      : {
          toolRadiusMm: p.case.toolRadiusMm,
          cornerRadiusMm: p.case.cornerRadiusMm,
          hMm: h,
          passes: 'waterline',
          rasterAngleDeg: 90,
          feedRadiusMm: p.case.feedRadiusMm,
          crossRadiusMm: p.case.crossRadiusMm,
          count: SLOPE_SWEEP_COUNT,
          ...(stepMm === undefined ? {} : { programmedStepMm: stepMm }),
        };
  // The sweep's own errors: h and the step below 1e-9 mm, no slope where h is valid (gouging or h's limit).
  const sweep = slopeSweep(input);
  if (!sweep.ok) return { ok: false, errors: sweep.errors };
  return { ok: true, input, sweep: sweep.value, typed: stepMm !== undefined };
}
