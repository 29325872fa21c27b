/**
 * The inverse of the areal roughness (issue 29, shared/notes/surface-finish.md): for a target `Sa`
 * on a plane, the pairs (step-over `L`, feed per tooth `fz`) whose surface has that `Sa`, and the
 * pair among them with the largest `L * fz` (the area machined per tooth, so the fastest finish at
 * a given spindle speed). Lengths mm.
 *
 * Along the curve. As `fz -> 0` the teeth's surface tends to the continuous one, so `Sa -> Ra` of
 * the cross-feed profile: the curve meets `fz = 0` at `L0`, the step-over whose passes leave
 * `Ra = Sa` (roughness.ts's target-Ra solve). For `L` in (0, L0) the pair's `fz` is a root of
 * `Sa(L, fz) = target`, bracketed by steps from a start (the ball-end rule, then the neighbouring
 * pair's feed: the curve is followed) and closed by the shared bracketed root finder on `fz^2` (in
 * which Sa is close to linear at small feeds); where even the largest feed accepted (R) leaves less,
 * `fz = R` and the pair is marked `feedLimited`. Sa need not be monotone in fz: with zigzag passes
 * and a tilt the teeth of neighbouring passes interfere (R 6, Rcr 2, lead 15, tilt 10, L 0.59 mm: Sa
 * rises 14 % from fz 0.350 to 0.362 mm, then falls 3 % by 0.365), so there the curve can step
 * between roots and the best pair is the best of the roots followed, not a proven global maximum.
 * `L * fz` vanishes at both ends (fz bounded as L -> 0; fz -> 0 as L -> L0), so it has an interior
 * maximum, searched over (L0 / 4, L0) (see SCAN_FROM) by the shared maximiser (a scan, then Brent)
 * on a quick Sa (areal.ts's integrals without grading or halving: about 1e-3 relative, 5e-3 at
 * worst measured); the best pair's `fz` is then solved again on the full Sa (1e-6 relative), so its
 * Sa is the target within 1e-6 relative (checked in the tests with the full areal parameters).
 * Runout is not taken here: its Sa costs seconds a point (the caller refuses it, with
 * {@link TARGET_SA_RUNOUT}). The answer carries the scallop h across the feed at the best pair's
 * step-over (the continuous answer on the pass's surface), which the command line and the page show.
 */
import type { PassInput } from '../domain/pass';
import type { PassPattern, ToolInput } from '../domain/tool';
import { AREAL_BUDGET, arealSa } from '../finish/areal';
import { balancedFeed } from '../finish/feedMarks';
import type { FinishInput } from '../finish/finishInput';
import { maxFeedPerToothMm } from '../finish/finishInput';
import { toothModel } from '../finish/toothModel';
import { forwardInput, inverseInput } from '../input/validate';
import { bracketedRoot, maximise, newSearchEnd } from '../math/rootFinder';
import { exactForward, exactInverse } from '../surfaces/solve';
import { forwardOfRaTarget } from './raTarget';
import { exactRoughnessAtInterval } from './roughness';

/** One pair of the curve: step-over, feed per tooth and the Sa they leave (mm). */
export interface SaPair {
  readonly intervalMm: number;
  readonly feedPerToothMm: number;
  readonly saMm: number;
  /** True where the largest feed accepted (R) still leaves less than the target: fz is R. */
  readonly feedLimited: boolean;
}

/** The answer of a target Sa: the best pair, the curve of pairs (L ascending) and its end at fz = 0. */
export interface TargetSaAnswer {
  readonly targetSaMm: number;
  /** The pair with the largest L * fz; its Sa is the target within 1e-6 relative (or below, feedLimited). */
  readonly best: SaPair;
  /** The scallop h across the feed at the best pair's step-over (mm). */
  readonly bestScallopHeightMm: number;
  /** Pairs across (L0 / 4, L0), L ascending, from the quick Sa (within about 1e-3 of the target). */
  readonly curve: readonly SaPair[];
  /** L0: the step-over whose passes leave Ra = the target, where the curve meets fz = 0 (mm). */
  readonly zeroFeedIntervalMm: number;
}

/**
 * The most smooth line pieces a search integrates (areal.ts's count: deterministic, unlike time).
 * The paper's tools at a lead take 30,000 to 60,000 (a few seconds); a zigzag with tilt 30 about
 * 110,000, a bull-nose R 6 zigzag at 3 teeth 240,000 (refused); a target near the largest Ra, whose pairs
 * feed several mm a tooth, many more. About 0.1 to 0.5 ms a piece on this machine.
 */
export const TARGET_SA_WORK = 200_000;

/** Root steps of a quick feed (Sa bumpy in fz can make the secant creep) and of the best pair's. */
const QUICK_STEPS = 10;
const FINE_STEPS = 40;
/** The most Sa evaluations of one search: the paper's tools take 80 to 130. */
const MAX_EVALUATIONS = 220;

/**
 * Thrown when a target-Sa search exceeds {@link TARGET_SA_WORK} pieces or {@link MAX_EVALUATIONS}
 * evaluations (both deterministic): its message is one line for the user.
 */
export class TargetSaTooLongError extends Error {
  constructor() {
    super(
      'The search for this target Sa stopped before its end (it would take minutes): its pairs feed too far or the passes are too many; ask the finish of a step-over and feed instead.',
    );
    this.name = 'TargetSaTooLongError';
  }
}

/**
 * The one line that refuses runout with a target Sa (the command line's --runout, the page's runout
 * field): the inverse is computed with the teeth cutting equally.
 */
export const TARGET_SA_RUNOUT =
  'Target Sa is computed without runout: set the runout e to 0 (or leave it out) for the best pair; with runout the Sa of one pair takes seconds, and the search needs about a hundred.';

/** The teeth of the inverse: everything of a finish but its feed (no runout). */
export type TeethInput = Omit<FinishInput, 'feedPerToothMm'>;

/** Points of the scan of L * fz over (L0 / 4, L0), and so of the curve. */
const CURVE_POINTS = 10;
/**
 * Where the scan starts, in L0. The best pair lies near 0.7 to 0.85 L0 (where the cross-feed Ra and
 * the feed marks share the target: measured on the paper's tools, and so in the models Sa ~ Ra + Sf
 * or Sa^2 ~ Ra^2 + Sf^2, with Ra ~ L^2 and Sf ~ fz^2, at L0 / sqrt 2 and L0 / 2^(1/4)); below L0 / 4
 * the product is small (fz stays bounded as L -> 0) while each Sa costs in proportion to the
 * passes that reach a line (the tool's width over L), and Sa(fz) turns non-monotone at feeds of
 * several times the step-over.
 */
const SCAN_FROM = 0.25;
/** Relative tolerance, in L0, of the best pair's step-over (L * fz is flat there: its square matters). */
const BEST_L_TOL = 1e-2;
/** Relative bracket on fz^2 of the quick curve's roots. */
const QUICK_TOL = 1e-3;
/** Relative bracket on fz^2 of the best pair's root (Sa within about 1e-9 relative of the target). */
const FINE_TOL = 1e-9;

/** The bracketing step of the best pair's fine solve, from the quick feed (Sa within about 1e-3). */
const FINE_GROWTH = 1.004;

/** The finish input of a pair (mm). */
function finishOf(teeth: TeethInput, feedPerToothMm: number): FinishInput {
  return { ...teeth, feedPerToothMm };
}

/**
 * A feed per tooth at which `sa(fz)` is `target` (`saZero`: its limit at 0, below the target), within
 * `relTol` on fz^2: bracketed by steps from `guess` (down while past the target, up while short; the
 * step `growth` squared at each), then closed by the shared bracketed root finder.
 */
function feedForSa(
  sa: (fz: number) => number,
  saZero: number,
  target: number,
  maxFz: number,
  guess: number,
  relTol: number,
  growth: number,
  maxSteps: number,
): { readonly fz: number; readonly feedLimited: boolean } {
  let lo = 0;
  let fLo = saZero - target;
  let fz = Math.min(guess, maxFz);
  let f = sa(fz) - target;
  // Down while the guess is past the target (keeping it as the upper end), up by doubling while short.
  let step = growth;
  while (f > 0 && fz > 1e-6 * maxFz) {
    const below = fz / step;
    step *= step;
    const fb = sa(below) - target;
    if (fb > 0) {
      fz = below;
      f = fb;
    } else {
      lo = below;
      fLo = fb;
      break;
    }
  }
  while (f < 0) {
    if (fz >= maxFz) return { fz: maxFz, feedLimited: true };
    lo = fz;
    fLo = f;
    fz = Math.min(step * fz, maxFz);
    step *= step;
    f = sa(fz) - target;
  }
  const u = bracketedRoot({ value: (v) => sa(Math.sqrt(v)) - target }, lo * lo, fz * fz, fLo, f, relTol, maxSteps);
  return { fz: Math.sqrt(u), feedLimited: false };
}

/**
 * The pairs (L, fz) of a tool on a plane that leave the target Sa, and the one with the largest
 * L * fz (see the module comment).
 * @param pass a validated tool, posture and pattern on a plane.
 * @param teeth flutes and phases, runout 0.
 * @param targetSaMm the target Sa, mm, > 0 and below the largest Ra the passes can leave.
 * @param zeroFeedIntervalMm L0 (mm): the step-over of the target-Ra solve at Ra = targetSaMm.
 * @param raAt the continuous cross-feed profile's Ra at a step-over (mm): Sa at fz -> 0.
 * @param scallopAt the continuous answer's scallop h at a step-over (mm), for the best pair.
 */
export function targetSaCurve(
  pass: PassInput,
  teeth: TeethInput,
  targetSaMm: number,
  zeroFeedIntervalMm: number,
  raAt: (intervalMm: number) => number,
  scallopAt: (intervalMm: number) => number,
): TargetSaAnswer {
  if (teeth.runoutMm > 0) throw new Error('targetSaPairs: runout is not taken (see the module comment)');
  const tool: ToolInput = pass;
  const pattern: PassPattern = pass.pattern;
  const L0 = zeroFeedIntervalMm;
  const maxFz = maxFeedPerToothMm(pass.toolRadiusMm);
  let work = 0;
  let evaluations = 0;
  const saOf = (L: number, fz: number, quick: boolean) => {
    if (++evaluations > MAX_EVALUATIONS) throw new TargetSaTooLongError();
    const m = toothModel({ tool, pattern, intervalMm: L, finish: finishOf(teeth, fz) });
    try {
      const r = arealSa(m, quick, TARGET_SA_WORK - work);
      work += r.pieces;
      return r.saMm;
    } catch (e) {
      if (e instanceof Error && e.message === AREAL_BUDGET) throw new TargetSaTooLongError();
      throw e;
    }
  };
  // The shop's ball-end rule Ra ~ fz^2 / (32 R) turned round: a start for the doubling.
  let guess = Math.min(maxFz, Math.sqrt(32 * pass.toolRadiusMm * targetSaMm));
  const solved = new Map<number, SaPair>();
  const pairAt = (L: number): SaPair => {
    const known = solved.get(L);
    if (known !== undefined) return known;
    // From a neighbour's feed (the curve is smooth) in small steps; from the rule's guess in doublings.
    const growth = solved.size > 0 ? 1.25 : 2;
    const r = feedForSa((fz) => saOf(L, fz, true), raAt(L), targetSaMm, maxFz, guess, QUICK_TOL, growth, QUICK_STEPS);
    guess = Math.max(r.fz, 1e-6 * maxFz);
    const pair = { intervalMm: L, feedPerToothMm: r.fz, saMm: targetSaMm, feedLimited: r.feedLimited };
    solved.set(L, pair);
    return pair;
  };
  const end = newSearchEnd();
  maximise(
    {
      value: (L) => {
        if (!(L > SCAN_FROM * L0 && L < L0)) return 0;
        const p = pairAt(L);
        return p.intervalMm * p.feedPerToothMm;
      },
    },
    SCAN_FROM * L0,
    L0,
    CURVE_POINTS,
    BEST_L_TOL * L0,
    end,
  );
  const bestL = end.x;
  const curve = [...solved.values()].sort((a, b) => a.intervalMm - b.intervalMm);
  const quick = solved.get(bestL);
  // The best pair's feed on the full Sa, started from the quick one.
  const fine = feedForSa(
    (fz) => saOf(bestL, fz, false),
    raAt(bestL),
    targetSaMm,
    maxFz,
    quick?.feedPerToothMm ?? guess,
    FINE_TOL,
    FINE_GROWTH,
    FINE_STEPS,
  );
  const best: SaPair = {
    intervalMm: bestL,
    feedPerToothMm: fine.fz,
    saMm: saOf(bestL, fine.fz, false),
    feedLimited: fine.feedLimited,
  };
  return { targetSaMm, best, bestScallopHeightMm: scallopAt(bestL), curve, zeroFeedIntervalMm: L0 };
}

/**
 * The target-Sa inverse of a validated tool, posture and pattern on a plane (see the module
 * comment): `targetSaMm` > 0 and below the largest Ra the passes can leave (validateTargetRa's
 * bound, as Sa -> Ra at fz -> 0), teeth without runout. Lengths mm.
 */
export function targetSaPairs(pass: PassInput, teeth: TeethInput, targetSaMm: number): TargetSaAnswer {
  const L0 = exactForward(forwardOfRaTarget({ ...pass, targetRaMm: targetSaMm })).intervalMm;
  const inverseAt = (L: number) => exactInverse(inverseInput(pass, pass.pattern, L, pass.surface));
  const raAt = (L: number) => exactRoughnessAtInterval(pass, pass.pattern, inverseAt(L), pass.surface).raMm;
  return targetSaCurve(pass, teeth, targetSaMm, L0, raAt, (L) => inverseAt(L).cuspHeightMm);
}

// The validation (no solver: the page's first script takes it) lives in targetSaInput.ts.
export { type RawTargetSaInput, type TargetSaInput, validateTargetSa } from './targetSaInput';

/** The pair for a target Rz: across the feed the scallop h, along it the feed marks hf, both at most Rz. */
export interface TargetRzAnswer {
  readonly targetRzMm: number;
  /** The step-over whose scallop h is the target (mm). */
  readonly intervalMm: number;
  /** The balanced feed at that step-over (hf = h = the target), or R where the marks stay lower (mm). */
  readonly feedPerToothMm: number;
  /** True where even fz = R leaves marks below the target (a ball end at lead 0 drags its tip). */
  readonly feedLimited: boolean;
}

/**
 * The pair (L, fz) with the largest L * fz whose profile across the feed (the scallop h) and along
 * the CC path (the feed marks hf) both have Rz at most `targetRzMm`: h <= Rz holds up to the
 * forward step-over L(h = Rz), and hf does not depend on L while the neighbouring passes stay above
 * the CC path, so the best pair is that step-over with its balanced feed (hf = h = Rz, feedMarks.ts),
 * or fz = R where the marks never reach it. Requires a valid pass and Rz below its scallop limit.
 */
export function targetRzPair(pass: PassInput, teeth: TeethInput, targetRzMm: number): TargetRzAnswer {
  const L = exactForward(forwardInput(pass, pass.pattern, targetRzMm, pass.surface)).intervalMm;
  const b = balancedFeed(pass, pass.pattern, L, finishOf(teeth, maxFeedPerToothMm(pass.toolRadiusMm)));
  return b.ok
    ? { targetRzMm, intervalMm: L, feedPerToothMm: b.feedPerToothMm, feedLimited: false }
    : { targetRzMm, intervalMm: L, feedPerToothMm: maxFeedPerToothMm(pass.toolRadiusMm), feedLimited: true };
}
