/**
 * The surface the teeth leave with radial runout e > 0 (shared/notes/surface-finish.md): the tool's
 * own axis is offset from the spindle axis by e at phi_e from tooth 0's half-plane, rotating with the
 * tool. Lengths mm, angles radians.
 *
 * Derivation. Write w(t) = cos t u1 + sin t u2 and v(t) = -sin t u1 + cos t u2 (toothModel.ts's
 * basis about the axis a). Tooth k at tooth angle theta carries its edge point of profile arc length s
 * (radius r(s), height h(s) along a from the tool centre point O) to
 *
 *     E(theta, s) = r w(theta) + e w(theta + phi_k) + h a = p(s) w(theta) + q v(theta) + h(s) a
 *
 * relative to the spindle's O, with phi_k = phi_e - 2 pi k / z (the offset seen from tooth k),
 * p = r + e cos phi_k and q = e sin phi_k: every edge point moves by the same rotating vector, so the
 * tooth is an edge twisted about the spindle axis, and the body of revolution that the e = 0 solver
 * (envelope.ts) walks on is no longer shared by the teeth, nor convex near the axis. So each tooth is
 * taken alone, in the plane of its two parameters (theta, s): at spindle position u tooth k is at
 * theta = -omega u + 2 pi k / z, and its point E lies over the pass-local point (x, y) when
 *
 *     K(theta, s) := E_y - (y - O_y) = 0   and   u = x - E_x,
 *
 * that is theta - omega E_x = -omega x + 2 pi k / z (mod 2 pi). Its height is O_z + E_z. The curve
 * K = 0 (the section of the tooth's swept surface by the plane y) is fixed along a line y = const;
 * only the level -omega x + 2 pi k / z moves with x. The lowest event of a tooth is found by branch
 * and bound over boxes of (theta, s): a box is dropped when it provably holds no point of K = 0
 * (mean-value enclosure of K), none of the levels (enclosure of F = theta - omega E_x), or no point
 * lower than the best event found (a lower bound of E_z on K = 0: the enclosure of E_z - lambda K,
 * lambda chosen at the box's centre so that it is stationary where E_z is on the curve, which makes
 * the bound second order there); a box small enough to hold one level crossing (its Jacobian
 * enclosure regular) is solved by Newton on (K, F - level), and accepted when the root lies in it.
 * The boxes and their x-independent enclosures are kept per line (RunoutTrack), so that the many x
 * of a line share them. Every tooth of every pass that reaches the point is searched, the lowest
 * first, each pruned by the best so far. With e = 0 the same search gives the e = 0 surface (tested
 * against envelope.ts).
 */
import { PassRow, passesAt, envelopeHeightMm as walkHeightMm } from './envelope';
import type { ToothModel } from './toothModel';

const TWO_PI = 2 * Math.PI;
/**
 * A box whose edge points move by at most this much over it (rho dtheta + ds, mm) is taken as an
 * event at its centre when K and F may still meet a level in it (where Newton cannot settle: a level
 * touching the curve): its height is then within about 1e-10 mm of an edge point's over the point,
 * below the 1e-9 mm asked.
 */
const TINY_MM = 1e-10;
/** Boxes of at most this size (rho dtheta + ds, mm) do not keep their children (RunoutTrack.split). */
const CACHED_MM = 1e-6;
/** Most boxes the tracks of one line keep between searches (RunoutRow.heightAt), about 50 MB. */
export const MAX_KEPT = 250000;

/** The profile of an edge by arc length s from the axis: flat bottom, corner, side (up to R above). */
export interface EdgeProfile {
  readonly rb: number;
  readonly rcr: number;
  readonly r: number;
  readonly sArc: number;
  readonly sMax: number;
}

export function edgeProfile(m: ToothModel): EdgeProfile {
  const rb = m.ringRadiusMm;
  const rcr = m.cornerRadiusMm;
  const sArc = rb + (rcr * Math.PI) / 2;
  return { rb, rcr, r: m.toolRadiusMm, sArc, sMax: sArc + m.toolRadiusMm };
}

/** r(s), h(s), r'(s), h'(s) into `out` (side: the piece to the right of a joint unless `left`). */
function profileAt(p: EdgeProfile, s: number, out: Float64Array, left = false): void {
  if (s < p.rb || (left && s === p.rb && p.rb > 0)) {
    out[0] = s;
    out[1] = -p.rcr;
    out[2] = 1;
    out[3] = 0;
    return;
  }
  if (p.rcr > 0 && (s < p.sArc || (left && s === p.sArc))) {
    const t = (s - p.rb) / p.rcr;
    out[0] = p.rb + p.rcr * Math.sin(t);
    out[1] = -p.rcr * Math.cos(t);
    out[2] = Math.cos(t);
    out[3] = Math.sin(t);
    return;
  }
  out[0] = p.r;
  out[1] = s - p.sArc;
  out[2] = 0;
  out[3] = 1;
}

/**
 * Lower and upper ends of U cos over [a, b] given its values at the ends (`ya`, `yb`): -U or U where a
 * minimum (pi + 2 pi n) or maximum (2 pi n) lies inside.
 */
function scaledCosRange(a: number, b: number, ya: number, yb: number, U: number, out: Float64Array, at: number): void {
  if (b - a >= TWO_PI) {
    out[at] = -U;
    out[at + 1] = U;
    return;
  }
  out[at] = Math.ceil((a - Math.PI) / TWO_PI) * TWO_PI + Math.PI <= b ? -U : Math.min(ya, yb);
  out[at + 1] = Math.ceil(a / TWO_PI) * TWO_PI <= b ? U : Math.max(ya, yb);
}

/** Lower and upper ends of [a0, a1] x [b0, b1]. */
function mulLo(a0: number, a1: number, b0: number, b1: number): number {
  return Math.min(a0 * b0, a0 * b1, a1 * b0, a1 * b1);
}
function mulHi(a0: number, a1: number, b0: number, b1: number): number {
  return Math.max(a0 * b0, a0 * b1, a1 * b0, a1 * b1);
}

/** Magnitude bounds of a pair, returned by `partials` (read at once). */
const MAG: [number, number] = [0, 0];

/**
 * For a direction nu (components n1, n2 of u1, u2 and an of a along it) and f = E . nu over the box
 * [t0, t1] x (p, r', h' in their ranges): f_theta = p S - q C and f_s = r' C + h' a_nu, with
 * C = U cos(theta - g), S = U cos(theta - g + pi/2). Their ranges go to CS[4..7]; the magnitude
 * bounds are returned (in MAG).
 */
function partials(
  t0: number,
  t1: number,
  pLo: number,
  pHi: number,
  q: number,
  drLo: number,
  drHi: number,
  dhLo: number,
  dhHi: number,
  n1: number,
  n2: number,
  an: number,
): [number, number] {
  const U = Math.hypot(n1, n2);
  const g = Math.atan2(n2, n1);
  // C = U cos(theta - g) = n1 cos theta + n2 sin theta and S = -U sin(theta - g), from the cosines and
  // sines of the box's ends (BOX_TRIG), with U or -U where a maximum or minimum lies inside.
  const c0 = BOX_TRIG[0] as number;
  const s0 = BOX_TRIG[1] as number;
  const c1 = BOX_TRIG[2] as number;
  const s1 = BOX_TRIG[3] as number;
  scaledCosRange(t0 - g, t1 - g, n1 * c0 + n2 * s0, n1 * c1 + n2 * s1, U, CS, 0);
  scaledCosRange(t0 - g + Math.PI / 2, t1 - g + Math.PI / 2, n2 * c0 - n1 * s0, n2 * c1 - n1 * s1, U, CS, 2);
  const cLo = CS[0] as number;
  const cHi = CS[1] as number;
  const sLo = CS[2] as number;
  const sHi = CS[3] as number;
  const ftLo = mulLo(pLo, pHi, sLo, sHi) - Math.max(q * cLo, q * cHi);
  const ftHi = mulHi(pLo, pHi, sLo, sHi) - Math.min(q * cLo, q * cHi);
  const fsLo = mulLo(drLo, drHi, cLo, cHi) + Math.min(dhLo * an, dhHi * an);
  const fsHi = mulHi(drLo, drHi, cLo, cHi) + Math.max(dhLo * an, dhHi * an);
  CS[4] = ftLo;
  CS[5] = ftHi;
  CS[6] = fsLo;
  CS[7] = fsHi;
  MAG[0] = Math.max(Math.abs(ftLo), Math.abs(ftHi));
  MAG[1] = Math.max(Math.abs(fsLo), Math.abs(fsHi));
  return MAG;
}

/** One box of (theta, s) with its x-independent enclosures. */
class Box {
  /** Centre and half-widths. */
  tc = 0;
  sc = 0;
  dt = 0;
  ds = 0;
  /** K, E_x, E_z at the centre and the partial derivatives there. */
  k = 0;
  w = 0;
  z = 0;
  kt = 0;
  ks = 0;
  wt = 0;
  ws = 0;
  zt = 0;
  zs = 0;
  /** Radius of the enclosure of K; whether K = 0 can meet the box. */
  kRad = 0;
  meets = false;
  /** Lower bound of the height on K = 0 in the box (mm, O_z included). */
  zLo = 0;
  /** F = theta - omega E_x at the centre and the radius of its enclosure. */
  f = 0;
  fRad = 0;
  /** G = F - mu K at the centre and the radius of its enclosure (F on the curve K = 0; see box). */
  g = 0;
  gRad = 0;
  /** Largest distance from the spindle axis of the box's edge points (theta moves them by rho dtheta). */
  rho = 0;
  /** Whether the Jacobian of (K, F) is provably regular over the box. */
  regular = false;
  children: [Box, Box] | null = null;
}

/** The ranges over the box being built (RunoutTrack.box): t0, t1, p, q, r', h' (see partials). */
const BOX_RANGES = new Float64Array(9);
/** cos t0, sin t0, cos t1, sin t1 of the box being built. */
const BOX_TRIG = new Float64Array(4);

/** The partials of E . nu over the box of BOX_RANGES, nu given by its components along u1, u2 and a. */
function along(n1: number, n2: number, an: number): [number, number] {
  const r = BOX_RANGES;
  return partials(
    r[0] as number,
    r[1] as number,
    r[2] as number,
    r[3] as number,
    r[4] as number,
    r[5] as number,
    r[6] as number,
    r[7] as number,
    r[8] as number,
    n1,
    n2,
    an,
  );
}

/** Scratch for the interval evaluations. */
const PR = new Float64Array(4);
const PR0 = new Float64Array(4);
const PR1 = new Float64Array(4);
const CS = new Float64Array(8);

/**
 * One tooth of one pass along one line y = const (pass-local y): its boxes, built as searches need
 * them, shared by every x of the line.
 */
export class RunoutTrack {
  private readonly m: ToothModel;
  private readonly prof: EdgeProfile;
  /** Pass-local y relative to O. */
  private readonly yRel: number;
  private readonly p0: number;
  private readonly q: number;
  /** Level offset of this tooth: 2 pi k / z. */
  readonly levelOffset: number;
  private readonly roots: Box[] = [];
  /** Boxes the tracks of one line made and keep (shared), for the bound on the trees kept (RunoutRow). */
  private readonly counter: { made: number; kept: number };
  /** Bound of the distance of any edge point from the axis. */
  private readonly rhoMax: number;
  private readonly scale: number;
  /** A lower bound of the height anywhere on the curve (the least of the roots' bounds). */
  readonly floorBound: number;
  /** A tighter lower bound of the height on the curve, set by the line (RunoutRow). */
  floor = Number.NEGATIVE_INFINITY;
  private minCache = Number.NaN;
  /** Where the last event that lowered `best` in lowestEvent lies: theta, s. */
  eventTheta = Number.NaN;
  eventS = Number.NaN;

  /** Pass-local y of the line and the tooth's index. */
  readonly yLocalMm: number;
  readonly tooth: number;

  /** With `boxes` false the track has no boxes (no search): it only follows events (followEvent). */
  constructor(m: ToothModel, yLocalMm: number, tooth: number, counter = { made: 0, kept: 0 }, boxes = true) {
    this.m = m;
    this.counter = counter;
    this.yLocalMm = yLocalMm;
    this.tooth = tooth;
    this.prof = edgeProfile(m);
    this.yRel = yLocalMm - m.centreYMm;
    const f = m.input.finish;
    const phik = (f.runoutPhaseDeg * Math.PI) / 180 - (TWO_PI * tooth) / f.flutes;
    this.p0 = f.runoutMm * Math.cos(phik);
    this.q = f.runoutMm * Math.sin(phik);
    this.levelOffset = (TWO_PI * tooth) / f.flutes;
    this.rhoMax = m.toolRadiusMm + f.runoutMm;
    this.scale = m.toolRadiusMm;
    const cuts = [0];
    const p = this.prof;
    if (p.rb > 0) cuts.push(p.rb);
    if (p.rcr > 0) cuts.push(p.sArc);
    cuts.push(p.sMax);
    const nt = 12;
    let floor = Number.POSITIVE_INFINITY;
    for (let i = 0; boxes && i + 1 < cuts.length; i++) {
      const a = cuts[i] as number;
      const b = cuts[i + 1] as number;
      const ns = 4;
      for (let js = 0; js < ns; js++) {
        for (let jt = 0; jt < nt; jt++) {
          const box = this.box(
            (TWO_PI * jt) / nt,
            (TWO_PI * (jt + 1)) / nt,
            a + ((b - a) * js) / ns,
            a + ((b - a) * (js + 1)) / ns,
          );
          if (box.meets) {
            this.roots.push(box);
            floor = Math.min(floor, box.zLo);
          }
        }
      }
    }
    this.floorBound = floor;
    // Lowest bound first: a search takes the roots in this order, merged with its heap (lowestEvent).
    this.roots.sort((a, b) => a.zLo - b.zLo);
  }

  /** Lets go of the boxes its searches kept (their children), back to its roots. */
  forget(): void {
    for (const b of this.roots) b.children = null;
  }

  /** Distance from the spindle axis of the edge point at s: |r(s) + e e^(i phi_k)|, mm. */
  radiusAt(s: number): number {
    profileAt(this.prof, s, PR);
    return Math.hypot((PR[0] as number) + this.p0, this.q);
  }

  /** Evaluates E at (theta, s) into the fields of `b` (centre values and partials). */
  private centre(b: Box, theta: number, s: number): void {
    const m = this.m;
    profileAt(this.prof, s, PR);
    const r = PR[0] as number;
    const h = PR[1] as number;
    const dr = PR[2] as number;
    const dh = PR[3] as number;
    const p = r + this.p0;
    const q = this.q;
    const c = Math.cos(theta);
    const sn = Math.sin(theta);
    const u1 = m.u1;
    const u2 = m.u2;
    const a = m.axis;
    // w and v at theta, components x, y, z.
    const wx = c * u1[0] + sn * u2[0];
    const wy = c * u1[1] + sn * u2[1];
    const wz = c * u1[2] + sn * u2[2];
    const vx = -sn * u1[0] + c * u2[0];
    const vy = -sn * u1[1] + c * u2[1];
    const vz = -sn * u1[2] + c * u2[2];
    b.tc = theta;
    b.sc = s;
    b.k = p * wy + q * vy + h * a[1] - this.yRel;
    b.w = p * wx + q * vx + h * a[0];
    b.z = m.centreZMm + p * wz + q * vz + h * a[2];
    // d w / d theta = v, d v / d theta = -w.
    b.kt = p * vy - q * wy;
    b.wt = p * vx - q * wx;
    b.ks = dr * wy + dh * a[1];
    b.ws = dr * wx + dh * a[0];
    b.zt = p * vz - q * wz;
    b.zs = dr * wz + dh * a[2];
  }

  /** A box over [t0, t1] x [s0, s1] with its enclosures. */
  private box(t0: number, t1: number, s0: number, s1: number): Box {
    const b = new Box();
    this.counter.made++;
    const m = this.m;
    const tc = 0.5 * (t0 + t1);
    const sc = 0.5 * (s0 + s1);
    this.centre(b, tc, sc);
    const zt = b.zt;
    const zs = b.zs;
    b.dt = 0.5 * (t1 - t0);
    b.ds = 0.5 * (s1 - s0);
    // Profile ranges over [s0, s1]: r, h nondecreasing, r' nonincreasing, h' nondecreasing.
    profileAt(this.prof, s0, PR0);
    profileAt(this.prof, s1, PR1, true);
    const pLo = (PR0[0] as number) + this.p0;
    const pHi = (PR1[0] as number) + this.p0;
    b.rho = Math.sqrt(Math.max(pLo * pLo, pHi * pHi) + this.q * this.q);
    const drLo = PR1[2] as number;
    const drHi = PR0[2] as number;
    const dhLo = PR0[3] as number;
    const dhHi = PR1[3] as number;
    const q = this.q;
    const u1 = m.u1;
    const u2 = m.u2;
    const a = m.axis;
    const ranges = BOX_RANGES;
    ranges[0] = t0;
    ranges[1] = t1;
    ranges[2] = pLo;
    ranges[3] = pHi;
    ranges[4] = q;
    ranges[5] = drLo;
    ranges[6] = drHi;
    ranges[7] = dhLo;
    ranges[8] = dhHi;
    BOX_TRIG[0] = Math.cos(t0);
    BOX_TRIG[1] = Math.sin(t0);
    BOX_TRIG[2] = Math.cos(t1);
    BOX_TRIG[3] = Math.sin(t1);
    const [ktMag, ksMag] = along(u1[1], u2[1], a[1]);
    b.kRad = ktMag * b.dt + ksMag * b.ds;
    b.meets = Math.abs(b.k) <= b.kRad * (1 + 1e-12) + 1e-15 * this.scale;
    if (!b.meets) return b;
    const ktLo = CS[4] as number;
    const ktHi = CS[5] as number;
    const ksLo = CS[6] as number;
    const ksHi = CS[7] as number;
    // The height on the curve: E_z - lambda K, lambda from the centre's gradients (metric rho^2).
    const r2 = this.rhoMax * this.rhoMax;
    const den = b.kt * b.kt + r2 * b.ks * b.ks;
    const lambda = den > 0 ? (zt * b.kt + r2 * zs * b.ks) / den : 0;
    const [ztMag, zsMag] = along(u1[2] - lambda * u1[1], u2[2] - lambda * u2[1], a[2] - lambda * a[1]);
    b.zLo = b.z - lambda * b.k - (ztMag * b.dt + zsMag * b.ds) * (1 + 1e-12) - 1e-15 * this.scale;
    const wsMag = along(u1[0], u2[0], a[0])[1];
    const wtLo = CS[4] as number;
    const wtHi = CS[5] as number;
    const wsLo = CS[6] as number;
    const wsHi = CS[7] as number;
    const omega = m.omegaRadPerMm;
    // F_theta = 1 - omega W_theta, F_s = -omega W_s.
    const ftLo = 1 - omega * wtHi;
    const ftHi = 1 - omega * wtLo;
    b.f = tc - omega * b.w;
    b.fRad = (Math.max(Math.abs(ftLo), Math.abs(ftHi)) * b.dt + omega * wsMag * b.ds) * (1 + 1e-12);
    // det = K_theta F_s - K_s F_theta over the box.
    const fsLo = -omega * wsHi;
    const fsHi = -omega * wsLo;
    const dLo = mulLo(ktLo, ktHi, fsLo, fsHi) - mulHi(ksLo, ksHi, ftLo, ftHi);
    const dHi = mulHi(ktLo, ktHi, fsLo, fsHi) - mulLo(ksLo, ksHi, ftLo, ftHi);
    b.regular = dLo > 0 || dHi < 0;
    // F on the curve K = 0 is G = F - mu K for any mu; mu from the centre's gradients (metric rho^2)
    // makes G stationary across the curve, so its enclosure's radius is about F's rate along the curve
    // times the box: where a level touches the curve (F - level with a double root along it) boxes
    // beside the touching point are dropped at about their distance from it, not at its square.
    const gt = 1 - omega * b.wt;
    const gs = -omega * b.ws;
    const mu = den > 0 ? (gt * b.kt + r2 * gs * b.ks) / den : 0;
    along(omega * u1[0] + mu * u1[1], omega * u2[0] + mu * u2[1], omega * a[0] + mu * a[1]);
    const gtMag = Math.max(Math.abs(1 - (CS[4] as number)), Math.abs(1 - (CS[5] as number)));
    const gsMag = Math.max(Math.abs(CS[6] as number), Math.abs(CS[7] as number));
    b.g = b.f - mu * b.k;
    b.gRad = (gtMag * b.dt + gsMag * b.ds) * (1 + 1e-12);
    return b;
  }

  private split(b: Box): [Box, Box] {
    if (b.children !== null) return b.children;
    const t0 = b.tc - b.dt;
    const t1 = b.tc + b.dt;
    const s0 = b.sc - b.ds;
    const s1 = b.sc + b.ds;
    const kids: [Box, Box] =
      b.dt * b.rho > b.ds
        ? [this.box(t0, b.tc, s0, s1), this.box(b.tc, t1, s0, s1)]
        : [this.box(t0, t1, s0, b.sc), this.box(t0, t1, b.sc, s1)];
    // Only boxes coarser than CACHED_MM keep their children for the line's other searches: where a
    // level touches the curve K = 0 (F - level has a double root along it) a search splits a strip
    // of boxes down to TINY_MM, about (size / TINY_MM)^(1/2) of them (0.1 to 0.9 million seen at a
    // large fz with runout), which kept would grow without bound over a line's searches.
    if (b.dt * b.rho + b.ds > CACHED_MM) {
      b.children = kids;
      this.counter.kept += 2;
    }
    return kids;
  }

  private tiny(b: Box): boolean {
    return b.dt * b.rho + b.ds <= TINY_MM;
  }

  /**
   * The lowest event of this tooth at pass-local x, or `best` when none is lower (mm).
   */
  lowestEvent(xLocalMm: number, best: number): number {
    if (this.floorBound >= best || this.floor >= best) return best;
    const omega = this.m.omegaRadPerMm;
    // Levels: F = c0 (mod 2 pi); reduce omega x first (it can be large).
    const c0 = this.levelOffset - ((((omega * xLocalMm) % TWO_PI) + TWO_PI) % TWO_PI);
    const heap = HEAP;
    heap.clear();
    // The roots (sorted by their bound) enter the search as it reaches them, not all at its start.
    const roots = this.roots;
    let next = 0;
    this.eventTheta = Number.NaN;
    for (;;) {
      const root = roots[next];
      const top = heap.peek();
      const b = root !== undefined && (top === undefined || root.zLo <= top.zLo) ? roots[next++] : heap.pop();
      if (b === undefined || b.zLo >= best) break;
      const n = Math.round((b.f - c0) / TWO_PI);
      const level = c0 + TWO_PI * n;
      if (Math.abs(b.f - level) > b.fRad) continue;
      if (b.gRad < Math.PI) {
        const gap = Math.abs(b.g - c0 - TWO_PI * Math.round((b.g - c0) / TWO_PI));
        if (gap > b.gRad) continue;
      }
      if (b.fRad < Math.PI && b.regular) {
        const z = this.solve(b, level);
        if (!Number.isNaN(z)) {
          if (z < best) {
            best = z;
            this.eventTheta = SOLVE.tc;
            this.eventS = SOLVE.sc;
          }
          continue;
        }
      }
      if (this.tiny(b)) {
        if (b.z < best) {
          best = b.z;
          this.eventTheta = b.tc;
          this.eventS = b.sc;
        }
        continue;
      }
      const [l, r] = this.split(b);
      if (l.meets) heap.push(l);
      if (r.meets) heap.push(r);
    }
    return best;
  }

  /**
   * Newton on (K, F - level) from the box's centre: the root's height when it lies in the box
   * (then the only one there: the Jacobian is regular over it), else NaN.
   */
  private solve(b: Box, level: number): number {
    const omega = this.m.omegaRadPerMm;
    const e = SOLVE;
    let t = b.tc;
    let s = b.sc;
    let k = b.k;
    let f = b.f - level;
    let kt = b.kt;
    let ks = b.ks;
    let ft = 1 - omega * b.wt;
    let fs = -omega * b.ws;
    for (let it = 0; it < 40; it++) {
      const det = kt * fs - ks * ft;
      if (!(det !== 0)) return Number.NaN;
      const dtStep = -(fs * k - ks * f) / det;
      const dsStep = -(-ft * k + kt * f) / det;
      t += dtStep;
      s += dsStep;
      if (Math.abs(t - b.tc) > 2 * b.dt + 1e-12 || Math.abs(s - b.sc) > 2 * b.ds + 1e-12 * this.scale)
        return Number.NaN;
      this.centre(e, t, s);
      k = e.k;
      f = t - omega * e.w - level;
      kt = e.kt;
      ks = e.ks;
      ft = 1 - omega * e.wt;
      fs = -omega * e.ws;
      if (Math.abs(dtStep) * this.rhoMax + Math.abs(dsStep) <= 1e-14 * this.scale) {
        const tolT = b.dt * 1e-9 + 1e-15;
        const tolS = b.ds * 1e-9 + 1e-15 * this.scale;
        if (Math.abs(t - b.tc) > b.dt + tolT || Math.abs(s - b.sc) > b.ds + tolS) return Number.NaN;
        if (s < 0 || s > this.prof.sMax) return Number.NaN;
        return e.z;
      }
    }
    return Number.NaN;
  }

  /**
   * The event of this tooth at pass-local x followed from an edge point (theta, s) of a nearby x (the
   * same bite: Newton on (K, F - level) from it, the level the nearest to F there): its height, with
   * its place in eventTheta, eventS; NaN when Newton does not settle on the edge. It need not be the
   * tooth's lowest event at x (lowestEvent), only one of its events: runoutLine.ts checks the bites it
   * follows against the search.
   */
  followEvent(xLocalMm: number, theta: number, s: number): number {
    const omega = this.m.omegaRadPerMm;
    const c0 = this.levelOffset - ((((omega * xLocalMm) % TWO_PI) + TWO_PI) % TWO_PI);
    const e = SOLVE;
    let t = theta;
    let u = s;
    this.centre(e, t, u);
    const level = c0 + TWO_PI * Math.round((t - omega * e.w - c0) / TWO_PI);
    for (let it = 0; it < 30; it++) {
      const k = e.k;
      const f = t - omega * e.w - level;
      const ft = 1 - omega * e.wt;
      const fs = -omega * e.ws;
      const det = e.kt * fs - e.ks * ft;
      if (!(det !== 0)) return Number.NaN;
      const dtStep = -(fs * k - e.ks * f) / det;
      const dsStep = -(-ft * k + e.kt * f) / det;
      t += dtStep;
      u += dsStep;
      if (!(Math.abs(dtStep) * this.rhoMax + Math.abs(dsStep) <= this.scale)) return Number.NaN;
      this.centre(e, t, u);
      if (Math.abs(dtStep) * this.rhoMax + Math.abs(dsStep) <= 1e-14 * this.scale) {
        if (u < 0 || u > this.prof.sMax) return Number.NaN;
        this.eventTheta = t;
        this.eventS = u;
        return e.z;
      }
    }
    return Number.NaN;
  }

  /**
   * The lowest point of the curve K = 0 (the tooth's lowest height on this line, whatever x), mm, to
   * `tol` (mm): with `bound` the search's rigorous lower bound, else the height of a point on the
   * curve (within `tol` above the lowest).
   */
  lowestPoint(tol = 1e-13 * this.scale, bound = false): number {
    if (!bound && !Number.isNaN(this.minCache)) return this.minCache;
    let best = Number.POSITIVE_INFINITY;
    const heap = new BoxHeap();
    for (const b of this.roots) heap.push(b);
    const e = SOLVE;
    let lowest = Number.POSITIVE_INFINITY;
    for (;;) {
      const b = heap.pop();
      if (b === undefined) break;
      if (b.zLo >= best - tol) {
        lowest = b.zLo;
        break;
      }
      // An upper bound: the centre moved onto the curve (Newton on K along its gradient).
      let t = b.tc;
      let s = b.sc;
      this.centre(e, t, s);
      for (let it = 0; it < 8 && Math.abs(e.k) > 1e-15 * this.scale; it++) {
        const g2 = e.kt * e.kt + e.ks * e.ks;
        if (!(g2 > 0)) break;
        t -= (e.k * e.kt) / g2;
        s -= (e.k * e.ks) / g2;
        if (Math.abs(t - b.tc) > b.dt || Math.abs(s - b.sc) > b.ds) break;
        this.centre(e, t, s);
      }
      if (Math.abs(e.k) <= 1e-14 * this.scale && Math.abs(t - b.tc) <= b.dt && Math.abs(s - b.sc) <= b.ds)
        best = Math.min(best, e.z);
      if (this.tiny(b)) continue;
      const [l, r] = this.split(b);
      if (l.meets) heap.push(l);
      if (r.meets) heap.push(r);
    }
    if (bound) return Math.min(lowest, best);
    this.minCache = best;
    return best;
  }
}

const SOLVE = new Box();

/** A binary heap of boxes by their lower bound. */
class BoxHeap {
  private readonly a: Box[] = [];
  clear(): void {
    this.a.length = 0;
  }
  push(b: Box): void {
    const a = this.a;
    a.push(b);
    let i = a.length - 1;
    while (i > 0) {
      const p = (i - 1) >> 1;
      if ((a[p] as Box).zLo <= b.zLo) break;
      a[i] = a[p] as Box;
      i = p;
    }
    a[i] = b;
  }
  /** The box with the least bound, left in the heap. */
  peek(): Box | undefined {
    return this.a[0];
  }
  pop(): Box | undefined {
    const a = this.a;
    if (a.length === 0) return undefined;
    const top = a[0] as Box;
    const last = a.pop() as Box;
    if (a.length > 0) {
      let i = 0;
      for (;;) {
        const l = 2 * i + 1;
        if (l >= a.length) break;
        const r = l + 1;
        const c = r < a.length && (a[r] as Box).zLo < (a[l] as Box).zLo ? r : l;
        if ((a[c] as Box).zLo >= last.zLo) break;
        a[i] = a[c] as Box;
        i = c;
      }
      a[i] = last;
    }
    return top;
  }
}

/** One tooth of one pass on a line: its track and how global x maps to its local x. */
interface TrackOnLine {
  readonly track: RunoutTrack;
  readonly sign: 1 | -1;
  readonly shiftMm: number;
  /** Its place in the order the line built its tracks (a stable name: `lastTrack`). */
  readonly id: number;
}

/** A pass that reaches a line, its teeth not yet prepared, with a lower bound of its heights there. */
interface PendingPass {
  readonly yLocal: number;
  readonly sign: 1 | -1;
  readonly shiftMm: number;
  readonly boundMm: number;
}

/**
 * A lower bound (mm) of every height a pass's teeth reach on the pass-local line y with runout e:
 * every edge point is the e = 0 edge point (on the body of revolution) moved by a vector of length e,
 * so it lies over some y' within e of y, at most e lower than the body's lowest point over y'
 * (PassRow.zStar, a convex function of y' least on the CC path y' = 0, where it is 0).
 */
function passBoundMm(m: ToothModel, yLocal: number): number {
  const e = m.input.finish.runoutMm;
  if (Math.abs(yLocal) <= e) return -e;
  return new PassRow(m, yLocal - Math.sign(yLocal) * e).zStar - e;
}

/**
 * Every tooth of every pass that reaches a line y = const (global), lowest first. A pass's teeth are
 * prepared (their boxes and floors: the costly part) only when a search needs them: when its lower
 * bound (passBoundMm) lies below the best height found so far, nearest passes first.
 */
export class RunoutRow {
  private readonly m: ToothModel;
  /** The prepared teeth, by floor. */
  private readonly list: TrackOnLine[] = [];
  /** The prepared teeth, by id. */
  private readonly byId: TrackOnLine[] = [];
  /** The passes not yet prepared, by lower bound (highest first: the next is the last). */
  private readonly pending: PendingPass[] = [];
  /** Boxes its tracks made and keep (RunoutTrack.box, split), for the bound MAX_KEPT. */
  private readonly counter = { made: 0, kept: 0 };

  constructor(m: ToothModel, yMm: number) {
    this.m = m;
    passesAt(
      m,
      0,
      yMm,
      (_x, yLocal, sign, shiftMm) => {
        const boundMm = passBoundMm(m, yLocal);
        if (boundMm < Number.POSITIVE_INFINITY) this.pending.push({ yLocal, sign, shiftMm, boundMm });
      },
      m.input.finish.runoutMm,
    );
    this.pending.sort((p, q) => q.boundMm - p.boundMm);
  }

  /** Boxes its tracks made, and those they keep between searches (at most MAX_KEPT past a search). */
  boxes(): { readonly made: number; readonly kept: number } {
    return { made: this.counter.made, kept: this.counter.kept };
  }

  /** The prepared teeth, lowest floor first (the passes prepared so far). */
  get tracks(): readonly TrackOnLine[] {
    return this.list;
  }

  /** Prepares the next pending pass's teeth when its bound lies below `best`; whether it did. */
  private prepareBelow(best: number): boolean {
    const next = this.pending[this.pending.length - 1];
    if (next === undefined || !(next.boundMm < best)) return false;
    this.pending.pop();
    const m = this.m;
    for (let k = 0; k < m.input.finish.flutes; k++) {
      const track = new RunoutTrack(m, next.yLocal, k, this.counter);
      if (!Number.isFinite(track.floorBound)) continue;
      // Each tooth's floor on this line, a rigorous lower bound to 1e-4 R: a tooth whose floor is at
      // or above the best event so far cannot lower it.
      track.floor = track.lowestPoint(1e-4 * m.toolRadiusMm, true);
      const t = { track, sign: next.sign, shiftMm: next.shiftMm, id: this.byId.length };
      this.byId.push(t);
      this.list.push(t);
    }
    this.list.sort((p, q) => p.track.floor - q.track.floor);
    return true;
  }

  /** Which track's event the last heightAt returned (its id; -1: none) and where on its edge: theta, s. */
  lastTrack = -1;
  lastTheta = Number.NaN;
  lastS = Number.NaN;

  /** The distance from the spindle axis of the last event's edge point (heightAt), mm. */
  lastRho(): number {
    const t = this.byId[this.lastTrack];
    return t === undefined ? 0 : t.track.radiusAt(this.lastS);
  }

  /** Heights already found on this line, by x (with their event), for the pieces' nodes. */
  private readonly known = new Map<number, [number, number, number, number]>();

  /** s(x, y) on this line, mm (Infinity where no tooth reaches). */
  heightAt(xMm: number): number {
    const seen = this.known.get(xMm);
    if (seen !== undefined) {
      this.lastTrack = seen[1];
      this.lastTheta = seen[2];
      this.lastS = seen[3];
      return seen[0];
    }
    // The boxes the line's tracks keep are bounded: past MAX_KEPT they start again from their roots.
    if (this.counter.kept > MAX_KEPT) {
      for (const t of this.list) t.track.forget();
      this.counter.kept = 0;
    }
    let best = Number.POSITIVE_INFINITY;
    this.lastTrack = -1;
    // The prepared teeth (a sort may reorder them: each is searched once per round), then the next
    // pass whose bound lies below the best, until none does.
    const searched = new Set<number>();
    do {
      for (const t of this.list) {
        if (t.track.floor >= best) break;
        if (searched.has(t.id)) continue;
        searched.add(t.id);
        const h = t.track.lowestEvent(t.sign * (xMm - t.shiftMm), best);
        if (h < best) {
          best = h;
          this.lastTrack = t.id;
          this.lastTheta = t.track.eventTheta;
          this.lastS = t.track.eventS;
        }
      }
    } while (this.prepareBelow(best));
    if (this.known.size < 20000) this.known.set(xMm, [best, this.lastTrack, this.lastTheta, this.lastS]);
    return best;
  }

  /** Track `id` without its boxes (it only follows events) and how global x maps to its local x. */
  bareTrack(id: number): { readonly track: RunoutTrack; readonly sign: 1 | -1; readonly shiftMm: number } | undefined {
    const t = this.byId[id];
    if (t === undefined) return undefined;
    const track = new RunoutTrack(this.m, t.track.yLocalMm, t.track.tooth, undefined, false);
    return { track, sign: t.sign, shiftMm: t.shiftMm };
  }

  /**
   * The height at x of the bite of track `id` through its edge point (theta, s) at a nearby x
   * (RunoutTrack.followEvent), NaN where it cannot be followed; its place in lastTheta, lastS.
   */
  followBite(id: number, xMm: number, theta: number, s: number): number {
    const t = this.byId[id];
    if (t === undefined) return Number.NaN;
    const h = t.track.followEvent(t.sign * (xMm - t.shiftMm), theta, s);
    this.lastTrack = id;
    this.lastTheta = t.track.eventTheta;
    this.lastS = t.track.eventS;
    return h;
  }

  /** The lowest height of the line over all x: the least of its teeth's lowest points, mm. */
  lowestMm(): number {
    let best = Number.POSITIVE_INFINITY;
    const searched = new Set<number>();
    do {
      for (const t of this.list) {
        if (searched.has(t.id)) continue;
        searched.add(t.id);
        if (t.track.floorBound < best) best = Math.min(best, t.track.lowestPoint());
      }
    } while (this.prepareBelow(best));
    return best;
  }
}

/**
 * The height s(x, y) (mm above the design plane) of the surface the teeth leave at global (x, y):
 * with runout by the search above, without by the e = 0 walk (envelope.ts).
 */
export function envelopeHeightMm(m: ToothModel, xMm: number, yMm: number): number {
  return m.input.finish.runoutMm > 0 ? new RunoutRow(m, yMm).heightAt(xMm) : walkHeightMm(m, xMm, yMm);
}

/** The search above whatever the runout (with e = 0 it answers the e = 0 surface: a check of both). */
export function runoutEnvelopeHeightMm(m: ToothModel, xMm: number, yMm: number): number {
  return new RunoutRow(m, yMm).heightAt(xMm);
}

const HEAP = new BoxHeap();
