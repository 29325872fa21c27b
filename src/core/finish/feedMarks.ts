/**
 * The feed marks along the CC path (shared/notes/surface-finish.md, "What is reported"): their height
 * `hf` (highest minus lowest height of the surface left along y = y_cc over one period) and period,
 * and the balanced feed `fz*` at which `hf` equals the scallop `h` of the step-over. Lengths mm.
 *
 * Without runout the lowest height along the line is the continuous contact (z = 0 on the CC path):
 * as x runs over a period the tooth events sweep the section curve, and at the valleys one sits at its
 * lowest point (rowEnvelope.ts). The highest is the crest between two valleys, where the first events
 * on either side of the contact are equally high: the maximum over one period from the valley, by the
 * shared maximiser (a scan, then Brent's method, whose golden steps handle the crest's kink).
 * With runout (runout.ts, runoutLine.ts) the period is a turn, z fz; the lowest height along the line is
 * the least of the teeth's lowest points on it (each tooth cuts every point of its section once a
 * turn), and the highest is found at the line's breaks (the crests between bites).
 */
import type { PassPattern, ToolInput } from '../domain/tool';
import { inverseInput } from '../input/validate';
import { bracketedRoot, maximise, newSearchEnd, type Objective } from '../math/rootFinder';
import { planeInverse } from '../surfaces/exact';
import { crestFeedMm } from './crestFeed';
import type { FinishInput } from './finishInput';
import { maxFeedPerToothMm } from './finishInput';
import { RowEnvelope } from './rowEnvelope';
import { RunoutRow } from './runout';
import { runoutLineBreaks, runoutLineMax } from './runoutLine';
import { type ToothModel, toothModel } from './toothModel';

/** The feed marks along the CC path. */
export interface FeedMarks {
  /** Highest minus lowest height along the CC path over one period, mm (>= 0). */
  readonly heightMm: number;
  /** The period along the feed: fz, or z fz with runout, mm. */
  readonly periodMm: number;
  /** Lowest and highest height along the CC path, mm above the design plane. */
  readonly lowMm: number;
  readonly highMm: number;
  /** Global x of the highest point (a crest) in [valley, valley + period). */
  readonly crestXMm: number;
}

/** The extremes of the surface along a line y = const over one feed period (mm). */
export function lineExtremes(m: ToothModel, row: RowEnvelope): { low: number; high: number; highX: number } {
  const P = m.feedPeriodMm;
  if (row.passes.length === 0) return { low: Number.POSITIVE_INFINITY, high: Number.POSITIVE_INFINITY, highX: 0 };
  const x0 = row.valleyXMm(0);
  const low = Math.min(row.floorMm, row.heightAt(x0));
  // One pass alone shapes the line (the others stay above its peak): its peak is the highest point
  // (its crest, or a plateau near the tip: RowEnvelope.peakXMm).
  const active = row.activePasses();
  if (active.length === 1) {
    const x = row.peakXMm(active[0] as number);
    return { low, high: row.heightAt(x), highX: x };
  }
  const f: Objective = { value: (x) => row.heightAt(x) };
  const end = newSearchEnd();
  const high = maximise(f, x0, x0 + P, 48, 1e-13 * P + 1e-15, end);
  return { low, high, highX: end.x };
}

/**
 * The feed marks of a prepared model along pass 0's CC path (y = 0).
 * @param runoutLowMm with runout, the line's lowest height when known ({@link runoutLineLowMm}).
 */
export function feedMarks(m: ToothModel, runoutLowMm?: number): FeedMarks {
  if (m.input.finish.runoutMm > 0) {
    // With runout (runoutLine.ts): the least of the teeth's lowest points on the line, the highest at
    // its breaks over one turn.
    const row = new RunoutRow(m, 0);
    const low = runoutLowMm ?? row.lowestMm();
    const { high, x } = runoutLineMax(m, row, runoutLineBreaks(m, row, 0));
    return { heightMm: Math.max(0, high - low), periodMm: m.feedPeriodMm, lowMm: low, highMm: high, crestXMm: x };
  }
  return rowMarks(m, new RowEnvelope(m, 0));
}

/**
 * With runout, the lowest height along pass 0's CC path (mm): the least of the teeth's lowest points
 * on the line, which fz does not move (the curves the teeth sweep over a line do not depend on it).
 */
export function runoutLineLowMm(m: ToothModel): number {
  return new RunoutRow(m, 0).lowestMm();
}

/** The feed marks of a model without runout along a prepared line (pass 0's CC path, y = 0). */
export function rowMarks(m: ToothModel, row: RowEnvelope): FeedMarks {
  const { low, high, highX } = lineExtremes(m, row);
  return { heightMm: Math.max(0, high - low), periodMm: m.feedPeriodMm, lowMm: low, highMm: high, crestXMm: highX };
}

/** The balanced feed: fz* or why there is none. */
export type BalancedFeed =
  | { readonly ok: true; readonly feedPerToothMm: number; readonly scallopHeightMm: number }
  | { readonly ok: false; readonly reason: 'no-scallop' | 'marks-below-scallop'; readonly scallopHeightMm: number };

/**
 * A lower bound of hf (mm) along a prepared line without runout (y = 0), cheaper than
 * {@link rowMarks} where several passes shape the line (no search for its highest point): the
 * line's height at its lowest pass's crest (any point's height is at most the highest) minus its
 * lowest. Where one pass shapes the line it is hf itself. 0 where no pass reaches the line.
 */
export function feedMarkLowerBoundMm(row: RowEnvelope): number {
  const active = row.activePasses();
  if (active.length === 0) return 0;
  const low = Math.min(row.floorMm, row.heightAt(row.valleyXMm(0)));
  return Math.max(0, row.heightAt(row.crestXMm(active[0] as number)) - low);
}

/**
 * How close hf must come to h for fz to count as fz* (mm): 1e-11 of h, at most 1e-12 mm. The notes
 * ask hf within 1e-9 mm (the tests hold hf to 1e-12 mm of closed forms); closer than this
 * the root finder only walks the last bits of fz (fz* moves by at most 5e-12 of itself: dfz / fz =
 * dhf / (2 hf) as hf grows like fz^2).
 */
export function balancedFeedToleranceMm(scallopHeightMm: number): number {
  return Math.min(1e-12, 1e-11 * scallopHeightMm);
}

/**
 * The feed per tooth fz* (mm) at which the feed marks along the CC path are as tall as the scallop
 * of the step-over `intervalMm` (planeInverse's cusp height h): the root of `sqrt(hf(fz)) - sqrt(h)`
 * (nearly linear in fz, as hf grows like fz^2) by the shared bracketed root finder, from the ball's
 * shop estimate `sqrt(8 R h)`, to hf within {@link balancedFeedToleranceMm} of h (there the function
 * the finder sees is 0). No answer when the step-over leaves no scallop, or when the marks stay
 * below h for every fz up to its limit R (a ball end at lead 0 drags its tip along the CC path:
 * hf = 0 there at any feed).
 * Without runout the geometric scan's probes above the root read a lower bound of hf where it
 * already exceeds h ({@link feedMarkLowerBoundMm}: the sign is all the scan needs), and inside the
 * bracket the closed form of crestFeed.ts (one pass shaping the line) is tried first: taken where hf
 * there is within the tolerance of h, else it narrows the bracket.
 * With runout the definition is the same, hf(fz*) = h at the given e and phi_e (the marks over a turn,
 * z fz); as fz -> 0 the tooth that reaches lowest cuts alone and hf tends to 0 as (z fz)^2 / (8 r), so
 * fz* is at most about that of e = 0. hf(fz) need not be monotone then (teeth start and stop to cut
 * as fz grows): fz* is the root the same bracketing finds, the first sign change of hf - h in the
 * geometric scan from the ball's estimate.
 * @param finish the finish inputs; its fz is ignored.
 */
export function balancedFeed(
  tool: ToolInput,
  pattern: PassPattern,
  intervalMm: number,
  finish: FinishInput,
): BalancedFeed {
  const h = planeInverse(inverseInput(tool, pattern, intervalMm)).cuspHeightMm;
  if (!(h > 0)) return { ok: false, reason: 'no-scallop', scallopHeightMm: 0 };
  const root = Math.sqrt(h);
  const tolerance = balancedFeedToleranceMm(h);
  const model = (fz: number) => toothModel({ tool, pattern, intervalMm, finish: { ...finish, feedPerToothMm: fz } });
  const gOf = (hf: number) => (Math.abs(hf - h) <= tolerance ? 0 : Math.sqrt(hf) - root);
  const noRunout = !(finish.runoutMm > 0);
  // With runout the line's lowest height is the same at every fz: found once.
  let low: number | undefined;
  const g = (fz: number) => {
    const m = model(fz);
    if (!noRunout) low ??= runoutLineLowMm(m);
    return gOf(feedMarks(m, low).heightMm);
  };
  // A probe of the scan: its sign (a lower bound of hf above h is enough), and a value of that sign.
  const probe = (fz: number) => {
    if (!noRunout) return g(fz);
    const m = model(fz);
    const bound = feedMarkLowerBoundMm(new RowEnvelope(m, 0, false));
    return bound - h > tolerance ? Math.sqrt(bound) - root : gOf(rowMarks(m, new RowEnvelope(m, 0)).heightMm);
  };
  const fzMax = maxFeedPerToothMm(tool.toolRadiusMm);
  let lo = Math.min(fzMax, Math.sqrt(8 * tool.toolRadiusMm * h)) / 2;
  let gLo = g(lo);
  while (gLo > 0 && lo > 1e-6) {
    lo /= 4;
    gLo = g(lo);
  }
  let hi = Math.min(fzMax, lo * 4);
  let gHi = probe(hi);
  while (gHi < 0 && hi < fzMax) {
    lo = hi;
    gLo = gHi;
    hi = Math.min(fzMax, hi * 4);
    gHi = probe(hi);
  }
  if (gHi < 0) return { ok: false, reason: 'marks-below-scallop', scallopHeightMm: h };
  if (noRunout && gLo < 0 && gHi > 0) {
    const fz = crestFeedMm(model(lo), h);
    if (fz > lo && fz < hi) {
      const gFz = g(fz);
      if (gFz === 0) return { ok: true, feedPerToothMm: fz, scallopHeightMm: h };
      if (gFz < 0) {
        lo = fz;
        gLo = gFz;
      } else {
        hi = fz;
        gHi = gFz;
      }
    }
  }
  const fz = bracketedRoot({ value: g }, lo, hi, gLo, gHi, 1e-13);
  return { ok: true, feedPerToothMm: fz, scallopHeightMm: h };
}
