/**
 * The surface the teeth leave along one line y = const of the global frame: every pass that reaches
 * the line, with its section prepared once (envelope.ts's PassRow), so that many x cost one event
 * search each. Also where each pass leaves its valleys along the line: an event at the section's
 * lowest point, where the bottom's level `(Phi_b + omega x) / pitch` is a whole number. Lengths mm.
 */
import { bracketedRoot, MAX_ITERATIONS, maximise, newSearchEnd } from '../math/rootFinder';
import { SectionPoint } from './bodySection';
import { PassRow, passEventMinMm, passEventOrNaNMm, passesAt, passSideEventsMm } from './envelope';
import type { ToothModel } from './toothModel';

/**
 * A difference of the two sides' first events (relative to R) above which the crest search's root is
 * a jump of one side, not a crossing: a crossing leaves about 1e-15 of it at the final bracket's ends.
 */
const CREST_JUMP = 1e-12;

/**
 * Near the tool's axis (the tip, the centre of its flat bottom) the angle psi about the axis turns
 * fast along a section passing close to it, and one side's first event can stay there for a range of
 * x while the other side's comes higher: a plateau at about the tip's height, above the crest (a ball
 * at lead 3.9, tilt -0.05, zigzag, 4 teeth, fz 0.611: crest 0.003572, plateau 0.003732 mm). For arcs
 * about the lowest point the other side comes higher only while the tip is below about 4 times the
 * crest's height above the lowest point (the arc's width grows like the root of the height); within
 * this many times a pass's highest point is searched, not read at the crest.
 */
export const TIP_REACH = 8;

/** One pass on the line: its row and how global x maps to its local x (`sign (x - shift)`). */
interface PassOnLine {
  readonly row: PassRow;
  readonly sign: 1 | -1;
  readonly shiftMm: number;
}

/**
 * The passes that reach a line y = const and can shape it, ordered by their lowest point (nearest CC
 * path first). The lowest point of a pass at local y (the continuous surface's height there) is a
 * convex function of y, least on its CC path: on either side of the line it rises with the distance
 * to the pass. So the passes are prepared nearest first on each side, and a side stops at the first
 * pass whose lowest point is at or above the crest of the line's lowest pass (the highest that pass
 * reaches): it and the passes beyond it stay above that pass everywhere and never shape the line
 * (a side whose nearest pass is such adds no other).
 */
export class RowEnvelope {
  readonly m: ToothModel;
  readonly yMm: number;
  readonly passes: readonly PassOnLine[];
  /** Lowest point of the continuous surface on this line (the least of the passes' contacts), mm. */
  readonly floorMm: number;
  /** The highest point of the lowest pass on the line (its peak), NaN when unknown, mm. */
  private readonly topMm: number;
  /** The crests and peaks found so far, by pass. */
  private readonly crests = new Map<PassOnLine, number>();
  private readonly peaks = new Map<PassOnLine, number>();

  /**
   * @param peaks bound the passes by the lowest pass's peak (its highest point: `peakXMm`), as every
   * height of the line needs; false bounds them by its crest alone, cheaper where the tip is near
   * (no search over the period), for a lower bound of the line's highest point that needs no more.
   */
  constructor(m: ToothModel, yMm: number, peaks = true) {
    this.m = m;
    this.yMm = yMm;
    const sides: Array<Array<[number, 1 | -1, number]>> = [[], []];
    passesAt(m, 0, yMm, (_x, yLocal, sign, shiftMm) => {
      (sides[yLocal >= 0 ? 0 : 1] as Array<[number, 1 | -1, number]>).push([yLocal, sign, shiftMm]);
    });
    for (const side of sides) side.sort((p, q) => Math.abs(p[0]) - Math.abs(q[0]));
    const list: PassOnLine[] = [];
    const build = (c: [number, 1 | -1, number]): PassOnLine => {
      const p = { row: new PassRow(m, c[0]), sign: c[1], shiftMm: c[2] };
      list.push(p);
      return p;
    };
    let lowest: PassOnLine | undefined;
    const nearest: Array<PassOnLine | undefined> = [];
    for (const side of sides) {
      const first = side[0];
      const p = first === undefined ? undefined : build(first);
      nearest.push(p);
      if (p?.row.reaches && (lowest === undefined || p.row.zStar < lowest.row.zStar)) lowest = p;
    }
    this.topMm =
      lowest === undefined ? Number.NaN : this.passHeightOf(lowest, peaks ? this.peakOf(lowest) : this.crestOf(lowest));
    for (const [s, side] of sides.entries()) {
      // A side whose nearest pass already stands at or above the crest adds none beyond it.
      const first = nearest[s];
      if (first?.row.reaches && first.row.zStar >= this.topMm) continue;
      for (let k = 1; k < side.length; k++) {
        const p = build(side[k] as [number, 1 | -1, number]);
        if (p.row.zStar >= this.topMm) break;
      }
    }
    list.sort((p, q) => p.row.zStar - q.row.zStar);
    this.passes = list;
    this.floorMm = list.length > 0 ? (list[0] as PassOnLine).row.zStar : Number.POSITIVE_INFINITY;
  }

  /**
   * The passes that can be the line's lowest somewhere: the lowest reaching pass and those whose
   * lowest point lies below its crest (all reaching passes when that crest's height is not known).
   */
  activePasses(): number[] {
    const out: number[] = [];
    for (let i = 0; i < this.passes.length; i++) {
      const row = (this.passes[i] as PassOnLine).row;
      if (row.reaches && (out.length === 0 || !(row.zStar >= this.topMm))) out.push(i);
    }
    return out;
  }

  /** s(x, y) on this line, mm (Infinity where no pass reaches). */
  heightAt(xMm: number): number {
    let best = Number.POSITIVE_INFINITY;
    for (const p of this.passes) best = passEventMinMm(this.m, p.row, p.sign * (xMm - p.shiftMm), best);
    return best;
  }

  /** The height of one pass alone at x (mm), or NaN where its search stalled (passEventOrNaNMm). */
  passHeightOrNaN(index: number, xMm: number): number {
    return this.passHeightOf(this.passes[index] as PassOnLine, xMm);
  }

  private passHeightOf(p: PassOnLine, xMm: number): number {
    return passEventOrNaNMm(this.m, p.row, p.sign * (xMm - p.shiftMm));
  }

  /** The height of one pass alone at x (mm). */
  passHeightAt(index: number, xMm: number): number {
    const p = this.passes[index] as PassOnLine;
    return passEventMinMm(this.m, p.row, p.sign * (xMm - p.shiftMm), Number.POSITIVE_INFINITY);
  }

  /**
   * A global x where pass `index` leaves a valley on this line (an event at its section's lowest
   * point); the others are `fz` apart. Without runout the valleys are the line's lowest points.
   */
  valleyXMm(index: number): number {
    const p = this.passes[index] as PassOnLine;
    return this.levelXMm(p, p.row.bottom);
  }

  /**
   * A global x where a level meets pass `index`'s Phi at a point of its section (the others `fz`
   * apart): where (psi - omega w + omega x_local) / pitch is a whole number (the one nearest 0).
   */
  private levelXMm(p: PassOnLine, at: SectionPoint): number {
    const m = this.m;
    const phi = at.psi - m.omegaRadPerMm * at.w;
    const xLocal = (-phi - m.toothPitchRad * Math.round(-phi / m.toothPitchRad)) / m.omegaRadPerMm;
    return p.shiftMm + p.sign * xLocal;
  }

  /**
   * The global x (one per point, the others `fz` apart) where a level touches pass `index`'s Phi at
   * its turning points (a vertical axis: PassRow.vertical): there the first event on that side jumps
   * from the turning point further up, and the line's height may jump.
   */
  turnXsMm(index: number): number[] {
    const p = this.passes[index] as PassOnLine;
    const out: number[] = [];
    const at = new SectionPoint();
    for (const alpha of [p.row.turnRightAlpha, p.row.turnLeftAlpha]) {
      if (Number.isNaN(alpha)) continue;
      p.row.section.pointAt(p.row.cw, p.row.cz, alpha, at);
      out.push(this.levelXMm(p, at));
    }
    return out;
  }

  /**
   * The global x of pass `index`'s crest in the period after its valley `valleyXMm(index)`: where the
   * first events on either side of the section's lowest point are equally high (one rises and the
   * other falls as x runs over the period), by the shared bracketed root finder; the
   * shared maximiser where that difference does not change sign (a pass that never meets its
   * levels on one side).
   */
  crestXMm(index: number): number {
    return this.crestOf(this.passes[index] as PassOnLine);
  }

  private crestOf(p: PassOnLine): number {
    return memo(this.crests, p, () => this.findCrestXMm(p));
  }

  /**
   * The global x of pass `index`'s highest point on this line over the period after its valley: its
   * crest, unless the tool's tip is near enough above the crest to hold a plateau (see TIP_REACH):
   * then the shared maximiser over the period (48 samples, the crest evaluated too).
   */
  peakXMm(index: number): number {
    return this.peakOf(this.passes[index] as PassOnLine);
  }

  private peakOf(p: PassOnLine): number {
    return memo(this.peaks, p, () => this.findPeakXMm(p));
  }

  private findPeakXMm(p: PassOnLine): number {
    const x = this.crestOf(p);
    const high = this.passHeightOf(p, x);
    const low = p.row.zStar;
    if (!(p.row.tipZ - low <= TIP_REACH * (high - low))) return x;
    const P = this.m.feedPeriodMm;
    const v = this.levelXMm(p, p.row.bottom);
    const end = newSearchEnd();
    const f = { value: (t: number) => this.passHeightOf(p, t) };
    const top = maximise(f, v, v + P, 48, 1e-13 * P + 1e-15, end, x);
    return top > high ? end.x : x;
  }

  private findCrestXMm(p: PassOnLine): number {
    const P = this.m.feedPeriodMm;
    const v = this.levelXMm(p, p.row.bottom);
    const values = new Map<number, number>();
    const f = {
      value: (x: number) => {
        const [r, l] = passSideEventsMm(this.m, p.row, p.sign * (x - p.shiftMm));
        const d = p.sign * (r - l);
        values.set(x, d);
        return d;
      },
    };
    const a = v + 1e-9 * P;
    const b = v + P - 1e-9 * P;
    const fa = f.value(a);
    const fb = f.value(b);
    // Near a tip's track the right event can start the period above the left one: the crest is still
    // where they are equal (the lower one rises to it, the other falls to it).
    if (fa < 0 !== fb < 0 && fa !== 0 && fb !== 0 && Number.isFinite(fa) && Number.isFinite(fb)) {
      const end = newSearchEnd();
      const x = bracketedRoot(f, a, b, fa, fb, 1e-15, MAX_ITERATIONS, end);
      // The difference changes sign through 0, or by a jump: where a level first touches the section
      // on one side, that side's first event drops to the new touching point (the height is lowest
      // there, at that one x). Then the highest of the line is the limit beside the jump on the side
      // where the height is larger: the other end of the final bracket (within 1e-15 of x) may be it.
      if (!(Math.abs(values.get(x) ?? 0) > CREST_JUMP * this.m.toolRadiusMm)) return x;
      const other = x === end.lo ? end.hi : end.lo;
      return this.passHeightOf(p, other) > this.passHeightOf(p, x) ? other : x;
    }
    const end = newSearchEnd();
    maximise({ value: (x) => this.passHeightOf(p, x) }, v, v + P, 16, 1e-13 * P, end);
    return end.x;
  }
}

/** The value of `key` in `found`, computed and kept on first asking. */
function memo<K>(found: Map<K, number>, key: K, compute: () => number): number {
  let x = found.get(key);
  if (x === undefined) {
    x = compute();
    found.set(key, x);
  }
  return x;
}
