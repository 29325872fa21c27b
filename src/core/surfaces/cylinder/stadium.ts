/**
 * Axis along the feed, degenerate rings (see ../cylinder.ts's module comment): a flank whose ring
 * projects onto a segment or a point, in closed form. Lengths mm, angles radians.
 */
import { evalSection, newSection, type PostureShape } from '../../tool/posture';
import { ballHalfAngleRad, radialHeightOf } from './feedProfile';

/**
 * Below this ratio b / a the ring's projection is taken as its segment (a stadium flank, below): the
 * profile moves by at most b, under 1e-11 mm for R <= 1000 mm, while the section parametrisation
 * loses the normal's digits (its components are of the order of b / a, and their squares underflow
 * below 1e-154).
 */
export const THIN_RING = 1e-14;

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
export interface Stadium {
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
export function stadiumOf(s: PostureShape, sign: number): Stadium | null {
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
export function tangentThroughAxisRad(ey: number, ez: number, rcr: number, rs: number): number {
  const qz = ez + rs;
  const d = Math.sqrt(ey * ey + qz * qz);
  return Math.PI / 2 - Math.asin(Math.min(1, rcr / d)) - Math.atan2(ey, qz);
}

/**
 * Radial limits of a stadium flank (see Stadium): its wall's height and the shank's, mm. Positions
 * along the flank are compared as (piece, parameter): ball S by normal angle, the tangent by its
 * fraction, ball E by normal angle.
 */
export function stadiumLimit(st: Stadium, rcr: number, rs: number): { topMm: number; shankMm: number | null } {
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
export function stadiumReach(st: Stadium, rcr: number, rs: number, h: number): number {
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
export function stadiumHeightAtAngle(st: Stadium, rcr: number, rs: number, beta: number): number {
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
