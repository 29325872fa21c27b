/**
 * Brute-force double-precision profile of a filleted end mill in any posture, from samples
 * of the actual 3D tool surface. It shares nothing with `highPrecision.ts` (no support
 * function, no projected ellipse): it works with 3D circles on the tool.
 *
 * Conventions as in `highPrecision.ts` (X feed, Z normal, Y = Z x X; axis
 * `a = (cos(beta) sin(rho), sin(beta), cos(beta) cos(rho))`; tool centre point O at the origin).
 *
 * 1. Sampling: points of the torus's outer half (meridian angle phi in [-90, 90] degrees,
 *    ring angle psi all round), of the flat bottom disk and of the shank cylinder (radius R,
 *    axial 0 to `shankLengthMm`) are projected along X (x dropped) and binned in Y; each bin
 *    keeps its lowest point: the lower envelope, for the tool end alone and with the shank.
 * 2. Polish. The contact is the lowest point of the family of parallel circles of the torus
 *    (circle phi: centre `Rcr sin(phi) a`, radius `Rb + Rcr cos(phi)`, lowest point along the
 *    in-plane steepest-descent direction), minimised over phi by bisection on the sign of a
 *    central difference; the widest points likewise (the circles' extreme Y). A flank at height h is `max Y` (right) or `min Y` (left) over the
 *    tool's points at `Z = z0 + h`: each parallel circle meets that plane in at most two
 *    points (solved directly), whose extreme Y is sampled over the interval of phi where the
 *    circle reaches the plane (its ends found by bisection) and refined by golden section.
 *    The bottom and top disks need no separate term (a chord's extreme Y lies on their rims,
 *    the circles phi = -90 and 90); the shank adds the circles of radius R at axial z >= 0.
 * 3. Check: every polished flank point is confronted with the sampled envelope (no sample
 *    may lie below the level beyond the flank; some sample must lie within the sampling gap
 *    of the flank point), and an Error is thrown on disagreement. This guards against gross
 *    polish failures (beyond about 1 % of R), not against small errors.
 *
 * Error bound (h at least 1e-6 of the flank height, flanks at least 1e-6 R, R in
 * [0.001, 1000] mm): `contactOffsetMm` within about 1e-10 R (the central-difference
 * bisection resolves phi to about 1e-10), widths within that plus about 1e-14 R (the golden
 * section's value error is quadratic in its argument error). Measured: at most 4e-11 R over
 * 300 random postures against the high-precision reference; the self-test asserts 1e-9 R.
 * Below those heights the level `z0 + h` carries the rounding of `z0` (1e-16 R), a relative
 * error of 1e-16 R / h in h: do not use it there. Cost: about 10-15 ms to sample (390k
 * points), well under 1 ms per width.
 */
import { goldenSection } from './goldenSection';

type Vec3 = readonly [number, number, number];

/** Options of {@link bruteForceProfile}. */
export interface BruteForceOptions {
  /** Samples of the ring angle psi around the axis (default 720). */
  readonly psiSamples?: number;
  /** Samples of the meridian angle phi over the torus's outer half (default 181). */
  readonly phiSamples?: number;
  /** Y bins of the lower envelope (default 800). */
  readonly bins?: number;
  /** Length of the shank sampled above the disk plane, mm (default 3 R). */
  readonly shankLengthMm?: number;
}

/** Brute-force profile (mm), see {@link bruteForceProfile}. */
export interface BruteForceProfile {
  /** y0 = Y(contact) - Y(O), mm (the flat bottom's midpoint, 0, when the bottom lies flat). */
  readonly contactOffsetMm: number;
  /** Contact height relative to O, mm. */
  readonly contactHeightMm: number;
  /** Height above the contact of the right flank's widest point (largest Y of the end), mm. */
  readonly hmaxRightMm: number;
  /** Height above the contact of the left flank's widest point, mm. */
  readonly hmaxLeftMm: number;
  /** Width from the contact of the right flank's widest point, mm. */
  readonly wmaxRightMm: number;
  /** Width from the contact of the left flank's widest point, mm. */
  readonly wmaxLeftMm: number;
  /** Right flank of the tool end: width from the contact at height h above it, mm. */
  widthRightMm(h: number): number;
  /** Left flank of the tool end. */
  widthLeftMm(h: number): number;
  /** Right flank of the whole tool (end and shank up to shankLengthMm). */
  widthRightWithShankMm(h: number): number;
  /** Left flank of the whole tool. */
  widthLeftWithShankMm(h: number): number;
  /** The sampled lower envelope: per bin, lowest Z of the end (and with the shank), NaN if empty. */
  readonly envelope: {
    readonly yMin: number;
    readonly binWidth: number;
    readonly endZ: Float64Array;
    readonly fullZ: Float64Array;
  };
}

const cross = (p: Vec3, q: Vec3): Vec3 => [
  p[1] * q[2] - p[2] * q[1],
  p[2] * q[0] - p[0] * q[2],
  p[0] * q[1] - p[1] * q[0],
];

/** Maximum of f on [a, b] by golden section (f unimodal there, or monotone). */
function goldenMax(f: (x: number) => number, a0: number, b0: number): { x: number; value: number } {
  const bracket = goldenSection((x) => -f(x), a0, b0, 200, 1e-15, 1e-300);
  const [c, d, fc, fd] = [bracket.c, bracket.d, -bracket.fc, -bracket.fd];
  const candidates: [number, number][] = [
    [a0, f(a0)],
    [b0, f(b0)],
    [c, fc],
    [d, fd],
  ];
  let best: [number, number] = [c, fc];
  for (const cand of candidates) if (cand[1] > best[1]) best = cand;
  return { x: best[0], value: best[1] };
}

/** Largest x in [a, b] with pred(x) true, pred true at a and monotone (true then false). */
function lastTrue(pred: (x: number) => boolean, a: number, b: number): number {
  if (pred(b)) return b;
  let lo = a;
  let hi = b;
  for (let i = 0; i < 200; i++) {
    const mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if (pred(mid)) lo = mid;
    else hi = mid;
  }
  return lo;
}

/**
 * Brute-force profile of a tool of radius `R` (mm), corner radius `Rcr` (mm, 0..R), lead
 * `rhoDeg` (0 <= rho < 90) and tilt `betaDeg` (|beta| < 90). Widths accept heights from 0 to
 * the flank's widest point (end) and return NaN where the plane misses the tool.
 */
export function bruteForceProfile(
  R: number,
  Rcr: number,
  rhoDeg: number,
  betaDeg: number,
  options: BruteForceOptions = {},
): BruteForceProfile {
  const nPsi = options.psiSamples ?? 720;
  const nPhi = options.phiSamples ?? 181;
  const nBins = options.bins ?? 800;
  const shankLength = options.shankLengthMm ?? 3 * R;
  const rho = (rhoDeg * Math.PI) / 180;
  const beta = (betaDeg * Math.PI) / 180;
  const a: Vec3 = [Math.cos(beta) * Math.sin(rho), Math.sin(beta), Math.cos(beta) * Math.cos(rho)];
  const Rb = R - Rcr;
  // In the plane normal to a: g, the steepest descent direction (g_z = -m), k = a x g horizontal.
  const m2 = a[0] * a[0] + a[1] * a[1];
  const m = Math.sqrt(m2);
  const g: Vec3 = m > 0 ? [(a[2] * a[0]) / m, (a[2] * a[1]) / m, -m2 / m] : [1, 0, 0];
  const k = cross(a, g);
  const kY = Math.abs(k[1]);

  // 1. Samples and their lower envelope in Y bins (end alone, and with the shank).
  const yMin = Math.min(-R, -R + shankLength * a[1]) - 1e-9 * R;
  const yMax = Math.max(R, R + shankLength * a[1]) + 1e-9 * R;
  const binWidth = (yMax - yMin) / nBins;
  const endZ = new Float64Array(nBins).fill(Number.NaN);
  const fullZ = new Float64Array(nBins).fill(Number.NaN);
  const binOf = (y: number): number => Math.min(nBins - 1, Math.max(0, Math.floor((y - yMin) / binWidth)));
  const lower = (arr: Float64Array, b: number, z: number): void => {
    const cur = arr[b] ?? Number.NaN;
    if (!(cur <= z)) arr[b] = z;
  };
  const cosPsi = Float64Array.from({ length: nPsi }, (_, j) => Math.cos((2 * Math.PI * j) / nPsi));
  const sinPsi = Float64Array.from({ length: nPsi }, (_, j) => Math.sin((2 * Math.PI * j) / nPsi));
  const ring = (axial: number, radius: number, isShank: boolean): void => {
    for (let j = 0; j < nPsi; j++) {
      const c = cosPsi[j] ?? 0;
      const s = sinPsi[j] ?? 0;
      const y = axial * a[1] + radius * (c * g[1] + s * k[1]);
      const z = axial * a[2] + radius * (c * g[2] + s * k[2]);
      const b = binOf(y);
      lower(fullZ, b, z);
      if (!isShank) lower(endZ, b, z);
    }
  };
  for (let i = 0; i < nPhi; i++) {
    const phi = -Math.PI / 2 + (Math.PI * i) / (nPhi - 1);
    ring(Rcr * Math.sin(phi), Rb + Rcr * Math.cos(phi), false);
  }
  const nDisk = Math.max(2, nPhi);
  for (let i = 0; i < nDisk; i++) ring(-Rcr, (Rb * i) / nDisk, false);
  const nShank = Math.max(2, nPhi);
  for (let i = 0; i <= nShank; i++) ring((shankLength * i) / nShank, R, true);
  // Largest distance from a point of the sampled surfaces to the nearest sample.
  // (half a step along each sampled parameter, summed: a bound, not an estimate).
  const gapEnd = 0.5 * (R * ((2 * Math.PI) / nPsi) + Rcr * (Math.PI / (nPhi - 1)) + Rb / nDisk);
  const gapFull = gapEnd + (0.5 * shankLength) / nShank;

  // 2a. The contact: lowest point of the parallel circles, over phi.
  const lowest = (phi: number): { y: number; z: number } => {
    const sa = Rcr * Math.sin(phi);
    const r = Rb + Rcr * Math.cos(phi);
    return { y: sa * a[1] + r * g[1], z: sa * a[2] + r * g[2] };
  };
  let contact: { y: number; z: number };
  if (m === 0) {
    contact = { y: 0, z: -Rcr }; // flat bottom: its midpoint
  } else {
    const delta = 1e-5;
    const phi = lastTrue((x) => lowest(x + delta).z - lowest(x - delta).z < 0, -Math.PI / 2 - 0.5 * delta, Math.PI / 2);
    contact = lowest(phi);
  }
  const y0 = contact.y;
  const z0 = contact.z;

  // 2b. The widest points: the extreme Y of circle phi is its centre's -+ radius |(g_y, k_y)|,
  // maximised over phi like the contact.
  const spread = Math.hypot(g[1], k[1]);
  const widest = (sign: number): { w: number; h: number } => {
    const at = (phi: number): { y: number; z: number } => {
      const sa = Rcr * Math.sin(phi);
      const r = Rb + Rcr * Math.cos(phi);
      const dy = spread > 0 ? (sign * g[1]) / spread : 0;
      const dk = spread > 0 ? (sign * k[1]) / spread : 0;
      return { y: sa * a[1] + r * (dy * g[1] + dk * k[1]), z: sa * a[2] + r * (dy * g[2] + dk * k[2]) };
    };
    const delta = 1e-5;
    const phi = lastTrue(
      (x) => sign * (at(x + delta).y - at(x - delta).y) > 0,
      -Math.PI / 2 - 0.5 * delta,
      Math.PI / 2 + 0.5 * delta,
    );
    const p = at(Math.max(-Math.PI / 2, Math.min(Math.PI / 2, phi)));
    return { w: sign * (p.y - y0), h: p.z - z0 };
  };
  const widestRight = widest(1);
  const widestLeft = widest(-1);

  // 2c. Flanks: extreme Y over the points of the tool at Z = level.
  type Circle = (t: number) => { centre: Vec3; radius: number };
  const torus: Circle = (phi) => {
    const sa = Rcr * Math.sin(phi);
    return { centre: [sa * a[0], sa * a[1], sa * a[2]], radius: Rb + Rcr * Math.cos(phi) };
  };
  const shank: Circle = (z) => ({ centre: [z * a[0], z * a[1], z * a[2]], radius: R });
  // Y of the circle's point at Z = level on the given side (sign +1 right, -1 left), or NaN.
  const atLevel = (circle: Circle, t: number, level: number, sign: number): number => {
    const { centre, radius } = circle(t);
    if (m === 0) return Math.abs(centre[2] - level) <= 1e-14 * R ? centre[1] + sign * radius : Number.NaN;
    if (radius === 0) return Math.abs(centre[2] - level) <= 1e-14 * R ? centre[1] : Number.NaN;
    let cosChi = (centre[2] - level) / (radius * m);
    // Tangency within rounding (a level at a widest point) counts as reached.
    if (Math.abs(cosChi) > 1 && Math.abs(cosChi) <= 1 + 1e-12) cosChi = Math.sign(cosChi);
    if (!(Math.abs(cosChi) <= 1)) return Number.NaN;
    const sinChi = Math.sqrt(1 - cosChi * cosChi);
    return centre[1] + radius * (cosChi * g[1] + sign * sinChi * kY);
  };
  // Interval of t in [t0, t1] where the circle reaches the level: low(t) <= level <= high(t).
  // low and high are each unimodal in t (sinusoids in phi, linear in z): located by sampling
  // and bisection.
  const reach = (circle: Circle, t0: number, t1: number, level: number): [number, number] | null => {
    const low = (t: number): number => circle(t).centre[2] - circle(t).radius * m;
    const high = (t: number): number => circle(t).centre[2] + circle(t).radius * m;
    const n = 64;
    let best = -1;
    let bestSlack = Number.NEGATIVE_INFINITY;
    for (let i = 0; i <= n; i++) {
      const t = t0 + ((t1 - t0) * i) / n;
      const slack = Math.min(level - low(t), high(t) - level);
      if (slack > bestSlack) {
        bestSlack = slack;
        best = t;
      }
    }
    // Refine the most inside point (golden section on the concave-ish slack), then the ends.
    const inside = goldenMax(
      (t) => Math.min(level - low(t), high(t) - level),
      Math.max(t0, best - (t1 - t0) / n),
      Math.min(t1, best + (t1 - t0) / n),
    );
    if (inside.value < -1e-13 * R) return null;
    const ok = (t: number): boolean => low(t) <= level && high(t) >= level;
    const tc = inside.x;
    const hi = ok(tc) ? lastTrue(ok, tc, t1) : tc;
    const lo = ok(tc) ? -lastTrue((x) => ok(-x), -tc, -t0) : tc;
    return [lo, hi];
  };
  const extreme = (circle: Circle, t0: number, t1: number, level: number, sign: number): number => {
    if (Rcr === 0 && circle === torus) {
      const y = atLevel(circle, 0, level, sign);
      return Number.isNaN(y) ? Number.NEGATIVE_INFINITY : sign * y;
    }
    if (m === 0) {
      // Horizontal circles: the one at the level (torus: sin(phi) = level / Rcr; shank: z = level).
      if (circle === torus) {
        const phi = Math.asin(Math.max(-1, Math.min(1, level / (Rcr * a[2]))));
        return sign * (torus(phi).centre[1] + sign * torus(phi).radius);
      }
      return level >= 0 && level <= shankLength ? R : Number.NEGATIVE_INFINITY;
    }
    const span = reach(circle, t0, t1, level);
    if (span === null) return Number.NEGATIVE_INFINITY;
    const [lo, hi] = span;
    const f = (t: number): number => {
      const y = atLevel(circle, Math.min(hi, Math.max(lo, t)), level, sign);
      return Number.isNaN(y) ? Number.NEGATIVE_INFINITY : sign * y;
    };
    const n = 200;
    let bestI = 0;
    let bestV = Number.NEGATIVE_INFINITY;
    for (let i = 0; i <= n; i++) {
      const v = f(lo + ((hi - lo) * i) / n);
      if (v > bestV) {
        bestV = v;
        bestI = i;
      }
    }
    const step = (hi - lo) / n;
    return goldenMax(f, Math.max(lo, lo + (bestI - 1) * step), Math.min(hi, lo + (bestI + 1) * step)).value;
  };

  // Both checks are rigorous: a flank point F = (yF, level) maximises sign*Y over the tool's
  // points with Z <= level, so no sample beyond yF lies below the level; and F is a point of
  // the tool's surface, so some sample lies within `gap` of it. They catch polish errors
  // beyond about the bin width (inwards) and the sampling gap (outwards), 0.3-2 % of R: a
  // guard against gross failures; the finer agreement is what the self-test establishes.
  const check = (withShank: boolean, yFlank: number, level: number, sign: number, what: string): void => {
    const env = withShank ? fullZ : endZ;
    const gap = withShank ? gapFull : gapEnd;
    for (let b = 0; b < nBins; b++) {
      const lowEdge = yMin + b * binWidth;
      const fullyBeyond = sign > 0 ? lowEdge > yFlank : lowEdge + binWidth < yFlank;
      if (fullyBeyond && (env[b] ?? Number.NaN) < level - 1e-12 * R) {
        throw new Error(`brute force: a sample lies below the level beyond the ${what} flank at ${yFlank}`);
      }
    }
    let near = false;
    for (let b = binOf(yFlank - gap - binWidth); b <= binOf(yFlank + gap + binWidth); b++) {
      if ((env[b] ?? Number.NaN) <= level + gap) near = true;
    }
    if (!near) throw new Error(`brute force: no sample near the ${what} flank point (${yFlank}, ${level})`);
  };

  const width = (h: number, sign: number, withShank: boolean): number => {
    const level = z0 + h;
    let best = extreme(torus, -Math.PI / 2, withShank ? 0 : Math.PI / 2, level, sign);
    if (withShank) best = Math.max(best, extreme(shank, 0, shankLength, level, sign));
    if (best === Number.NEGATIVE_INFINITY) return Number.NaN;
    const yFlank = sign * best;
    check(withShank, yFlank, level, sign, sign > 0 ? 'right' : 'left');
    return sign * (yFlank - y0);
  };

  return {
    contactOffsetMm: y0,
    contactHeightMm: z0,
    hmaxRightMm: widestRight.h,
    hmaxLeftMm: widestLeft.h,
    wmaxRightMm: widestRight.w,
    wmaxLeftMm: widestLeft.w,
    widthRightMm: (h) => width(h, 1, false),
    widthLeftMm: (h) => width(h, -1, false),
    widthRightWithShankMm: (h) => width(h, 1, true),
    widthLeftWithShankMm: (h) => width(h, -1, true),
    envelope: { yMin, binWidth, endZ, fullZ },
  };
}
