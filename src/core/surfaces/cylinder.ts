/**
 * Exact step-over on cylinders (shared/notes/posture-and-surfaces.md, "Curved surfaces"): convex
 * (Rs > 0, axis Rs below the contact) or concave (Rs < 0, axis |Rs| above), with the axis along the
 * feed or across it, any posture, one-way or zigzag. Scallop heights are measured radially. Lengths
 * mm, angles radians. Frame: the contact of the pass at the origin, X feed, Z the surface normal.
 *
 * Axis along the feed. A pass translates along X, so it leaves the plane profile of posture.ts; the
 * next pass is that profile turned about the axis by phi = L / |Rs|. In polar coordinates about the
 * axis (angle measured from the contact), a flank at radius r = |Rs| + s h (s = +1 convex, -1
 * concave) lies at a polar angle A(h); the cusp of a right and a left flank sits where
 * A_R + A_L = phi (one-way) and the zigzag cusps where A = phi / 2. The flank point at that radius is
 * the section whose profile point (Y, H) satisfies
 *
 *   G(delta) = Y^2 + (H - h)(H + h + 2 Rs) = 0            (|(Y, H) - C| = r, without cancellation)
 *
 * and the angle is taken, as on the plane, as a maximum over sections: the ring point's polar angle
 * plus the half-angle its ball subtends at radius r (law of cosines in half-angle form), which is
 * second-order insensitive to the root's error.
 *
 * Axis across the feed. A pass turns the tool about the axis (along Y); revolving a ball of radius
 * Rcr centred at e gives, in the meridian plane (Y, rho = distance from the axis), the circle of
 * radius Rcr around (e_y, rho(e)). So the revolved profile is the offset by Rcr of the bottom disk's
 * image: its lower boundary B(y) = min of rho over the disk's chord at y (convex; closed form: the
 * foot of the axis on the chord, or a chord end) or upper boundary U(y) = max (concave: a chord end).
 * A flank's width at radius r is the maximum over y of y + sqrt(Rcr^2 - (B(y) - r)^2), found by a scan
 * and golden-section search to the last bits. The next pass is that profile translated by L.
 *
 * Walls. Along the feed on a convex cylinder a flank's polar angle peaks where its tangent passes
 * through the axis, below the plane's widest point: beyond, a pass reaches no farther (a wall). On a
 * concave one the wall is where the radial height stops growing, at most the plane's widest point.
 * Across the feed it is the end of the revolved profile (the disk's widest chord). Without lead the
 * ring projects onto a segment (a point for a ball end) and whole arcs of the profile hang on one
 * ring angle; those flanks are two corner balls joined by the flat bottom's edge (Stadium), in
 * closed form.
 *
 * The shank (the cylinder of radius R above the corner): along the feed, radially, where its
 * silhouette leaves the plane profile; across it, where the revolved profile's nearest (concave:
 * farthest) point moves from the corner onto the shank (crossShankHeights).
 *
 * Gouging (concave). The tool end must stay inside the cylinder except at the contact: every ring
 * point e (relative to the contact, seen along the feed for axis = feed, along the axis for
 * axis = cross) needs |Rs| >= (E^2 + E_z^2 - Rcr^2) / (2 (E_z - Rcr)), E its horizontal offset. The
 * head's smallest admissible radius is the maximum of that over the ring; the shank must not cross
 * the wall up to the axis height (shankMinConcaveRadiusMm); the larger of the two is the limit.
 */

import { type CylinderSurface, PLANE, type Surface, type SurfaceAxis } from '../domain/surface';
import type { ToolInput } from '../domain/tool';
import { radToDeg } from '../input/units';
import { type Placement, placeTool } from '../tool/placement';
import {
  evalSection,
  type Flank,
  type FlankLimits,
  flankSign,
  newSection,
  type PostureShape,
  type Section,
} from '../tool/posture';

/** The surface descriptors, defined in domain/surface.ts; re-exported for the callers. */
export type { CylinderSurface, Surface, SurfaceAxis };
export { PLANE };

// ---------------------------------------------------------------------------------------------
// Axis along the feed

/** A point of the cross-feed profile, relative to the contact (mm), and its section's normal. */
interface ProfilePoint {
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

const section: Section = newSection();
const point: ProfilePoint = { y: 0, h: 0, ey: 0, ez: 0, n: 0, st: 0, ct: 1 };

/**
 * The profile point of section delta on the flank `sign` (posture.ts's evalSection, then the ball
 * of radius Rcr along the profile normal). Fills and returns a shared scratch object: read it
 * before the next call.
 */
function profilePoint(s: PostureShape, sign: number, delta: number): ProfilePoint {
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
function feedAngleAtHeight(s: PostureShape, flank: Flank, rs: number, h: number, top: number): number {
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
function feedAngleOfSection(s: PostureShape, sign: number, delta: number, rs: number, h: number): number {
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
function ballHalfAngleRad(cy: number, zeta: number, rcr: number, rs: number, h: number): number | null {
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
function feedHeightAtAngle(s: PostureShape, flank: Flank, rs: number, beta: number, deltaTop: number): number {
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
function planeTop(s: PostureShape, sign: number): number {
  if (s.flatOnPlane) return Math.PI / 2;
  if (s.a === 0) return 0;
  return Math.atan2(s.a * s.b, (s.a * s.a - s.b * s.b) * sign * s.sinPhi * s.cosPhi);
}

/** Radial height (mm) of a point (y, z) relative to the contact: `d - Rs` convex, `|Rs| - d` concave. */
function radialHeightOf(y: number, z: number, rs: number): number {
  const d = Math.sqrt(y * y + (z + rs) * (z + rs));
  const num = y * y + z * (z + 2 * rs);
  return rs > 0 ? num / (d + rs) : -num / (d - rs);
}

/**
 * Below this ratio b / a the ring's projection is taken as its segment (a stadium flank, below): the
 * profile moves by at most b, under 1e-11 mm for R <= 1000 mm, while the section parametrisation
 * loses the normal's digits (its components are of the order of b / a, and their squares underflow
 * below 1e-154).
 */
const THIN_RING = 1e-14;

/**
 * The flank of a profile whose ring projects onto a segment or a point (no lead, or a lead so small
 * that b < 1e-14 a; or a ball end), in the flank's frame (y out from the contact, z up): two balls
 * of radius Rcr around the ring points S (the contact's) and E (the ring point at t = pi/2, the end
 * of the ellipse's long axis, `evalSection` at pi/2 - t0) joined by their common tangent, whose
 * normal makes the angle `theta` with straight down. The flank runs around S from normal angle 0 to
 * theta, along the tangent, then around E up to pi/2 (the plane's widest point). Away from the lean
 * E is the far end of the segment; towards it (and for a ball end) E is S. The section
 * parametrisation of posture.ts collapses here (a whole arc hangs on one ring angle), so these
 * flanks are handled in closed form.
 */
interface Stadium {
  /** Ring point (ball centre) S relative to the contact, mm. */
  readonly sy: number;
  readonly sz: number;
  /** E - S (kept apart: added to S a tiny segment would round away), mm; 0 when E is S. */
  readonly dy: number;
  readonly dz: number;
  /** Normal angle of the tangent from S to E (radians from straight down); pi/2 when E is S. */
  readonly theta: number;
  /**
   * Normal angle at which the shank's silhouette leaves the flank (the side the tool leans to: the
   * normal (cos phi, -sin phi), at the ring point t = pi/2, E), or null.
   */
  readonly shankTheta: number | null;
}

/** The flank `sign` as a stadium when the ring is degenerate (b < 1e-14 a, or a ball end), else null. */
function stadiumOf(s: PostureShape, sign: number): Stadium | null {
  if (s.a > 0 && s.b > THIN_RING * s.a) return null;
  const rcr = s.rcr;
  const lean = sign * s.sinPhi > 0;
  // The segment from the contact's ring point t0 to t = pi/2; a flat bottom lying on the plane
  // (t0 = 0 by convention) gives its half, from the centre to the rim.
  const sec = newSection();
  // pi/2 - t0 as atan2(cos t0, sin t0): without the cancellation of pi/2 - t0 when t0 is near pi/2.
  if (s.a > 0) evalSection(s, sign, Math.atan2(s.cosT0, sign * s.sinT0), sec);
  // A segment shorter than the thin ring's own error (towards the lean: of the order of b^2 / a) is
  // no segment: S and E are one ball.
  const long = s.a > 0 && Math.sqrt(sec.dy * sec.dy + sec.dz * sec.dz) > THIN_RING * s.a;
  const dy = long ? sec.dy : 0;
  const dz = long ? sec.dz : 0;
  return {
    sy: 0,
    sz: rcr,
    dy,
    dz,
    theta: long ? Math.atan2(dz, dy) : Math.PI / 2,
    shankTheta: lean ? Math.PI / 2 - Math.abs(s.phi) : null,
  };
}

/**
 * Normal angle (radians) on a ball around (ey, ez) at which its tangent passes through the axis of a
 * convex cylinder (the ball's farthest polar angle): `cos(theta) (ez + Rs) - sin(theta) ey = Rcr`.
 */
function tangentThroughAxisRad(ey: number, ez: number, rcr: number, rs: number): number {
  const qz = ez + rs;
  const d = Math.sqrt(ey * ey + qz * qz);
  return Math.PI / 2 - Math.asin(Math.min(1, rcr / d)) - Math.atan2(ey, qz);
}

/**
 * Radial limits of a stadium flank (see Stadium): its wall's height and the shank's, mm. Positions
 * along the flank are compared as (piece, parameter): ball S by normal angle, the tangent by its
 * fraction, ball E by normal angle.
 */
function stadiumLimit(st: Stadium, rcr: number, rs: number): { topMm: number; shankMm: number | null } {
  // The point at normal angle theta on the ball around (cy, cz): z = (cz - Rcr) + 2 Rcr sin^2(theta / 2).
  const onBall = (cy: number, cz: number, theta: number) => {
    const half = Math.sin(theta / 2);
    return radialHeightOf(cy + rcr * Math.sin(theta), cz - rcr + 2 * rcr * half * half, rs);
  };
  let topMm: number;
  let top: [number, number];
  if (rs > 0) {
    // Convex: the flank's polar angle peaks where its tangent passes through the axis; beyond, the
    // pass reaches no farther (a wall). The tangent's signed distance from the axis,
    // cos(theta) (z + Rs) - sin(theta) y, falls along the flank (constant along the straight part).
    const along = Math.cos(st.theta) * (st.sz + rs) - Math.sin(st.theta) * st.sy - rcr;
    if (along <= 0 || st.theta >= Math.PI / 2) {
      const theta = Math.max(0, Math.min(st.theta, tangentThroughAxisRad(st.sy, st.sz, rcr, rs)));
      top = [0, theta];
      topMm = onBall(st.sy, st.sz, theta);
    } else {
      const theta = Math.max(
        st.theta,
        Math.min(Math.PI / 2, tangentThroughAxisRad(st.sy + st.dy, st.sz + st.dz, rcr, rs)),
      );
      top = [2, theta];
      topMm = onBall(st.sy + st.dy, st.sz + st.dz, theta);
    }
  } else if (st.theta >= Math.PI / 2) {
    // Concave, one ball: the radial height grows up to the plane's widest point.
    top = [0, Math.PI / 2];
    topMm = onBall(st.sy, st.sz, Math.PI / 2);
  } else {
    // Concave: the radial height grows around S and along the tangent, up to the tangent's foot
    // nearest the axis (0, -Rs) if that lies on it; then it falls along the rest of the tangent, and
    // around E until E's farthest point from the axis, before it grows again up to the widest point.
    // Where it falls, a lower point beyond the first crossing of a height would reach farther: the
    // flanks hold (for every pass and pattern) below the lowest point of that dip (as the smooth
    // profiles, feedFlankLimit).
    const half = Math.sin(st.theta / 2);
    const py = st.sy + rcr * Math.sin(st.theta);
    const pz = st.sz - rcr + 2 * rcr * half * half + rs;
    const { dy, dz } = st;
    const lambda = -(py * dy + pz * dz) / (dy * dy + dz * dz);
    const ey = st.sy + dy;
    const ez = st.sz + dz;
    if (lambda >= 1) {
      top = [2, Math.PI / 2];
      topMm = onBall(ey, ez, Math.PI / 2);
    } else {
      // The dip's lowest point: the tangent's end, or E's farthest point from the axis past it.
      const far = Math.atan2(ey, -rs - ez);
      const theta = Math.min(Math.PI / 2, Math.max(st.theta, far));
      top = [2, theta];
      topMm = onBall(ey, ez, theta);
    }
  }
  let shankMm: number | null = null;
  if (st.shankTheta !== null) {
    // The junction lies on E (t = pi/2) once past the tangent; else S and E coincide.
    const onE = st.shankTheta >= st.theta;
    const at: [number, number] = [onE ? 2 : 0, st.shankTheta];
    if (at[0] < top[0] || (at[0] === top[0] && at[1] < top[1]))
      shankMm = onE ? onBall(st.sy + st.dy, st.sz + st.dz, st.shankTheta) : onBall(st.sy, st.sz, st.shankTheta);
  }
  return { topMm, shankMm };
}

/**
 * Polar angle (radians, from the contact) that a stadium flank reaches at radial height h: the
 * largest over its pieces (the two balls, as in feedAngleOfSection, and the tangent between them) of
 * the angle of their crossing with the circle of radius |Rs| + s h about the axis. Each crossing is a
 * point of the tool at that radius, and the flank's own is among them.
 */
function stadiumReach(st: Stadium, rcr: number, rs: number, h: number): number {
  const side = rs > 0 ? 1 : -1;
  // A ball around S + (cy, zeta): its crossing (a flat end's corner point only where it lies at h).
  const ball = (cy: number, zeta: number) => {
    const alpha = Math.atan2(cy, side * (zeta + rcr + rs));
    const half = ballHalfAngleRad(cy, zeta, rcr, rs, h);
    if (half !== null) return alpha + half;
    return rcr === 0 && radialHeightOf(cy, zeta, rs) === h ? alpha : Number.NEGATIVE_INFINITY;
  };
  let best = Math.max(ball(st.sy, st.sz - rcr), ball(st.sy + st.dy, st.sz - rcr + st.dz));
  const { dy, dz } = st;
  if (dy > 0 || dz > 0) {
    // The tangent (sy, sz) + Rcr n(theta) + lambda (dy, dz) against the circle: relative to the
    // contact's height h above, |P - C|^2 - r^2 = (py^2 + (pz - h)(pz + h + 2 Rs)) + 2 lambda (..) + lambda^2 |D|^2.
    const py = st.sy + rcr * Math.sin(st.theta);
    const half = Math.sin(st.theta / 2);
    const pz = st.sz - rcr + 2 * rcr * half * half;
    const c0 = py * py + (pz - h) * (pz + h + 2 * rs);
    const c1 = py * dy + (pz + rs) * dz;
    const c2 = dy * dy + dz * dz;
    const disc = c1 * c1 - c2 * c0;
    if (disc >= 0) {
      const root = Math.sqrt(disc);
      // The two roots without cancellation: q = -(c1 + sign(c1) root), lambda = q / c2 and c0 / q.
      const q = -(c1 + (c1 >= 0 ? root : -root));
      for (const lambda of [q / c2, q !== 0 ? c0 / q : Number.NaN]) {
        if (!(lambda >= 0 && lambda <= 1)) continue;
        best = Math.max(best, Math.atan2(py + lambda * dy, side * (pz + lambda * dz + rs)));
      }
    }
  }
  return best;
}

/**
 * Radial height (mm) of a stadium flank at polar angle beta from the contact: where the ray from the
 * axis at beta enters (convex) or leaves (concave) the union of the two balls and the band between.
 */
function stadiumHeightAtAngle(st: Stadium, rcr: number, rs: number, beta: number): number {
  const side = rs > 0 ? 1 : -1;
  const uy = Math.sin(beta);
  const uz = side * Math.cos(beta);
  let best = side > 0 ? Number.POSITIVE_INFINITY : Number.NEGATIVE_INFINITY;
  const keep = (distance: number) => {
    best = side > 0 ? Math.min(best, distance) : Math.max(best, distance);
  };
  const ball = (cy: number, cz: number) => {
    const qz = cz + rs;
    const along = cy * uy + qz * uz;
    const perp = cy * uz - qz * uy;
    const disc = (rcr - perp) * (rcr + perp);
    if (disc >= 0) keep(along - side * Math.sqrt(disc));
  };
  ball(st.sy, st.sz);
  ball(st.sy + st.dy, st.sz + st.dz);
  const { dy, dz } = st;
  if (dy > 0 || dz > 0) {
    // The band's outer edge: (sy, sz) + Rcr n(theta) + lambda (dy, dz), met by the ray (0, -Rs) + s u.
    const py = st.sy + rcr * Math.sin(st.theta);
    const half = Math.sin(st.theta / 2);
    const pz = st.sz - rcr + 2 * rcr * half * half + rs;
    const det = uy * dz - uz * dy;
    if (det !== 0) {
      const distance = (py * dz - pz * dy) / det;
      const lambda = (py * uz - pz * uy) / det;
      if (lambda >= 0 && lambda <= 1) keep(distance);
    }
  }
  return side * (best - Math.abs(rs));
}

/**
 * The profile point of the flank `sign` whose normal makes the angle theta with straight down,
 * relative to the contact (mm), and its section offset delta (radians): the ring ellipse's support
 * point in that direction, `(sin t, cos t) ~ (a sin(theta + phi), b cos(theta + phi))`, offset by
 * Rcr along the normal. Unlike the section parametrisation this stays well conditioned for a thin
 * ellipse (b << a), where the normal turns within a tiny range of t. Requires b > 0.
 */
function profileAtNormal(s: PostureShape, sign: number, theta: number): { y: number; z: number; delta: number } {
  const sinPhi = sign * s.sinPhi;
  const sinT0 = sign * s.sinT0;
  const st = Math.sin(theta);
  const ct = Math.cos(theta);
  const u = s.a * (st * s.cosPhi + ct * sinPhi);
  const v = s.b * (ct * s.cosPhi - st * sinPhi);
  const n = Math.sqrt(u * u + v * v);
  const sinT = u / n;
  const cosT = v / n;
  // y(t) = a cos(phi) sin t - b sin(phi) cos t, z(t) = -(a sin(phi) sin t + b cos(phi) cos t), from t0.
  const ds = sinT - sinT0;
  const dc = cosT - s.cosT0;
  const half = Math.sin(theta / 2);
  return {
    y: s.a * s.cosPhi * ds - s.b * sinPhi * dc + s.rcr * st,
    z: -(s.a * sinPhi * ds + s.b * s.cosPhi * dc) + 2 * s.rcr * half * half,
    delta: Math.atan2(sinT * s.cosT0 - cosT * sinT0, cosT * s.cosT0 + sinT * sinT0),
  };
}

/**
 * Golden-section search for the minimum of f on [lo, hi] (f unimodal there); its argument.
 */
function goldenMin(f: (x: number) => number, lo0: number, hi0: number): number {
  let lo = lo0;
  let hi = hi0;
  const g = (Math.sqrt(5) - 1) / 2;
  let c = hi - g * (hi - lo);
  let e = lo + g * (hi - lo);
  let fc = f(c);
  let fe = f(e);
  for (let i = 0; i < 200 && hi - lo > 1e-15 * Math.max(hi0, 1e-300); i++) {
    if (fc < fe) {
      hi = e;
      e = c;
      fe = fc;
      c = hi - g * (hi - lo);
      fc = f(c);
    } else {
      lo = c;
      c = e;
      fc = fe;
      e = lo + g * (hi - lo);
      fe = f(e);
    }
  }
  return 0.5 * (lo + hi);
}

/**
 * The wall of a flank on a concave cylinder along the feed (smooth profile): its radial height and
 * section offset. Along the flank the profile point's distance from the axis is stationary where
 * its normal passes through the axis, that is where the ring point's own distance D(delta) = |e -
 * C| is (its derivative is (e - C).e'), and there it is D + Rcr. So the flank's radial height grows
 * up to the first minimum of D (golden section; no profile normal needed, which a thin ring would
 * garble), or to the plane's widest point if D still falls there. If it peaks before that, it falls
 * to the next maximum of D (or the widest point) and grows again: a lower point beyond the first
 * crossing of a height would reach farther, so the flank holds below that dip's lowest height,
 * which is then the limit (the first crossing stays the flank below it, with the peak's offset as
 * the bracket). D is unimodal on each side of the peak in every posture measured.
 */
function concaveFlankTop(s: PostureShape, sign: number, rs: number): { topMm: number; deltaTop: number } {
  const rcr = s.rcr;
  const abs = -rs;
  const sec = newSection();
  const ring = (delta: number) => {
    evalSection(s, sign, delta, sec);
    return { y: sec.dy, z: sec.dz };
  };
  const distance = (delta: number) => {
    const e = ring(delta);
    return Math.sqrt(e.y * e.y + (e.z + rcr - abs) * (e.z + rcr - abs));
  };
  // |Rs| - (D + Rcr) = ((|Rs| - Rcr)^2 - D^2) / (|Rs| - Rcr + D), the numerator dz (2 (|Rs| - Rcr) - dz) - dy^2.
  const atCritical = (delta: number) => {
    const e = ring(delta);
    const d = Math.sqrt(e.y * e.y + (e.z + rcr - abs) * (e.z + rcr - abs));
    return (e.z * (2 * (abs - rcr) - e.z) - e.y * e.y) / (abs - rcr + d);
  };
  const plane = planeTop(s, sign);
  const widest = () => {
    const e = ring(plane);
    return radialHeightOf(e.y + rcr, e.z + rcr, rs);
  };
  const peak = goldenMin(distance, 0, plane);
  if (!(distance(peak) < distance(plane)) || peak >= plane * (1 - 1e-12)) return { topMm: widest(), deltaTop: plane };
  // The dip's lowest height: the profile point is never farther from the axis than D + Rcr, so
  // |Rs| - max D - Rcr bounds it from below (exactly where that maximum is a critical point).
  const low = goldenMin((d) => -distance(d), peak, plane);
  return { topMm: Math.min(atCritical(low), widest(), atCritical(peak)), deltaTop: peak };
}

/** The shank's radial height on a flank of a smooth profile (where the normal is (cos phi, -sin phi)), if it leans that way. */
function concaveShank(s: PostureShape, sign: number, rs: number): number | null {
  if (!(sign * s.sinPhi > 0)) return null;
  const p = profileAtNormal(s, sign, Math.PI / 2 - Math.abs(s.phi));
  return radialHeightOf(p.y, p.z, rs);
}

/** Radial limits of one flank along the feed (mm) and the section offset of its wall (radians; 0 for a stadium). */
interface FeedFlankLimit {
  readonly topMm: number;
  readonly shankMm: number | null;
  readonly deltaTop: number;
}

/**
 * Radial limits of one flank on a cylinder with the axis along the feed (mm), and the section offset
 * of its wall. The wall: on a convex cylinder where the flank's polar angle peaks, its tangent
 * through the axis (the tangent's signed distance from the axis, `cos(theta) (z + Rs) - sin(theta)
 * y`, falls strictly along the flank: its derivative in theta is `-(sin(theta) (z + Rs) + cos(theta)
 * y)`; bisection); on a concave one where its radial height stops growing, at most the plane's
 * widest point, or below a dip (concaveFlankTop). The shank: it leaves the profile at the
 * end of the ellipse's long axis, where the normal is (cos phi, -sin phi), on the side the tool
 * leans to (posture.ts); radially, its height is that point's, if it comes before the wall.
 */
function feedFlankLimit(s: PostureShape, sign: number, rs: number): FeedFlankLimit {
  const st = stadiumOf(s, sign);
  if (st !== null) return { ...stadiumLimit(st, s.rcr, rs), deltaTop: 0 };
  if (rs < 0) return { ...concaveFlankTop(s, sign, rs), shankMm: concaveShank(s, sign, rs) };
  let lo = 0;
  let hi = Math.PI / 2;
  for (let i = 0; i < 200; i++) {
    const mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    const p = profileAtNormal(s, sign, mid);
    if (Math.cos(mid) * (p.z + rs) - Math.sin(mid) * p.y > 0) lo = mid;
    else hi = mid;
  }
  const top = profileAtNormal(s, sign, lo);
  const shankTheta = Math.PI / 2 - Math.abs(s.phi);
  const shank = sign * s.sinPhi > 0 && shankTheta < lo ? profileAtNormal(s, sign, shankTheta) : null;
  return {
    topMm: radialHeightOf(top.y, top.z, rs),
    shankMm: shank === null ? null : radialHeightOf(shank.y, shank.z, rs),
    deltaTop: top.delta,
  };
}

/**
 * The binding limit of two flanks and their shank heights. Heights are clamped at 0: a flank that
 * dips below the surface belongs to a trough the tool gouges, which validation refuses first.
 */
function limitsOf(topRight: number, topLeft: number, shankRight: number | null, shankLeft: number | null): FlankLimits {
  const topRightMm = Math.max(0, topRight);
  const topLeftMm = Math.max(0, topLeft);
  const shankRightMm = shankRight === null ? null : Math.max(0, shankRight);
  const shankLeftMm = shankLeft === null ? null : Math.max(0, shankLeft);
  const candidates: Array<[number, FlankLimits['limitBy']]> = [];
  if (shankRightMm !== null) candidates.push([shankRightMm, 'shank-right']);
  if (shankLeftMm !== null) candidates.push([shankLeftMm, 'shank-left']);
  candidates.push([topRightMm, 'right-flank'], [topLeftMm, 'left-flank']);
  let best = candidates[0] as [number, FlankLimits['limitBy']];
  for (const c of candidates) if (c[0] < best[0]) best = c;
  return { topRightMm, topLeftMm, shankRightMm, shankLeftMm, limitMm: best[0], limitBy: best[1] };
}

// ---------------------------------------------------------------------------------------------
// Axis across the feed

/**
 * The bottom disk's chords in meridian coordinates: on the chord at y, the point nearest the axis
 * (convex) or farthest from it (concave), and its radial height above the design surface.
 */
interface Chords {
  readonly yLo: number;
  readonly yHi: number;
  /**
   * Signed radial height (mm) of the chord's chosen point: `rho - Rs` convex, `|Rs| - rho` concave,
   * computed as `(x^2 + z (z + 2 Rs)) / (rho + |Rs|)` without cancellation (x, z relative to the
   * contact), so that scallops of a nanometre on a cylinder of a kilometre keep their digits.
   */
  height(y: number): number;
}

function crossChords(p: Placement, rs: number): Chords {
  const rb = p.ringRadiusMm;
  const { centre, v1, v2 } = p;
  const gy1 = v1[1];
  const gy2 = v2[1];
  const G = Math.sqrt(gy1 * gy1 + gy2 * gy2);
  const concave = rs < 0;
  const side = concave ? -1 : 1;
  const abs = Math.abs(rs);
  // A disk point: centre + u v1 + w v2 (u^2 + w^2 <= Rb^2), relative to the contact; the axis runs
  // along Y through (x = 0, z = -Rs). Its squared distance from the axis, and its radial height.
  const rho2 = (x: number, z: number) => x * x + (z + rs) * (z + rs);
  const heightOf = (x: number, z: number) => (side * (x * x + z * (z + 2 * rs))) / (Math.sqrt(rho2(x, z)) + abs);
  const at = (u: number, w: number, out: number[]) => {
    out[0] = centre[0] + u * v1[0] + w * v2[0];
    out[1] = centre[2] + u * v1[2] + w * v2[2];
  };
  const pa = [0, 0];
  const pb = [0, 0];
  const pf = [0, 0];
  if (!(rb > 0) || !(G > 0)) {
    // A ball end (one point), or a disk seen edge-on along Y (all at one y): a single chord.
    const y = centre[1];
    const pts: Array<[number, number]> =
      rb > 0
        ? [
            [rb, 0],
            [-rb, 0],
            [0, rb],
            [0, -rb],
          ]
        : [[0, 0]];
    const heights = pts.map(([u, w]) => {
      at(u, w, pa);
      return { r2: rho2(pa[0] as number, pa[1] as number), h: heightOf(pa[0] as number, pa[1] as number) };
    });
    heights.sort((m, n) => m.r2 - n.r2);
    const chosen = (concave ? heights[heights.length - 1] : heights[0]) as { h: number };
    return { yLo: y, yHi: y, height: () => chosen.h };
  }
  return {
    yLo: centre[1] - rb * G,
    yHi: centre[1] + rb * G,
    height(y) {
      const c = Math.min(rb * G, Math.max(-rb * G, y - centre[1]));
      // Chord: (u, w) = c g / G^2 + tau g_perp / G, |tau| <= sqrt(Rb^2 - c^2 / G^2).
      const u0 = (c * gy1) / (G * G);
      const w0 = (c * gy2) / (G * G);
      const du = -gy2 / G;
      const dw = gy1 / G;
      const tMax = Math.sqrt(Math.max(0, rb * rb - (c * c) / (G * G)));
      at(u0 + tMax * du, w0 + tMax * dw, pa);
      at(u0 - tMax * du, w0 - tMax * dw, pb);
      const ra = rho2(pa[0] as number, pa[1] as number);
      const rbb = rho2(pb[0] as number, pb[1] as number);
      if (concave)
        return ra >= rbb ? heightOf(pa[0] as number, pa[1] as number) : heightOf(pb[0] as number, pb[1] as number);
      // Convex: the distance along a straight chord is convex; its minimum is at the foot of the
      // axis on the chord's line (clipped to the chord).
      at(u0, w0, pf);
      const x0 = pf[0] as number;
      const z0 = (pf[1] as number) + rs;
      const dx = du * v1[0] + dw * v2[0];
      const dz = du * v1[2] + dw * v2[2];
      const den = dx * dx + dz * dz;
      const tau = den > 0 ? Math.min(tMax, Math.max(-tMax, -(x0 * dx + z0 * dz) / den)) : 0;
      at(u0 + tau * du, w0 + tau * dw, pf);
      const rf = rho2(pf[0] as number, pf[1] as number);
      const q = rf <= ra && rf <= rbb ? pf : ra <= rbb ? pa : pb;
      return heightOf(q[0] as number, q[1] as number);
    },
  };
}

/**
 * The maximum of f on [lo, hi]: a scan of `samples` points brackets the best one, then Brent's
 * method (parabolic steps, golden-section ones where they do not help, so kinks are safe) to
 * `tol` in the argument. Returns the largest value seen.
 */
function maximise(
  f: (x: number) => number,
  lo: number,
  hi: number,
  samples: number,
  tol: number,
  must?: number,
): number {
  let best = 0;
  let fBest = Number.NEGATIVE_INFINITY;
  for (let i = 0; i <= samples; i++) {
    const v = f(lo + ((hi - lo) * i) / samples);
    if (v > fBest) {
      fBest = v;
      best = i;
    }
  }
  let a = lo + ((hi - lo) * Math.max(0, best - 1)) / samples;
  let b = lo + ((hi - lo) * Math.min(samples, best + 1)) / samples;
  let x = lo + ((hi - lo) * best) / samples;
  // A point known to count (the contact's chord, feasible at any height): when it beats the scan,
  // search around it, between its neighbouring samples.
  if (must !== undefined && must >= lo && must <= hi) {
    const fm = f(must);
    if (fm > fBest) {
      fBest = fm;
      x = must;
      const k = Math.floor(((must - lo) / (hi - lo)) * samples);
      a = lo + ((hi - lo) * Math.max(0, k)) / samples;
      b = lo + ((hi - lo) * Math.min(samples, k + 1)) / samples;
    }
  }
  const golden = 0.381966011250105;
  let w = x;
  let v = x;
  let fx = fBest;
  let fw = fx;
  let fv = fx;
  let d = 0;
  let e = 0;
  for (let i = 0; i < 200; i++) {
    const m = 0.5 * (a + b);
    if (Math.abs(x - m) <= 2 * tol - 0.5 * (b - a)) break;
    let u: number;
    let parabolic = false;
    if (Math.abs(e) > tol) {
      // Parabola through x, w, v (maximising: the same algebra on -f).
      const r = (x - w) * (fv - fx);
      let q = (x - v) * (fw - fx);
      let pp = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) pp = -pp;
      q = Math.abs(q);
      if (Math.abs(pp) < Math.abs(0.5 * q * e) && pp > q * (a - x) && pp < q * (b - x)) {
        e = d;
        d = pp / q;
        parabolic = true;
      }
    }
    if (!parabolic) {
      e = x < m ? b - x : a - x;
      d = golden * e;
    }
    u = Math.abs(d) >= tol ? x + d : x + (d > 0 ? tol : -tol);
    const fu = f(u);
    if (fu >= fx) {
      if (u < x) b = x;
      else a = x;
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      if (u < x) a = u;
      else b = u;
      if (fu >= fw || w === x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu >= fv || v === x || v === w) {
        v = u;
        fv = fu;
      }
    }
  }
  return Math.max(fBest, fx);
}

/**
 * Width of a flank of the revolved profile at radial height h (axis across the feed): the largest
 * distance out from the contact (along Y) at which some chord's circle reaches radius |Rs| + s h.
 */
function crossWidthAtHeight(ch: Chords, sign: number, rcr: number, h: number, contactY: number): number {
  // Reach of the chord at y: its circle (radius Rcr around its point, radial height d) at height h.
  const reach = (y: number) => {
    const gap = ch.height(y) - h;
    if (gap <= 0) return rcr;
    return gap <= rcr ? Math.sqrt((rcr - gap) * (rcr + gap)) : Number.NEGATIVE_INFINITY;
  };
  const f = (y: number) => sign * (y - contactY) + reach(y);
  if (!(ch.yHi > ch.yLo)) return f(ch.yLo);
  // The maximum is flat, so 1e-13 of the disk's span in y leaves its value exact to the last bits
  // (a kink, where the nearest point of a chord moves to its end, is handled by Brent's golden steps).
  return maximise(f, ch.yLo, ch.yHi, 16, 1e-13 * (ch.yHi - ch.yLo), contactY);
}

/** Radial height of the revolved profile at a distance w out from the contact (the inverse). */
function crossHeightAtWidth(ch: Chords, sign: number, rcr: number, w: number, contactY: number): number {
  const Y = contactY + sign * w;
  // The profile's radial height at Y: the lowest, over chords within Rcr of Y, of the chord point's
  // height less the circle's vertical reach, d(y) - sqrt(Rcr^2 - (Y - y)^2). Scan then Brent.
  const lo = Math.max(ch.yLo, Y - rcr);
  const hi = Math.min(ch.yHi, Y + rcr);
  const f = (y: number) => {
    const d = Y - y;
    const v = Math.sqrt(Math.max(0, (rcr - d) * (rcr + d)));
    return v - ch.height(y);
  };
  if (!(hi >= lo)) return Number.POSITIVE_INFINITY;
  const top = hi > lo ? maximise(f, lo, hi, 16, 1e-13 * Math.max(hi - lo, rcr)) : f(lo);
  return -top;
}

/**
 * Radial heights (mm) at which the shank starts to shape each flank of the revolved profile (axis
 * across the feed), or null on a side where it does not. A pass turns the tool about the axis, so
 * the profile at y is the point of the tool's slice at y nearest the axis (convex; farthest,
 * concave). The shank starts to cut where that point moves from the end onto the shank, across the
 * equator (the circle of radius R at the corner's top, `O + R r(t)`), where the two surfaces share
 * the normal r(t). There the slice's boundary normal, (r_x, r_z), points at the axis (convex: the
 * nearest point of a convex slice; concave: away from it, the farthest):
 *
 *   F(t) = P_x r_z - (P_z + Rs) r_x = 0,   side (-(P_x r_x + (P_z + Rs) r_z)) > 0,
 *
 * P relative to the contact, side = sign(Rs). Roots by a scan of the ring and bisection; on each side
 * the one nearest the contact. At the equator's points across the axis (r = +-Y: the widest point
 * of an untilted tool, where the shank joins without cutting) the slice's normal vanishes; those
 * are left out.
 */
function crossShankHeights(p: Placement, rs: number): { right: number | null; left: number | null } {
  const R = p.ringRadiusMm + p.cornerRadiusMm;
  const { centre, v1, v2 } = p;
  const side = rs > 0 ? 1 : -1;
  const r = [0, 0, 0];
  const P = [0, 0, 0];
  const at = (t: number) => {
    const sn = Math.sin(t);
    const c = Math.cos(t);
    for (let k = 0; k < 3; k++) {
      r[k] = sn * (v1[k] as number) + c * (v2[k] as number);
      P[k] = (centre[k] as number) + R * (r[k] as number);
    }
    return (P[0] as number) * (r[2] as number) - ((P[2] as number) + rs) * (r[0] as number);
  };
  let right: { y: number; h: number } | null = null;
  let left: { y: number; h: number } | null = null;
  const n = 64;
  let tPrev = 0;
  let fPrev = at(0);
  for (let i = 1; i <= n; i++) {
    const t = (2 * Math.PI * i) / n;
    const f = at(t);
    if (fPrev <= 0 !== f <= 0) {
      let lo = tPrev;
      let hi = t;
      for (let k = 0; k < 200; k++) {
        const mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        if (at(mid) <= 0 === fPrev <= 0) lo = mid;
        else hi = mid;
      }
      at(0.5 * (lo + hi));
      const [x, y, z] = P as [number, number, number];
      const rx = r[0] as number;
      const rz = r[2] as number;
      if (Math.sqrt(rx * rx + rz * rz) > 1e-9 && side * -(x * rx + (z + rs) * rz) > 0) {
        const h = (side * (x * x + z * (z + 2 * rs))) / (Math.sqrt(x * x + (z + rs) * (z + rs)) + Math.abs(rs));
        if (y > 0 && (right === null || y < right.y)) right = { y, h };
        if (y < 0 && (left === null || y > left.y)) left = { y, h };
      }
    }
    tPrev = t;
    fPrev = f;
  }
  return { right: right?.h ?? null, left: left?.h ?? null };
}

// ---------------------------------------------------------------------------------------------
// Public API

/** A cylinder prepared for one tool and posture. */
export interface CylinderSolver {
  readonly surface: CylinderSurface;
  /** Radial height limits: each flank's wall, and the shank where it starts to cut (module comment), mm. */
  limits(): FlankLimits;
  /**
   * How far a flank reaches at radial height h: the polar angle about the axis (axis = feed,
   * radians) or the distance along the axis from the contact (axis = cross, mm).
   */
  reach(flank: Flank, heightMm: number): number;
  /** The inverse: radial height of a flank at that reach. */
  heightAt(flank: Flank, reach: number): number;
  /** Step-over (arc length on the surface for axis = feed, along the axis for cross) from reaches. */
  intervalFromReach(reachMm: number): number;
  /** The reach a step-over corresponds to. */
  reachFromInterval(intervalMm: number): number;
}

/** Axis along the feed: flank angles about the axis (classes: no closures built per call). */
class FeedSolver implements CylinderSolver {
  private cached: FlankLimits | null = null;
  /** Each flank's limits (feedFlankLimit), found once. */
  private readonly flanks: [FeedFlankLimit | null, FeedFlankLimit | null] = [null, null];
  private readonly s: PostureShape;
  private readonly rs: number;
  /** Each flank as a stadium when the ring is degenerate (no lead, or a ball end), else null. */
  private readonly stadiums: [Stadium | null, Stadium | null];

  constructor(
    readonly surface: CylinderSurface,
    p: Placement,
  ) {
    this.s = p.shape;
    this.rs = surface.radiusMm;
    this.stadiums = [stadiumOf(p.shape, 1), stadiumOf(p.shape, -1)];
  }

  private flank(sign: number): FeedFlankLimit {
    const index = sign > 0 ? 0 : 1;
    const known = this.flanks[index];
    if (known !== null && known !== undefined) return known;
    const found = feedFlankLimit(this.s, sign, this.rs);
    this.flanks[index] = found;
    return found;
  }

  limits(): FlankLimits {
    if (this.cached === null) {
      const right = this.flank(1);
      const left = this.flank(-1);
      this.cached = limitsOf(right.topMm, left.topMm, right.shankMm, left.shankMm);
    }
    return this.cached;
  }

  /**
   * An offset past the root for height h: the plane flank's widest point, where G has changed sign
   * on a convex cylinder and on a concave one that is not tight; else the concave radial top.
   */
  private bracket(sign: number, h: number): number {
    const s = this.s;
    const plane = planeTop(s, sign);
    if (this.rs > 0) return plane;
    const at = profilePoint(s, sign, plane);
    if (at.y * at.y + (at.h - h) * (at.h + h + 2 * this.rs) < 0) return plane;
    return this.flank(sign).deltaTop;
  }

  reach(flank: Flank, h: number): number {
    const sign = flankSign(flank);
    const stadium = this.stadiums[sign > 0 ? 0 : 1] ?? null;
    if (stadium !== null) return stadiumReach(stadium, this.s.rcr, this.rs, h);
    return feedAngleAtHeight(this.s, flank, this.rs, h, this.bracket(sign, h));
  }

  heightAt(flank: Flank, beta: number): number {
    const sign = flankSign(flank);
    const s = this.s;
    const stadium = this.stadiums[sign > 0 ? 0 : 1] ?? null;
    if (stadium !== null) return stadiumHeightAtAngle(stadium, s.rcr, this.rs, beta);
    return feedHeightAtAngle(s, flank, this.rs, beta, this.flank(sign).deltaTop);
  }

  intervalFromReach(angle: number): number {
    return Math.abs(this.rs) * angle;
  }

  reachFromInterval(L: number): number {
    return L / Math.abs(this.rs);
  }
}

/** Axis across the feed: widths along the axis of the revolved profile. */
class CrossSolver implements CylinderSolver {
  private cached: FlankLimits | null = null;
  private readonly ch: Chords;

  constructor(
    readonly surface: CylinderSurface,
    private readonly p: Placement,
  ) {
    this.ch = crossChords(p, surface.radiusMm);
  }

  limits(): FlankLimits {
    if (this.cached === null) {
      // The widest point of each flank: the chord at the end of the disk's Y range (one ring
      // point). The shank: where the revolved profile's lowest (highest) point moves onto it.
      const topRight = this.ch.height(this.ch.yHi);
      const topLeft = this.ch.height(this.ch.yLo);
      const shank = crossShankHeights(this.p, this.surface.radiusMm);
      this.cached = limitsOf(
        topRight,
        topLeft,
        shank.right !== null && shank.right < topRight ? shank.right : null,
        shank.left !== null && shank.left < topLeft ? shank.left : null,
      );
    }
    return this.cached;
  }

  reach(flank: Flank, h: number): number {
    return crossWidthAtHeight(this.ch, flankSign(flank), this.p.cornerRadiusMm, h, 0);
  }

  heightAt(flank: Flank, w: number): number {
    return crossHeightAtWidth(this.ch, flankSign(flank), this.p.cornerRadiusMm, w, 0);
  }

  intervalFromReach(w: number): number {
    return w;
  }

  reachFromInterval(L: number): number {
    return L;
  }
}

/** Prepares the cylinder solver for a tool and posture. @param surface |Rs| > 0. */
export function cylinderSolver(tool: ToolInput, surface: CylinderSurface): CylinderSolver {
  const p = placeTool(tool);
  return surface.axis === 'feed' ? new FeedSolver(surface, p) : new CrossSolver(surface, p);
}

/**
 * The smallest concave radius |Rs| (mm) the tool end (its head) fits in without gouging: the maximum over the
 * ring of `(E^2 + E_z^2 - Rcr^2) / (2 (E_z - Rcr))`, written `E^2 / (2 rise) + (rise + 2 Rcr) / 2`
 * with `rise = E_z - Rcr` the ring point's height above the contact's ring point (Eq. 1
 * generalised, `2 D0 sin^2(delta/2)`) and E its horizontal offset (the chord: seen along the feed
 * for axis = feed, along the axis for axis = cross), so that the contact's neighbourhood keeps its
 * digits: there the value tends to the curvature radius of the view. Infinity when the tool gouges
 * every concave cylinder (a ring point other than the contact at the contact's height: a flat
 * bottom without lead across the axis). Sampled over the ring, then refined by golden-section search.
 */
function headMinConcaveRadiusMm(p: Placement, axis: SurfaceAxis): number {
  const s = p.shape;
  const rb = p.ringRadiusMm;
  const rcr = p.cornerRadiusMm;
  if (!(rb > 0)) return rcr; // a ball end fits any trough of at least its radius
  const t0 = p.contactRingAngleRad;
  const k = axis === 'feed' ? 1 : 0;
  const ratio = (delta: number): number => {
    const half = Math.sin(delta / 2);
    const rise = 2 * s.d0 * half * half;
    const m = t0 + delta / 2;
    // Chord of the ring from the contact's ring point: 2 sin(delta/2) (cos m v1 - sin m v2), times Rb.
    const e = 2 * half * rb * (Math.cos(m) * p.v1[k] - Math.sin(m) * p.v2[k]);
    if (!(rise > 0)) return e === 0 ? 0 : Number.POSITIVE_INFINITY;
    return (e * e) / (2 * rise) + (rise + 2 * rcr) / 2;
  };
  if (!(s.d0 > 0)) return Number.POSITIVE_INFINITY;
  const n = 720;
  let best = 1;
  let value = 0;
  for (let i = 1; i < n; i++) {
    const v = ratio((2 * Math.PI * i) / n);
    if (v > value) {
      value = v;
      best = i;
    }
  }
  if (!Number.isFinite(value)) return value;
  let a = (2 * Math.PI * (best - 1)) / n;
  let b = (2 * Math.PI * (best + 1)) / n;
  const g = (Math.sqrt(5) - 1) / 2;
  for (let i = 0; i < 100; i++) {
    const c = b - g * (b - a);
    const e = a + g * (b - a);
    if (ratio(c) > ratio(e)) b = e;
    else a = c;
  }
  // Near the contact the ratio tends to the local curvature radius: include that limit.
  return Math.max(value, ratio(0.5 * (a + b)), ratio(1e-7), ratio(2 * Math.PI - 1e-7));
}

/**
 * The smallest concave radius |Rs| (mm) at and above which the shank stays inside the cylinder up to
 * the height of its axis (shared/notes/posture-and-surfaces.md): 0 when it never meets the wall,
 * Infinity when it does at any radius. Seen along the axis (along the feed for axis = feed, along Y
 * for cross), the shank is a strip of half-width R around the projected tool axis, leaning from the
 * normal by `k = a_w / a_z` (w the horizontal of the view); its edges start on the head at the two
 * equator points `J = O +- R c`, c = a x view / |a x view|. An edge stays inside up to the axis
 * height rho iff, where it reaches that height, `|J_w + k (rho - J_z)| <= rho` (the distance from the
 * axis is convex along the edge, and its start J lies on the head, inside). Each side is a condition
 * `m rho >= q`: with m > 0 it holds from `q / m` up; with m <= 0 and q > 0 it fails at every radius
 * above J_z (a lean of 45 degrees or more towards the wall: the chord from the contact to the wall
 * at the axis height leans 45 degrees). Radii up to J_z, where the edge starts above the axis
 * height, are not needed: the head's own limit lies above them in every posture measured.
 */
function shankMinConcaveRadiusMm(p: Placement, axis: SurfaceAxis): number {
  const a = p.axis;
  const R = p.ringRadiusMm + p.cornerRadiusMm;
  // View along X (feed): w = Y; along Y (cross): w = X. c = a x view, normalised.
  const w = axis === 'feed' ? 1 : 0;
  const cw = axis === 'feed' ? a[2] : -a[2];
  const cz = axis === 'feed' ? -a[1] : a[0];
  const cn = Math.sqrt(cw * cw + cz * cz);
  const k = a[w] / a[2];
  let need = 0;
  for (const edge of [1, -1]) {
    const jw = (p.centre[w] as number) + (edge * R * cw) / cn;
    const jz = (p.centre[2] as number) + (edge * R * cz) / cn;
    const w0 = jw - k * jz;
    for (const s of [1, -1]) {
      // s = 1: w <= rho (the wall at +w); s = -1: w >= -rho.
      const m = 1 - s * k;
      const q = s * w0;
      if (m > 0) {
        if (q / m > jz) need = Math.max(need, q / m);
      } else if (q > 0 || m < 0) return Number.POSITIVE_INFINITY;
    }
  }
  return need;
}

/** What a concave cylinder must be for a tool and posture, and why (mm, degrees). */
export interface ConcaveFit {
  /** Smallest radius |Rs| the head (corner and bottom) fits in; Infinity if none. */
  readonly headMm: number;
  /** Smallest radius from which the shank stays inside up to the axis height; 0 if any, Infinity if none. */
  readonly shankMm: number;
  /** The smallest admissible radius: the larger of both. */
  readonly minRadiusMm: number;
  /** Which of them sets it (the head on a tie). */
  readonly limitedBy: 'head' | 'shank';
  /**
   * The shank's lean from the surface normal seen along the cylinder's axis, degrees (>= 0): the
   * projected lean `atan(tan(beta) / cos(rho))` along the feed, the lead rho across it.
   */
  readonly shankLeanDeg: number;
}

/**
 * Whether and from which radius a concave cylinder takes the tool (gouging by the head or the
 * shank): see headMinConcaveRadiusMm and shankMinConcaveRadiusMm.
 * @param tool validated tool and posture. @param axis the cylinder's axis.
 */
export function concaveFit(tool: ToolInput, axis: SurfaceAxis): ConcaveFit {
  const p = placeTool(tool);
  const headMm = headMinConcaveRadiusMm(p, axis);
  const shankMm = shankMinConcaveRadiusMm(p, axis);
  const a = p.axis;
  const lean = Math.atan2(Math.abs(axis === 'feed' ? a[1] : a[0]), a[2]);
  return {
    headMm,
    shankMm,
    minRadiusMm: Math.max(headMm, shankMm),
    limitedBy: shankMm > headMm ? 'shank' : 'head',
    shankLeanDeg: radToDeg(lean),
  };
}

/**
 * The smallest concave radius |Rs| (mm) that takes the tool in its posture without gouging: the
 * larger of the head's and the shank's limits (concaveFit); Infinity when no radius does.
 * @param tool validated tool and posture. @param axis the cylinder's axis.
 */
export function minConcaveRadiusMm(tool: ToolInput, axis: SurfaceAxis): number {
  return concaveFit(tool, axis).minRadiusMm;
}

/**
 * The profile one pass leaves on a cylinder, in the coordinates a cross-section view draws (mm):
 * along the feed, the plane profile of geometry.ts (y, z from the contact), which a view turns about
 * the axis at (0, -Rs) for the next pass; across the feed, the revolved profile in the meridian
 * plane, (position along the axis from the contact, radial height above the surface), from one
 * flank's widest point to the other's.
 * @param samplesPerHalf points per flank (>= 8).
 */
export function revolvedProfile(tool: ToolInput, surface: CylinderSurface, samplesPerHalf = 96): Float64Array {
  const n = Math.max(8, Math.round(samplesPerHalf));
  const c = cylinderSolver(tool, surface);
  const lim = c.limits();
  const out: number[] = [];
  const flankPoints = (flank: Flank) => {
    const wTop = c.reach(flank, flank === 'right' ? lim.topRightMm : lim.topLeftMm);
    const pts: Array<[number, number]> = [];
    for (let i = 0; i <= n; i++) {
      // Denser near the contact, where scallops form.
      const u = i / n;
      const w = wTop * u * u;
      pts.push([w, Math.max(0, c.heightAt(flank, w))]);
    }
    return pts;
  };
  const left = flankPoints('left');
  const right = flankPoints('right');
  for (let i = left.length - 1; i >= 1; i--)
    out.push(-(left[i] as [number, number])[0], (left[i] as [number, number])[1]);
  for (const [w, h] of right) out.push(w, h);
  return Float64Array.from(out);
}
