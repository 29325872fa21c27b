/**
 * Axis along the feed (see ../cylinder.ts's module comment): the profile point of a section, the
 * polar angle a flank reaches at a radial height and its inverse. Lengths mm, angles radians.
 */
import { evalSection, type Flank, flankSign, newSection, type PostureShape, type Section } from '../../tool/posture';

/** A point of the cross-feed profile, relative to the contact (mm), and its section's normal. */
export interface ProfilePoint {
  /** Width Y and height H of the profile point. */
  y: number;
  h: number;
  /** The section's ring point (its ball's centre): ey, ez. */
  ey: number;
  ez: number;
  /** Norm of the profile's (unnormalised) normal, and the normal (sin theta, cos theta). */
  n: number;
  st: number;
  ct: number;
}

export const section: Section = newSection();
export const point: ProfilePoint = { y: 0, h: 0, ey: 0, ez: 0, n: 0, st: 0, ct: 1 };

/**
 * The profile point of section delta on the flank `sign` (posture.ts's evalSection, then the ball
 * of radius Rcr along the profile normal). Fills and returns a shared scratch object: read it
 * before the next call.
 */
export function profilePoint(s: PostureShape, sign: number, delta: number): ProfilePoint {
  evalSection(s, sign, delta, section);
  const n = Math.sqrt(section.nSin * section.nSin + section.nCos * section.nCos);
  // Profile normal (sin theta, cos theta); where a corner collapses (b = 0, n = 0) take the ring point.
  const st = n > 0 ? section.nSin / n : 0;
  const ct = n > 0 ? section.nCos / n : 1;
  point.y = section.dy + s.rcr * st;
  point.h = section.dz + (s.rcr * (st * st)) / (1 + ct);
  point.ey = section.dy;
  point.ez = section.dz + s.rcr;
  point.n = n;
  point.st = st;
  point.ct = ct;
  return point;
}

/**
 * Polar angle of a flank point at radial height h on a cylinder with the axis along the feed: a
 * bracketed Newton on G(delta) = Y^2 + (H - h)(H + h + 2 Rs), with G' = 2 K (Y cos theta +
 * (H + Rs) sin theta), K = N + Rcr a b / N^2 (N the norm of the ellipse normal), started from the
 * plane's osculating estimate; then the angle as a maximum over sections (feedAngleOfSection).
 * @param top an offset past the root, where G has changed sign.
 */
export function feedAngleAtHeight(s: PostureShape, flank: Flank, rs: number, h: number, top: number): number {
  const sign = flankSign(flank);
  const rcr = s.rcr;
  const ab = s.a * s.b;
  // G(0) = -h (h + 2 Rs): negative on a convex cylinder, positive on a concave one (it falls).
  const falling = rs < 0;
  let lo = 0;
  let hi = top;
  let delta = 0;
  if (hi > 0) {
    const reff = rcr + (s.d0 > 0 ? (ab * ab) / (s.d0 * s.d0 * s.d0) : 0);
    delta = s.d0 > 0 ? (Math.sqrt((2 * h) / reff) * ab) / (s.d0 * s.d0) : 0.5 * hi;
    if (!(delta > lo && delta < hi)) delta = 0.5 * (lo + hi);
    for (let i = 0; i < 100; i++) {
      const { y: Y, h: H, n, st, ct } = profilePoint(s, sign, delta);
      const g = Y * Y + (H - h) * (H + h + 2 * rs);
      if (g === 0) break;
      const before = falling ? g > 0 : g < 0;
      if (before) lo = delta;
      else hi = delta;
      const k = n > 0 ? n + (rcr * ab) / (n * n) : Number.POSITIVE_INFINITY;
      const slope = 2 * k * (Y * ct + (H + rs) * st);
      let next = Number.isFinite(slope) && slope !== 0 ? delta - g / slope : Number.NaN;
      if (Math.abs(next - delta) <= 1e-12 * delta) {
        delta = Math.min(Math.max(next, lo), hi);
        break;
      }
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      delta = next;
      if (hi - lo <= 4e-16 * hi) break;
    }
  }
  return feedAngleOfSection(s, sign, delta, rs, h);
}

/**
 * The polar angle reached by the ball of section delta at radius r = |Rs| + s h: the ring point's
 * angle plus the half-angle its ball subtends (0 when it does not reach r).
 */
export function feedAngleOfSection(s: PostureShape, sign: number, delta: number, rs: number, h: number): number {
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

/** Height (radial) of the flank point at polar angle beta (the inverse), by the same root approach. */
export function feedHeightAtAngle(s: PostureShape, flank: Flank, rs: number, beta: number, deltaTop: number): number {
  const sign = flankSign(flank);
  const side = rs > 0 ? 1 : -1;
  const cb = Math.cos(beta);
  const sb = Math.sin(beta);
  // J = Y cos(beta) - (|Rs| + s H) sin(beta): the profile point's angle against beta.
  const J = (d: number) => {
    const p = profilePoint(s, sign, d);
    return p.y * cb - (Math.abs(rs) + side * p.h) * sb;
  };
  let lo = 0;
  let hi = deltaTop;
  let jLo = J(lo);
  let jHi = J(hi);
  for (let i = 0; i < 200 && hi - lo > 1e-16 * Math.max(hi, 1e-300); i++) {
    let m = lo - (jLo * (hi - lo)) / (jHi - jLo);
    if (!(m > lo && m < hi) || i % 4 === 3) m = 0.5 * (lo + hi);
    const jm = J(m);
    if (jm === 0) {
      lo = m;
      hi = m;
      break;
    }
    if (jm > 0) {
      hi = m;
      jHi = jm;
      jLo /= 2;
    } else {
      lo = m;
      jLo = jm;
      jHi /= 2;
    }
  }
  // The radius along the ray at beta through the section's ball: the entry (convex) or exit
  // (concave) distance, second-order insensitive to the section's error.
  const p = profilePoint(s, sign, 0.5 * (lo + hi));
  const qy = p.ey;
  const qz = p.ez + rs;
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
