/**
 * The areal parameters of the surface the teeth leave over one period cell (shared/notes/
 * surface-finish.md, "What is reported"): Sa, Sq, Sz, Sp, Sv, Ssk, Sku about the cell's integral mean
 * height m, on the primary surface (the design plane the reference). Lengths mm.
 *
 * Integration. Along a line y = const the surface is piecewise smooth: each pass's height is smooth
 * between its valley (an event at the section's lowest point) and its crest (where the first events
 * on either side are equally high), and the line's height, the least of the passes', has kinks where
 * two passes cross; |s - m| has kinks where s crosses m. Those points are found (the crests by the
 * shared maximiser, the crossings by its bracketed root finder) and each smooth piece is integrated
 * by a 12-point Gauss-Legendre rule (20 points change no result by more than 1e-15 relative). The
 * line integrals are integrated over y by adaptive 10-point Gauss-Legendre panels, graded towards
 * the cusps between passes, halved until the disagreements of panels with their halves add up to a
 * relative 1e-7 of the whole, for the mean, and for Sa and Sq^2 each. The moments start from the
 * panels the mean ended with (their lines already prepared), cut at the lines where the continuous
 * surface crosses the mean (where the integral of |s - m| turns like |y - y_m| as the marks shrink:
 * the kink then at a panel's end). Each line is prepared once for both integrals (the mean, then the
 * moments); with runout a piece's cut at the mean and its parts follow the piece's bite (Newton from
 * its nodes' edge points, no search). Checked in the tests against the continuous profile's Ra, Rq as
 * fz -> 0.
 * The lowest point is the continuous contact on the CC path (no runout); the highest is the largest
 * line maximum over y (the shared maximiser over the cell's width, and again about the highest sample
 * of the integral's lines: the line maxima have narrow ridges in y that a scan can step over).
 */
import { inverseInput } from '../input/validate';
import { bracketedRoot, maximise, newSearchEnd } from '../math/rootFinder';
import { planeInverse } from '../surfaces/exact';
import { NOT_SWEPT, PassRow, passesAt } from './envelope';
import { gaussLegendre } from './gaussLegendre';
import { RowEnvelope } from './rowEnvelope';
import { RunoutRow, type RunoutTrack } from './runout';
import { piecesMax, runoutLineBreaks, runoutLineMax, runoutLowestMm } from './runoutLine';
import type { ToothModel } from './toothModel';

/** The areal parameters (ISO 25178-2 names), mm except the dimensionless Ssk and Sku. */
export interface ArealParameters {
  readonly saMm: number;
  readonly sqMm: number;
  readonly szMm: number;
  readonly spMm: number;
  readonly svMm: number;
  readonly ssk: number;
  readonly sku: number;
  /** The cell's mean height m above the design plane, mm. */
  readonly meanMm: number;
}

const ROW_RULE = gaussLegendre(12);
const PANEL_RULE = gaussLegendre(10);
/** Relative agreement of a y panel with its halves at which it is accepted. */
const Y_TOL = 1e-7;
/** Most panel halvings of one integral over y (each 20 lines). */
const MAX_SPLITS = 120;
/** Panels graded towards each cusp: widths halving 4 times. */
const GRADING = 4;

/** The breakpoints of a line over one feed period from x0: valleys, crests and crossings of passes. */
function lineBreaks(m: ToothModel, row: RowEnvelope, x0: number): number[] {
  const P = m.feedPeriodMm;
  const into = (x: number) => x0 + ((((x - x0) % P) + P) % P);
  const breaks = [x0, x0 + P];
  const active = row.activePasses();
  for (const i of active) {
    breaks.push(into(row.valleyXMm(i)), into(row.crestXMm(i)), into(row.peakXMm(i)));
    for (const x of row.turnXsMm(i)) breaks.push(into(x));
  }
  breaks.sort((a, b) => a - b);
  if (active.length > 1) {
    // Where the lowest pass changes between samples of a piece, the crossing of the two.
    const pieces = breaks.slice();
    for (let k = 0; k + 1 < pieces.length; k++) {
      const a = pieces[k] as number;
      const b = pieces[k + 1] as number;
      if (!(b - a > 1e-14 * P)) continue;
      let prevX = a;
      let prevLow = lowestPass(row, active, a + 1e-12 * (b - a));
      for (let s = 1; s <= 8; s++) {
        const x = s === 8 ? b - 1e-12 * (b - a) : a + ((b - a) * s) / 8;
        const low = lowestPass(row, active, x);
        if (low !== prevLow && low >= 0 && prevLow >= 0) {
          const f = { value: (t: number) => row.passHeightOrNaN(prevLow, t) - row.passHeightOrNaN(low, t) };
          const fa = f.value(prevX);
          const fb = f.value(x);
          if (fa < 0 !== fb < 0 && Number.isFinite(fa) && Number.isFinite(fb))
            breaks.push(bracketedRoot(f, prevX, x, fa, fb, 1e-15));
        }
        prevX = x;
        prevLow = low;
      }
    }
    breaks.sort((a, b) => a - b);
  }
  return breaks;
}

/** Index of the pass (among `active`) lowest at x on the line, -1 when none reaches. */
function lowestPass(row: RowEnvelope, active: readonly number[], x: number): number {
  let best = Number.POSITIVE_INFINITY;
  let index = -1;
  for (const i of active) {
    const h = row.passHeightOrNaN(i, x);
    if (h < best) {
      best = h;
      index = i;
    }
  }
  return index;
}

/** The highest point of the line at y over one feed period: its height and x (mm). */
export function arealLineMax(m: ToothModel, y: number): { high: number; x: number } {
  if (m.input.finish.runoutMm > 0) {
    const r = new RunoutRow(m, y);
    return runoutLineMax(m, r, runoutLineBreaks(m, r, 0));
  }
  const row = new RowEnvelope(m, y);
  const x0 = row.passes.length > 0 ? row.valleyXMm(0) : 0;
  const breaks = lineBreaks(m, row, x0);
  // Between breaks the line need not be monotone: near the tip a pass's first event can hold a
  // plateau, and where a level touches a turn of Phi (a leaning or tilted axis) one side's first
  // event jumps, and the line with it: each piece is searched too (piecesMax).
  return piecesMax((x) => row.heightAt(x), breaks, 1e-13 * m.feedPeriodMm + 1e-15, 0);
}

/** One smooth piece of a line: its ends, their heights, and the heights at the rule's nodes. */
interface Piece {
  readonly a: number;
  readonly b: number;
  readonly ha: number;
  readonly hb: number;
  readonly nodes: Float64Array;
  /** With runout, the one bite whose events the nodes are (each node's edge point), when they are. */
  readonly bite?: Bite;
}

/** A tooth's bite along a runout line: its track (no boxes) and the edge points of a piece's nodes. */
interface Bite {
  readonly track: RunoutTrack;
  readonly sign: 1 | -1;
  readonly shiftMm: number;
  readonly thetas: Float64Array;
  readonly ss: Float64Array;
}

/**
 * The height at x (inside piece p) of the piece's bite, followed by Newton from the edge point of the
 * node nearest x (RunoutTrack.followEvent): the same as the search's within the line's pieces (one bite
 * each), without a search; NaN where it cannot be followed.
 */
function biteHeight(p: Piece, bite: Bite, x: number): number {
  const c = 0.5 * (p.a + p.b);
  const r = 0.5 * (p.b - p.a);
  let k = 0;
  for (let j = 1; j < ROW_RULE.nodes.length; j++)
    if (Math.abs(c + r * (ROW_RULE.nodes[j] as number) - x) < Math.abs(c + r * (ROW_RULE.nodes[k] as number) - x))
      k = j;
  return bite.track.followEvent(bite.sign * (x - bite.shiftMm), bite.thetas[k] as number, bite.ss[k] as number);
}

/** The part [a, b] of piece p by its bite's heights (biteHeight), undefined where one cannot be followed. */
function bitePiece(p: Piece, bite: Bite, a: number, b: number, ha: number, hb: number): Piece | undefined {
  const c = 0.5 * (a + b);
  const r = 0.5 * (b - a);
  const nodes = new Float64Array(ROW_RULE.nodes.length);
  for (let k = 0; k < nodes.length; k++) {
    const h = biteHeight(p, bite, c + r * (ROW_RULE.nodes[k] as number));
    if (Number.isNaN(h)) return undefined;
    nodes[k] = h;
  }
  return { a, b, ha, hb, nodes };
}

/** A runout line's piece: its nodes by the search, with their bite when they are one track's. */
function runoutPiece(
  row: RunoutRow,
  bares: Map<number, ReturnType<RunoutRow['bareTrack']>>,
  a: number,
  b: number,
  ha: number,
  hb: number,
): Piece {
  const c = 0.5 * (a + b);
  const r = 0.5 * (b - a);
  const n = ROW_RULE.nodes.length;
  const nodes = new Float64Array(n);
  const thetas = new Float64Array(n);
  const ss = new Float64Array(n);
  let track = Number.NaN;
  for (let k = 0; k < n; k++) {
    nodes[k] = row.heightAt(c + r * (ROW_RULE.nodes[k] as number));
    thetas[k] = row.lastTheta;
    ss[k] = row.lastS;
    if (k === 0) track = row.lastTrack;
    else if (row.lastTrack !== track) track = -1;
  }
  if (!(track >= 0)) return { a, b, ha, hb, nodes };
  if (!bares.has(track)) bares.set(track, row.bareTrack(track));
  const bare = bares.get(track);
  return bare === undefined ? { a, b, ha, hb, nodes } : { a, b, ha, hb, nodes, bite: { ...bare, thetas, ss } };
}

/** A line's heights: the e = 0 row (rowEnvelope.ts) or the runout one (runout.ts). */
interface HeightLine {
  heightAt(xMm: number): number;
  /** Lets go of what the heights needed (a runout line's search boxes), if anything. */
  release?(): void;
}

/** A line y = const prepared once for both integrals (the mean, then the moments about it). */
interface Line {
  readonly row: HeightLine;
  readonly pieces: readonly Piece[];
}

function piece(row: HeightLine, a: number, b: number, ha: number, hb: number): Piece {
  const c = 0.5 * (a + b);
  const r = 0.5 * (b - a);
  const nodes = new Float64Array(ROW_RULE.nodes.length);
  for (let k = 0; k < nodes.length; k++) nodes[k] = row.heightAt(c + r * (ROW_RULE.nodes[k] as number));
  return { a, b, ha, hb, nodes };
}

function prepareLine(m: ToothModel, y: number): Line {
  let row: HeightLine;
  let breaks: number[];
  if (m.input.finish.runoutMm > 0) {
    const r = new RunoutRow(m, y);
    const pieces = runoutPieces(m, r);
    // The line's search boxes are let go after its first integral (a line keeps only its pieces, whose
    // bites follow the cuts at the mean); a cut whose bite cannot be followed prepares it anew.
    let again: RunoutRow | undefined = r;
    row = {
      heightAt: (x: number) => {
        again ??= new RunoutRow(m, y);
        return again.heightAt(x);
      },
      release: () => {
        again = undefined;
      },
    };
    return { row, pieces };
  } else {
    const r = new RowEnvelope(m, y);
    row = r;
    breaks = lineBreaks(m, r, r.passes.length > 0 ? r.valleyXMm(0) : 0);
  }
  return { row, pieces: linePieces(row, breaks) };
}

/**
 * A runout line's pieces (runoutPiece) between its breaks. Its own function: the closures of the line
 * (prepareLine) must not hold the row, whose search boxes it lets go.
 */
function runoutPieces(m: ToothModel, r: RunoutRow): Piece[] {
  const bares = new Map<number, ReturnType<RunoutRow['bareTrack']>>();
  return linePieces(r, runoutLineBreaks(m, r, 0), (a, b, ha, hb) => runoutPiece(r, bares, a, b, ha, hb));
}

/** The pieces of a line between its breaks, with their heights (each made by `make`). */
function linePieces(
  row: HeightLine,
  breaks: readonly number[],
  make: (a: number, b: number, ha: number, hb: number) => Piece = (a, b, ha, hb) => piece(row, a, b, ha, hb),
): Piece[] {
  const pieces: Piece[] = [];
  let ha = row.heightAt(breaks[0] as number);
  for (let k = 0; k + 1 < breaks.length; k++) {
    const a = breaks[k] as number;
    const b = breaks[k + 1] as number;
    if (!(b > a)) continue;
    const hb = row.heightAt(b);
    pieces.push(make(a, b, ha, hb));
    ha = hb;
  }
  return pieces;
}

/** Adds the integrals of one piece's node heights (see lineIntegrals) to `sums`. */
function addPiece(p: Piece, mean: number, sums: number[]): void {
  const r = 0.5 * (p.b - p.a);
  for (let k = 0; k < p.nodes.length; k++) {
    const s = p.nodes[k] as number;
    const w = r * (ROW_RULE.weights[k] as number);
    sums[0] = (sums[0] as number) + w * s;
    if (!Number.isNaN(mean)) {
      const d = s - mean;
      const d2 = d * d;
      sums[1] = (sums[1] as number) + w * Math.abs(d);
      sums[2] = (sums[2] as number) + w * d2;
      sums[3] = (sums[3] as number) + w * d2 * d;
      sums[4] = (sums[4] as number) + w * d2 * d2;
    }
  }
}

/**
 * Integrals over one feed period of the line at y: [s, |s - m|, (s - m)^2, (s - m)^3, (s - m)^4] (mm^k
 * times mm). With `mean` NaN only the first is meaningful. Lines are prepared once per y (`lines`).
 * Between breakpoints one pass is lowest and its height monotone (rising from a valley to a crest,
 * falling after), so s crosses the mean at most once in a piece, where the piece's samples change
 * sign: there the piece is split (|s - m| has a kink) and each part integrated anew.
 */
/** The prepared lines of one computation, with a budget of pieces (Infinity: none). */
class BudgetedLines extends Map<number, Line> {
  pieces = 0;
  constructor(private readonly budget: number) {
    super();
  }
  /** Counts a prepared line's pieces; throws {@link AREAL_BUDGET} past the budget. */
  spend(count: number): void {
    this.pieces += count;
    if (this.pieces > this.budget) throw new Error(AREAL_BUDGET);
  }
}

/** The message of a computation stopped at its budget of line pieces (arealSa). */
export const AREAL_BUDGET = 'areal: budget of line pieces spent';

function lineIntegrals(m: ToothModel, y: number, mean: number, lines: Map<number, Line>): number[] {
  let line = lines.get(y);
  if (line === undefined) {
    line = prepareLine(m, y);
    lines.set(y, line);
    if (lines instanceof BudgetedLines) lines.spend(line.pieces.length);
  }
  const row = line.row;
  const sums = [0, 0, 0, 0, 0];
  for (const p of line.pieces) {
    if (Number.isNaN(mean)) {
      addPiece(p, mean, sums);
      continue;
    }
    // The samples in order (ends and nodes): the first sign change brackets the crossing.
    let prevX = p.a;
    let prevD = p.ha - mean;
    let cut = Number.NaN;
    let lo = Number.NaN;
    let hi = Number.NaN;
    let dLo = Number.NaN;
    let dHi = Number.NaN;
    const c = 0.5 * (p.a + p.b);
    const r = 0.5 * (p.b - p.a);
    for (let k = 0; k <= p.nodes.length && Number.isNaN(lo); k++) {
      const x = k < p.nodes.length ? c + r * (ROW_RULE.nodes[k] as number) : p.b;
      const d = (k < p.nodes.length ? (p.nodes[k] as number) : p.hb) - mean;
      if (d > 0 !== prevD > 0 && d !== 0 && prevD !== 0) {
        lo = prevX;
        hi = x;
        dLo = prevD;
        dHi = d;
      }
      prevX = x;
      prevD = d;
    }
    if (Number.isNaN(lo)) {
      addPiece(p, mean, sums);
      continue;
    }
    // With runout the piece's bite is followed (no search); where it cannot be, the line's search.
    const bite = p.bite;
    if (bite !== undefined) {
      let failed = false;
      const f = {
        value: (t: number) => {
          const h = biteHeight(p, bite, t);
          if (Number.isNaN(h)) failed = true;
          return h - mean;
        },
      };
      cut = bracketedRoot(f, lo, hi, dLo, dHi, 1e-15);
      const left = failed ? undefined : bitePiece(p, bite, p.a, cut, p.ha, mean);
      const right = left === undefined ? undefined : bitePiece(p, bite, cut, p.b, mean, p.hb);
      if (left !== undefined && right !== undefined) {
        addPiece(left, mean, sums);
        addPiece(right, mean, sums);
        continue;
      }
    }
    cut = bracketedRoot({ value: (t: number) => row.heightAt(t) - mean }, lo, hi, dLo, dHi, 1e-15);
    addPiece(piece(row, p.a, cut, p.ha, mean), mean, sums);
    addPiece(piece(row, cut, p.b, mean, p.hb), mean, sums);
  }
  row.release?.();
  return sums;
}

/** Adaptive integral over y in [a, b] of the line integrals (see the module comment). */
function integrateY(
  m: ToothModel,
  a: number,
  b: number,
  mean: number,
  keys: readonly number[],
  cusps: readonly number[],
  lines: Map<number, Line>,
  relTol: number = Y_TOL,
): number[] {
  return adaptY(m, a, b, mean, keys, gradedEnds(a, b, cusps), lines, relTol).total;
}

/**
 * The ends of the panels over y in [a, b] graded towards each cusp between passes: near it, where a
 * neighbouring pass starts to cut below the line's crests, the line integral turns like a power 3/2,
 * in a strip narrower than the feed marks' slope allows; graded panels put nodes there.
 */
function gradedEnds(a: number, b: number, cusps: readonly number[]): number[] {
  const ends = [a, b];
  for (const c of cusps) {
    if (!(c > a && c < b)) continue;
    ends.push(c);
    for (let k = 1; k <= GRADING; k++) {
      ends.push(c - (c - a) * 2 ** -k, c + (b - c) * 2 ** -k);
    }
  }
  return ends.sort((p, q) => p - q);
}

/**
 * The adaptive integral over y from the panels between `ends` (sorted, a and b the first and last),
 * halved as the module comment says: the total and the ends of the panels it ended with.
 */
function adaptY(
  m: ToothModel,
  a: number,
  b: number,
  mean: number,
  keys: readonly number[],
  ends: readonly number[],
  lines: Map<number, Line>,
  relTol: number,
): { readonly total: number[]; readonly ends: number[] } {
  const panel = (lo: number, hi: number) => {
    const c = 0.5 * (lo + hi);
    const r = 0.5 * (hi - lo);
    const out = [0, 0, 0, 0, 0];
    for (let k = 0; k < PANEL_RULE.nodes.length; k++) {
      const sums = lineIntegrals(m, c + r * (PANEL_RULE.nodes[k] as number), mean, lines);
      const w = r * (PANEL_RULE.weights[k] as number);
      for (let i = 0; i < 5; i++) out[i] = (out[i] as number) + w * (sums[i] as number);
    }
    return out;
  };
  // Each panel carries its 10-point value and its halves'; the panel whose halves disagree most
  // with it is halved next (singular points of the line integral, where a neighbouring pass starts
  // to cut, are then refined where they lie), until the disagreements add up to the tolerance.
  interface Panel {
    readonly lo: number;
    readonly hi: number;
    readonly left: number[];
    readonly right: number[];
    /** |halves - whole| of each watched integral. */
    readonly diff: number[];
  }
  const make = (lo: number, hi: number, whole: number[]): Panel => {
    const mid = 0.5 * (lo + hi);
    const left = panel(lo, mid);
    const right = panel(mid, hi);
    return {
      lo,
      hi,
      left,
      right,
      diff: keys.map((k) => Math.abs((left[k] as number) + (right[k] as number) - (whole[k] as number))),
    };
  };
  const panels: Panel[] = [];
  for (let i = 0; i + 1 < ends.length; i++) {
    const lo = ends[i] as number;
    const hi = ends[i + 1] as number;
    if (hi > lo) panels.push(make(lo, hi, panel(lo, hi)));
  }
  const scales = keys.map(
    (k) => Math.abs(panels.reduce((s, p) => s + (p.left[k] as number) + (p.right[k] as number), 0)) + 1e-300,
  );
  // A panel's error: the largest of its watched integrals' disagreements, each relative to its whole.
  const err = (p: Panel) => Math.max(...p.diff.map((d, i) => d / (scales[i] as number)));
  for (let split = 0; split < MAX_SPLITS; split++) {
    let worst = 0;
    let worstErr = 0;
    const sums = keys.map(() => 0);
    for (let i = 0; i < panels.length; i++) {
      const p = panels[i] as Panel;
      for (let k = 0; k < keys.length; k++) sums[k] = (sums[k] as number) + (p.diff[k] as number);
      const e = err(p);
      if (e > worstErr) {
        worstErr = e;
        worst = i;
      }
    }
    if (sums.every((d, k) => d <= relTol * (scales[k] as number))) break;
    const p = panels[worst] as Panel;
    if (!(p.hi - p.lo > 1e-9 * (b - a))) break;
    const mid = 0.5 * (p.lo + p.hi);
    panels.splice(worst, 1, make(p.lo, mid, p.left), make(mid, p.hi, p.right));
  }
  const total = [0, 0, 0, 0, 0];
  for (const p of panels)
    for (let i = 0; i < 5; i++) total[i] = (total[i] as number) + (p.left[i] as number) + (p.right[i] as number);
  return { total, ends: [...panels.map((p) => p.lo), b] };
}
/**
 * The quick integral over y in [a, b] of the line integrals: one 10-point Gauss-Legendre panel
 * between each pair of neighbouring `cuts` (no grading, no halving; about 1e-3 relative for Sa).
 * For searches that refine their answer on the full integral after.
 */
function quickIntegrateY(
  m: ToothModel,
  a: number,
  b: number,
  mean: number,
  _keys: readonly number[],
  cuts: readonly number[],
  lines: Map<number, Line>,
): number[] {
  const ends = [a, ...cuts.filter((c) => c > a && c < b), b].sort((p, q) => p - q);
  const total = [0, 0, 0, 0, 0];
  for (let i = 0; i + 1 < ends.length; i++) {
    const c = 0.5 * ((ends[i] as number) + (ends[i + 1] as number));
    const r = 0.5 * ((ends[i + 1] as number) - (ends[i] as number));
    if (!(r > 0)) continue;
    for (let k = 0; k < PANEL_RULE.nodes.length; k++) {
      const sums = lineIntegrals(m, c + r * (PANEL_RULE.nodes[k] as number), mean, lines);
      const w = r * (PANEL_RULE.weights[k] as number);
      for (let j = 0; j < 5; j++) total[j] = (total[j] as number) + w * (sums[j] as number);
    }
  }
  return total;
}

/**
 * The continuous model's cusps between passes in the cell [0, cross period): one-way at the right
 * flank's reach wR(h); zigzag at L/2 (two right flanks) and 3L/2 (two left flanks).
 */
function cuspLines(m: ToothModel): number[] {
  const { tool, pattern, intervalMm } = m.input;
  if (pattern === 'zigzag') return [intervalMm / 2, 1.5 * intervalMm];
  return [planeInverse(inverseInput(tool, pattern, intervalMm)).halfWidthRightMm];
}

/** The continuous surface's height on the line y (the least of the passes' lowest points), mm. */
function floorAt(m: ToothModel, y: number): number {
  let least = Number.POSITIVE_INFINITY;
  passesAt(m, 0, y, (_x, yLocal) => {
    least = Math.min(least, new PassRow(m, yLocal).zStar);
  });
  return least;
}

/**
 * The lines where the continuous surface crosses the height `mean` in the cell [0, height): as the
 * feed marks shrink the line integral of |s - m| turns there like |y - y_m|, a kink a panel and its
 * halves can agree on by chance. Sign changes of the continuous height minus the mean between
 * `ends` (the profile rises from each CC path to a cusp and falls beyond it), each located by the
 * shared bracketed root finder.
 */
function meanLines(m: ToothModel, ends: readonly number[], mean: number): number[] {
  const out: number[] = [];
  const f = { value: (y: number) => floorAt(m, y) - mean };
  let prevY = ends[0] as number;
  let prevF = f.value(prevY);
  for (let i = 1; i < ends.length; i++) {
    const y = ends[i] as number;
    const fy = f.value(y);
    if (fy < 0 !== prevF < 0 && Number.isFinite(fy) && Number.isFinite(prevF))
      out.push(bracketedRoot(f, prevY, y, prevF, fy, 1e-15));
    prevY = y;
    prevF = fy;
  }
  return out;
}

/**
 * The cell's integral mean height and the integrals about it that `keys` watch (see lineIntegrals),
 * over one period cell, with the cell's area: the mean by `integral` graded towards the cusps, then
 * the moments graded towards the cusps and the lines where the continuous surface crosses the mean.
 */
function cellMoments(
  m: ToothModel,
  keys: readonly number[],
  integral: typeof integrateY,
  lines: Map<number, Line>,
): { readonly area: number; readonly mean: number; readonly sums: number[] } {
  const height = m.crossPeriodMm;
  const area = m.feedPeriodMm * height;
  const cusps = cuspLines(m);
  // The full integral: the moments start from the panels the mean ended with (their lines prepared),
  // each line where the continuous surface crosses the mean made a panel end (the kink at an end).
  const first =
    integral === integrateY
      ? adaptY(m, 0, height, Number.NaN, [0], gradedEnds(0, height, cusps), lines, Y_TOL)
      : undefined;
  const mean = ((first?.total ?? integral(m, 0, height, Number.NaN, [0], cusps, lines))[0] as number) / area;
  const ends = [0, ...cusps.filter((c) => c > 0 && c < height), height];
  if (m.input.pattern === 'zigzag') ends.push(m.input.intervalMm);
  ends.sort((p, q) => p - q);
  const crossings = meanLines(m, ends, mean);
  if (first !== undefined) {
    const start = [...first.ends, ...crossings.filter((y) => y > 0 && y < height && !first.ends.includes(y))];
    const sums = adaptY(
      m,
      0,
      height,
      mean,
      keys,
      start.sort((p, q) => p - q),
      lines,
      Y_TOL,
    ).total;
    return { area, mean, sums };
  }
  const sums = integral(m, 0, height, mean, keys, [...cusps, ...crossings], lines);
  return { area, mean, sums };
}

/**
 * Sa alone (and the mean it is taken about) over one period cell of a prepared model, mm: as
 * {@link arealParameters} (within 1e-6 relative), or `quick` (one panel between the cusps and the
 * mean's lines: about 1e-3 relative, a tenth of the work) for searches that refine after; with
 * the work done, as the number of smooth line pieces integrated (deterministic, for budgets).
 * Past `budgetPieces` it stops, throwing {@link AREAL_BUDGET}.
 */
export function arealSa(
  m: ToothModel,
  quick = false,
  budgetPieces = Number.POSITIVE_INFINITY,
): { readonly saMm: number; readonly meanMm: number; readonly pieces: number } {
  const lines = new BudgetedLines(budgetPieces);
  const { area, mean, sums } = cellMoments(m, [1], quick ? quickIntegrateY : integrateY, lines);
  if (!Number.isFinite(mean)) throw new Error(NOT_SWEPT);
  return { saMm: (sums[1] as number) / area, meanMm: mean, pieces: lines.pieces };
}

/**
 * The highest point of the surface over one period cell (the largest line maximum over y: the shared
 * maximiser, 24 lines then Brent's method to 1e-12 of the cross period): height and place, mm.
 */
export function arealPeak(
  m: ToothModel,
  lines?: ReadonlyMap<number, Line>,
): { readonly highMm: number; readonly xMm: number; readonly yMm: number } {
  const height = m.crossPeriodMm;
  const tol = 1e-12 * height;
  const lineMax = { value: (y: number) => arealLineMax(m, y).high };
  const end = newSearchEnd();
  let highMm = maximise(lineMax, 0, height, 24, tol, end);
  let yMm = end.x;
  // The line maxima over y are kinked, with narrow ridges the scan can step over (Sz 1e-4 mm low seen
  // with runout, 6e-5 mm without): the lines the integrals prepared (hundreds, graded towards the
  // cusps) sample them densely; the best of their samples (breaks and nodes) is searched again between
  // its neighbouring lines, and the higher of the two answers kept.
  if (lines !== undefined && lines.size > 2) {
    const ys = [...lines.keys()].sort((a, b) => a - b);
    let best = Number.NEGATIVE_INFINITY;
    let at = 0;
    for (const [i, y] of ys.entries()) {
      for (const p of (lines.get(y) as Line).pieces) {
        const h = Math.max(p.ha, p.hb, ...p.nodes);
        if (h > best) {
          best = h;
          at = i;
        }
      }
    }
    const again = newSearchEnd();
    const h = maximise(
      lineMax,
      ys[Math.max(0, at - 1)] as number,
      ys[Math.min(ys.length - 1, at + 1)] as number,
      8,
      tol,
      again,
    );
    if (h > highMm) {
      highMm = h;
      yMm = again.x;
    }
  }
  return { highMm, xMm: arealLineMax(m, yMm).x, yMm };
}

/** The areal parameters of a prepared model over one period cell (see the module comment). */
export function arealParameters(m: ToothModel): ArealParameters {
  const lines = new Map<number, Line>();
  const { area, mean, sums } = cellMoments(m, [1, 2], integrateY, lines);
  const sa = (sums[1] as number) / area;
  const sq = Math.sqrt(Math.max(0, (sums[2] as number) / area));
  const low = m.input.finish.runoutMm > 0 ? runoutLowestMm(m) : new RowEnvelope(m, 0).floorMm;
  const high = arealPeak(m, lines).highMm;
  // A point no tooth reaches has no height (+Infinity): the parameters are not defined.
  if (!Number.isFinite(mean) || !Number.isFinite(high)) throw new Error(NOT_SWEPT);
  const sp = high - mean;
  const sv = mean - low;
  return {
    saMm: sa,
    sqMm: sq,
    szMm: sp + sv,
    spMm: sp,
    svMm: sv,
    ssk: sq > 0 ? (sums[3] as number) / area / (sq * sq * sq) : 0,
    sku: sq > 0 ? (sums[4] as number) / area / (sq * sq * sq * sq) : 0,
    meanMm: mean,
  };
}
