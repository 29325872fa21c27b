/**
 * Axis along the feed: each flank's radial limits (its wall, the shank) (see ../cylinder.ts's
 * module comment). Lengths mm, angles radians.
 */
import { bracketedRoot, goldenMinimum, MAX_ITERATIONS, newSearchEnd } from '../../math/rootFinder';
import { evalSection, type FlankLimits, flankLimitsOf, newSection, type PostureShape } from '../../tool/posture';
import { planeTop, radialHeightOf } from './feedProfile';
import { stadiumLimit, stadiumOf } from './stadium';

/**
 * The profile point of the flank `sign` whose normal makes the angle theta with straight down,
 * relative to the contact (mm), and its section offset delta (radians): the ring ellipse's support
 * point in that direction, `(sin t, cos t) ~ (a sin(theta + phi), b cos(theta + phi))`, offset by
 * Rcr along the normal. Unlike the section parametrisation this stays well conditioned for a thin
 * ellipse (b << a), where the normal turns within a tiny range of t. Requires b > 0.
 */
export function profileAtNormal(s: PostureShape, sign: number, theta: number): { y: number; z: number; delta: number } {
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
export function concaveFlankTop(s: PostureShape, sign: number, rs: number): { topMm: number; deltaTop: number } {
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
  const peak = goldenMinimum({ value: distance }, 0, plane);
  if (!(distance(peak) < distance(plane)) || peak >= plane * (1 - 1e-12)) return { topMm: widest(), deltaTop: plane };
  // The dip's lowest height: the profile point is never farther from the axis than D + Rcr, so
  // |Rs| - max D - Rcr bounds it from below (exactly where that maximum is a critical point).
  const low = goldenMinimum({ value: (d: number) => -distance(d) }, peak, plane);
  return { topMm: Math.min(atCritical(low), widest(), atCritical(peak)), deltaTop: peak };
}

/** The shank's radial height on a flank of a smooth profile (where the normal is (cos phi, -sin phi)), if it leans that way. */
export function concaveShank(s: PostureShape, sign: number, rs: number): number | null {
  if (!(sign * s.sinPhi > 0)) return null;
  const p = profileAtNormal(s, sign, Math.PI / 2 - Math.abs(s.phi));
  return radialHeightOf(p.y, p.z, rs);
}

/** Radial limits of one flank along the feed (mm) and the section offset of its wall (radians; 0 for a stadium). */
export interface FeedFlankLimit {
  readonly topMm: number;
  readonly shankMm: number | null;
  readonly deltaTop: number;
}

/**
 * Radial limits of one flank on a cylinder with the axis along the feed (mm), and the section offset
 * of its wall. The wall: on a convex cylinder where the flank's polar angle peaks, its tangent
 * through the axis (the tangent's signed distance from the axis, `cos(theta) (z + Rs) - sin(theta)
 * y`, falls strictly along the flank: its derivative in theta is `-(sin(theta) (z + Rs) + cos(theta)
 * y)`; the shared bracketed root); on a concave one where its radial height stops growing, at most the plane's
 * widest point, or below a dip (concaveFlankTop). The shank: it leaves the profile at the
 * end of the ellipse's long axis, where the normal is (cos phi, -sin phi), on the side the tool
 * leans to (posture.ts); radially, its height is that point's, if it comes before the wall.
 */
export function feedFlankLimit(s: PostureShape, sign: number, rs: number): FeedFlankLimit {
  const st = stadiumOf(s, sign);
  if (st !== null) return { ...stadiumLimit(st, s.rcr, rs), deltaTop: 0 };
  if (rs < 0) return { ...concaveFlankTop(s, sign, rs), shankMm: concaveShank(s, sign, rs) };
  const tangent = {
    value(theta: number): number {
      const p = profileAtNormal(s, sign, theta);
      return Math.cos(theta) * (p.z + rs) - Math.sin(theta) * p.y;
    },
  };
  // The last normal angle whose tangent still passes above the axis (the bracket's positive end).
  const gLo = tangent.value(0);
  const gHi = tangent.value(Math.PI / 2);
  let lo = gLo > 0 ? Math.PI / 2 : 0;
  if (gLo > 0 && gHi < 0) {
    const end = newSearchEnd();
    bracketedRoot(tangent, 0, Math.PI / 2, gLo, gHi, 0, MAX_ITERATIONS, end);
    lo = end.lo;
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
export function limitsOf(
  topRight: number,
  topLeft: number,
  shankRight: number | null,
  shankLeft: number | null,
): FlankLimits {
  const topRightMm = Math.max(0, topRight);
  const topLeftMm = Math.max(0, topLeft);
  const shankRightMm = shankRight === null ? null : Math.max(0, shankRight);
  const shankLeftMm = shankLeft === null ? null : Math.max(0, shankLeft);
  return flankLimitsOf(topRightMm, topLeftMm, shankRightMm, shankLeftMm);
}
