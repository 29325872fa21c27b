/**
 * Exact path interval of an inclined filleted end mill (the paper's "3D geometrical
 * computation", solved in closed form up to one bracketed 1-D root; see profile.ts).
 */
import {
  normalAngleAtHalfWidth,
  normalAngleAtHeight,
  type ProfileShape,
  profileHalfWidthMm,
  profileHeightMm,
  profileShape,
  ringAngleRad,
} from './profile';
import { cutSection, ringTangent, sectionCentre, type TorusFrame, torusFrame } from './torus';
import type { ForwardInput, InverseInput } from './validate';
import { addScaled, type Vec3 } from './vec';

const DEG = Math.PI / 180;

function shapeOf(input: { toolRadiusMm: number; cornerRadiusMm: number; leadAngleDeg: number }): ProfileShape {
  return profileShape(input.toolRadiusMm, input.cornerRadiusMm, input.leadAngleDeg * DEG);
}

/**
 * Exact half path interval `L/2` in mm for a validated input (see validateForward).
 * Error below 1e-9 mm over the whole valid domain. Allocation-free hot path.
 */
export function exactHalfIntervalMm(input: ForwardInput): number {
  const s = shapeOf(input);
  return profileHalfWidthMm(s, normalAngleAtHeight(s, input.scallopHeightMm));
}

/**
 * Exact scallop height in mm left by passes `2 * halfIntervalMm` apart (the inverse of
 * {@link exactHalfIntervalMm}); 0 when the point lies on the flat bottom (rho = 0, L/2 <= Rb).
 * @param input validated by validateInverse (0 < L/2 < R).
 */
export function exactScallopHeightMm(input: InverseInput): number {
  const s = shapeOf(input);
  const theta = normalAngleAtHalfWidth(s, input.halfIntervalMm);
  return theta === 0 ? 0 : profileHeightMm(s, theta);
}

/** A circle in 3D: centre (mm), unit normal of its plane, radius (mm). */
export interface Circle3 {
  readonly centre: Vec3;
  readonly normal: Vec3;
  readonly radiusMm: number;
}

/** Exact solution with the geometry a viewer needs, in the torus frame of torus.ts (mm). */
export interface ExactSolution {
  readonly halfIntervalMm: number;
  readonly intervalMm: number;
  /** Normal angle of the profile at the cusp point (radians): the profile slope there is tan(theta). */
  readonly normalAngleRad: number;
  /** Ring angle gamma* (radians) of the torus section through P_hp. */
  readonly ringAngleRad: number;
  /** Tool centre O (centre of the ring of corner centres), mm. */
  readonly toolCentre: Vec3;
  /** Unit tool axis ZT. */
  readonly toolAxis: Vec3;
  /** Contact point of the tool with the designed plane (z = 0), mm. */
  readonly pBase: Vec3;
  /** Point of the h pseudo plane farthest from the tool centre line: (x, L/2, h), mm. */
  readonly pHp: Vec3;
  /** The torus section (radius Rcr) through P_hp. */
  readonly sectionCircle: Circle3;
  /**
   * Torus / h pseudo plane intersection: closed polylines, each a flat array x0,y0,z0,x1,...
   * (mm). One loop around the contact, two (outer and inner) when every section meets the
   * plane, as for rho = 0.
   */
  readonly intersectionLoops: Float64Array[];
  /** Cross-feed profile of the tool, flat array y0,z0,y1,z1,... (mm, z above the designed plane), y from -R to R. */
  readonly profile: Float64Array;
}

/**
 * Solves the forward problem exactly and returns the viewer geometry.
 * @param input validated by validateForward.
 * @param samples polyline resolution (points per half profile and per loop branch), 8..4096.
 */
export function solveExact(input: ForwardInput, samples = 96): ExactSolution {
  const s = shapeOf(input);
  const h = input.scallopHeightMm;
  const theta = normalAngleAtHeight(s, h);
  const halfIntervalMm = profileHalfWidthMm(s, theta);
  const gamma = ringAngleRad(s, theta);
  const frame = torusFrame(input.toolRadiusMm, input.cornerRadiusMm, input.leadAngleDeg * DEG);
  const centre = sectionCentre(frame, gamma);
  const pHp: Vec3 = addScaled(centre, [0, Math.sin(theta), -Math.cos(theta)], input.cornerRadiusMm);
  const n = Math.max(8, Math.min(4096, Math.round(samples)));
  return {
    halfIntervalMm,
    intervalMm: 2 * halfIntervalMm,
    normalAngleRad: theta,
    ringAngleRad: gamma,
    toolCentre: frame.centre,
    toolAxis: frame.zt,
    pBase: [frame.ringRadiusMm * frame.cosRho, 0, 0],
    pHp: [pHp[0], halfIntervalMm, h],
    sectionCircle: { centre, normal: ringTangent(frame, gamma), radiusMm: input.cornerRadiusMm },
    intersectionLoops: intersectionLoops(frame, h, n),
    profile: profilePolyline(s, n),
  };
}

/**
 * The tool's cross-feed profile as a flat (y, z) array from y = -R to y = R, z measured
 * from the lowest point. Samples are denser near the bottom, where scallops form.
 */
export function profilePolyline(s: ProfileShape, samplesPerHalf: number): Float64Array {
  const n = Math.max(2, Math.round(samplesPerHalf));
  const half: number[] = [];
  // theta = 0 is the end of the flat bottom (y = a when b = 0, else the lowest point y = 0).
  for (let k = 0; k <= n; k++) {
    const u = k / n;
    const theta = (Math.PI / 2) * u * u;
    half.push(profileHalfWidthMm(s, theta), profileHeightMm(s, theta));
  }
  const m = half.length / 2;
  const out = new Float64Array(4 * m - (s.b === 0 && s.a > 0 ? 0 : 2));
  let w = 0;
  for (let k = m - 1; k >= 0; k--) {
    out[w++] = -(half[2 * k] as number);
    out[w++] = half[2 * k + 1] as number;
  }
  // Without a flat bottom the lowest point would be written twice: skip its mirror.
  for (let k = s.b === 0 && s.a > 0 ? 0 : 1; k < m; k++) {
    out[w++] = half[2 * k] as number;
    out[w++] = half[2 * k + 1] as number;
  }
  return out;
}

/** Ring angles in [0, pi] where the sections meet the plane, as intervals. */
function meetingIntervals(f: TorusFrame, h: number): Array<[number, number]> {
  const k = f.cornerRadiusMm;
  const gap = (g: number) => Math.abs(cutSection(f, g, h).inPlaneDistanceMm) - k;
  const steps = 180;
  const out: Array<[number, number]> = [];
  let start: number | null = gap(0) <= 0 ? 0 : null;
  let prev = 0;
  let prevGap = gap(0);
  for (let i = 1; i <= steps; i++) {
    const g = (Math.PI * i) / steps;
    const cur = gap(g);
    if (prevGap <= 0 !== cur <= 0) {
      let lo = prev;
      let hi = g;
      for (let j = 0; j < 52; j++) {
        const mid = 0.5 * (lo + hi);
        if (gap(mid) <= 0 === prevGap <= 0) lo = mid;
        else hi = mid;
      }
      const edge = prevGap <= 0 ? lo : hi;
      if (prevGap <= 0 && start !== null) {
        out.push([start, edge]);
        start = null;
      } else start = edge;
    }
    prev = g;
    prevGap = cur;
  }
  if (start !== null) out.push([start, Math.PI]);
  return out;
}

function pushBranch(out: number[], f: TorusFrame, h: number, g0: number, g1: number, n: number, side: 0 | 1): void {
  for (let i = 0; i <= n; i++) {
    // Cosine spacing: crossings move fastest near the single-contact ends.
    const u = side === 0 ? i / n : 1 - i / n;
    const g = g0 + (g1 - g0) * 0.5 * (1 - Math.cos(Math.PI * u));
    const cut = cutSection(f, g, h);
    if (cut.psi === null) continue;
    const psi = cut.psi[side];
    const c = sectionCentre(f, g);
    const cg = Math.cos(g);
    const sg = Math.sin(g);
    const cp = Math.cos(psi) * f.cornerRadiusMm;
    const sp = Math.sin(psi) * f.cornerRadiusMm;
    out.push(c[0] + cp * cg * f.xt[0] + sp * f.zt[0], c[1] + cp * sg, c[2] + cp * cg * f.xt[2] + sp * f.zt[2]);
  }
}

/**
 * The curve where the torus meets the plane z = h, as closed polylines (flat xyz arrays, mm).
 * For a flat end (Rcr = 0) the "torus" is the ring itself, which crosses the plane at two
 * points; the plane then cuts the flat bottom along the chord between them, returned as a
 * two-point loop. Ring height: z(gamma) = Rb sin(rho) (1 - cos gamma) + Rcr (Eq. 1 with Eq. 7).
 */
export function intersectionLoops(f: TorusFrame, h: number, n: number): Float64Array[] {
  if (f.cornerRadiusMm === 0) {
    const rise = f.ringRadiusMm * f.sinRho;
    if (rise <= 0 || h > 2 * rise) return [];
    const gamma = Math.acos(Math.max(-1, Math.min(1, 1 - h / rise)));
    return [Float64Array.from([...sectionCentre(f, gamma), ...sectionCentre(f, -gamma)])];
  }
  const intervals = meetingIntervals(f, h);
  const loops: Float64Array[] = [];
  const full = intervals.length === 1 && intervals[0]?.[0] === 0 && intervals[0][1] === Math.PI;
  if (full) {
    // Every section meets the plane: two closed curves, one per crossing.
    const first: number[] = [];
    const second: number[] = [];
    pushBranch(first, f, h, -Math.PI, Math.PI, 2 * n, 0);
    pushBranch(second, f, h, -Math.PI, Math.PI, 2 * n, 1);
    return [Float64Array.from(first), Float64Array.from(second)];
  }
  for (const [g0, g1] of intervals) {
    // Mirror across Y = 0: an interval touching 0 or pi joins its mirror image.
    const lo = g0 === 0 ? -g1 : g0;
    const hi = g1 === Math.PI ? 2 * Math.PI - g0 : g1;
    const pts: number[] = [];
    pushBranch(pts, f, h, lo, hi, n, 0);
    pushBranch(pts, f, h, lo, hi, n, 1);
    loops.push(Float64Array.from(pts));
    if (g0 !== 0 && g1 !== Math.PI) {
      const mirror: number[] = [];
      pushBranch(mirror, f, h, -g1, -g0, n, 0);
      pushBranch(mirror, f, h, -g1, -g0, n, 1);
      loops.push(Float64Array.from(mirror));
    }
  }
  return loops;
}
