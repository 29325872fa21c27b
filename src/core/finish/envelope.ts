/**
 * The height s(x, y) of the surface the teeth leave (shared/notes/surface-finish.md): the lower
 * envelope in Z of every position of every tooth's edge, over all time and all passes. Lengths mm.
 *
 * Derivation. Fix a pass and a point (x, y) in its local frame (toothModel.ts). At spindle position u
 * the vertical line through the point meets the body of revolution where the section curve of the
 * plane y (bodySection.ts) lies, at w = x - u: a boundary point at angle psi about the axis. Tooth k's
 * edge is the body's meridian at angle theta_k(u) = -omega u + 2 pi k / z, so tooth k cuts the point
 * at that height exactly when psi = theta_k(u) (mod 2 pi). With u = x - w this reads
 *
 *     Phi(w) := psi - omega w  =  -omega x  (mod 2 pi / z):
 *
 * the events are the points of the section curve where the continuous function Phi crosses one of
 * the levels `-omega x + j 2 pi / z`. The curve is convex, so its height rises monotonically from its
 * lowest point (the continuous model's contact at this y, z = p(y)) in both directions up to its top;
 * the envelope of this pass is therefore the lower of the first events met walking from the lowest
 * point in each direction. Walking uses a bound on Phi's rate along the curve: the point moves at
 * speed |dP/dalpha| (alpha the polar angle of bodySection.ts), so |dw/dalpha| <= |dP/dalpha| and
 * |dpsi/dalpha| <= |dP/dalpha| / rho (rho its distance from the axis). Where Phi is provably monotone
 * on a step a level crossed is found by the shared bracketed root finder; elsewhere (near the axis,
 * where psi turns fast, and near the curve's vertical tangents) the steps are kept short enough that
 * Phi cannot reach a level and come back. A point of the curve on the axis is the tip, which lies on
 * every tooth's edge: always an event. The point's height is the least over the passes that reach it.
 */
import { NewtonState, newtonStart, newtonStep, type Objective } from '../math/rootFinder';
import { flankAtWidth } from '../tool/posture';
import { BodySection, SectionPoint } from './bodySection';
import type { ToothModel } from './toothModel';

/** The error a point whose event search stalled raises (never a silent wrong height). */
export const NOT_CONVERGED = 'The tooth event search did not converge at this point (please report the inputs).';
/**
 * The error the areal parameters raise where some point of the cell is cut by no tooth (a flat end
 * upright at a step-over of 2R: beside the pass boundary its bottom edges, turning, miss thin slivers
 * that only the vertical side, an instant at a time, reaches): the surface left is not defined there.
 */
export const NOT_SWEPT = 'Some points of the period cell are cut by no tooth: the surface left is not defined there.';

/**
 * The one line a page or command line says where a finish part could not be computed, or null for
 * any other error (which is a bug, thrown on).
 */
export function finishFailureWords(e: unknown, part: 'areal' | 'marks'): string | null {
  const kind = finishFailureKind(e);
  const what = part === 'areal' ? 'The areal parameters' : 'The feed marks';
  if (kind === 'not-converged')
    return `${what} could not be computed for this feed: the event search did not converge; try a smaller fz.`;
  if (kind === 'not-swept')
    return `${what} are not defined here: thin slivers between the passes are cut by no tooth (the bottom edges miss them); try a smaller step-over.`;
  return null;
}

/** Which failure of a finish part an error is (a page words it in its language), or null for any other. */
export function finishFailureKind(e: unknown): 'not-converged' | 'not-swept' | null {
  if (!(e instanceof Error)) return null;
  return e.message === NOT_CONVERGED ? 'not-converged' : e.message === NOT_SWEPT ? 'not-swept' : null;
}
/**
 * Most steps of one walk from the contact: a few tens are usual; where Phi turns just short of a level
 * (a tangential approach) the safe steps stay short and take thousands.
 */
const MAX_WALK_STEPS = 20000;
/** Largest polar step, radians. */
const MAX_STEP_RAD = 0.2;
/** Levels within this fraction of the pitch count as met (an edge within ~1e-13 rad of the point). */
const LEVEL_TOL = 1e-13;

/** The section of one pass at one y, prepared for every x of a row. */
export class PassRow {
  readonly section: BodySection;
  /** False when the pass does not reach this y (beyond the end's silhouette). */
  readonly reaches: boolean;
  /** Lowest point of the section (the continuous model's contact at this y): w, z. */
  readonly wStar: number;
  readonly zStar: number;
  /** Interior point C of the polar parametrisation. */
  readonly cw: number;
  readonly cz: number;
  readonly bottom = new SectionPoint();
  /**
   * Polar angle of the tool's tip (the centre of the flat bottom, on the axis) when the plane passes
   * through it, else NaN: there psi jumps by pi, and the tip, on every tooth's edge, is an event.
   */
  readonly tipAlpha: number;
  readonly tipZ: number;
  /**
   * With the axis vertical (lead 0, tilt 0) psi is atan2(y - O_y, w) on the section, so Phi is a
   * function of w alone, Phi'(w) = -(y - O_y) / (w^2 + (y - O_y)^2) - omega, which vanishes only at
   * w = +-sqrt(-(y - O_y) / omega - (y - O_y)^2) (for y < O_y): Phi is monotone between those turning
   * points and w's own turning points (the curve's vertical tangents). `vertical` says so; the polar
   * angles of the turning points right (w > 0) and left, NaN where there are none.
   */
  readonly vertical: boolean;
  readonly turnRightAlpha: number;
  readonly turnLeftAlpha: number;

  constructor(m: ToothModel, yMm: number) {
    this.section = new BodySection(m, yMm);
    const s = m.shape;
    const flank = yMm >= 0 ? 'right' : 'left';
    const width = Math.abs(yMm);
    const reach = flank === 'right' ? m.reachRightMm : m.reachLeftMm;
    let wStar = 0;
    if (width < reach && !(s.a === 0 || s.flatOnPlane)) {
      const p = flankAtWidth(s, flank, width);
      const t = Math.atan2(s.sinT0, s.cosT0) + (flank === 'right' ? 1 : -1) * p.ringOffsetRad;
      wStar = m.ringRadiusMm * Math.sqrt(Math.max(0, 1 - m.axis[0] * m.axis[0])) * Math.cos(t);
    }
    const below = -1e-3 * m.toolRadiusMm - 2 * m.input.finish.runoutMm - 1e-9;
    const zStar = width < reach ? this.section.entryZ(wStar, below) : Number.NaN;
    const zUp = Number.isFinite(zStar) ? this.section.exitZ(wStar, zStar) : Number.NaN;
    const chord = zUp - zStar;
    this.reaches = chord > 1e-12 * m.toolRadiusMm;
    this.wStar = wStar;
    this.zStar = this.reaches ? zStar : Number.POSITIVE_INFINITY;
    this.cw = wStar;
    this.cz = zStar + 0.5 * Math.min(chord, m.toolRadiusMm);
    if (this.reaches) this.section.pointAt(this.cw, this.cz, -Math.PI / 2, this.bottom);
    const a = m.axis;
    const rcr = m.cornerRadiusMm;
    const tipGap = this.section.yRel + rcr * a[1];
    const tipW = -rcr * a[0];
    this.tipZ = m.centreZMm - rcr * a[2];
    this.tipAlpha =
      this.reaches && Math.abs(tipGap) <= 1e-14 * m.toolRadiusMm
        ? Math.atan2(this.tipZ - this.cz, tipW - this.cw)
        : Number.NaN;
    this.vertical = this.reaches && a[0] === 0 && a[1] === 0 && Number.isNaN(this.tipAlpha);
    const y = this.section.yRel;
    const w2 = -y / m.omegaRadPerMm - y * y;
    let right = Number.NaN;
    let left = Number.NaN;
    if (this.vertical && w2 > 0) {
      const wt = Math.sqrt(w2);
      const zr = this.section.entryZ(wt, below);
      const zl = this.section.entryZ(-wt, below);
      if (Number.isFinite(zr)) right = Math.atan2(zr - this.cz, wt - this.cw);
      if (Number.isFinite(zl)) left = Math.atan2(zl - this.cz, -wt - this.cw);
      // The left side's angles run below -pi/2 (down to -3 pi / 2).
      if (left > Math.PI / 2) left -= 2 * Math.PI;
    }
    this.turnRightAlpha = right;
    this.turnLeftAlpha = left;
  }
}

/** Wraps an angle difference into (-pi, pi]. */
function wrap(d: number): number {
  return d - 2 * Math.PI * Math.round(d / (2 * Math.PI));
}

/** Distance of m from the nearest integer. */
function distToInt(m: number): number {
  return Math.abs(m - Math.round(m));
}

/** The level index function along a step: (psi unwrapped from psi0 - omega w - beta) / pitch - n. */
class LevelObjective implements Objective {
  row!: PassRow;
  psi0 = 0;
  theta0 = 0;
  omega = 0;
  beta = 0;
  pitch = 0;
  n = 0;
  readonly p = new SectionPoint();
  value(alpha: number): number {
    const row = this.row;
    row.section.pointAt(row.cw, row.cz, alpha, this.p);
    const theta = this.theta0 + wrap(this.p.psi - this.psi0);
    return (theta - this.omega * this.p.w - this.beta) / this.pitch - this.n;
  }
}

const objective = new LevelObjective();
const newton = new NewtonState();
const p0 = new SectionPoint();
const p1 = new SectionPoint();

function copyPoint(from: SectionPoint, to: SectionPoint): void {
  to.t = from.t;
  to.w = from.w;
  to.z = from.z;
  to.rho = from.rho;
  to.psi = from.psi;
  to.speed = from.speed;
  to.dw = from.dw;
  to.dpsi = from.dpsi;
  to.inPlane = from.inPlane;
}

/**
 * The lowest tooth event of one pass at local x on the row, or `best` when none is lower (mm).
 * `best` prunes: walking stops where the curve rises to it.
 */
export function passEventMinMm(m: ToothModel, row: PassRow, xLocalMm: number, best: number): number {
  if (!row.reaches || row.zStar >= best) return best;
  const beta = levelsOffset(m, xLocalMm);
  if (row.bottom.rho <= 1e-12 * m.toolRadiusMm) return Math.min(best, row.bottom.z);
  const right = sideEventMm(m, row, beta, 1, best);
  const least = sideEventMm(m, row, beta, -1, right);
  // Never a silent wrong height.
  if (Number.isNaN(least)) throw new Error(NOT_CONVERGED);
  return least;
}

/**
 * The lowest event of one pass at local x, unpruned, or NaN where the search stalled (for searches
 * that can do without this pass's value, such as finding where passes cross), mm.
 */
export function passEventOrNaNMm(m: ToothModel, row: PassRow, xLocalMm: number): number {
  if (!row.reaches) return Number.POSITIVE_INFINITY;
  const beta = levelsOffset(m, xLocalMm);
  if (row.bottom.rho <= 1e-12 * m.toolRadiusMm) return row.bottom.z;
  const right = sideEventMm(m, row, beta, 1, Number.POSITIVE_INFINITY);
  if (Number.isNaN(right)) return Number.NaN;
  return sideEventMm(m, row, beta, -1, right);
}

/** The first event on each side of the lowest point (right: w increasing), unpruned, mm. */
export function passSideEventsMm(m: ToothModel, row: PassRow, xLocalMm: number): [number, number] {
  if (!row.reaches) return [Number.POSITIVE_INFINITY, Number.POSITIVE_INFINITY];
  const beta = levelsOffset(m, xLocalMm);
  if (row.bottom.rho <= 1e-12 * m.toolRadiusMm) return [row.bottom.z, row.bottom.z];
  // A side whose walk ran out of steps counts as having no event (the crest search then falls back).
  const r = sideEventMm(m, row, beta, 1, Number.POSITIVE_INFINITY);
  const l = sideEventMm(m, row, beta, -1, Number.POSITIVE_INFINITY);
  return [Number.isNaN(r) ? Number.POSITIVE_INFINITY : r, Number.isNaN(l) ? Number.POSITIVE_INFINITY : l];
}

/** The levels -omega x + j pitch, as an offset reduced to (-pitch, 0] (omega x can be large). */
function levelsOffset(m: ToothModel, xLocalMm: number): number {
  const pitch = m.toothPitchRad;
  return -((((m.omegaRadPerMm * xLocalMm) % pitch) + pitch) % pitch);
}

/** The first event walking from the lowest point in direction `dir`, or `best` when none is lower. */
function sideEventMm(m: ToothModel, row: PassRow, beta: number, dir: number, best: number): number {
  const tiltSine = Math.abs(m.axis[1]);
  // A bound of |P_perp,y| along the section near its bottom: |y - O_y| + |a_y| |zeta|, |zeta| <= 2 R.
  const sideOffset = Math.abs(row.section.yRel) + tiltSine * 2 * (m.toolRadiusMm + m.cornerRadiusMm);
  const omega = m.omegaRadPerMm;
  const pitch = m.toothPitchRad;
  const scale = m.toolRadiusMm;
  const bottom = row.bottom;
  let tip = row.tipAlpha;
  if (tip > Math.PI / 2) tip -= 2 * Math.PI;
  const tipAhead = dir > 0 ? tip >= -Math.PI / 2 : tip < -Math.PI / 2;
  // Walk to the top, or to the tip when the plane passes through it (an event there).
  const alphaEnd = tipAhead ? tip : dir > 0 ? Math.PI / 2 : -1.5 * Math.PI;
  const throughTip = !Number.isNaN(row.tipAlpha);
  // Phi's turning point on this side (vertical axis), where a step must end (see PassRow.vertical).
  const turn = dir > 0 ? row.turnRightAlpha : row.turnLeftAlpha;
  let alpha = -Math.PI / 2;
  copyPoint(bottom, p0);
  let theta = p0.psi;
  let level = (theta - omega * p0.w - beta) / pitch;
  if (distToInt(level) <= LEVEL_TOL) return Math.min(best, p0.z);
  let grow = MAX_STEP_RAD;
  let iter = 0;
  // With the axis vertical the body above its widest section is the cylinder of radius R: the section
  // goes on up the vertical line |w| = sqrt(R^2 - (y - O_y)^2), along which w, psi and so Phi stay
  // constant. A walk that reaches that wall meets no level beyond it (the level, if met exactly,
  // was met where the wall begins).
  const wall = row.vertical ? Math.sqrt(Math.max(0, scale * scale - row.section.yRel * row.section.yRel)) : -1;
  for (; iter < MAX_WALK_STEPS; iter++) {
    const onWall = Math.abs(Math.abs(p0.w) - wall) <= 1e-12 * scale && Math.abs(p0.dw) <= 1e-9 * p0.speed;
    if (row.vertical && dir * p0.w > 0 && onWall) break;
    if (p0.rho <= 1e-12 * scale && !throughTip) {
      best = Math.min(best, p0.z);
      break;
    }
    const s0 = p0.speed;
    const rate0 = throughTip ? Math.abs(p0.dpsi) + 1e-3 : s0 / p0.rho;
    let delta = Math.min(MAX_STEP_RAD, grow, (0.5 * pitch) / (1.5 * (s0 * omega + rate0)));
    let final = false;
    let alpha1 = alpha;
    let speed = 0;
    let rhoLo = 0;
    let psiRate = 0;
    let bound = 0;
    // Shrink the step until the rate bound over it holds (at most half a pitch of Phi).
    for (let k = 0; k < 200; k++) {
      final = false;
      alpha1 = alpha + dir * delta;
      if (dir * (alpha1 - alphaEnd) >= 0) {
        alpha1 = alphaEnd;
        delta = Math.abs(alphaEnd - alpha);
        final = true;
      } else if (dir * (turn - alpha) > 0 && dir * (alpha1 - turn) > 0) {
        alpha1 = turn;
        delta = Math.abs(turn - alpha);
      }
      // At the tip psi is undefined: its limit just before it.
      const at = final && tipAhead ? alpha1 - dir * 1e-12 : alpha1;
      row.section.pointAt(row.cw, row.cz, at, p1);
      if (!Number.isFinite(p1.t)) break;
      speed = 1.25 * Math.max(s0, p1.speed);
      rhoLo = Math.min(p0.rho, p1.rho) - speed * delta;
      // Through the tip the curve crosses the axis transversally: psi is smooth on either side
      // (its rate bounded by the curvature), and jumps by pi only at the tip itself.
      // Otherwise |dpsi/dalpha| = |P_perp . (v x a)| / rho^2 <= speed (|P_perp,y| / rho^2 + |a_y| / rho):
      // v lies in the plane y = const, so v x a_xz is along y and v x (a_y e_y) in the plane. Without
      // tilt that is speed |y - O_y| / rho^2, far below speed / rho near the axis's own plane.
      psiRate = throughTip
        ? 2 * Math.max(Math.abs(p0.dpsi), Math.abs(p1.dpsi)) + 1e-3
        : rhoLo > 0
          ? speed * (Math.min(sideOffset, rhoLo) / (rhoLo * rhoLo) + tiltSine / rhoLo)
          : Number.POSITIVE_INFINITY;
      bound = speed * omega + psiRate;
      if (bound * delta <= 0.5 * pitch || delta <= 1e-15) break;
      // Past the axis within the step (rhoLo <= 0): shorten it to half the distance to the axis.
      delta =
        rhoLo > 0
          ? Math.min(0.5 * delta, (0.45 * pitch) / bound)
          : Math.min(0.5 * delta, (0.5 * Math.min(p0.rho, p1.rho)) / speed);
    }
    if (!Number.isFinite(p1.t)) break;
    grow = 4 * delta;
    const theta1 = theta + wrap(p1.psi - p0.psi);
    const level1 = (theta1 - omega * p1.w - beta) / pitch;
    // With the axis vertical Phi is monotone while w is and the step stays on one side of the axis
    // and of Phi's turning point (steps end there).
    const monotone =
      p0.dw * p1.dw > 0 &&
      ((row.vertical && p0.w * p1.w >= 0) || 0.5 * omega * Math.min(Math.abs(p0.dw), Math.abs(p1.dw)) > psiRate);
    const n = Math.floor(Math.max(level, level1));
    const crossed = Math.floor(level) !== Math.floor(level1) || distToInt(level1) <= LEVEL_TOL;
    if (crossed) {
      let alphaEvent = alpha1;
      if (distToInt(level1) > LEVEL_TOL) {
        objective.row = row;
        objective.psi0 = p0.psi;
        objective.theta0 = theta;
        objective.omega = omega;
        objective.beta = beta;
        objective.pitch = pitch;
        objective.n = n;
        if (monotone) {
          // Safeguarded Newton on the level: its slope (dpsi - omega dw) / pitch is at hand.
          const lo = dir > 0 ? alpha : alpha1;
          const hi = dir > 0 ? alpha1 : alpha;
          const gHi = (dir > 0 ? level1 : level) - n;
          const gLo = (dir > 0 ? level : level1) - n;
          newtonStart(newton, lo, hi, lo + ((hi - lo) * gLo) / (gLo - gHi));
          for (let k = 0; k < 60 && !newton.done; k++) {
            const g = objective.value(newton.x);
            const slope = (objective.p.dpsi - omega * objective.p.dw) / pitch;
            newtonStep(newton, g, slope, gHi > 0, 1e-15);
          }
          alphaEvent = newton.x;
          // Stopped on a step below 1e-15 of alpha: the last point evaluated is the event's to
          // within ~1e-14 mm.
          if (newton.done) {
            best = Math.min(best, objective.p.z);
            break;
          }
        } else {
          // Not provably monotone: bisect on the sign change (a crossing within this short step).
          let lo = alpha;
          let hi = alpha1;
          const fLo = level - n;
          for (let k = 0; k < 200 && Math.abs(hi - lo) > 1e-16 * Math.max(1, Math.abs(lo)); k++) {
            const mid = 0.5 * (lo + hi);
            const f = objective.value(mid);
            if (f === 0) {
              lo = mid;
              hi = mid;
            } else if (f > 0 === fLo > 0) lo = mid;
            else hi = mid;
          }
          alphaEvent = 0.5 * (lo + hi);
        }
      }
      row.section.pointAt(row.cw, row.cz, alphaEvent, objective.p);
      best = Math.min(best, objective.p.z);
      break;
    }
    if (!monotone) {
      const gap = distToInt(level) * pitch;
      if (bound * delta >= 0.9 * gap) {
        if (gap <= LEVEL_TOL * pitch || delta <= 1e-15) {
          best = Math.min(best, p0.z);
          break;
        }
        // Where Phi turns just short of a level its rate nearly vanishes while the bound does not:
        // the second-order bound lets the steps past the turn grow with sqrt(gap), not with gap.
        const reach = throughTip ? Number.NaN : secondOrderStep(m, p0, p1, speed * delta, rhoLo, gap);
        if (!(reach >= 1)) {
          grow = Math.max((0.8 * gap) / bound, Number.isFinite(reach) ? reach * delta : 0);
          continue;
        }
      }
    }
    if (final && tipAhead) {
      best = Math.min(best, row.tipZ);
      break;
    }
    alpha = alpha1;
    copyPoint(p1, p0);
    theta = theta1;
    level = level1;
    if (p0.z >= best || final) break;
  }
  // A walk that ran out of steps has no answer (NaN): the callers say so or look elsewhere.
  if (iter >= MAX_WALK_STEPS) {
    return Number.NaN;
  }
  return best;
}

/**
 * The second-order test of a step from p0 to p1 of arc length at most `arc` keeping at least `rhoLo`
 * from the axis: the fraction of the step (>= 1: the whole) over which Phi provably stays within
 * 0.9 `gap` of its value at p0, or NaN when no bound is at hand (a sharp corner, or the plane near
 * tangent to the body).
 *
 * In arc length s along the section, |Phi(s) - Phi(0) - Phi'(0) s| <= M s^2 / 2 with |Phi''| <= M:
 * Phi = psi - omega w, |w''| <= kappa (the section's curvature), and with P_perp the point's part
 * across the axis (|P_perp| = rho) and v the unit tangent, psi' = (P_perp x v) . a / rho^2, whose
 * derivative is (P_perp x v') . a / rho^2 - 2 (P_perp x v) . a (P_perp . v) / rho^4 (the term of
 * P_perp' = v_perp vanishes: (v_perp x v) . a = 0), so |psi''| <= kappa / rho + 2 / rho^2. The body
 * is the parallel body at distance Rcr of a convex set: its normal curvatures are at most 1 / Rcr
 * and its normal n turns at most s / Rcr over s; by Meusnier the section's curvature is a normal
 * curvature over |n_plane| = sqrt(1 - n_y^2), which over the step is at least (g0 + g1 - arc / Rcr) / 2.
 */
function secondOrderStep(
  m: ToothModel,
  p0: SectionPoint,
  p1: SectionPoint,
  arc: number,
  rhoLo: number,
  gap: number,
): number {
  const rcr = m.cornerRadiusMm;
  if (!(rcr > 0) || !(rhoLo > 0) || !(arc > 0)) return Number.NaN;
  const gLo = 0.5 * (p0.inPlane + p1.inPlane - arc / rcr);
  if (!(gLo > 0)) return Number.NaN;
  const kappa = 1 / (rcr * gLo);
  const omega = m.omegaRadPerMm;
  const slope = Math.abs(p0.dpsi - omega * p0.dw) / p0.speed;
  const curv = kappa * (omega + 1 / rhoLo) + 2 / (rhoLo * rhoLo);
  const change = slope * arc + 0.5 * curv * arc * arc;
  if (change < 0.9 * gap) return 1;
  // The arc over which the bound stays below 0.8 gap, as a fraction of this one.
  const s = (0.8 * 2 * gap) / (slope + Math.sqrt(slope * slope + 1.6 * curv * gap));
  return s / arc;
}

/**
 * Which passes can reach global y, with their local coordinates (see toothModel.ts): `x_local =
 * sign (x - shift)`. `marginMm` widens each pass's reach (runout moves every edge point by e).
 */
export function passesAt(
  m: ToothModel,
  xMm: number,
  yMm: number,
  visit: (xLocal: number, yLocal: number, sign: 1 | -1, shiftMm: number) => void,
  marginMm = 0,
): void {
  const L = m.input.intervalMm;
  const right = m.reachRightMm + marginMm;
  const left = m.reachLeftMm + marginMm;
  const reach = Math.max(right, left);
  const shift = m.input.finish.passPhase * m.feedPeriodMm;
  const zigzag = m.input.pattern === 'zigzag';
  const jLo = Math.floor((yMm - reach) / L) - 1;
  const jHi = Math.ceil((yMm + reach) / L) + 1;
  for (let j = jLo; j <= jHi; j++) {
    const odd = zigzag && (j & 1) !== 0;
    const yLocal = odd ? j * L - yMm : yMm - j * L;
    if (!(yLocal < right && yLocal > -left)) continue;
    const xShifted = xMm - j * shift;
    visit(odd ? -xShifted : xShifted, yLocal, odd ? -1 : 1, j * shift);
  }
}

/**
 * The height s(x, y) (mm above the design plane) of the surface the teeth leave at global (x, y):
 * the least event over every pass that reaches the point (Infinity where none does).
 */
export function envelopeHeightMm(m: ToothModel, xMm: number, yMm: number): number {
  const rows: Array<[number, PassRow]> = [];
  passesAt(m, xMm, yMm, (xl, yl) => {
    rows.push([xl, new PassRow(m, yl)]);
  });
  rows.sort((p, q) => p[1].zStar - q[1].zStar);
  let best = Number.POSITIVE_INFINITY;
  for (const [xl, row] of rows) best = passEventMinMm(m, row, xl, best);
  return best;
}
