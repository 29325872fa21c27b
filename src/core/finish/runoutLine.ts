/**
 * A line y = const of the surface the teeth leave with runout (runout.ts), cut into smooth pieces for
 * the areal integrals and searched for its extremes. Lengths mm.
 *
 * Along the line the height is, piece by piece, one tooth's one bite: the event found by the search
 * moves continuously over that tooth's edge as x moves (its (theta, s) by about as much as x, see
 * below), and the line has a kink or a step where the lowest event passes to another tooth or another
 * bite (another turn) of the same tooth: the crests between bites, and where a bite ends. The line is
 * sampled 16 times per tooth pitch; where two neighbouring samples are not the same bite (another
 * track, or the event moved on the edge by more than 4 times the step in x plus a tolerance), the
 * change is located where the two bites' heights cross, each bite followed across the bracket by
 * Newton from its sample (no search), and checked by the search either side; where that fails (a bite
 * that ends, a third between them) by bisection on the search to 1e-13 of the period, where a bracket
 * whose events draw together as it shrinks (to a quarter in 4 halvings) holds a fast continuous
 * motion, not a change. Within a bite the event's motion per unit x
 * is 1 / |dX/dl| with X = E_x - theta / omega the position along the line a point of the edge cuts
 * (l the arc length on the section in the metric (rho theta, s)); it is about 1 near the bites'
 * valleys, where the section runs along the feed. A change the sampling misses (a bite narrower than
 * a sample step) is a limit of this cut: the brute-force tests bound what it costs.
 * The lowest point of a line is the least of its teeth's lowest points (every point of a tooth's
 * section is cut once a turn); the highest is at a change (a crest), taken on both sides of it.
 */
import { bracketedRoot, maximise, newSearchEnd } from '../math/rootFinder';
import { NOT_CONVERGED } from './envelope';
import { gaussLegendre } from './gaussLegendre';
import { RunoutRow } from './runout';
import type { ToothModel } from './toothModel';

/** Most changes of bite located on one line (a few per tooth pitch are usual). */
const MAX_CUTS = 2000;
/** Pieces per tooth pitch the line starts from. */
const PIECES_PER_TOOTH = 4;
/** The rule the areal integrals use on each piece (areal.ts). */
const RULE = gaussLegendre(12);

/** The event of a sample: its track and place on the edge. */
interface Ident {
  readonly x: number;
  readonly h: number;
  readonly track: number;
  readonly theta: number;
  readonly s: number;
  /** The edge point's distance from the spindle axis. */
  readonly rho: number;
}

function identAt(row: RunoutRow, x: number): Ident {
  const h = row.heightAt(x);
  return { x, h, track: row.lastTrack, theta: row.lastTheta, s: row.lastS, rho: row.lastRho() };
}

/** How far apart two samples' events are on the edge (rho dtheta + ds, mm); Infinity across tracks. */
function eventDistance(a: Ident, b: Ident): number {
  if (a.track !== b.track) return Number.POSITIVE_INFINITY;
  if (a.track < 0) return 0;
  // The edge point's distance from the axis: near the axis theta turns fast for a short move.
  const rho = Math.max(a.rho, b.rho);
  let dt = Math.abs(a.theta - b.theta) % (2 * Math.PI);
  dt = Math.min(dt, 2 * Math.PI - dt);
  return dt * rho + Math.abs(a.s - b.s);
}

/** Whether two samples are the same bite of the same tooth (see the module comment). */
function sameBite(m: ToothModel, a: Ident, b: Ident): boolean {
  return eventDistance(a, b) <= 4 * Math.abs(a.x - b.x) + 1e-12 * m.toolRadiusMm;
}

/** The bite of `from` followed to x (RunoutRow.followBite), undefined where it cannot be. */
function followAt(row: RunoutRow, from: Ident, x: number): Ident | undefined {
  const h = row.followBite(from.track, x, from.theta, from.s);
  if (Number.isNaN(h)) return undefined;
  return { x, h, track: row.lastTrack, theta: row.lastTheta, s: row.lastS, rho: row.lastRho() };
}

/** locateChange's answer where the change between two samples lies at an end of the piece (none). */
const NO_CHANGE = Number.NEGATIVE_INFINITY;

/**
 * Where the lowest event passes from the bite of `lo` to the bite of `hi` (neighbouring samples of the
 * piece [a, b], not one bite) when both bites are smooth across the bracket: the root of their height
 * difference, each bite followed by Newton from its sample (no search), closed by the shared bracketed
 * root finder to adjacent doubles; then checked by the search on either side of it (each side the bite
 * followed, within 1e-11 of the period). NO_CHANGE where the root lies at an end of the piece (the break
 * already there); NaN where a bite cannot be followed across the bracket, the heights do not cross in
 * it, or the search disagrees: the caller then bisects on the search (a bite that ends, a change of
 * bite between them, a fast continuous motion).
 */
function locateChange(m: ToothModel, row: RunoutRow, lo: Ident, hi: Ident, a: number, b: number): number {
  if (lo.track < 0 || hi.track < 0) return Number.NaN;
  const P = m.feedPeriodMm;
  const endTol = 1e-13 * P;
  const lowAtHi = followAt(row, lo, hi.x);
  const highAtLo = followAt(row, hi, lo.x);
  if (lowAtHi === undefined || highAtLo === undefined) return Number.NaN;
  // One bite after all (a fast motion): the bisection's own test decides.
  if (lowAtHi.track === hi.track && eventDistance(lowAtHi, hi) <= 1e-12 * m.toolRadiusMm) return Number.NaN;
  const fLo = lo.h - highAtLo.h;
  const fHi = lowAtHi.h - hi.h;
  const noise = 1e-12 * m.toolRadiusMm;
  if (!(fLo < 0 && fHi > 0)) {
    // The two bites meet at an end of the piece, within the heights' rounding: the break already there.
    if (lo.x - a <= endTol && fLo >= 0 && fLo <= noise) return NO_CHANGE;
    if (b - hi.x <= endTol && fHi <= 0 && fHi >= -noise) return NO_CHANGE;
    return Number.NaN;
  }
  // Each bite followed from its latest event (the root finder closes in, so that is the nearest).
  let left = lo;
  let right = hi;
  let failed = false;
  const f = {
    value: (x: number) => {
      const l = followAt(row, left, x);
      const r = l === undefined ? undefined : followAt(row, right, x);
      if (l === undefined || r === undefined) {
        failed = true;
        return Number.NaN;
      }
      left = l;
      right = r;
      return l.h - r.h;
    },
  };
  const root = bracketedRoot(f, lo.x, hi.x, fLo, fHi, 0);
  if (failed) return Number.NaN;
  if (root - a <= endTol || b - root <= endTol) return NO_CHANGE;
  const l = followAt(row, left, root);
  const r = followAt(row, right, root);
  if (l === undefined || r === undefined) return Number.NaN;
  // The search on either side finds the bites followed.
  const d = 1e-11 * P;
  const sideTol = 4 * d + 1e-12 * m.toolRadiusMm;
  const x0 = Math.max(lo.x, root - d);
  const x1 = Math.min(hi.x, root + d);
  const sl = x0 === lo.x ? lo : identAt(row, x0);
  const sr = x1 === hi.x ? hi : identAt(row, x1);
  if (!(eventDistance(sl, l) <= sideTol + 4 * (root - x0) && eventDistance(sr, r) <= sideTol + 4 * (x1 - root)))
    return Number.NaN;
  return root;
}

/**
 * The breakpoints of a line over one feed period from x0 (x0 and x0 + P included), sorted: the period
 * cut into 4 pieces per tooth pitch, then every piece whose ends and 12-point Gauss-Legendre nodes
 * (those the areal integrals use) are not all one bite, cut where the first change between
 * neighbouring samples lies, until none is left: where the two bites can be followed across the
 * bracket, at the root of their difference (locateChange), else by bisection on the search to 1e-13 of
 * the period (`follow` false: bisection always, the way the tests check the roots against).
 */
export function runoutLineBreaks(m: ToothModel, row: RunoutRow, x0: number, follow = true): number[] {
  const P = m.feedPeriodMm;
  const n = PIECES_PER_TOOTH * m.input.finish.flutes;
  const done: number[] = [x0 + P];
  const todo: Array<[number, number]> = [];
  for (let i = 0; i < n; i++) todo.push([x0 + (P * i) / n, i + 1 === n ? x0 + P : x0 + (P * (i + 1)) / n]);
  let guard = 0;
  while (todo.length > 0) {
    const [a, b] = todo.pop() as [number, number];
    const c = 0.5 * (a + b);
    const r = 0.5 * (b - a);
    let prev = identAt(row, a);
    let cut = Number.NaN;
    // The rule's nodes run from +1 down to -1: taken in increasing x.
    const nn = RULE.nodes.length;
    for (let k = 0; k <= nn && Number.isNaN(cut); k++) {
      const x = k < nn ? c + r * (RULE.nodes[nn - 1 - k] as number) : b;
      const cur = identAt(row, x);
      if (!sameBite(m, prev, cur)) {
        // Never a silent wrong integral: a line that keeps cutting is an error.
        if (++guard > MAX_CUTS) throw new Error(NOT_CONVERGED);
        const located = follow ? locateChange(m, row, prev, cur, a, b) : Number.NaN;
        if (located === NO_CHANGE) {
          prev = cur;
          continue;
        }
        if (!Number.isNaN(located)) {
          cut = located;
          break;
        }
        let lo = prev;
        let hi = cur;
        const d0 = eventDistance(lo, hi);
        let halvings = 0;
        while (hi.x - lo.x > 1e-13 * P) {
          const mid = identAt(row, 0.5 * (lo.x + hi.x));
          // Across teeth the bracket follows the tooth (a fast motion of one tooth's event within it,
          // seen as a change of bite, would lead it away from the change of tooth and close up).
          if (lo.track !== hi.track ? mid.track === lo.track : sameBite(m, lo, mid)) lo = mid;
          else hi = mid;
          // A change of bite keeps its size as the bracket shrinks; a fast continuous motion shrinks
          // with it (a quarter after 4 halvings): then there is no change here.
          if (++halvings >= 4 && eventDistance(lo, hi) < 0.25 * d0) break;
        }
        const at = 0.5 * (lo.x + hi.x);
        // A change at an end of the piece is the break already there, and one that closes up at the
        // finest step was a fast but continuous motion: look on.
        if (at - a > 1e-13 * P && b - at > 1e-13 * P && hi.x - lo.x <= 1e-13 * P && !sameBite(m, lo, hi)) cut = at;
      }
      prev = cur;
    }
    if (Number.isNaN(cut)) done.push(a);
    else todo.push([cut, b], [a, cut]);
  }
  return done.sort((p, q) => p - q);
}

/** Inner samples of each piece of a line searched for its highest point (piecesMax). */
const PIECE_SAMPLES = 7;

/**
 * The highest point of a line over its pieces between `breaks` (sorted): the heights at the breaks
 * (and `beside` either side of each, for a step there), and inside each piece, which need not be
 * monotone (a plateau by the tip, or where the event runs fast over a nearly level edge, as a flat
 * bottom at a small lead: a peak inside a bite), PIECE_SAMPLES inner samples; where one stands
 * above both ends the shared maximiser (Brent's method, whose golden steps close in on a jump's
 * higher side) searches between its neighbours, to `tol` in x.
 */
export function piecesMax(
  height: (x: number) => number,
  breaks: readonly number[],
  tol: number,
  beside: number,
  inner: (a: number, b: number) => number[] = uniformInner,
): { high: number; x: number } {
  let high = Number.NEGATIVE_INFINITY;
  let at = breaks[0] as number;
  const take = (h: number, x: number) => {
    if (h > high) {
      high = h;
      at = x;
    }
  };
  const heights = breaks.map((b) => height(b));
  for (const [k, b] of breaks.entries()) {
    take(heights[k] as number, b);
    if (beside > 0) for (const x of [b - beside, b + beside]) take(height(x), x);
  }
  const f = { value: height };
  const end = newSearchEnd();
  for (let k = 0; k + 1 < breaks.length; k++) {
    const a = breaks[k] as number;
    const b = breaks[k + 1] as number;
    if (!(b > a)) continue;
    const xs = [a, ...inner(a, b), b];
    let best = Math.max(heights[k] as number, heights[k + 1] as number);
    let j = -1;
    for (let i = 1; i + 1 < xs.length; i++) {
      const h = height(xs[i] as number);
      if (h > best) {
        best = h;
        j = i;
      }
    }
    if (j > 0) take(maximise(f, xs[j - 1] as number, xs[j + 1] as number, 2, tol, end), end.x);
  }
  return { high, x: at };
}

/** PIECE_SAMPLES equally spaced inner points of [a, b], increasing. */
function uniformInner(a: number, b: number): number[] {
  const n = PIECE_SAMPLES + 1;
  return Array.from({ length: PIECE_SAMPLES }, (_, i) => a + ((b - a) * (i + 1)) / n);
}

/** The rule's nodes in [a, b], increasing (those runoutLineBreaks checked, whose heights the row keeps). */
function ruleInner(a: number, b: number): number[] {
  const c = 0.5 * (a + b);
  const r = 0.5 * (b - a);
  const nn = RULE.nodes.length;
  return Array.from({ length: nn }, (_, k) => c + r * (RULE.nodes[nn - 1 - k] as number));
}

/**
 * The highest point of a line over one feed period: at its breaks, either side, and inside its pieces
 * (sampled at the rule's nodes, whose heights the break search left in the row).
 */
export function runoutLineMax(m: ToothModel, row: RunoutRow, breaks: readonly number[]): { high: number; x: number } {
  const P = m.feedPeriodMm;
  return piecesMax((x) => row.heightAt(x), breaks, 1e-13 * P + 1e-15, 1e-12 * P, ruleInner);
}

/**
 * The lowest point of the surface over the cross period: the least over y of the lines' lowest points
 * (the shared maximiser on its negative: a scan of 24 lines, then Brent's method to 1e-12 of the period).
 */
export function runoutLowestMm(m: ToothModel): number {
  const H = m.crossPeriodMm;
  return -maximise({ value: (y) => -new RunoutRow(m, y).lowestMm() }, -0.5 * H, 0.5 * H, 24, 1e-12 * H);
}
