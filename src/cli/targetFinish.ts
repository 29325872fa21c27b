/**
 * The finish asked backwards on the command line (issue 29): `--target-sa VALUE` answers the pair
 * (step-over L, feed per tooth fz) whose areal Sa is the target with the largest L * fz, and the
 * curve of pairs; `--target-rz VALUE` the pair whose scallop h (across the feed) and feed marks hf
 * (along it) are both at most the target. A tool on a plane (five-axis lead and tilt), with
 * `--flutes` (fz is the answer); lengths in the unit, as `--ra`.
 */
import type { PassInput } from '../core/domain/pass';
import { feedMarks } from '../core/finish/feedMarks';
import type { FinishError } from '../core/finish/finishInput';
import { maxFeedPerToothMm, validateFinish } from '../core/finish/finishInput';
import { toothModel } from '../core/finish/toothModel';
import type { AnyInputError } from '../core/input/inputErrors';
import { fromMm, type LengthUnit } from '../core/input/units';
import {
  type SaPair,
  TARGET_SA_RUNOUT,
  TargetSaTooLongError,
  type TeethInput,
  targetRzPair,
  targetSaPairs,
  validateTargetSa,
} from '../core/roughness/targetSa';
import { validateForward } from '../core/surfaces/validate';
import type { ValueOption } from './args';
import { rawPass } from './question';
import type { JsonValue } from './reportJson';
import { type Lengths, length, lengthsIn } from './table';

type Values = Readonly<Partial<Record<ValueOption, string>>>;

/** What a target asks: Sa (areal) or Rz (across and along). */
export type FinishTarget = 'sa' | 'rz';

/** A target answered: its table and JSON, or the input errors (core errors, or the teeth's). */
export type TargetRun =
  | { readonly ok: true; readonly table: string; readonly json: { [key: string]: JsonValue } }
  | {
      readonly ok: false;
      readonly inputErrors: readonly AnyInputError[];
      readonly finishErrors: readonly FinishError[];
    };

/** The teeth of the options (fz checked at R, then dropped: it is the answer). */
function teethOf(
  values: Values,
  toolRadiusMm: number,
): { readonly ok: true; readonly teeth: TeethInput } | { readonly ok: false; readonly errors: FinishError[] } {
  const v = validateFinish(
    {
      flutes: values.flutes,
      fz: String(maxFeedPerToothMm(toolRadiusMm)),
      runout: values.runout,
      runoutPhase: values['runout-phase'],
      passPhase: values['pass-phase'],
    },
    toolRadiusMm,
  );
  if (!v.ok) return { ok: false, errors: [...v.errors] };
  const { feedPerToothMm: _answer, ...teeth } = v.value;
  return { ok: true, teeth };
}

/** A length in the unit with its symbol. */
function withUnit(L: Lengths, mm: number): string {
  return `${L.length(mm)} ${L.u}`;
}

/** The feed marks hf of a pair along the CC path (mm). */
function pairFeedMarkMm(pass: PassInput, teeth: TeethInput, L: number, fz: number): number {
  return feedMarks(
    toothModel({ tool: pass, pattern: pass.pattern, intervalMm: L, finish: { ...teeth, feedPerToothMm: fz } }),
  ).heightMm;
}

/**
 * Answers `--target-sa` or `--target-rz` from the options in mm (`values`, as valuesInMm gives
 * them); args.ts has refused every option that does not go with a target.
 */
export function targetFinish(values: Values, target: FinishTarget, unit: LengthUnit): TargetRun {
  const L = lengthsIn(unit);
  const value = values[target === 'sa' ? 'target-sa' : 'target-rz'];
  let pass: PassInput;
  let targetMm: number;
  if (target === 'sa') {
    const v = validateTargetSa(rawPass(values, 'sa', value));
    if (!v.ok) return { ok: false, inputErrors: v.errors, finishErrors: [] };
    pass = v.value;
    targetMm = v.value.targetSaMm;
  } else {
    const v = validateForward(rawPass(values, 'h', value));
    if (!v.ok)
      return {
        ok: false,
        inputErrors: v.errors.map((e) => (e.field === 'h' ? { ...e, field: 'targetRz' } : e)),
        finishErrors: [],
      };
    pass = v.value;
    targetMm = v.value.scallopHeightMm;
  }
  const t = teethOf(values, pass.toolRadiusMm);
  if (!t.ok) return { ok: false, inputErrors: [], finishErrors: t.errors };
  const teeth = t.teeth;
  if (target === 'sa' && teeth.runoutMm > 0)
    return {
      ok: false,
      inputErrors: [],
      finishErrors: [{ field: 'runout', code: 'not-computed-here', got: '', message: TARGET_SA_RUNOUT }],
    };
  // An area in the unit squared (each side converted).
  const area = (a: number, b: number) => `${length(fromMm(a, unit) * fromMm(b, unit))} ${L.u}^2`;
  if (target === 'rz') {
    const r = targetRzPair(pass, teeth, targetMm);
    const hf = pairFeedMarkMm(pass, teeth, r.intervalMm, r.feedPerToothMm);
    const table = [
      `Target Rz ${withUnit(L, targetMm)} across the feed (scallop h) and along it (feed marks hf):`,
      `  step-over L      ${withUnit(L, r.intervalMm)}   (h = the target)`,
      `  feed per tooth   ${withUnit(L, r.feedPerToothMm)}   ${r.feedLimited ? '(the largest accepted, R: the marks stay below the target at every feed)' : '(the balanced feed: hf = h)'}`,
      `  L x fz           ${area(r.intervalMm, r.feedPerToothMm)}   area machined per tooth, the largest with both Rz at most the target`,
      `  hf               ${withUnit(L, hf)}`,
    ].join('\n');
    return {
      ok: true,
      table,
      json: {
        targetRz: {
          Rz: targetMm,
          interval: r.intervalMm,
          feedPerTooth: r.feedPerToothMm,
          feedLimited: r.feedLimited,
          feedMarkHeight: hf,
        },
      },
    };
  }
  let a: ReturnType<typeof targetSaPairs>;
  try {
    a = targetSaPairs(pass, teeth, targetMm);
  } catch (e) {
    if (!(e instanceof TargetSaTooLongError)) throw e;
    return {
      ok: false,
      inputErrors: [],
      finishErrors: [{ field: 'flutes', code: 'not-computed-here', got: '', message: e.message }],
    };
  }
  const b = a.best;
  const h = a.bestScallopHeightMm;
  const hf = pairFeedMarkMm(pass, teeth, b.intervalMm, b.feedPerToothMm);
  const table = [
    `Target Sa ${withUnit(L, targetMm)}: the pair with the largest L x fz (area machined per tooth)`,
    `  step-over L      ${withUnit(L, b.intervalMm)}`,
    `  feed per tooth   ${withUnit(L, b.feedPerToothMm)}${b.feedLimited ? '   (the largest accepted, R: Sa stays below the target)' : ''}`,
    `  L x fz           ${area(b.intervalMm, b.feedPerToothMm)}`,
    `  Sa               ${withUnit(L, b.saMm)}   ${b.feedLimited ? '(below the target: the largest feed accepted leaves less)' : '(the target within 1e-6 relative)'}`,
    `  h                ${withUnit(L, h)}   scallop across the feed at L`,
    `  hf               ${withUnit(L, hf)}   feed marks along the CC path at fz`,
    `  L0               ${withUnit(L, a.zeroFeedIntervalMm)}   where the curve meets fz = 0 (the step-over for Ra = the target)`,
    '',
    `Pairs that leave Sa = the target (within about 1e-3), L ascending (${L.u}):`,
    '  L            fz           L x fz',
    ...a.curve.map(
      (p: SaPair) =>
        `  ${L.length(p.intervalMm).padEnd(12)} ${L.length(p.feedPerToothMm).padEnd(12)} ${length(fromMm(p.intervalMm, unit) * fromMm(p.feedPerToothMm, unit))}${p.feedLimited ? '  (fz = R)' : ''}`,
    ),
  ].join('\n');
  const pair = (p: { intervalMm: number; feedPerToothMm: number; feedLimited: boolean }) => ({
    interval: p.intervalMm,
    feedPerTooth: p.feedPerToothMm,
    feedLimited: p.feedLimited,
  });
  return {
    ok: true,
    table,
    json: {
      targetSa: {
        Sa: targetMm,
        best: { ...pair(b), Sa: b.saMm, scallopHeight: h, feedMarkHeight: hf },
        zeroFeedInterval: a.zeroFeedIntervalMm,
        curve: a.curve.map(pair),
      },
    },
  };
}
