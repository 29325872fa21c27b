/**
 * The tool's body of revolution cut by a vertical plane y = const of the pass-local frame, in the
 * coordinates (w, z): w = x - u, the horizontal offset along the feed from the tool centre point O
 * (u its spindle position), z the height above the design plane. Lengths mm, angles radians.
 *
 * The body is the ring of corner centres (radius Rb about the axis a, centre O) swept up the shank
 * (a semi-infinite solid cylinder of radius Rb) and grown by a ball of radius Rcr: flat bottom out to
 * the axis, corner, and the side of radius R above the corner. Its signed distance at a point with
 * meridian coordinates (rho, zeta) (distance from the axis, height along a from O) is that of the
 * half-strip {rho <= Rb, zeta >= 0} minus Rcr; it is convex, so along any line it is a convex function
 * whose roots are where the line enters and leaves the body, and a Newton iteration started outside
 * converges monotonically onto the nearer root. The body's boundary is the union of every tooth's
 * edge over a turn: a boundary point at angle psi about the axis lies on tooth k's edge exactly when
 * tooth k is at angle psi.
 *
 * The section's boundary is a convex closed curve (unbounded upwards only when the axis is
 * vertical), parametrised here by the polar angle `alpha` of rays from an interior point C.
 */
import type { ToothModel } from './toothModel';

/** A point of the section's boundary and what the event search needs there (filled in place). */
export class SectionPoint {
  /** Ray length from C, mm (Infinity: the ray never leaves the body). */
  t = 0;
  /** w and z of the point, mm. */
  w = 0;
  z = 0;
  /** Distance from the tool axis, mm. */
  rho = 0;
  /** Angle about the axis from u1 towards u2, radians in (-pi, pi]. */
  psi = 0;
  /** |dP/dalpha|: the speed of the point along the curve per radian of alpha, mm. */
  speed = 0;
  /** dw/dalpha, mm. */
  dw = 0;
  /** dpsi/dalpha, the angle's actual rate (radians per radian). */
  dpsi = 0;
  /**
   * Length of the body's unit normal's part in the plane, sqrt(1 - n_y^2) (the section's curvature is
   * a normal curvature of the body over it, Meusnier).
   */
  inPlane = 0;
}

/** Scratch of the distance evaluation (read right after the call). */
class DistanceEval {
  d = 0;
  /** Gradient of the distance in the (w, z) plane. */
  gw = 0;
  gz = 0;
  rho = 0;
  /** Components of the point relative to O along u1 and u2 (for psi). */
  c1 = 0;
  c2 = 0;
}

/** The body of a model cut by the plane y (pass-local). */
export class BodySection {
  readonly m: ToothModel;
  /** y relative to O, mm. */
  readonly yRel: number;
  private readonly ev = new DistanceEval();

  constructor(m: ToothModel, yMm: number) {
    this.m = m;
    this.yRel = yMm - m.centreYMm;
  }

  /** Signed distance to the body of the point (w, z), with its gradient in (w, z) (see DistanceEval). */
  distance(w: number, z: number): DistanceEval {
    const m = this.m;
    const a = m.axis;
    const vx = w;
    const vy = this.yRel;
    const vz = z - m.centreZMm;
    const zeta = vx * a[0] + vy * a[1] + vz * a[2];
    const px = vx - zeta * a[0];
    const py = vy - zeta * a[1];
    const pz = vz - zeta * a[2];
    const rho = Math.sqrt(px * px + py * py + pz * pz);
    const q = rho - m.ringRadiusMm;
    let d: number;
    let dRho: number;
    let dZeta: number;
    if (zeta >= 0) {
      if (q > 0 || q > -zeta) {
        d = q;
        dRho = 1;
        dZeta = 0;
      } else {
        d = -zeta;
        dRho = 0;
        dZeta = -1;
      }
    } else if (q > 0) {
      d = Math.sqrt(q * q + zeta * zeta);
      dRho = q / d;
      dZeta = zeta / d;
    } else {
      d = -zeta;
      dRho = 0;
      dZeta = -1;
    }
    const ev = this.ev;
    ev.d = d - m.cornerRadiusMm;
    // d rho / dw = px_perp . e_x / rho; d rho / dz = p_perp . e_z / rho; d zeta = a.
    const inv = rho > 0 ? 1 / rho : 0;
    ev.gw = dRho * px * inv + dZeta * a[0];
    ev.gz = dRho * pz * inv + dZeta * a[2];
    ev.rho = rho;
    const u1 = m.u1;
    const u2 = m.u2;
    ev.c1 = px * u1[0] + py * u1[1] + pz * u1[2];
    ev.c2 = px * u2[0] + py * u2[1] + pz * u2[2];
    return ev;
  }

  /**
   * Where the ray from (w0, z0) in the direction (cw, cz) (unit) leaves the body's bounding region
   * {rho <= R + margin, zeta >= -Rcr - margin}: a point outside the body (Infinity if it never leaves).
   */
  boundExit(w0: number, z0: number, cw: number, cz: number): number {
    const m = this.m;
    const a = m.axis;
    const margin = 1e-3 * m.toolRadiusMm + 1e-9;
    const vx = w0;
    const vy = this.yRel;
    const vz = z0 - m.centreZMm;
    const zeta0 = vx * a[0] + vy * a[1] + vz * a[2];
    const da = cw * a[0] + cz * a[2];
    let t = Number.POSITIVE_INFINITY;
    if (da < 0) t = (-m.cornerRadiusMm - margin - zeta0) / da;
    // rho^2(t) = |V + tD|^2 - (zeta0 + t da)^2 = A t^2 + B t + C.
    const A = cw * cw + cz * cz - da * da;
    if (A > 1e-12) {
      const B = 2 * (vx * cw + vz * cz - zeta0 * da);
      const r = m.toolRadiusMm + margin;
      const C = vx * vx + vy * vy + vz * vz - zeta0 * zeta0 - r * r;
      const disc = B * B - 4 * A * C;
      if (disc > 0) {
        const root = (-B + Math.sqrt(disc)) / (2 * A);
        if (root > 0 && root < t) t = root;
      } else t = Math.min(t, 0);
    }
    return Math.max(t, 0);
  }

  /**
   * The root of the distance along the ray (w0, z0) + t (cw, cz) reached by Newton steps from `tStart`
   * (a point outside the body, beyond the root); the distance is convex along the ray, so the steps
   * fall monotonically onto the root nearest tStart on its side. NaN when the ray misses the body.
   */
  rayRoot(w0: number, z0: number, cw: number, cz: number, tStart: number): number {
    let t = tStart;
    const scale = this.m.toolRadiusMm;
    for (let i = 0; i < 100; i++) {
      const ev = this.distance(w0 + t * cw, z0 + t * cz);
      const slope = ev.gw * cw + ev.gz * cz;
      if (ev.d <= 0) return t;
      // From beyond the root the distance falls towards it: slope > 0 when walking back (t decreasing).
      if (!(slope > 0)) return Number.NaN;
      const step = ev.d / slope;
      t -= step;
      if (step <= 1e-16 * scale + 1e-15 * Math.abs(t)) return t;
    }
    return t;
  }

  /**
   * Entry height of the vertical line at w (the lowest z where it meets the body), or NaN when it
   * misses. Newton from below the body (its lowest point is at or above -runout).
   */
  entryZ(w: number, below: number): number {
    let z = below;
    const scale = this.m.toolRadiusMm;
    for (let i = 0; i < 100; i++) {
      const ev = this.distance(w, z);
      if (ev.d <= 0) return z;
      if (!(ev.gz < 0)) return Number.NaN;
      const step = -ev.d / ev.gz;
      z += step;
      if (step <= 1e-16 * scale + 1e-15 * Math.abs(z)) return z;
    }
    return z;
  }

  /** Exit height of the vertical line at w (the highest z in the body), Infinity when it never leaves. */
  exitZ(w: number, zInside: number): number {
    const t = this.boundExit(w, zInside, 0, 1);
    if (!Number.isFinite(t)) return Number.POSITIVE_INFINITY;
    return zInside + this.rayRoot(w, zInside, 0, 1, t);
  }

  /**
   * The boundary point on the ray from C = (cw0, cz0) (inside the body) at polar angle alpha; `out`
   * filled. `tGuess` (> 0, beyond the root) speeds the Newton steps up when known, else the bounding
   * region's exit is used.
   */
  pointAt(cw0: number, cz0: number, alpha: number, out: SectionPoint): void {
    const cw = Math.cos(alpha);
    const cz = Math.sin(alpha);
    const tb = this.boundExit(cw0, cz0, cw, cz);
    if (!Number.isFinite(tb)) {
      out.t = Number.POSITIVE_INFINITY;
      out.w = cw0;
      out.z = Number.POSITIVE_INFINITY;
      out.rho = Number.POSITIVE_INFINITY;
      out.psi = 0;
      out.speed = Number.POSITIVE_INFINITY;
      out.dw = 0;
      out.dpsi = 0;
      out.inPlane = 0;
      return;
    }
    const t = this.rayRoot(cw0, cz0, cw, cz, tb);
    const ev = this.distance(cw0 + t * cw, cz0 + t * cz);
    out.t = t;
    out.w = cw0 + t * cw;
    out.z = cz0 + t * cz;
    out.rho = ev.rho;
    out.psi = Math.atan2(ev.c2, ev.c1);
    // Implicit t(alpha): grad . (t' D + t D_perp) = 0, D_perp = (-sin, cos).
    const gd = ev.gw * cw + ev.gz * cz;
    const gp = -ev.gw * cz + ev.gz * cw;
    const dt = gd > 0 ? (-t * gp) / gd : 0;
    out.speed = Math.sqrt(t * t + dt * dt);
    const vw = dt * cw - t * cz;
    const vz = dt * cz + t * cw;
    out.dw = vw;
    out.inPlane = Math.sqrt(ev.gw * ev.gw + ev.gz * ev.gz);
    // dpsi/dalpha = (c1 v.u2 - c2 v.u1) / rho^2 with v = (vw, 0, vz).
    const u1 = this.m.u1;
    const u2 = this.m.u2;
    const rho2 = ev.rho * ev.rho;
    out.dpsi = rho2 > 0 ? (ev.c1 * (vw * u2[0] + vz * u2[2]) - ev.c2 * (vw * u1[0] + vz * u1[2])) / rho2 : 0;
  }
}
