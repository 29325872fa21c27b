/**
 * Axis along the feed (see ../cylinder.ts's module comment): the profile point of a section, the
 * polar angle a flank reaches at a radial height and its inverse. Lengths mm, angles radians.
 */
import { bracketedRoot, NewtonState, newtonStart, newtonStep, type Objective } from '../../math/rootFinder';
import { evalSection, type Flank, flankSign, newSection, type PostureShape, type Section } from '../../tool/posture';

/**
 * A point of the cross-feed profile, relative to the contact (mm), and its section's normal, with
 * the section evaluated (posture.ts's evalSection): an object the caller owns and fills within one
 * call. A class with fixed fields, its section of the one class every solver uses, so that
 * evalSection sees a single shape.
 */
export class ProfilePoint {
  /** The section last evaluated (posture.ts's evalSection): its ring point, the ball's centre, is (dy, dz + Rcr). */
  readonly section: Section = newSection();
  /** Width Y and height H of the profile point. */
  y = 0;
  h = 0;
  /** Norm of the profile's (unnormalised) normal, and the normal (sin theta, cos theta). */
  n = 0;
  st = 0;
  ct = 1;
}

/** A profile point to be filled by {@link profilePoint}. */
export function newProfilePoint(): ProfilePoint {
  return new ProfilePoint();
}

/**
 * The profile point of section delta on the flank `sign` (posture.ts's evalSection, then the ball
 * of radius Rcr along the profile normal). Fills `out` (allocation-free) and returns it.
 */
export function profilePoint(s: PostureShape, sign: number, delta: number, out: ProfilePoint): ProfilePoint {
  const section = out.section;
  evalSection(s, sign, delta, section);
  const n = Math.sqrt(section.nSin * section.nSin + section.nCos * section.nCos);
  // Profile normal (sin theta, cos theta); where a corner collapses (b = 0, n = 0) take the ring point.
  const st = n > 0 ? section.nSin / n : 0;
  const ct = n > 0 ? section.nCos / n : 1;
  out.y = section.dy + s.rcr * st;
  out.h = section.dz + (s.rcr * (st * st)) / (1 + ct);
  out.n = n;
  out.st = st;
  out.ct = ct;
  return out;
}

/**
 * feedAngleAtHeight's section (filled and read within one call, never by a caller): module-level,
 * as posture.ts's, because a solver-owned work object allocated per solve was measured at +5 % of
 * the exact solve along the feed.
 */
const angleSection: Section = newSection();

/**
 * Polar angle of a flank point at radial height h on a cylinder with the axis along the feed: the
 * shared safeguarded Newton step (rootFinder.ts) on G(delta) = Y^2 + (H - h)(H + h + 2 Rs), with
 * G' = 2 K (Y cos theta + (H + Rs) sin theta), K = N + Rcr a b / N^2 (N the norm of the ellipse
 * normal), started from the plane's osculating estimate; then the angle as a maximum over sections
 * (feedAngleOfSection).
 * @param top an offset past the root, where G has changed sign.
 */
export function feedAngleAtHeight(s: PostureShape, flank: Flank, rs: number, h: number, top: number): number {
  const sign = flankSign(flank);
  const rcr = s.rcr;
  const ab = s.a * s.b;
  let delta = 0;
  if (top > 0) {
    const reff = rcr + (s.d0 > 0 ? (ab * ab) / (s.d0 * s.d0 * s.d0) : 0);
    const start = s.d0 > 0 ? (Math.sqrt((2 * h) / reff) * ab) / (s.d0 * s.d0) : 0.5 * top;
    // G(0) = -h (h + 2 Rs): negative on a convex cylinder (G rises), positive on a concave one (it falls).
    const newton = new NewtonState();
    newtonStart(newton, 0, top, start);
    // The profile point in locals (profilePoint's arithmetic), the section in the caller's scratch.
    const sec = angleSection;
    for (let i = 0; i < 100 && !newton.done; i++) {
      evalSection(s, sign, newton.x, sec);
      const n = Math.sqrt(sec.nSin * sec.nSin + sec.nCos * sec.nCos);
      const sn = n > 0 ? sec.nSin / n : 0;
      const ct = n > 0 ? sec.nCos / n : 1;
      const Y = sec.dy + rcr * sn;
      const H = sec.dz + (rcr * (sn * sn)) / (1 + ct);
      const k = n > 0 ? n + (rcr * ab) / (n * n) : Number.POSITIVE_INFINITY;
      newtonStep(newton, Y * Y + (H - h) * (H + h + 2 * rs), 2 * k * (Y * ct + (H + rs) * sn), rs > 0, 1e-12);
    }
    delta = newton.x;
  }
  return feedAngleOfSection(s, sign, delta, rs, h, angleSection);
}

/**
 * The polar angle reached by the ball of section delta at radius r = |Rs| + s h: the ring point's
 * angle plus the half-angle its ball subtends (0 when it does not reach r).
 */
export function feedAngleOfSection(
  s: PostureShape,
  sign: number,
  delta: number,
  rs: number,
  h: number,
  section: Section,
): number {
  evalSection(s, sign, delta, section);
  const half = ballHalfAngleRad(section.dy, section.dz, s.rcr, rs, h);
  // Ring point relative to the axis C = (0, -Rs): (dy, dz + Rcr + Rs); polar angle from C's direction to the contact.
  return Math.atan2(section.dy, (rs > 0 ? 1 : -1) * (section.dz + s.rcr + rs)) + (half ?? 0);
}

/**
 * Half the polar angle (radians) that a ball of radius Rcr subtends at the radius r = |Rs + h| about
 * a cylinder's axis (axis along the feed; h the radial height), or null when it does not reach r.
 * The ball's centre lies `cy` across and `zeta + Rcr` above the contact (zeta: its ring point's rise
 * above the contact's, e.g. evalSection's dz), at distance de from the axis; the half-angle is
 * `2 asin(sqrt((Rcr - (de - r)) (Rcr + (de - r)) / (4 de r)))`, each factor written as a product
 * of terms free of cancellation, so that h of 1e-9 mm keeps its digits beside a corner of 100 mm.
 */
export function ballHalfAngleRad(cy: number, zeta: number, rcr: number, rs: number, h: number): number | null {
  if (!(rcr > 0)) return null;
  const qz = zeta + rcr + rs;
  const de = Math.sqrt(cy * cy + qz * qz);
  const r = Math.abs(rs + h);
  const cy2 = cy * cy;
  let lo: number; // Rcr - (de - r) = ((Rcr + r)^2 - de^2) / (Rcr + r + de)
  let hi: number; // Rcr + (de - r) = (de^2 - (r - Rcr)^2) / (de + r - Rcr)
  if (rs > 0) {
    lo = ((h - zeta) * (2 * rcr + 2 * rs + h + zeta) - cy2) / (rcr + r + de);
    hi = r >= rcr ? ((2 * rcr + zeta - h) * (2 * rs + zeta + h) + cy2) / (de + r - rcr) : de + rcr - r;
  } else {
    lo = ((-2 * rs - h - zeta) * (2 * rcr - h + zeta) - cy2) / (rcr + r + de);
    hi = r >= rcr ? ((zeta - h) * (2 * rcr + zeta + h + 2 * rs) + cy2) / (de + r - rcr) : de + rcr - r;
  }
  if (!(lo > 0) || !(hi > 0)) return null;
  return 2 * Math.asin(Math.min(1, Math.sqrt((lo * hi) / (4 * de * r))));
}

/** J(delta) = Y cos(beta) - (|Rs| + s H) sin(beta): the profile point's angle against beta (rising). */
class AngleMismatch implements Objective {
  private readonly cb: number;
  private readonly sb: number;
  constructor(
    private readonly s: PostureShape,
    private readonly sign: number,
    private readonly rs: number,
    beta: number,
    private readonly at: ProfilePoint,
  ) {
    this.cb = Math.cos(beta);
    this.sb = Math.sin(beta);
  }
  value(delta: number): number {
    const p = profilePoint(this.s, this.sign, delta, this.at);
    return p.y * this.cb - (Math.abs(this.rs) + (this.rs > 0 ? 1 : -1) * p.h) * this.sb;
  }
}

/**
 * Height (radial) of the flank point at polar angle beta (the inverse): the section where J = 0
 * (AngleMismatch) by the shared bracketed root, then the ray's crossing with that section's ball.
 */
export function feedHeightAtAngle(s: PostureShape, flank: Flank, rs: number, beta: number, deltaTop: number): number {
  const at = new ProfilePoint();
  const sign = flankSign(flank);
  const side = rs > 0 ? 1 : -1;
  const cb = Math.cos(beta);
  const sb = Math.sin(beta);
  const J = new AngleMismatch(s, sign, rs, beta, at);
  const jLo = J.value(0);
  const jHi = J.value(deltaTop);
  // Without a sign change the section is the bracket's end that J approaches.
  const root = jLo >= 0 ? 0 : jHi <= 0 ? deltaTop : bracketedRoot(J, 0, deltaTop, jLo, jHi, 1e-16);
  // The radius along the ray at beta through the section's ball: the entry (convex) or exit
  // (concave) distance, second-order insensitive to the section's error.
  const p = profilePoint(s, sign, root, at);
  const qy = p.section.dy;
  const qz = p.section.dz + s.rcr + rs;
  // Ray direction from C: (sin beta, side cos beta).
  const te = qy * sb + side * qz * cb;
  const perp = qy * side * cb - qz * sb;
  const rcr = s.rcr;
  const reach = Math.sqrt(Math.max(0, rcr * rcr - perp * perp));
  const r = side > 0 ? te - reach : te + reach;
  return side * (r - Math.abs(rs));
}

/** Ring-angle offset where the plane flank's normal turns horizontal (its widest point). */
export function planeTop(s: PostureShape, sign: number): number {
  if (s.flatOnPlane) return Math.PI / 2;
  if (s.a === 0) return 0;
  return Math.atan2(s.a * s.b, (s.a * s.a - s.b * s.b) * sign * s.sinPhi * s.cosPhi);
}

/** Radial height (mm) of a point (y, z) relative to the contact: `d - Rs` convex, `|Rs| - d` concave. */
export function radialHeightOf(y: number, z: number, rs: number): number {
  const d = Math.sqrt(y * y + (z + rs) * (z + rs));
  const num = y * y + z * (z + 2 * rs);
  return rs > 0 ? num / (d + rs) : -num / (d - rs);
}
