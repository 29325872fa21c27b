/**
 * High-precision (decimal.js, 64 significant digits by default) reference for the
 * cross-feed profile of a filleted (bull-nose) end mill in any posture on a plane.
 *
 * Written independently of the solvers in `src/core`; it shares no code with them.
 *
 * ## Conventions (notes/geometry.md, notes/posture-and-surfaces.md)
 * Local frame: X feed, Z surface normal (up), Y = Z x X. Lead `rho`, tilt `beta` (degrees),
 * tool axis `a = (cos(beta) sin(rho), sin(beta), cos(beta) cos(rho))`. Tool radius `R`,
 * corner radius `Rcr`, `Rb = R - Rcr`. The tool end is the disk of radius `Rb` (centre `O`,
 * normal `a`) grown by a ball of radius `Rcr`; the shank is the cylinder of radius `R` about
 * `a` at axial coordinates >= 0 from `O`. All heights are above the contact point, all
 * widths are horizontal (Y) distances from the contact point, in mm.
 *
 * ## Derivation
 * The tool translates along X, so the surface it leaves is bounded by the projection of the
 * tool along X onto the YZ plane. Write `a' = (a_y, a_z)` (the projected axis; `|a'|^2 =
 * 1 - a_x^2`). The disk projects onto a filled ellipse (a segment when `a_x = 0`), the image of
 * the disk under the 2x2 map `M = P [u v]` (`u, v` an orthonormal basis of the disk plane,
 * `P` drops x). The tool end projects onto that ellipse grown by a disk of radius `Rcr`: a
 * convex set `S`. Its support function, for a (not necessarily unit) direction `n` in YZ, is
 *
 *     H(n) = Rb |M^T n| + Rcr |n|,   |M^T n|^2 = |n|^2 - (a'.n)^2 = s^2 + a_x^2 |n|^2,
 *     s = a_y n_z - a_z n_y   (|a x (0, n_y, n_z)|^2, free of cancellation).
 *
 * The boundary point of `S` with outward normal `n` is the gradient of `H`:
 *
 *     p(n) = Rb (a_x^2 n + s a'perp) / sqrt(s^2 + a_x^2 |n|^2) + Rcr n / |n|,
 *     a'perp = (-a_z, a_y)
 *
 * (using `|a'|^2 n = (a'.n) a' + s a'perp`, so `n - a'(a'.n) = a_x^2 n + s a'perp`; where the
 * root is 0 the projected disk is a segment seen along its normal, and `p` returns the
 * segment's midpoint, the boundary there being the whole straight piece). The profile (the
 * lower boundary) runs from the leftmost point (`n = (-1, 0)`) through the lowest point, the
 * contact (`n = (0, -1)`), to the rightmost (`n = (1, 0)`). Along each flank both coordinates
 * are monotone in the direction of `n`, parametrised here as `n = (+-t, t - 1)`, `t` in [0, 1];
 * a height or a width is found by a bracketing root finder on `t` (to the working precision),
 * and the last bracket is closed by linear interpolation between its two boundary points;
 * the straight pieces (the flat bottom, the disk seen edge-on, where `p` jumps) are
 * interpolated exactly between their ends.
 *
 * Closed forms that follow (with `c = a'.n` for the unit normal `n`):
 * - contact: `y0 = Rb a_y a_z / sqrt(a_x^2 + a_y^2)`, `z0 = -Rb sqrt(a_x^2 + a_y^2) - Rcr`
 *   (relative to `O`; `y0 = 0` for the flat bottom `a_x = a_y = 0`, its midpoint);
 * - widest points: `hmaxR/L = Rb sqrt(a_x^2 + a_y^2) + Rcr -+ Rb a_y a_z / sqrt(1 - a_y^2)`;
 * - radius of curvature at the boundary point of unit normal `n`:
 *   `H + H'' = Rb a_x^2 / (1 - c^2)^(3/2) + Rcr`; at the contact `c = -a_z`:
 *   `Rb a_x^2 / (a_x^2 + a_y^2)^(3/2) + Rcr` (Redonnet's `Rb / sin(rho) + Rcr` at beta = 0);
 * - the shank: the whole tool (end and shank) is convex and its support in a direction `n`
 *   with `a.(0, n) > 0` is infinite, with `a.(0, n) <= 0` the end's. So the shank's projection
 *   (the projected equator ellipse swept along `a'`) leaves the end's boundary at the point of
 *   normal `n_J` perpendicular to `a'`, which is the equator point `p = R n_J` (exactly). On
 *   the side the shank leans to (`a_y > 0`: right) `n_J = (a_z, -a_y)/|a'|` points below the
 *   horizontal, so the shank becomes the lower boundary from the height
 *   `hShank = Rb sqrt(a_x^2 + a_y^2) + Rcr - R |a_y| / sqrt(a_y^2 + a_z^2)` upwards, as the
 *   straight half-line of direction `a'`; `R (1 - sin|beta'|)` for a ball end, `sin beta' =
 *   |a_y| / |a'|` the lean seen along the feed; `Rcr (1 - sin|beta|)` at rho = 0. On the
 *   other side the junction lies above the widest point (on the wall).
 *
 * ## Precision
 * Inputs are read as their shortest decimal representation (`new Decimal(0.05)` is 0.05).
 * Coordinates are computed relative to O to about R 10^-digits; heights and widths are
 * differences from the contact, so h = 1e-12 hmax costs 12 digits, and a flank much smaller
 * than R (a flat end seen almost edge-on) costs the decades between them, which
 * {@link HighPrecisionProfile.create} adds to the 64 working digits. Every returned quantity
 * then carries at least 40 correct significant digits over R in [0.001, 1000] mm, any
 * 0 <= Rcr <= R, 0 <= rho <= 89.9999, |beta| <= 89.99 and h down to 1e-12 of the flank
 * height; the self-test checks this against closed forms in 60 digits and 64 against 100
 * working digits. Root finding: a double-precision start, then safeguarded regula falsi,
 * about 6 evaluations and 3-10 ms per width (a few hundred near a flat end seen almost
 * edge-on); {@link referenceProfile} costs about 20-25 ms to set up.
 */
import Decimal from 'decimal.js';

/** Default number of working significant digits. */
export const DEFAULT_WORKING_DIGITS = 64;

/** A point of the profile (mm): Y and Z relative to O, or width and height relative to the contact. */
export interface Point {
  readonly y: Decimal;
  readonly z: Decimal;
}

/** A flank: right is +Y. */
export type Side = 'right' | 'left';

/**
 * The exact profile in high precision: every quantity as a `Decimal` of the constructor
 * `D` (mm, relative to the contact point unless named otherwise).
 */
export class HighPrecisionProfile {
  readonly D: Decimal.Constructor;
  readonly ax: Decimal;
  readonly ay: Decimal;
  readonly az: Decimal;
  readonly rb: Decimal;
  readonly rcr: Decimal;
  readonly r: Decimal;
  /** Contact point relative to the tool centre point O (Y and Z). */
  readonly contact: Point;
  private readonly ax2: Decimal;
  private readonly tolT: Decimal;
  private readonly iterations: number;
  private readonly noise: Decimal;
  private readonly doubles: {
    readonly axD: number;
    readonly ayD: number;
    readonly azD: number;
    readonly rbD: number;
    readonly rcrD: number;
    readonly y0: number;
    readonly z0: number;
  };
  /** Number of flank evaluations spent in root finding (for the cost report). */
  evaluations = 0;

  constructor(R: number, Rcr: number, rhoDeg: number, betaDeg: number, workingDigits = DEFAULT_WORKING_DIGITS) {
    checkPosture(R, Rcr, rhoDeg, betaDeg);
    const D = Decimal.clone({ precision: workingDigits, rounding: Decimal.ROUND_HALF_EVEN });
    this.D = D;
    const toRad = D.acos(-1).div(180);
    const rho = new D(rhoDeg).mul(toRad);
    const beta = new D(betaDeg).mul(toRad);
    const cb = D.cos(beta);
    this.ax = cb.mul(D.sin(rho));
    this.ay = D.sin(beta);
    this.az = cb.mul(D.cos(rho));
    this.ax2 = this.ax.mul(this.ax);
    this.r = new D(R);
    this.rcr = new D(Rcr);
    this.rb = this.r.sub(this.rcr);
    this.contact = this.boundaryPoint(new D(0), new D(-1));
    // t is bisected down to 10^-(digits + 2); each halving is one bit.
    this.iterations = Math.ceil((workingDigits + 2) * Math.log2(10));
    this.tolT = new D(10).pow(-(workingDigits + 2));
    // Coordinates are computed to about R 10^-digits; a residual below this is noise.
    this.noise = this.r.mul(new D(10).pow(-(workingDigits - 3)));
    this.doubles = {
      axD: this.ax.toNumber(),
      ayD: this.ay.toNumber(),
      azD: this.az.toNumber(),
      rbD: this.rb.toNumber(),
      rcrD: this.rcr.toNumber(),
      y0: this.contact.y.toNumber(),
      z0: this.contact.z.toNumber(),
    };
  }

  /**
   * The profile with enough working digits: `workingDigits`, plus as many as the smallest
   * flank extent (height or width of a widest point) lies decades below R. Coordinates are
   * computed to about R 10^-digits, so a flank 1e-16 R tall (a flat end seen almost edge-on)
   * needs 16 more digits to keep 40 at 1e-12 of its height. Extents at the rounding level
   * are sharp corners (exactly 0) and are ignored.
   */
  static create(
    R: number,
    Rcr: number,
    rhoDeg: number,
    betaDeg: number,
    workingDigits = DEFAULT_WORKING_DIGITS,
  ): HighPrecisionProfile {
    const probe = new HighPrecisionProfile(R, Rcr, rhoDeg, betaDeg, workingDigits);
    const corner = probe.r.mul(new probe.D(10).pow(-(workingDigits - 10)));
    let smallest = probe.r;
    for (const side of ['right', 'left'] as const) {
      for (const extent of [probe.hmax(side), probe.wmax(side)]) {
        if (extent.gt(corner) && extent.lt(smallest)) smallest = extent;
      }
    }
    const extra = Math.min(60, Math.ceil(probe.r.div(smallest).log(10).toNumber()));
    return extra > 0 ? new HighPrecisionProfile(R, Rcr, rhoDeg, betaDeg, workingDigits + extra) : probe;
  }

  /** Boundary point of the projected tool end with outward normal (ny, nz), relative to O. */
  boundaryPoint(ny: Decimal, nz: Decimal): Point {
    const { D, ax2, ay, az, rb, rcr } = this;
    const n2 = ny.mul(ny).add(nz.mul(nz));
    const s = ay.mul(nz).sub(az.mul(ny));
    const root = D.sqrt(s.mul(s).add(ax2.mul(n2)));
    const norm = D.sqrt(n2);
    let y = ny.mul(rcr).div(norm);
    let z = nz.mul(rcr).div(norm);
    if (!root.isZero()) {
      // Ellipse point: Rb (a_x^2 n + s a'perp) / root, a'perp = (-a_z, a_y).
      y = y.add(rb.mul(ax2.mul(ny).sub(s.mul(az))).div(root));
      z = z.add(rb.mul(ax2.mul(nz).add(s.mul(ay))).div(root));
    }
    return { y, z };
  }

  /** Flank point at parameter t (0: contact normal, 1: horizontal normal), relative to the contact. */
  flankPoint(side: Side, t: Decimal): Point {
    const ny = side === 'right' ? t : t.neg();
    const p = this.boundaryPoint(ny, t.sub(1));
    const dy = p.y.sub(this.contact.y);
    return nonNegative({ y: side === 'right' ? dy : dy.neg(), z: p.z.sub(this.contact.z) });
  }

  /** {@link flankPoint} in double precision (only to start the high-precision root finding). */
  private flankPointDouble(side: Side, t: number): { readonly y: number; readonly z: number } {
    const { axD, ayD, azD, rbD, rcrD } = this.doubles;
    const ny = side === 'right' ? t : -t;
    const nz = t - 1;
    const n2 = ny * ny + nz * nz;
    const s = ayD * nz - azD * ny;
    const root = Math.sqrt(s * s + axD * axD * n2);
    const norm = Math.sqrt(n2);
    let y = (rcrD * ny) / norm;
    let z = (rcrD * nz) / norm;
    if (root > 0) {
      y += (rbD * (axD * axD * ny - s * azD)) / root;
      z += (rbD * (axD * axD * nz + s * ayD)) / root;
    }
    const dy = y - this.doubles.y0;
    return { y: side === 'right' ? dy : -dy, z: z - this.doubles.z0 };
  }

  /** Height of the widest point of a flank above the contact (vertical tangent). */
  hmax(side: Side): Decimal {
    return this.flankPoint(side, new this.D(1)).z;
  }

  /** Width of the widest point of a flank from the contact. */
  wmax(side: Side): Decimal {
    return this.flankPoint(side, new this.D(1)).y;
  }

  /**
   * The straight piece of a flank, if any: when `a_x = 0` the projected disk is a segment
   * and the boundary jumps, at the normal `n` parallel to `-a'`, from one end of the segment
   * to the other (the flat bottom at the contact when also `a_y = 0`). Returns the flank
   * parameter of that normal and the two one-sided boundary points, or null.
   */
  private straightPiece(side: Side): { readonly t: Decimal; readonly before: Point; readonly after: Point } | null {
    const { D, ax, ay, az, rb, rcr } = this;
    if (!ax.isZero() || rb.isZero()) return null;
    // Right flank n = (t, t - 1) parallel to -(a_y, a_z) at t = a_y / (a_y - a_z), in [0, 1) iff a_y <= 0;
    // left flank n = (-t, t - 1) at t = a_y / (a_y + a_z), in [0, 1) iff a_y >= 0.
    const lean = side === 'right' ? ay.neg() : ay;
    if (lean.isNeg()) return null;
    const t = lean.div(lean.add(az));
    // With a_x = 0 the ellipse point is Rb sign(s) a'perp, a'perp = (-a_z, a_y), s = a_y n_z - a_z n_y.
    const ny = side === 'right' ? t : t.neg();
    const nz = t.sub(1);
    const norm = D.sqrt(ny.mul(ny).add(nz.mul(nz)));
    const corner = (sign: number): Point => {
      const y = rb.mul(az).mul(-sign).add(rcr.mul(ny).div(norm));
      const z = rb.mul(ay).mul(sign).add(rcr.mul(nz).div(norm));
      const dy = y.sub(this.contact.y);
      return { y: side === 'right' ? dy : dy.neg(), z: z.sub(this.contact.z) };
    };
    // s is linear in t; its sign just past t (towards t = 1) is that of s(1) = a_y * 0 - a_z * (+-1).
    const signAfter = side === 'right' ? -1 : 1;
    const before = t.isZero() ? this.flankPoint(side, t) : corner(-signAfter);
    return { t, before, after: corner(signAfter) };
  }

  /**
   * The flank point whose coordinate `key` (y: width, z: height) equals `target`, the flank
   * being monotone in both. Straight pieces are interpolated exactly; on the smooth pieces a
   * double-precision bisection gives a start, a verified high-precision bracket around it is
   * closed by regula falsi (Illinois), stopped at the working precision's noise.
   */
  private solve(side: Side, key: 'y' | 'z', target: Decimal): Point {
    const { D } = this;
    const top = this.flankPoint(side, new D(1));
    if (top[key].lte(target)) return top;
    const bottom = this.flankPoint(side, new D(0));
    const straight = this.straightPiece(side);
    if (straight === null) return this.solveSmooth(side, key, target, new D(0), bottom, new D(1), top);
    const { t, before, after } = straight;
    if (target.lte(before[key])) return this.solveSmooth(side, key, target, new D(0), bottom, t, before);
    if (target.lt(after[key])) return interpolate(before, after, key, target);
    return this.solveSmooth(side, key, target, t, after, new D(1), top);
  }

  /** Regula falsi on t in [tA, tB], where key(pA) <= target < key(pB) and the flank is continuous. */
  private solveSmooth(
    side: Side,
    key: 'y' | 'z',
    target: Decimal,
    tA: Decimal,
    pA: Point,
    tB: Decimal,
    pB: Point,
  ): Point {
    const { D } = this;
    if (pA[key].gte(target)) return pA;
    // Double-precision start.
    const targetD = target.toNumber();
    let loD = tA.toNumber();
    let hiD = tB.toNumber();
    for (let i = 0; i < 64; i++) {
      const mid = 0.5 * (loD + hiD);
      if (mid <= loD || mid >= hiD) break;
      if (this.flankPointDouble(side, mid)[key] <= targetD) loD = mid;
      else hiD = mid;
    }
    // Verified bracket around it, widened until it holds.
    const guess = new D(0.5 * (loD + hiD));
    let lo = tA;
    let hi = tB;
    let pLo = pA;
    let pHi = pB;
    for (let margin = 1e-9; margin < 1; margin *= 1000) {
      const delta = guess.mul(margin).add(margin * 1e-30);
      const a = guess.sub(delta).gt(tA) ? guess.sub(delta) : tA;
      const b = guess.add(delta).lt(tB) ? guess.add(delta) : tB;
      const qa = a.eq(tA) ? pA : this.flankPoint(side, a);
      const qb = b.eq(tB) ? pB : this.flankPoint(side, b);
      if (qa[key].lte(target) && qb[key].gt(target)) {
        lo = a;
        hi = b;
        pLo = qa;
        pHi = qb;
        break;
      }
    }
    let fLo = pLo[key].sub(target);
    let fHi = pHi[key].sub(target);
    let kept: 'lo' | 'hi' | null = null;
    let widthBefore = hi.sub(lo);
    // At most 4 halvings per bit of the bracket (the safeguard below), and usually 5-10 in all.
    // Stop when the bracket is down to a few units of the last digit of t: t has only the
    // working digits, and the chord across such a bracket is exact to far below them.
    const tight = (): boolean => hi.sub(lo).lte(this.tolT.add(hi.mul(this.tolT).mul(1000)));
    for (let i = 0; i < 4 * this.iterations && !tight(); i++) {
      // Safeguard: when three steps did not halve the bracket, bisect it, geometrically when it
      // spans orders of magnitude (a root at t ~ 1e-6 of a strongly convex flank).
      let bisect = false;
      if (i % 3 === 2) {
        bisect = hi.sub(lo).gt(widthBefore.div(2));
        widthBefore = hi.sub(lo);
      }
      let t = lo.sub(fLo.mul(hi.sub(lo)).div(fHi.sub(fLo)));
      if (bisect || t.lte(lo) || t.gte(hi)) {
        if (lo.isZero()) t = hi.div(256);
        else if (hi.gt(lo.mul(16))) t = D.sqrt(lo.mul(hi));
        else t = lo.add(hi).div(2);
      }
      const p = this.flankPoint(side, t);
      this.evaluations++;
      const f = p[key].sub(target);
      if (f.abs().lte(this.noise)) return p;
      if (f.isNeg()) {
        lo = t;
        pLo = p;
        fLo = f;
        if (kept === 'hi') fHi = fHi.div(2);
        kept = 'hi';
      } else {
        hi = t;
        pHi = p;
        fHi = f;
        if (kept === 'lo') fLo = fLo.div(2);
        kept = 'lo';
      }
    }
    return interpolate(pLo, pHi, key, target);
  }

  /** Width of a flank at height h above the contact, 0 <= h <= hmax(side). */
  width(side: Side, h: Decimal): Decimal {
    const top = this.hmax(side);
    if (h.isNeg() || h.gt(top.add(this.roundingSlack(top)))) {
      throw new RangeError(`h = ${h.toString()} mm outside [0, hmax ${side} = ${top.toString()}]`);
    }
    return this.solve(side, 'z', h).y;
  }

  /** Slack above an upper bound that a double rounded from it may carry (a few ulps, plus R 1e-15). */
  private roundingSlack(bound: Decimal): Decimal {
    return bound.abs().mul('1e-15').add(this.r.mul('1e-15'));
  }

  /** Height above the contact of a flank at width w from the contact, 0 <= w <= wmax(side). */
  heightAtWidth(side: Side, w: Decimal): Decimal {
    const top = this.wmax(side);
    if (w.isNeg() || w.gt(top.add(this.roundingSlack(top)))) {
      throw new RangeError(`w = ${w.toString()} mm outside [0, wmax ${side} = ${top.toString()}]`);
    }
    return this.solve(side, 'y', w).z;
  }

  /**
   * The shank junction: the equator point `R n_J` with `n_J` perpendicular to a', on the
   * given side, relative to the contact (width, height). Below the widest point only on the
   * side the shank leans to.
   */
  shankJunction(side: Side): Point {
    const { D, ay, az, r } = this;
    const len = D.sqrt(ay.mul(ay).add(az.mul(az)));
    // Right: n_J = (a_z, -a_y)/|a'|; left: (-a_z, a_y)/|a'|.
    const sign = side === 'right' ? 1 : -1;
    const y = r.mul(az).div(len).mul(sign);
    const z = r.mul(ay).div(len).mul(-sign);
    const dy = y.sub(this.contact.y);
    return nonNegative({ y: side === 'right' ? dy : dy.neg(), z: z.sub(this.contact.z) });
  }

  /** Height above the contact from which the shank is the lower boundary (clamped to hmax). */
  shankHeight(side: Side): Decimal {
    const j = this.shankJunction(side).z;
    const top = this.hmax(side);
    return j.lt(top) ? j : top;
  }

  /**
   * Width of the whole tool's profile (end and shank) at height h >= 0. On the side the
   * shank leans to, above the junction it is the straight edge of direction a'; with no
   * tilt the shank is a vertical wall at the widest point; on the other side, only up to hmax.
   */
  widthWithShank(side: Side, h: Decimal): Decimal {
    const j = this.shankJunction(side);
    const leansThisWay = side === 'right' ? this.ay.gt(0) : this.ay.lt(0);
    if (leansThisWay && h.gt(j.z)) {
      return j.y.add(h.sub(j.z).mul(this.ay.abs()).div(this.az));
    }
    if (this.ay.isZero() && h.gt(this.hmax(side))) return this.wmax(side);
    return this.width(side, h);
  }

  /** Radius of curvature of the profile at the contact (closed form above); +Infinity if flat. */
  radiusOfCurvatureAtContact(): Decimal {
    const { D, ax2, ay, rb, rcr } = this;
    const m2 = ax2.add(ay.mul(ay));
    if (m2.isZero()) return rb.isZero() ? rcr : new D(Number.POSITIVE_INFINITY);
    return rb
      .mul(ax2)
      .div(m2.mul(D.sqrt(m2)))
      .add(rcr);
  }
}

/**
 * Flank coordinates are >= 0 by construction; rounding at the working precision can leave
 * -1e-64 R where a flank degenerates to the contact point itself (a sharp corner): snap to 0.
 */
function nonNegative(p: Point): Point {
  return { y: p.y.isNeg() ? p.y.abs().mul(0) : p.y, z: p.z.isNeg() ? p.z.abs().mul(0) : p.z };
}

/** The point of the chord from p to q whose coordinate `key` is `target` (clamped to the chord). */
function interpolate(p: Point, q: Point, key: 'y' | 'z', target: Decimal): Point {
  const span = q[key].sub(p[key]);
  if (!span.gt(0)) return p;
  let f = target.sub(p[key]).div(span);
  if (f.isNeg()) f = f.mul(0);
  if (f.gt(1)) f = f.div(f);
  return { y: p.y.add(q.y.sub(p.y).mul(f)), z: p.z.add(q.z.sub(p.z).mul(f)) };
}

/** Throws a RangeError unless the posture and tool are inside the reference's domain. */
function checkPosture(R: number, Rcr: number, rhoDeg: number, betaDeg: number): void {
  const ok =
    Number.isFinite(R) &&
    R > 0 &&
    Number.isFinite(Rcr) &&
    Rcr >= 0 &&
    Rcr <= R &&
    Number.isFinite(rhoDeg) &&
    rhoDeg >= 0 &&
    rhoDeg < 90 &&
    Number.isFinite(betaDeg) &&
    betaDeg > -90 &&
    betaDeg < 90;
  if (!ok) {
    throw new RangeError(`outside the domain: R=${R} Rcr=${Rcr} rho=${rhoDeg} beta=${betaDeg}`);
  }
}

/** The reference profile in plain numbers (mm), see {@link referenceProfile}. */
export interface ReferenceProfile {
  /** y0 = Y(contact) - Y(O), mm: where the contact lies across the feed from the tool centre point. */
  readonly contactOffsetMm: number;
  /** Height of the right (+Y) flank's widest point above the contact, mm. */
  readonly hmaxRightMm: number;
  /** Height of the left (-Y) flank's widest point above the contact, mm. */
  readonly hmaxLeftMm: number;
  /** Width of the right flank's widest point from the contact, mm (Rb sqrt(1 - a_y^2) + Rcr - y0). */
  readonly wmaxRightMm: number;
  /** Width of the left flank's widest point from the contact, mm. */
  readonly wmaxLeftMm: number;
  /**
   * Height above the contact from which the shank (cylinder of radius R above the disk) is
   * the lower boundary on the right, mm; hmaxRightMm when it never is (no tilt or tilt to -Y).
   */
  readonly shankHeightRightMm: number;
  /** As {@link shankHeightRightMm}, left side. */
  readonly shankHeightLeftMm: number;
  /**
   * Height above the contact of the point where the shank's edge leaves the end's boundary
   * on the right, mm, not clamped: above hmaxRightMm (on the wall) when the tool does not lean to +Y.
   */
  readonly shankJunctionRightMm: number;
  /** As {@link shankJunctionRightMm}, left side. */
  readonly shankJunctionLeftMm: number;
  /** Radius of curvature of the profile at the contact, mm; +Infinity for a flat bottom, 0 for a sharp corner. */
  readonly radiusOfCurvatureAtContactMm: number;
  /** Right flank of the tool end: width from the contact at height h, 0 <= h <= hmaxRightMm (RangeError else). */
  widthRightMm(h: number): number;
  /** Left flank of the tool end: width from the contact at height h, 0 <= h <= hmaxLeftMm. */
  widthLeftMm(h: number): number;
  /** Inverse of widthRightMm: height above the contact at width w, 0 <= w <= wmaxRightMm. */
  heightAtWidthRightMm(w: number): number;
  /** Inverse of widthLeftMm: height above the contact at width w, 0 <= w <= wmaxLeftMm. */
  heightAtWidthLeftMm(w: number): number;
  /**
   * Right width of the whole tool's profile (end and shank) at height h >= 0, mm: the end's
   * below shankJunctionRightMm, the shank's straight edge above it when the tool leans to +Y
   * (any h), the vertical wall at wmaxRightMm with no tilt, and only up to hmax otherwise.
   */
  widthRightWithShankMm(h: number): number;
  /** As {@link widthRightWithShankMm}, left side. */
  widthLeftWithShankMm(h: number): number;
  /** The underlying high-precision profile (Decimal values, 40+ correct digits). */
  readonly exact: HighPrecisionProfile;
}

/**
 * High-precision reference profile of a filleted end mill of radius `R` (mm, > 0), corner
 * radius `Rcr` (mm, 0 <= Rcr <= R), lead `rhoDeg` (0 <= rho < 90) and tilt `betaDeg`
 * (-90 < beta < 90), translating along X over the plane z = 0. See the module comment for
 * the derivation. Results are the 64-digit values rounded to the nearest double. Widths and
 * heights are of the tool end (corner and bottom); the `...WithShank` widths add the shank.
 */
export function referenceProfile(R: number, Rcr: number, rhoDeg: number, betaDeg: number): ReferenceProfile {
  const p = HighPrecisionProfile.create(R, Rcr, rhoDeg, betaDeg);
  const D = p.D;
  const num = (x: Decimal): number => x.toNumber();
  return {
    contactOffsetMm: num(p.contact.y),
    hmaxRightMm: num(p.hmax('right')),
    hmaxLeftMm: num(p.hmax('left')),
    wmaxRightMm: num(p.wmax('right')),
    wmaxLeftMm: num(p.wmax('left')),
    shankHeightRightMm: num(p.shankHeight('right')),
    shankHeightLeftMm: num(p.shankHeight('left')),
    shankJunctionRightMm: num(p.shankJunction('right').z),
    shankJunctionLeftMm: num(p.shankJunction('left').z),
    radiusOfCurvatureAtContactMm: num(p.radiusOfCurvatureAtContact()),
    widthRightMm: (h) => num(p.width('right', new D(h))),
    widthLeftMm: (h) => num(p.width('left', new D(h))),
    heightAtWidthRightMm: (w) => num(p.heightAtWidth('right', new D(w))),
    heightAtWidthLeftMm: (w) => num(p.heightAtWidth('left', new D(w))),
    widthRightWithShankMm: (h) => num(p.widthWithShank('right', new D(h))),
    widthLeftWithShankMm: (h) => num(p.widthWithShank('left', new D(h))),
    exact: p,
  };
}
