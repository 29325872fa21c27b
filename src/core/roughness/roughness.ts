/**
 * Roughness of the surface the passes leave, across the feed (ISO 4287 / ISO 21920-2 parameters as
 * defined in shared/notes/posture-and-surfaces.md): over one period (one step-over one-way, two
 * zigzag) with the mean line at the period's mean height, `Rz` = highest peak - deepest valley,
 * `Ra` = mean of |z - mean|, `Rq` = root mean square of z - mean. Lengths mm.
 *
 * Derivation. A period is made of flank segments, each running from a contact (z = 0) out to a cusp
 * at width W and height H (one-way: the right flank of one pass and the left flank of the next,
 * both up to h; zigzag: two right flanks meeting at L/2 and two left flanks meeting at L/2). On a
 * segment the height rises monotonically with the distance y from the contact, so with w(z) the
 * flank's width at height z (posture.ts), integration by parts gives for any f:
 *
 *   int_0^W f(z(y)) dy = f(H) W - int_0^H f'(z) w(z) dz.
 *
 * So the area is `H W - A1`, with `A1 = int_0^H w dz`; `int (z - m)^2 dy = (H - m)^2 W - 2 (A2 - m A1)`,
 * `A2 = int_0^H z w dz`; and `int |z - m| dy = (H - m) W - A1 + 2 ((m - z_m) y_m + int_0^{z_m} w dz)`
 * with `z_m = min(m, H)`, `y_m = w(z_m)` (the part below the mean line counted with its sign). The
 * integrals of w are taken in `u = sqrt(z)`, where `w(u^2)` is smooth (w grows like sqrt(z) at the
 * contact), by adaptive Gauss-Kronrod (7-15) to a relative 1e-13. A flat bottom lying on the plane
 * (w(0) = Rb) needs nothing special: its flat part is the rectangle `w(0) H` inside `H W - A1`.
 * On a cylinder the same holds with heights measured radially and widths along the design surface
 * (arc length about the axis, or distance along it): the mean line is then a coaxial cylinder.
 */

import type { ForwardInput, PassInput } from '../domain/pass';
import { PLANE, type Surface } from '../domain/surface';
import type { PassPattern, ToolInput } from '../domain/tool';
import { type AnyInputError, forwardInput, inputError, MIN_LENGTH_MM, type Validation } from '../input/validate';
import type { CylinderSolver } from '../surfaces/cylinder';
import { type SurfaceDescriptor, surfaceModel } from '../surfaces/registry';
import { type ExactForward, type ExactInverse, exactForward } from '../surfaces/solve';
import { scallopHeightLimits, validatePassAnd } from '../surfaces/validate';
import { type Flank, flankWidthMm, type PostureShape } from '../tool/posture';
import { type RawTargetRaInput, type TargetRaInput, targetRaFields, targetRaValidation } from './targetRaFields';

/** Roughness across the feed, mm. */
export interface Roughness {
  /** Highest peak minus deepest valley. */
  readonly rzMm: number;
  /** Arithmetic mean deviation from the mean line. */
  readonly raMm: number;
  /** Root mean square deviation from the mean line. */
  readonly rqMm: number;
  /** Height of the mean line above the deepest valley (the contacts). */
  readonly meanMm: number;
}

/** One flank from its contact out to a cusp, mm. */
export interface FlankSegment {
  readonly flank: Flank;
  /** Width from the contact (from O on a flat bottom lying on the plane) to the cusp. */
  readonly widthMm: number;
  /** Height of the cusp above the contact. */
  readonly heightMm: number;
}

// Gauss-Kronrod 7-15 nodes and weights on [-1, 1] (QUADPACK's qk15 table, 33 digits, rounded
// to the nearest double: the shortest decimal that reads back as that double).
const XGK = [
  0.9914553711208126, 0.9491079123427585, 0.8648644233597691, 0.7415311855993945, 0.5860872354676911,
  0.4058451513773972, 0.20778495500789848, 0,
];
const WGK = [
  0.022935322010529224, 0.06309209262997856, 0.10479001032225019, 0.14065325971552592, 0.1690047266392679,
  0.19035057806478542, 0.20443294007529889, 0.20948214108472782,
];
const WG = [0.1294849661688697, 0.27970539148927664, 0.3818300505051189, 0.4179591836734694];

/**
 * Integrals of `2u w(u^2)` and `2u^3 w(u^2)` over one panel [a, b]: the 15-point Kronrod estimates,
 * and the difference between the Kronrod and the embedded 7-point Gauss estimate of the first.
 * Kronrod nodes: +-XGK[j] (j = 0..6) and 0; the Gauss nodes are +-XGK[1], +-XGK[3], +-XGK[5] and 0.
 */
function panel(w: (z: number) => number, a: number, b: number): [number, number, number] {
  const c = 0.5 * (a + b);
  const r = 0.5 * (b - a);
  const f = (u: number): [number, number] => {
    const z = u * u;
    const f1 = 2 * u * w(z);
    return [f1, z * f1];
  };
  const [c1, c2] = f(c);
  let k1 = (WGK[7] as number) * c1;
  let k2 = (WGK[7] as number) * c2;
  let g1 = (WG[3] as number) * c1;
  for (let j = 0; j < 7; j++) {
    const d = r * (XGK[j] as number);
    const [l1, l2] = f(c - d);
    const [h1, h2] = f(c + d);
    k1 += (WGK[j] as number) * (l1 + h1);
    k2 += (WGK[j] as number) * (l2 + h2);
    if (j % 2 === 1) g1 += (WG[(j - 1) / 2] as number) * (l1 + h1);
  }
  return [k1 * r, k2 * r, Math.abs((k1 - g1) * r)];
}

/**
 * The largest error (mm) in the mean line, Ra and Rq that widthIntegrals may leave where it stops
 * at the rounding of the widths: 1e-12 mm, a thousandth of the 1e-9 mm the results promise.
 */
export const ROUNDOFF_FLOOR_MM = 1e-12;

/** A width function that answers 0 where the given one answers no finite non-negative width. */
function definedWidth(w: (z: number) => number): (z: number) => number {
  return (z) => {
    const v = w(z);
    return v >= 0 && v < Number.POSITIVE_INFINITY ? v : 0;
  };
}

/**
 * `[int_0^Z w dz, int_0^Z z w dz]` for a flank, in u = sqrt(z), by adaptive GK15 to a relative 1e-13
 * of the first integral.
 *
 * A panel is split in two until its error estimate meets its share of the tolerance, unless it is
 * down to the rounding of the width: the halves' estimates add up to half the panel's or more
 * (halving divides a rule's error by 8 or more on average; rounding noise stays as large; QUADPACK's
 * roundoff detection, in the same spirit) AND the panel's estimate is below its share of
 * {@link ROUNDOFF_FLOOR_MM} times the flank's width (what moves the mean line, Ra and Rq by at most
 * that). The width across a cylinder's axis carries the rounding of the corner centre's height
 * (about 1e-16 of R), a relative 1e-13 of a scallop of a few micrometres or less: without the
 * roundoff test the panels ran to the cap of 4000, some seconds of width solves per integral. The
 * floor is what keeps the test from taking a rule's error for rounding: where the profile has a kink
 * of curvature (a corner meeting a straight piece, at rho = 0 with tilt), one halving can shrink
 * the estimate by less than 2 (the kink sits at a different place among the nodes), and stopping
 * there lost 2.5e-8 mm^2 of a flank's area, 9.3e-9 mm of Rq (issue 26, point 4); past the floor
 * the panels go on halving around the kink, whose error does fall, as they do for any kink.
 *
 * A width that is not a finite non-negative number (a solver asked below the rounding of its own
 * heights: a doubly curved point's reach at 1e-16 mm, issue 26, point 6) is taken as 0: the
 * profile there lies within that rounding of its contact, and its share of the integral is below
 * the floor.
 */
export function widthIntegrals(width: (z: number) => number, zMax: number): [number, number] {
  if (!(zMax > 0)) return [0, 0];
  const w = definedWidth(width);
  const top = Math.sqrt(zMax);
  let a1 = 0;
  let a2 = 0;
  const widthMm = w(zMax);
  const scale = zMax * widthMm;
  // Panels waiting to be split: [lo, hi, its error estimate].
  const todo: Array<[number, number, number]> = [];
  let evaluations = 0;
  const tolOf = (lo: number, hi: number) => Math.max(1e-13 * scale * ((hi - lo) / top), 1e-300);
  const floorOf = (lo: number, hi: number) => ROUNDOFF_FLOOR_MM * widthMm * ((hi - lo) / top);
  // Start from 4 panels: the integrand can turn sharply where a flat face meets a corner.
  for (let i = 0; i < 4; i++) {
    const lo = (top * i) / 4;
    const hi = (top * (i + 1)) / 4;
    const [i1, i2, err] = panel(w, lo, hi);
    evaluations++;
    if (err <= tolOf(lo, hi)) {
      a1 += i1;
      a2 += i2;
    } else todo.push([lo, hi, err]);
  }
  while (todo.length > 0) {
    const [lo, hi, parentErr] = todo.pop() as [number, number, number];
    const mid = 0.5 * (lo + hi);
    const left = panel(w, lo, mid);
    const right = panel(w, mid, hi);
    evaluations += 2;
    const roundoff = left[2] + right[2] >= 0.5 * parentErr && parentErr <= floorOf(lo, hi);
    const last = roundoff || hi - lo <= 2e-9 * top || evaluations > 4000;
    for (const [from, to, p] of [
      [lo, mid, left],
      [mid, hi, right],
    ] as const) {
      if (last || p[2] <= tolOf(from, to)) {
        a1 += p[0];
        a2 += p[1];
      } else todo.push([from, to, p[2]]);
    }
  }
  return [a1, a2];
}

/** A flank's width (mm, along the surface from the contact) at a height (mm, normal to the surface). */
export type WidthAt = (flank: Flank) => (heightMm: number) => number;

/** Widths of the plane profile (posture.ts). */
export function planeWidths(shape: PostureShape): WidthAt {
  return (flank) => (z) => flankWidthMm(shape, flank, z);
}

/**
 * Widths on a cylinder: the flank's reach at radial height z as a length along the design surface
 * (arc length for the axis along the feed, distance along the axis across it), as the step-over is.
 */
export function cylinderWidths(solver: CylinderSolver): WidthAt {
  return (flank) => (z) => solver.intervalFromReach(solver.reach(flank, z));
}

/**
 * Roughness of a period made of flank segments (see the module comment). `widths` gives each
 * flank's width at a height (planeWidths, or cylinderWidths: heights measured radially, lengths
 * along the surface).
 */
export function roughnessOfSegments(widths: WidthAt | PostureShape, segments: readonly FlankSegment[]): Roughness {
  const widthAt: WidthAt = typeof widths === 'function' ? widths : planeWidths(widths);
  let length = 0;
  let area = 0;
  const data = segments.map((seg) => {
    const w = definedWidth(widthAt(seg.flank));
    const [a1, a2] = widthIntegrals(w, seg.heightMm);
    length += seg.widthMm;
    area += seg.heightMm * seg.widthMm - a1;
    return { seg, w, a1, a2 };
  });
  if (!(length > 0)) return { rzMm: 0, raMm: 0, rqMm: 0, meanMm: 0 };
  const m = area / length;
  let abs = 0;
  let sq = 0;
  let peak = 0;
  for (const { seg, w, a1, a2 } of data) {
    const H = seg.heightMm;
    const W = seg.widthMm;
    peak = Math.max(peak, H);
    sq += (H - m) * (H - m) * W - 2 * (a2 - m * a1);
    const zm = Math.min(m, H);
    const below = zm > 0 ? (m - zm) * w(zm) + widthIntegrals(w, zm)[0] : m * w(0);
    abs += (H - m) * W - a1 + 2 * below;
  }
  return { rzMm: peak, raMm: Math.max(0, abs / length), rqMm: Math.sqrt(Math.max(0, sq / length)), meanMm: m };
}

/** The width function of a tool on its surface. */
function widthsOf(tool: ToolInput, surface: SurfaceDescriptor): WidthAt {
  const width = surfaceModel(surface).flankWidths(tool, surface);
  return (flank) => (z) => width(flank, z);
}

/**
 * Exact roughness (mm) of the surface that passes of a forward solution leave, on any registered
 * surface (on a cylinder or a doubly curved point measured radially, over arc length). For zigzag the other cusp's flank pair is
 * included (two step-overs per period).
 */
export function exactRoughness(
  input: ForwardInput<SurfaceDescriptor>,
  e: ExactForward = exactForward(input),
): Roughness {
  if (e.noScallop) return { rzMm: 0, raMm: 0, rqMm: 0, meanMm: 0 };
  const shape = widthsOf(input, input.surface);
  if (input.pattern === 'zigzag') {
    // The narrow flank's cusp is h; the wider flank meets its mirror lower, at L/2.
    const rightNarrow = e.halfWidthRightMm <= e.halfWidthLeftMm;
    const other = e.otherCuspHeightMm ?? e.cuspHeightMm;
    return roughnessOfSegments(shape, [
      { flank: 'right', widthMm: e.halfIntervalMm, heightMm: rightNarrow ? e.cuspHeightMm : other },
      { flank: 'left', widthMm: e.halfIntervalMm, heightMm: rightNarrow ? other : e.cuspHeightMm },
    ]);
  }
  return roughnessOfSegments(shape, [
    { flank: 'right', widthMm: e.halfWidthRightMm, heightMm: e.cuspHeightMm },
    { flank: 'left', widthMm: e.halfWidthLeftMm, heightMm: e.cuspHeightMm },
  ]);
}

/** Exact roughness (mm) of the surface passes `e.intervalMm` apart leave (inverse solution). */
export function exactRoughnessAtInterval(
  tool: ToolInput,
  pattern: PassPattern,
  e: ExactInverse,
  surface: SurfaceDescriptor = PLANE,
): Roughness {
  if (e.cuspHeightMm === 0) return { rzMm: 0, raMm: 0, rqMm: 0, meanMm: 0 };
  const shape = widthsOf(tool, surface);
  if (pattern === 'zigzag') {
    return roughnessOfSegments(shape, [
      { flank: 'right', widthMm: e.intervalMm / 2, heightMm: e.rightCuspHeightMm },
      { flank: 'left', widthMm: e.intervalMm / 2, heightMm: e.leftCuspHeightMm },
    ]);
  }
  return roughnessOfSegments(shape, [
    { flank: 'right', widthMm: e.halfWidthRightMm, heightMm: e.cuspHeightMm },
    { flank: 'left', widthMm: e.halfWidthLeftMm, heightMm: e.cuspHeightMm },
  ]);
}

/** The shop rule of thumb `Ra ~ h/4` (for a parabolic scallop the exact ratio is 4/(9 sqrt 3) = 0.2566). */
export function raRuleOfThumbMm(scallopHeightMm: number): number {
  return scallopHeightMm / 4;
}

/** The largest Ra (mm) a tool, posture and pattern can reach on a surface while leaving a scallop. */
export function maxRaMm(tool: ToolInput, pattern: PassPattern, surface: Surface = PLANE): number {
  const limit = scallopHeightLimits(tool, surface).limitMm;
  if (!(limit > 0)) return 0;
  return exactRoughness(forwardInput(tool, pattern, limit * (1 - 1e-12), surface)).raMm;
}

/**
 * The scallop height h (mm) whose passes leave a roughness Ra equal to `targetRaMm` (then the
 * step-over follows from h). See {@link heightForRaMm}. Requires 0 < target < maxRaMm(tool, pattern).
 */
export function scallopHeightForRaMm(
  tool: ToolInput,
  pattern: PassPattern,
  targetRaMm: number,
  surface: Surface = PLANE,
): number {
  const limit = scallopHeightLimits(tool, surface).limitMm * (1 - 1e-12);
  return heightForRaMm((h) => exactRoughness(forwardInput(tool, pattern, h, surface)).raMm, targetRaMm, limit);
}

/**
 * The height h (mm) at which `raAt(h)` (the Ra of the passes that leave the scallop h, increasing
 * in h) equals `targetRaMm`: a bracketed secant (Illinois) in log h, started from the rule of thumb
 * h = 4 Ra, converges in a handful of steps; it stops when Ra is within a relative 1e-13 of the
 * target or h is bracketed to a relative 1e-12 (closer steps chased the rounding of Ra, twice as
 * many of them).
 *
 * The bracket's lower end is h = 2 Ra: the profile lies between the contacts (0) and the highest
 * cusp (h), so its mean deviation is at most h / 2 and Ra(2 Ra) <= Ra. (A lower end a thousand
 * times below the answer, as before, costs seconds across a cylinder's axis: there the flank width
 * at a height of a few nanometres carries the rounding of the corner centre's height, the adaptive
 * quadrature never meets its relative 1e-13 and runs to its cap.)
 * @param limitMm the largest height (just below the flank limit); requires 0 < target < raAt(limit).
 */
export function heightForRaMm(raAt: (h: number) => number, targetRaMm: number, limitMm: number): number {
  const limit = limitMm;
  const ra = (h: number) => raAt(h) - targetRaMm;
  let lo = Math.log(Math.min(limit, 2 * targetRaMm));
  let hi = Math.log(limit);
  let fLo = ra(Math.exp(lo));
  let fHi = ra(Math.exp(hi));
  if (fLo >= 0) return Math.exp(lo);
  if (fHi <= 0) return Math.exp(hi);
  // Start near the rule of thumb when it lies inside the bracket.
  let x = Math.log(Math.min(limit, Math.max(Math.exp(lo), 4 * targetRaMm)));
  let side = 0;
  for (let i = 0; i < 100; i++) {
    const f = ra(Math.exp(x));
    // Ra itself is integrated to a relative 1e-13: closer than that is noise, not progress.
    if (Math.abs(f) <= 1e-13 * targetRaMm) return Math.exp(x);
    if (f < 0) {
      lo = x;
      fLo = f;
      if (side === -1) fHi /= 2;
      side = -1;
    } else {
      hi = x;
      fHi = f;
      if (side === 1) fLo /= 2;
      side = 1;
    }
    // h to a relative 1e-12 (1e-14 mm at h = 0.01 mm): where the width carries rounding (across a
    // cylinder's axis), Ra's own noise is about that, and narrower brackets chased it.
    if (hi - lo <= 1e-12) break;
    x = hi - (fHi * (hi - lo)) / (fHi - fLo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
  }
  return Math.exp(0.5 * (lo + hi));
}

export type { RawTargetRaInput, TargetRaInput } from './targetRaFields';

/**
 * Validates a target roughness: the tool rules of validateForward, and `Ra` from
 * {@link MIN_LENGTH_MM} to below maxRaMm (the supremum, reached only at the scallop height where
 * adjacent passes start to leave a wall; error code `beyond-max-ra` with that limit, or with 0
 * for a flat end lying on a plane, which leaves no scallop; `wall-only` when the tool cuts a step
 * in this posture). The one validation of a target Ra, for the command line and the page.
 * @param maxRa the largest Ra of a valid pass (maxRaMm; the page passes a cached one).
 */
export function validateTargetRa(
  raw: RawTargetRaInput,
  maxRa: (pass: PassInput) => number = (p) => maxRaMm(p, p.pattern, p.surface),
): Validation<TargetRaInput, AnyInputError> {
  const f = targetRaFields(validatePassAnd(raw, 'ra'));
  if (!f.toSolve || f.pass === null || f.ra === undefined) return targetRaValidation(f);
  const p = f.pass;
  const flatLying = surfaceModel(p.surface).leavesNoScallop(p, p.surface);
  // As validateForward: in this posture the tool cuts a step, no scallop forms.
  if (!flatLying && !(scallopHeightLimits(p, p.surface).limitMm >= MIN_LENGTH_MM))
    return targetRaValidation(f, [inputError('ra', 'wall-only', f.shown)]);
  const max = flatLying ? 0 : maxRa(p);
  return targetRaValidation(f, f.ra < max ? [] : [inputError('ra', 'beyond-max-ra', f.shown, max)]);
}
