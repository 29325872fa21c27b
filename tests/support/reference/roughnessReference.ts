/**
 * Reference roughness (Rz, Ra, Rq and the mean line; notes/posture-and-surfaces.md, "Roughness")
 * of the surface that passes leave on a plane or on a cylinder with its axis along the feed, from the
 * high-precision profile (highPrecision.ts) alone. It shares nothing with src/core: not the flank
 * widths, not the cusp geometry, not the integration (src/core integrates the flank's width over
 * the height, in sqrt(height), by Gauss-Kronrod; this integrates the height over the width along
 * the profile's own parameter, by Gauss-Legendre).
 *
 * The profile. Each flank is the curve `p(t)` of highPrecision.ts (t from 0, the contact's normal,
 * to 1, the horizontal normal), analytic in t except where the projected disk is a segment
 * (`a_x = 0`, rho = 0): there p jumps at one t across a straight piece (the flat bottom at t = 0
 * when the tilt is 0 too), taken here as the straight segment between the one-sided limits. So a
 * flank is a chain of pieces, each a curve analytic in its parameter, each monotone in height.
 *
 * Where it is measured. On a plane a point (width y, height z) from the contact is itself the
 * (position, height) the roughness uses. On a cylinder of signed radius Rs with its axis along the
 * feed (the passes are the plane profile, the next pass turned about the axis), a point is at
 * radial height `d - Rs` (convex; `|Rs| - d` concave, d its distance from the axis) and at arc
 * length `|Rs|` times its polar angle about the axis from the contact.
 *
 * The period. One-way: the right flank of one pass and the left flank of the next, both up to the
 * scallop height h; the step-over is the sum of their positions there. Zigzag: the step-over is
 * twice the narrower flank's position at h; each flank runs to half the step-over (the narrower to
 * h, the wider to its lower cusp). Positions and heights at the ends are found by bisection on the
 * piece's parameter to the working precision.
 *
 * The integrals. Over each flank `int F(height) d(position)` for F = 1, z, z^2, as
 * `int F(z(s)) x'(s) ds` over each piece's parameter s, x' by a central difference of step 1e-16 in
 * the 40-digit profile (error about 1e-24 of the piece's scale), by adaptive Gauss-Legendre (16
 * points, a panel halved until it and its halves agree to 1e-14 of the period's width and area or
 * 1e-13 of the panel's own), split at the
 * mean line for Ra. Values are summed in double precision: the result carries a relative 1e-14 or
 * so of the period's height (1e-16 mm on a 0.01 mm scallop), far below what it checks (1e-9 mm).
 * Lengths mm.
 */
import type Decimal from 'decimal.js';
import { HighPrecisionProfile, type Point, type Side } from './highPrecision';

/** What is measured: a tool, its posture, a pattern, a scallop height and the surface. */
export interface RoughnessReferenceCase {
  readonly R: number;
  readonly Rcr: number;
  readonly rhoDeg: number;
  readonly tiltDeg: number;
  readonly pattern: 'one-way' | 'zigzag';
  /** The scallop height (the highest cusp), mm, below the flanks' and shank's limits. */
  readonly hMm: number;
  /** Signed radius (mm) of a cylinder with its axis along the feed; absent for the plane. */
  readonly feedAxisRadiusMm?: number;
}

/** The reference roughness, mm. */
export interface RoughnessReferenceResult {
  readonly rzMm: number;
  readonly raMm: number;
  readonly rqMm: number;
  readonly meanMm: number;
  /** The step-over the period is measured over (arc length on a cylinder). */
  readonly intervalMm: number;
}

/** A piece of a flank: its profile points (relative to the contact) for s in [0, 1]. */
type Piece = (s: Decimal) => Point;

/**
 * Where a profile point is measured: its height (radial on a cylinder) in full precision, its
 * position along the surface in double precision (enough to place a cusp), and the rate of that
 * position for a rate (dy, dz) of the point.
 */
interface Measure {
  height(q: Point): Decimal;
  position(q: Point): number;
  rate(q: Point, dy: Decimal, dz: Decimal): number;
}

/** A piece and the part of it [from, to] (in its parameter) a segment runs over. */
interface Span {
  readonly piece: Piece;
  readonly from: Decimal;
  readonly to: Decimal;
}

// 16-point Gauss-Legendre on [-1, 1], by Newton on P_16 (computed once, in double precision).
const [GL_X, GL_W] = ((n: number): [number[], number[]] => {
  const xs: number[] = [];
  const ws: number[] = [];
  for (let i = 1; i <= n; i++) {
    let x = Math.cos((Math.PI * (i - 0.25)) / (n + 0.5));
    let dp = 1;
    for (let k = 0; k < 100; k++) {
      let p0 = 1;
      let p1 = x;
      for (let j = 2; j <= n; j++) [p0, p1] = [p1, ((2 * j - 1) * x * p1 - (j - 1) * p0) / j];
      dp = (n * (x * p1 - p0)) / (x * x - 1);
      const dx = p1 / dp;
      x -= dx;
      if (Math.abs(dx) < 1e-17) break;
    }
    xs.push(x);
    ws.push(2 / ((1 - x * x) * dp * dp));
  }
  return [xs, ws];
})(16);

/**
 * The reference roughness of one case (see the module comment). Costs about 0.2-2 s (decimal.js).
 */
export function referenceRoughness(c: RoughnessReferenceCase): RoughnessReferenceResult {
  const p = HighPrecisionProfile.create(c.R, c.Rcr, c.rhoDeg, c.tiltDeg, WORKING_DIGITS);
  const D = p.D;
  const measure = measureOn(D, c.feedAxisRadiusMm);
  const flank = (side: Side): Piece[] => {
    const at = (t: Decimal) => p.flankPoint(side, t);
    const jump = straightPieceAt(p, side);
    if (jump === null) return [(s) => at(s)];
    const tiny = new D(10).pow(-(p.D.precision - 14));
    const before = jump.isZero() ? p.flankPoint(side, jump) : p.flankPoint(side, jump.sub(tiny));
    const after = p.flankPoint(side, jump.add(tiny));
    const line: Piece = (s) => ({
      y: before.y.add(after.y.sub(before.y).mul(s)),
      z: before.z.add(after.z.sub(before.z).mul(s)),
    });
    // The smooth pieces end just short of the jump (at the jump itself p is the segment's midpoint).
    const start = jump.add(tiny);
    const rest: Piece = (s) => at(start.add(new D(1).sub(start).mul(s)));
    if (jump.isZero()) return [line, rest];
    const end = jump.sub(tiny);
    return [(s) => at(end.mul(s)), line, rest];
  };
  const flanks = { right: flank('right'), left: flank('left') };
  const h = new D(c.hMm);
  const zero = new D(0);
  const one = new D(1);
  // The point of a flank where the height (z) or the position (x) reaches `target` (bisection on
  // the piece that holds it, to the working precision in height, to the double in position).
  const below = (key: 'x' | 'z', q: Point, target: Decimal): boolean =>
    key === 'z' ? measure.height(q).lt(target) : measure.position(q) < target.toNumber();
  const reach = (pieces: readonly Piece[], key: 'x' | 'z', target: Decimal): { index: number; s: Decimal } => {
    for (let i = 0; i < pieces.length; i++) {
      const piece = pieces[i] as Piece;
      if (below(key, piece(one), target) && i < pieces.length - 1) continue;
      let lo = zero;
      let hi = one;
      for (let k = 0; k < 3.4 * p.D.precision; k++) {
        const mid = lo.add(hi).div(2);
        if (below(key, piece(mid), target)) lo = mid;
        else hi = mid;
      }
      return { index: i, s: lo.add(hi).div(2) };
    }
    throw new RangeError('unreachable');
  };
  const spansTo = (pieces: readonly Piece[], end: { index: number; s: Decimal }): Span[] =>
    pieces.slice(0, end.index + 1).map((piece, i) => ({ piece, from: zero, to: i === end.index ? end.s : one }));
  const xAtHeight = (side: Side) => {
    const pieces = flanks[side];
    const e = reach(pieces, 'z', h);
    return new D(measure.position((pieces[e.index] as Piece)(e.s)));
  };
  let ends: Record<Side, { index: number; s: Decimal }>;
  let interval: Decimal;
  if (c.pattern === 'one-way') {
    ends = { right: reach(flanks.right, 'z', h), left: reach(flanks.left, 'z', h) };
    interval = xAtHeight('right').add(xAtHeight('left'));
  } else {
    const xr = xAtHeight('right');
    const xl = xAtHeight('left');
    const half = xr.lt(xl) ? xr : xl;
    interval = half.mul(2);
    ends = { right: reach(flanks.right, 'x', half), left: reach(flanks.left, 'x', half) };
  }
  const segments = (['right', 'left'] as const).map((side) => {
    const spans = spansTo(flanks[side], ends[side]);
    const last = spans[spans.length - 1] as Span;
    const top = last.piece(last.to);
    return { side, spans, width: measure.position(top), height: measure.height(top).toNumber() };
  });
  const length = segments.reduce((sum, g) => sum + g.width, 0);
  const rz = Math.max(...segments.map((g) => g.height));
  const tol: Tolerance = { width: 1e-14 * length, area: 1e-14 * rz * length };
  const moments = segments.map((g) => integrate(g.spans, measure, tol));
  const area = moments.reduce((sum, m) => sum + (m[1] as number), 0);
  const mean = area / length;
  let sq = 0;
  let abs = 0;
  for (let i = 0; i < segments.length; i++) {
    const g = segments[i] as (typeof segments)[number];
    const [i0, i1, i2] = moments[i] as [number, number, number];
    sq += i2 - 2 * mean * i1 + mean * mean * i0;
    abs += i1 - mean * i0;
    // The part below the mean line counts with the other sign: + 2 int_{z < m} (m - z) dx.
    const pieces = flanks[g.side];
    const crossing = g.height > mean ? reach(pieces, 'z', new D(mean)) : ends[g.side];
    const [b0, b1] = integrate(spansTo(pieces, crossing), measure, tol);
    abs += 2 * (mean * b0 - b1);
  }
  return {
    rzMm: rz,
    raMm: abs / length,
    rqMm: Math.sqrt(sq / length),
    meanMm: mean,
    intervalMm: interval.toNumber(),
  };
}

/** Working digits of the profile: 40 (a central difference of step 1e-16 keeps 1e-24 of the rate). */
const WORKING_DIGITS = 40;

/** Where profile points are measured: on the plane, or on a cylinder of signed radius `rs` along the feed. */
function measureOn(D: Decimal.Constructor, rs: number | undefined): Measure {
  if (rs === undefined) {
    return { height: (q) => q.z, position: (q) => q.y.toNumber(), rate: (_q, dy) => dy.toNumber() };
  }
  const r = new D(Math.abs(rs));
  const sign = rs > 0 ? 1 : -1;
  // The axis seen from the point along the contact's normal: Rs + z (convex), |Rs| - z (concave).
  const along = (q: Point) => r.add(q.z.mul(sign));
  return {
    height: (q) => {
      const a = along(q);
      return D.sqrt(q.y.mul(q.y).add(a.mul(a)))
        .sub(r)
        .mul(sign);
    },
    position: (q) => Math.abs(rs) * Math.atan2(q.y.toNumber(), along(q).toNumber()),
    // |Rs| d(atan2(y, a)) = |Rs| (a dy - y da) / (y^2 + a^2), da = sign dz.
    rate: (q, dy, dz) => {
      const a = along(q);
      const num = a.mul(dy).sub(q.y.mul(dz).mul(sign));
      return r
        .mul(num)
        .div(q.y.mul(q.y).add(a.mul(a)))
        .toNumber();
    },
  };
}

/**
 * The flank parameter t of the straight piece, if any (highPrecision.ts's module comment: when
 * a_x = 0 the boundary jumps at the normal parallel to -a'; right flank n = (t, t - 1) at
 * t = a_y / (a_y - a_z) for a_y <= 0, left n = (-t, t - 1) at a_y / (a_y + a_z) for a_y >= 0).
 */
function straightPieceAt(p: HighPrecisionProfile, side: Side): Decimal | null {
  if (!p.ax.isZero() || p.rb.isZero()) return null;
  const lean = side === 'right' ? p.ay.neg() : p.ay;
  // lt, not isNeg: without tilt the lean is -0 on the right, which isNeg counts as negative.
  if (lean.lt(0)) return null;
  return lean.div(lean.add(p.az));
}

/** How closely a panel and its halves must agree: on the width (mm) and on the area (mm^2), per unit of parameter. */
interface Tolerance {
  readonly width: number;
  readonly area: number;
}

/**
 * `[int dx, int z dx, int z^2 dx]` over spans, by adaptive 16-point Gauss-Legendre on each: a panel
 * is halved until the halves' sum agrees with it (width and area) to its share of `tol`.
 */
function integrate(spans: readonly Span[], measure: Measure, tol: Tolerance): [number, number, number] {
  const total: [number, number, number] = [0, 0, 0];
  for (const span of spans) {
    const D = span.from.constructor as Decimal.Constructor;
    const eps = new D(10).pow(-Math.floor(D.precision / 2.5));
    const length = span.to.sub(span.from);
    const f = (s: number): [number, number, number] => {
      const at = span.from.add(length.mul(s));
      const q = span.piece(at);
      const ahead = span.piece(at.add(eps));
      const behind = span.piece(at.sub(eps));
      // The point's rate along this span (d/ds): the piece's derivative times the span's length.
      const scale = length.div(eps.mul(2));
      const g = measure.rate(q, ahead.y.sub(behind.y).mul(scale), ahead.z.sub(behind.z).mul(scale));
      const z = measure.height(q).toNumber();
      return [g, z * g, z * z * g];
    };
    const rule = (a: number, b: number): [number, number, number] => {
      const out: [number, number, number] = [0, 0, 0];
      const c = 0.5 * (a + b);
      const r = 0.5 * (b - a);
      for (let i = 0; i < GL_X.length; i++) {
        const v = f(c + r * (GL_X[i] as number));
        const w = (GL_W[i] as number) * r;
        out[0] += w * v[0];
        out[1] += w * v[1];
        out[2] += w * v[2];
      }
      return out;
    };
    const todo: Array<[number, number, [number, number, number]]> = [[0, 1, rule(0, 1)]];
    while (todo.length > 0) {
      const [a, b, whole] = todo.pop() as [number, number, [number, number, number]];
      const m = 0.5 * (a + b);
      const left = rule(a, m);
      const right = rule(m, b);
      // Within the panel's share of the tolerance, or within 1e-13 of the panel's own value (a
      // panel across the near-jump of a thin ellipse, rho ~ 0.01 deg, carries most of the width).
      const close =
        Math.abs(left[0] + right[0] - whole[0]) <= Math.max(tol.width * (b - a), 1e-13 * Math.abs(whole[0])) &&
        Math.abs(left[1] + right[1] - whole[1]) <= Math.max(tol.area * (b - a), 1e-13 * Math.abs(whole[1]));
      if (close || b - a < 1e-7) {
        for (let k = 0; k < 3; k++) total[k] = (total[k] as number) + (left[k] as number) + (right[k] as number);
      } else todo.push([a, m, left], [m, b, right]);
    }
  }
  return total;
}
