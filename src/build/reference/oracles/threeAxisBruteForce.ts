/**
 * Independent references for three-axis machining (issue 20), in the machine frame: the real
 * upright tool (torus corner, flat bottom, shank), placed along the passes, and the material left
 * sampled in the cross-section. Shares no code and no derivation with src/core/threeAxis: no lead
 * or tilt, no meridian-profile construction, no closed-form cusp.
 *
 * The tool. An upright tool is a solid of revolution about its vertical axis; its horizontal
 * slice at height `zeta` above the tip is a disk of radius `rho(zeta) = Rb + sqrt(Rcr^2 -
 * (Rcr - zeta)^2)` (corner, `0 <= zeta < Rcr`) or `R` (shank, up to `zeta = Rcr + 3R` here).
 * Every query below is a question about these disks, answered from their rims.
 *
 * Placement. A pass is the tool touching the surface at a CC point: the tool's point that is
 * lowest in the direction of the surface normal `n` (its support point, minimum of `P.n` over the
 * tool: per slice the rim point opposite the normal's horizontal part, then the least over the
 * slices by golden section, a convex function of `zeta`) is put on the CC point.
 *
 * Raster on a sloped plane (section 2a): plane through the origin with normal
 * `n = (-sin a, 0, cos a)`; the pass's vertical plane has the plan direction `(cos psi, -sin psi)`
 * (angle psi to the fall line), the CC path is the plane cut by it, direction `X`; adjacent paths
 * are `L` apart along `Y = n x X` (in the plane). Each tool translates along `X`, so what it
 * leaves in the cross-section (the plane spanned by `Y` and `n`) is its projection along `X`: at
 * a column `y`, the lowest `P.n` over the tool's points with `P.Y = y`. Per slice the points of the
 * rim with `P.Y = y` are found exactly (a circle met by a plane), the least `P.n` over the slices
 * by sampling `zeta` and golden-section polishing (convex in `zeta` on the slices that reach `y`).
 *
 * Waterline on a surface of revolution (section 2b): the axis of revolution is the machine's z
 * axis, the CC point in the half-plane `y = 0, x > 0`, the meridian the circle of radius `|Rc|`
 * tangent there (a line when straight), the next CC point `L` further down the meridian (arc
 * length). Each tool turns about the z axis, so what it leaves in the meridian half-plane is, at a
 * radius `r`, the lowest slice that has a point at distance `r` from the axis: per slice the rim's
 * least and greatest distances from the axis (sampled and golden-polished; 0 when the disk covers
 * the axis), the lowest such slice by bisection (slices only grow upwards). With `Rf` infinite the
 * passes are straight (along y) and the distance is replaced by `x`.
 *
 * The cusp. The material top at a column is the lower of the two tools' lowest points there; the
 * cusp is its highest point between the CC points, its height measured along the normal (raster:
 * above the plane; waterline: radially from the meridian's centre, above the line when straight).
 * Sampled stage: `columns` equally spaced columns between the CC points; the best column's value
 * is within `bound = 2 K dy` of the true cusp, `K` the largest slope between neighbouring columns
 * around the best one (doubled for safety), `dy` the spacing: it shrinks with refinement (an
 * estimate: a peak narrower than the spacing, between two flat bottoms, escapes it). Polished
 * stage: the crossing of the two tools' lowest points by bisection, each column evaluated to
 * about 1e-13 mm.
 */
import { goldenSection } from './goldenSection';

/** The tool (mm). */
export interface BruteTool {
  readonly R: number;
  readonly Rcr: number;
}

type V3 = readonly [number, number, number];

/** Minimum of f on [a, b] by golden section (f unimodal there), value and argument. */
function goldenMin(f: (x: number) => number, a0: number, b0: number, iters = 90): { x: number; v: number } {
  const { c, d, fc } = goldenSection(f, a0, b0, iters, 1e-16, 1e-300);
  let best = { x: c, v: fc };
  for (const x of [a0, b0, d]) {
    const v = f(x);
    if (v < best.v) best = { x, v };
  }
  return best;
}

/** Minimum of f on [a, b]: dense samples, then golden section around the best sample. */
function sampledMin(
  f: (x: number) => number,
  a: number,
  b: number,
  samples: number,
  iters = 90,
): { x: number; v: number } {
  let bi = 0;
  let bv = Number.POSITIVE_INFINITY;
  for (let i = 0; i <= samples; i++) {
    const v = f(a + ((b - a) * i) / samples);
    if (v < bv) {
      bv = v;
      bi = i;
    }
  }
  const lo = a + ((b - a) * Math.max(0, bi - 1)) / samples;
  const hi = a + ((b - a) * Math.min(samples, bi + 1)) / samples;
  const g = goldenMin(f, lo, hi, iters);
  return g.v <= bv ? g : { x: a + ((b - a) * bi) / samples, v: bv };
}

/** Radius of the tool's slice at `zeta` above the tip (mm); -1 below the tip or above the sampled shank. */
export function sliceRadiusMm(t: BruteTool, zeta: number): number {
  if (zeta < 0 || zeta > t.Rcr + 3 * t.R) return -1;
  if (zeta >= t.Rcr) return t.R;
  const q = t.Rcr - zeta;
  return t.R - t.Rcr + Math.sqrt(Math.max(0, t.Rcr * t.Rcr - q * q));
}

const top = (t: BruteTool) => t.Rcr + 3 * t.R;

/**
 * The support point of the upright tool (tip at the origin) in the direction `-n` (n a unit
 * vector with n_z > 0): the tool point with the least `P.n`. Per slice that is the rim point
 * opposite `n`'s horizontal part, at `zeta n_z - rho(zeta) |n_h|`, a convex function of `zeta`;
 * its least value is where its derivative `n_z - rho'(zeta) |n_h|` changes sign, found by
 * bisection (`rho'` from the slice radius by calculus; locating the minimum by comparing values
 * would only place it to about 1e-8 mm, and the placement enters the cusp to first order). A flat
 * bottom facing `n` exactly (n vertical) returns the tip (the bottom's centre).
 */
export function supportPoint(t: BruteTool, n: V3): V3 {
  const nh = Math.hypot(n[0], n[1]);
  if (nh === 0) return [0, 0, 0];
  // rho'(zeta) = (Rcr - zeta) / sqrt(Rcr^2 - (Rcr - zeta)^2) on the corner, decreasing from +inf to 0.
  const slope = (z: number) => {
    const q = t.Rcr - z;
    return n[2] * Math.sqrt(Math.max(0, (t.Rcr - q) * (t.Rcr + q))) - q * nh;
  };
  let zeta = 0;
  if (t.Rcr > 0) {
    let a = 0;
    let b = t.Rcr;
    for (let k = 0; k < 200 && b - a > 0; k++) {
      const m = 0.5 * (a + b);
      if (m <= a || m >= b) break;
      if (slope(m) < 0) a = m;
      else b = m;
    }
    zeta = 0.5 * (a + b);
  }
  const rho = sliceRadiusMm(t, zeta);
  return [(-rho * n[0]) / nh, (-rho * n[1]) / nh, zeta];
}

/** The result of a brute-force cusp search. */
export interface BruteCusp {
  /** Best sampled column's cusp height, mm. */
  readonly sampledMm: number;
  /** Bound on |sampled - true| (mm): 2 K dy, see the module comment. */
  readonly boundMm: number;
  /** Polished cusp height, mm (golden section on the column). */
  readonly polishedMm: number;
  /** Column position of the polished cusp (y for raster, r or x for waterline), mm. */
  readonly atMm: number;
}

/**
 * The cusp from the two tools' columns (lowest points at a column position, `e0` and `e1`) and
 * the height of a material point (column, z). Sampled: the best of `columns + 1` equally spaced
 * columns from `a` (first CC point) to `b` (second). Polished: the crossing of the two tools' lowest
 * points, found by bisection on the sign of `e0 - e1` over [a, b] (it is negative at the first
 * contact and positive at the second, and, each tool's section being a translate of one convex
 * region, it changes sign once; bisection needs no unimodality, so a narrow peak between flat
 * bottoms is not missed), its height there.
 */
function cuspSearch(
  e0: (col: number) => number,
  e1: (col: number) => number,
  height: (col: number, z: number) => number,
  a: number,
  b: number,
  columns: number,
): BruteCusp {
  const top = (x: number) => height(x, Math.min(e0(x), e1(x)));
  const vals: number[] = [];
  for (let i = 0; i <= columns; i++) vals.push(top(a + ((b - a) * i) / columns));
  let bi = 0;
  for (let i = 1; i <= columns; i++) if ((vals[i] as number) > (vals[bi] as number)) bi = i;
  const dy = Math.abs(b - a) / columns;
  let K = 0;
  for (let i = Math.max(1, bi - 2); i <= Math.min(columns, bi + 2); i++)
    K = Math.max(K, Math.abs((vals[i] as number) - (vals[i - 1] as number)) / dy);
  let lo = a;
  let hi = b;
  for (let k = 0; k < 200 && Math.abs(hi - lo) > 1e-14 * (Math.abs(a) + Math.abs(b)); k++) {
    const m = 0.5 * (lo + hi);
    if (e0(m) - e1(m) < 0) lo = m;
    else hi = m;
  }
  const polished = Math.max(top(lo), top(hi));
  return { sampledMm: vals[bi] as number, boundMm: 2 * K * dy, polishedMm: polished, atMm: 0.5 * (lo + hi) };
}

const dot = (p: V3, q: V3) => p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
const crossV = (p: V3, q: V3): V3 => [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]];
const unit = (p: V3): V3 => {
  const l = Math.hypot(p[0], p[1], p[2]);
  return [p[0] / l, p[1] / l, p[2] / l];
};

/**
 * Lowest `P.n` over the tool with its tip at `tip` among its points with `P.Y = y` (raster
 * cross-section column), +Infinity when no point of the tool has that `P.Y`.
 */
function rasterColumn(t: BruteTool, tip: V3, n: V3, Y: V3, y: number): number {
  const yh = Math.hypot(Y[0], Y[1]);
  const u0 = Math.atan2(Y[1], Y[0]);
  const f = (z: number): number => {
    const rho = sliceRadiusMm(t, z);
    if (rho < 0) return Number.POSITIVE_INFINITY;
    const c: V3 = [tip[0], tip[1], tip[2] + z];
    const kappa = (y - dot(c, Y)) / (rho * yh);
    if (!(Math.abs(kappa) <= 1) || rho === 0) {
      // The bottom's centre alone (rho = 0 only for a ball end's tip).
      return rho === 0 && Math.abs(y - dot(c, Y)) < 1e-15 ? dot(c, n) : Number.POSITIVE_INFINITY;
    }
    const w = Math.acos(kappa);
    let best = Number.POSITIVE_INFINITY;
    for (const u of [u0 + w, u0 - w]) {
      const v = dot(c, n) + rho * (n[0] * Math.cos(u) + n[1] * Math.sin(u));
      if (v < best) best = v;
    }
    return best;
  };
  // The slices that reach y form an interval of zeta: sample, then bracket its ends and polish.
  const zMax = top(t);
  const S = 600;
  let first = -1;
  let last = -1;
  for (let i = 0; i <= S; i++) {
    if (Number.isFinite(f((zMax * i) / S))) {
      if (first < 0) first = i;
      last = i;
    }
  }
  if (first < 0) return Number.POSITIVE_INFINITY;
  const edge = (inside: number, outside: number) => {
    let a = inside;
    let b = outside;
    for (let k = 0; k < 80; k++) {
      const m = 0.5 * (a + b);
      if (Number.isFinite(f(m))) a = m;
      else b = m;
    }
    return a;
  };
  const za = first === 0 ? 0 : edge((zMax * first) / S, (zMax * (first - 1)) / S);
  const zb = last === S ? zMax : edge((zMax * last) / S, (zMax * (last + 1)) / S);
  return sampledMin(f, za, zb, 200).v;
}

/** Brute-force raster cusp on a sloped plane (module comment): slope, raster angle in degrees, L in mm. */
export function bruteRasterCusp(
  t: BruteTool,
  slopeDeg: number,
  rasterAngleDeg: number,
  intervalMm: number,
  columns = 64,
): BruteCusp {
  const a = (slopeDeg * Math.PI) / 180;
  const p = (rasterAngleDeg * Math.PI) / 180;
  const n: V3 = [-Math.sin(a), 0, Math.cos(a)];
  const d: V3 = [Math.cos(p), -Math.sin(p), 0];
  // The CC path: d + lambda z in the plane.
  const X = unit([d[0], d[1], -dot(d, n) / n[2]]);
  const Y = crossV(n, X);
  const sp = supportPoint(t, n);
  const tip0: V3 = [-sp[0], -sp[1], -sp[2]];
  const tip1: V3 = [tip0[0] + intervalMm * Y[0], tip0[1] + intervalMm * Y[1], tip0[2] + intervalMm * Y[2]];
  return cuspSearch(
    (y) => rasterColumn(t, tip0, n, Y, y),
    (y) => rasterColumn(t, tip1, n, Y, y),
    (_y, z) => z,
    0,
    intervalMm,
    columns,
  );
}

/** A surface of revolution for the waterline reference (mm, degrees; null radii are infinite). */
export interface BruteRevolution {
  readonly slopeDeg: number;
  readonly feedRadiusMm: number | null;
  readonly crossRadiusMm: number | null;
}

/** Least and greatest distance (mm) from the z axis of a horizontal disk (centre cx, cy; radius rho). */
function diskDistances(cx: number, cy: number, rho: number): [number, number] {
  const D = (u: number) => Math.hypot(cx + rho * Math.cos(u), cy + rho * Math.sin(u));
  const lo = sampledMin(D, 0, 2 * Math.PI, 24, 64).v;
  const hi = -sampledMin((u) => -D(u), 0, 2 * Math.PI, 24, 64).v;
  const covers = Math.hypot(cx, cy) <= rho;
  return [covers ? 0 : lo, hi];
}

/**
 * The waterline pair of the reference: CC points, normals and tool tips in the machine frame
 * (axis of revolution = z axis, meridian half-plane y = 0, x > 0; with Rf infinite the passes
 * run along y and the "axis" is absent).
 */
export interface BrutePair {
  readonly cc0: V3;
  readonly cc1: V3;
  readonly tip0: V3;
  readonly tip1: V3;
  /** Meridian centre in the half-plane (x, z), or null when straight. */
  readonly centre: readonly [number, number] | null;
  readonly n0: V3;
  readonly hasAxis: boolean;
}

/** Places the two passes (module comment). */
export function brutePair(t: BruteTool, s: BruteRevolution, intervalMm: number): BrutePair {
  const a = (s.slopeDeg * Math.PI) / 180;
  const hasAxis = s.feedRadiusMm !== null;
  // Distance of the CC point from the axis; the normal leans away from the axis on a dome (Rf > 0),
  // towards it in a bowl (Rf < 0). Without an axis, the slope descends towards +x.
  const sigma = s.feedRadiusMm !== null && s.feedRadiusMm < 0 ? -1 : 1;
  const r0 = hasAxis ? Math.abs(s.feedRadiusMm as number) * Math.sin(a) : 0;
  const cc0: V3 = [r0, 0, 0];
  const n0: V3 = [sigma * Math.sin(a), 0, Math.cos(a)];
  let cc1: V3;
  let n1: V3;
  let centre: [number, number] | null = null;
  if (s.crossRadiusMm === null) {
    // Down the straight meridian: the tangent with negative z.
    const tdir: V3 = [sigma * Math.cos(a), 0, -Math.sin(a)];
    cc1 = [cc0[0] + intervalMm * tdir[0], 0, intervalMm * tdir[2]];
    n1 = n0;
  } else {
    const rc = s.crossRadiusMm;
    const mx = cc0[0] - rc * n0[0];
    const mz = -rc * n0[2];
    centre = [mx, mz];
    // Polar angle of the CC point about the centre; turning by +-L/|Rc|, take the one that descends.
    const ang = Math.atan2(cc0[2] - mz, cc0[0] - mx);
    const step = intervalMm / Math.abs(rc);
    const at = (q: number): V3 => [mx + Math.abs(rc) * Math.cos(q), 0, mz + Math.abs(rc) * Math.sin(q)];
    const pa = at(ang + step);
    const pb = at(ang - step);
    const q1 = pa[2] < pb[2] ? ang + step : ang - step;
    cc1 = at(q1);
    const radial: V3 = [Math.cos(q1), 0, Math.sin(q1)];
    n1 = rc > 0 ? radial : [-radial[0], 0, -radial[2]];
  }
  const place = (cc: V3, n: V3): V3 => {
    const sp = supportPoint(t, n);
    return [cc[0] - sp[0], cc[1] - sp[1], cc[2] - sp[2]];
  };
  return { cc0, cc1, tip0: place(cc0, n0), tip1: place(cc1, n1), centre, n0, hasAxis };
}

/** Lowest z of the tool (tip `tip`) among its points at distance `r` from the z axis (or at x = r without axis). */
function revolutionColumn(t: BruteTool, tip: V3, r: number, hasAxis: boolean): number {
  const covers = (z: number): boolean => {
    const rho = sliceRadiusMm(t, z);
    if (rho < 0) return false;
    if (!hasAxis) return Math.abs(r - tip[0]) <= rho;
    const [lo, hi] = diskDistances(tip[0], tip[1], rho);
    return lo <= r && r <= hi;
  };
  const zMax = top(t);
  if (!covers(zMax)) return Number.POSITIVE_INFINITY;
  if (covers(0)) return tip[2];
  let a = 0;
  let b = zMax;
  for (let k = 0; k < 200 && b - a > 1e-14 * zMax; k++) {
    const m = 0.5 * (a + b);
    if (covers(m)) b = m;
    else a = m;
  }
  return tip[2] + b;
}

/** Height of the point (x, z) of the meridian half-plane along the normal (module comment). */
function revolutionHeight(p: BrutePair, rc: number | null, x: number, z: number): number {
  if (p.centre === null || rc === null) return (x - p.cc0[0]) * p.n0[0] + (z - p.cc0[2]) * p.n0[2];
  const d = Math.hypot(x - p.centre[0], z - p.centre[1]);
  return rc > 0 ? d - rc : -rc - d;
}

/** Brute-force waterline cusp on a surface of revolution (module comment). */
export function bruteWaterlineCusp(t: BruteTool, s: BruteRevolution, intervalMm: number, columns = 64): BruteCusp {
  const p = brutePair(t, s, intervalMm);
  return cuspSearch(
    (x) => revolutionColumn(t, p.tip0, x, p.hasAxis),
    (x) => revolutionColumn(t, p.tip1, x, p.hasAxis),
    (x, z) => revolutionHeight(p, s.crossRadiusMm, x, z),
    p.cc0[0],
    p.cc1[0],
    columns,
  );
}

/**
 * Brute-force gouging of a surface of revolution by the tool at the upper pass: the deepest
 * sampled point of the tool inside the material (mm; <= 0 when none), the material being the
 * torus patch of the notes: inside the meridian circle (convex), below the meridian line
 * (straight), outside the circle and below its centre (concave), all in terms of (distance from
 * the axis, z). Samples the slices' rims and the bottom disk (`rings` by `perRing`).
 */
export function bruteGougeDepthMm(t: BruteTool, s: BruteRevolution, tip: V3, rings = 400, perRing = 720): number {
  const a = (s.slopeDeg * Math.PI) / 180;
  const hasAxis = s.feedRadiusMm !== null;
  const sigma = s.feedRadiusMm !== null && s.feedRadiusMm < 0 ? -1 : 1;
  const r0 = hasAxis ? Math.abs(s.feedRadiusMm as number) * Math.sin(a) : 0;
  const n0s = sigma * Math.sin(a);
  const n0z = Math.cos(a);
  const rc = s.crossRadiusMm;
  const cx = rc === null ? 0 : r0 - rc * n0s;
  const cz = rc === null ? 0 : -rc * n0z;
  let deepest = Number.NEGATIVE_INFINITY;
  const test = (x: number, y: number, z: number) => {
    const r = hasAxis ? Math.hypot(x, y) : x;
    let depth: number;
    if (rc === null) depth = -((r - r0) * n0s + z * n0z);
    else {
      const d = Math.hypot(r - cx, z - cz);
      if (rc > 0) depth = rc - d;
      else depth = z <= cz ? d + rc : Number.NEGATIVE_INFINITY;
    }
    if (depth > deepest) deepest = depth;
  };
  const zMax = Math.min(top(t), t.Rcr + 2 * t.R);
  for (let i = 0; i <= rings; i++) {
    // Denser near the tip, where the corner curves.
    const z = zMax * (i / rings) ** 2;
    const rho = sliceRadiusMm(t, z);
    for (let j = 0; j < perRing; j++) {
      const u = (2 * Math.PI * j) / perRing;
      test(tip[0] + rho * Math.cos(u), tip[1] + rho * Math.sin(u), tip[2] + z);
    }
  }
  for (let i = 0; i <= 40; i++) {
    const rr = ((t.R - t.Rcr) * i) / 40;
    for (let j = 0; j < perRing; j++) {
      const u = (2 * Math.PI * j) / perRing;
      test(tip[0] + rr * Math.cos(u), tip[1] + rr * Math.sin(u), tip[2]);
    }
  }
  return deepest;
}
