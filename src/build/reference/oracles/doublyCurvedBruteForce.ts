/**
 * Brute-force cusp heights at a doubly curved point (shared/notes/doubly-curved-and-3-axis.md,
 * section 1), sharing nothing with src/core/surfaces/doublyCurved (no chords, no disks, no envelope): the
 * real tool surface is sampled (the lower outer quarter of the torus corner, the flat bottom disk,
 * the shank cylinder of radius R up to `shankLengthMm`), placed in its posture with its lowest point
 * at the CC point (its own support-point computation, not placement.ts), and carried along two
 * adjacent passes:
 *
 * - Pass 0 turns the tool rigidly about `l` (through (0, 0, -Rf), parallel to Y), at positions
 *   `psi_j = j dpsi` along the feed circle (`x_j = j dx` translations along X when Rf is infinite),
 *   `dpsi |Rf| = positionStepMm`. Each sample point's path crosses the plane X = 0 between two
 *   consecutive positions; the tool is placed at both (3D rotation matrices about l) and the crossing
 *   is interpolated linearly between them (exact for a translation; off by at most the sagitta
 *   `dist dpsi^2 / 8` of the arc, which the bound includes).
 * - Pass 1 is pass 0 turned about `m` (through (0, 0, -Rc), parallel to X) by `phi = L / |Rc|`
 *   (3D rotation matrix; translated by L along Y when Rc is infinite), the tool mirrored in Y first
 *   for zigzag.
 * - The material left in X = 0 is read on bins of the polar angle about m's trace (of Y when Rc is
 *   infinite): each bin keeps the lowest radial height `H` of any sample of either pass (convex
 *   `dist - Rc`, concave `|Rc| - dist`; `z` when Rc is infinite). The cusp is the highest bin between
 *   the two CC points.
 *
 * Refinement: level 0 samples the whole tool at `spacingMm`; each further level samples, for each
 * pass, only the boxes of tool parameters (ring angle, and corner angle, bottom radius or shank
 * height) of the samples that formed the boundary within a few bins of the previous level's cusp,
 * grown by half their size and two of its steps each way, `refine` times finer, with bins `refine`
 * times narrower around the cusp.
 *
 * Bound: a bin's value can exceed the true boundary's lowest value in it by the samples' spacing
 * along the boundary times its slope, and fall below the boundary at the bin's centre by half the
 * bin's width times the slope; the sweep's chords add their sagitta. So at the last level
 * `bound = slope (binWidth + 2 spacing) + sagitta`, slope the largest difference of neighbouring bins
 * around the cusp per unit length. It shrinks linearly with the spacing and the bin width.
 */

type Vec3 = [number, number, number];

/** Options of {@link bruteForceDoublyCurved}. */
export interface DoublyCurvedBruteForceOptions {
  /** Spacing of the samples on the tool surface, mm. */
  readonly spacingMm: number;
  /** Width of a bin along the equator (arc length), mm; default the spacing. */
  readonly binMm?: number;
  /** Distance between consecutive tool positions along a pass, mm; default 4 spacings. */
  readonly positionStepMm?: number;
  /** Shank length sampled above the corner, mm; default R. */
  readonly shankLengthMm?: number;
  /** Levels of local refinement after the whole tool (default 0). */
  readonly levels?: number;
  /** Refinement factor per level (default 8). */
  readonly refine?: number;
}

/** The brute-force answer. */
export interface DoublyCurvedBruteForce {
  /** Radial height of the cusp between pass 0 and pass 1 (the highest bin between their CC points), mm. */
  readonly cuspHeightMm: number;
  /** Its position: arc length along the equator from pass 0's CC point, mm. */
  readonly cuspReachMm: number;
  /** The error bound (see the module comment), mm. */
  readonly boundMm: number;
  /** The lowest radial height of pass 0 alone away from its CC point (negative: it gouges), mm. */
  readonly lowestAwayFromContactMm: number;
  /**
   * Per pass (0, then 1 before its turn about m), the tool-surface parameters of the sample that
   * was lowest in the cusp's bin (or the nearest bin that pass reached), for a polishing start
   * (doublyCurvedPolished.ts); null where the pass has no sample near the cusp.
   */
  readonly winners: [ToolSample | null, ToolSample | null];
}

/**
 * A point of the tool surface by its parameters: piece 0 the corner's lower outer quarter (v the
 * corner angle in [-pi/2, 0]), 1 the bottom disk (v the radius in [0, Rb]), 2 the shank (v the
 * height above the corner, mm); t the angle about the tool axis from e1 towards e2, radians.
 */
export interface ToolSample {
  readonly piece: 0 | 1 | 2;
  readonly t: number;
  readonly v: number;
}

const deg = Math.PI / 180;

/** The tool in its posture: centre O, axis a, and a basis (e1, e2) of the plane normal to a. */
export interface ToolGeometry {
  readonly R: number;
  readonly rcr: number;
  readonly rb: number;
  readonly O: Vec3;
  readonly a: Vec3;
  readonly e1: Vec3;
  readonly e2: Vec3;
}

/** Places the tool: its lowest point (the support point along -Z) at the origin. */
export function toolGeometry(R: number, Rcr: number, leadDeg: number, tiltDeg: number): ToolGeometry {
  const rho = leadDeg * deg;
  const beta = tiltDeg * deg;
  const a: Vec3 = [Math.cos(beta) * Math.sin(rho), Math.sin(beta), Math.cos(beta) * Math.cos(rho)];
  const n1 = Math.hypot(a[2], a[0]);
  const e1: Vec3 = [a[2] / n1, 0, -a[0] / n1];
  const e2: Vec3 = [a[1] * e1[2] - a[2] * e1[1], a[2] * e1[0] - a[0] * e1[2], a[0] * e1[1] - a[1] * e1[0]];
  const rb = R - Rcr;
  // The ring point along -Z's component normal to a; the ball's point below it along -Z.
  const along = -a[2];
  const perp: Vec3 = [-along * a[0], -along * a[1], -1 - along * a[2]];
  const pn = Math.hypot(perp[0], perp[1], perp[2]);
  const ring: Vec3 = pn > 1e-14 ? [(rb * perp[0]) / pn, (rb * perp[1]) / pn, (rb * perp[2]) / pn] : [0, 0, 0];
  return { R, rcr: Rcr, rb, O: [-ring[0], -ring[1], Rcr - ring[2]], a, e1, e2 };
}

/**
 * A box of tool-surface parameters: piece 0 the corner's lower outer quarter (v = corner angle psi in
 * [-pi/2, 0]), 1 the bottom disk (v = radius in [0, Rb]), 2 the shank (v = height above the corner);
 * t the angle about the axis.
 */
interface Box {
  readonly piece: 0 | 1 | 2;
  readonly t0: number;
  readonly t1: number;
  readonly v0: number;
  readonly v1: number;
}

/** Samples of the boxes: points (x, y, z) and their parameters (piece, t, v), with each box's steps. */
interface Samples {
  readonly xyz: Float64Array;
  readonly piece: Uint8Array;
  readonly t: Float64Array;
  readonly v: Float64Array;
  /** Parameter steps of each piece (t, v). */
  readonly steps: Array<[number, number]>;
}

function point(g: ToolGeometry, piece: number, t: number, v: number, out: number[]): void {
  let radial: number;
  let axial: number;
  if (piece === 0) {
    radial = g.rb + g.rcr * Math.cos(v);
    axial = g.rcr * Math.sin(v);
  } else if (piece === 1) {
    radial = v;
    axial = -g.rcr;
  } else {
    radial = g.R;
    axial = v;
  }
  const c = Math.cos(t);
  const s = Math.sin(t);
  for (let i = 0; i < 3; i++) {
    out.push(
      (g.O[i] as number) + radial * (c * (g.e1[i] as number) + s * (g.e2[i] as number)) + axial * (g.a[i] as number),
    );
  }
}

/** Samples boxes at a spacing (mm along the surface; `shankAxialMm` along the shank's generators). */
function sampleBoxes(g: ToolGeometry, boxes: readonly Box[], ds: number, shankAxialMm = ds): Samples {
  const xyz: number[] = [];
  const piece: number[] = [];
  const ts: number[] = [];
  const vs: number[] = [];
  const steps: Array<[number, number]> = [
    [0, 0],
    [0, 0],
    [0, 0],
  ];
  for (const b of boxes) {
    // Arc length per unit of t and v.
    const tScale = b.piece === 1 ? Math.max(b.v1, ds) : g.R;
    const vScale = b.piece === 0 ? g.rcr : 1;
    if (b.piece === 0 && !(g.rcr > 0)) continue;
    if (b.piece === 1 && !(g.rb > 0)) continue;
    const nT = Math.max(1, Math.ceil(((b.t1 - b.t0) * tScale) / ds));
    const nV = Math.max(1, Math.ceil(((b.v1 - b.v0) * vScale) / (b.piece === 2 ? shankAxialMm : ds)));
    const dt = (b.t1 - b.t0) / nT;
    const dv = (b.v1 - b.v0) / nV;
    const st = steps[b.piece] as [number, number];
    st[0] = Math.max(st[0], dt);
    st[1] = Math.max(st[1], dv);
    for (let i = 0; i <= nT; i++) {
      const t = b.t0 + i * dt;
      for (let j = 0; j <= nV; j++) {
        const v = b.v0 + j * dv;
        point(g, b.piece, t, v, xyz);
        piece.push(b.piece);
        ts.push(t);
        vs.push(v);
      }
    }
  }
  return {
    xyz: Float64Array.from(xyz),
    piece: Uint8Array.from(piece),
    t: Float64Array.from(ts),
    v: Float64Array.from(vs),
    steps,
  };
}

/** Tool surface samples in the posture, the lowest point at the origin (x, y, z triples). */
export function sampleTool(
  R: number,
  Rcr: number,
  leadDeg: number,
  tiltDeg: number,
  spacingMm: number,
  shankLengthMm: number,
): Float64Array {
  return sampleBoxes(toolGeometry(R, Rcr, leadDeg, tiltDeg), wholeTool(R - Rcr, shankLengthMm), spacingMm).xyz;
}

function wholeTool(rb: number, shankLengthMm: number): Box[] {
  return [
    { piece: 0, t0: 0, t1: 2 * Math.PI, v0: -0.5 * Math.PI, v1: 0 },
    { piece: 1, t0: 0, t1: 2 * Math.PI, v0: 0, v1: rb },
    { piece: 2, t0: 0, t1: 2 * Math.PI, v0: 0, v1: shankLengthMm },
  ];
}

/** Rotation about an axis parallel to `axisIndex` (0 = X, 1 = Y) through `centre`, applied to p. */
function rotate(p: Vec3, axisIndex: 0 | 1, centre: Vec3, angle: number): Vec3 {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const x = p[0] - centre[0];
  const y = p[1] - centre[1];
  const z = p[2] - centre[2];
  if (axisIndex === 1) return [centre[0] + c * x + s * z, p[1], centre[2] - s * x + c * z];
  return [p[0], centre[1] + c * y - s * z, centre[2] + s * y + c * z];
}

/**
 * The points where a pass (the tool carried along the feed circle) meets X = 0: y, z pairs. Only
 * the crossing on the CC point's side of l counts.
 */
function sweepPass(points: Float64Array, rf: number, positionStepMm: number): { yz: Float64Array; sagitta: number } {
  const out = new Float64Array((points.length / 3) * 2);
  if (!Number.isFinite(rf)) {
    for (let i = 0, j = 0; i < points.length; i += 3, j += 2) {
      out[j] = points[i + 1] as number;
      out[j + 1] = points[i + 2] as number;
    }
    return { yz: out, sagitta: 0 };
  }
  const F: Vec3 = [0, 0, -rf];
  const dpsi = positionStepMm / Math.abs(rf);
  const side = rf > 0 ? 1 : -1;
  let sagitta = 0;
  for (let i = 0, j = 0; i < points.length; i += 3, j += 2) {
    const p: Vec3 = [points[i] as number, points[i + 1] as number, points[i + 2] as number];
    const qx = p[0];
    const qz = p[2] - F[2];
    // The angle about +Y that brings p to X = 0 with z - Fz of the sign of Rf (x' = c qx + s qz).
    const target = Math.atan2(-qx * side, qz * side);
    const j0 = Math.floor(target / dpsi);
    const a = rotate(p, 1, F, j0 * dpsi);
    const b = rotate(p, 1, F, (j0 + 1) * dpsi);
    const t = a[0] / (a[0] - b[0]);
    out[j] = a[1] + t * (b[1] - a[1]);
    out[j + 1] = a[2] + t * (b[2] - a[2]);
    sagitta = Math.max(sagitta, (Math.hypot(qx, qz) * dpsi * dpsi) / 8);
  }
  return { yz: out, sagitta };
}

/** One level's bins over [from, to): the lowest radial height per pass and which sample gave it. */
interface Level {
  readonly from: number;
  readonly width: number;
  readonly lowest: [Float64Array, Float64Array];
  readonly who: [Int32Array, Int32Array];
  readonly samples: [Samples, Samples];
  readonly sagitta: number;
}

/**
 * The cusp between two adjacent passes L apart (arc length along the equator) at a doubly curved
 * point, by brute force (see the module comment).
 * @param rf signed Rf (mm) or Infinity; @param rc signed Rc (mm) or Infinity.
 */
export function bruteForceDoublyCurved(
  tool: { R: number; Rcr: number; leadDeg: number; tiltDeg: number },
  pattern: 'one-way' | 'zigzag',
  rf: number,
  rc: number,
  intervalMm: number,
  options: DoublyCurvedBruteForceOptions,
): DoublyCurvedBruteForce {
  const shank = options.shankLengthMm ?? tool.R;
  const levels = options.levels ?? 0;
  const refine = options.refine ?? 8;
  const geometry: [ToolGeometry, ToolGeometry] = [
    toolGeometry(tool.R, tool.Rcr, tool.leadDeg, tool.tiltDeg),
    toolGeometry(tool.R, tool.Rcr, tool.leadDeg, pattern === 'zigzag' ? -tool.tiltDeg : tool.tiltDeg),
  ];
  const finiteRc = Number.isFinite(rc);
  const abs = Math.abs(rc);
  const convex = rc > 0;
  const C: Vec3 = [0, 0, -rc];
  const phi = finiteRc ? intervalMm / abs : intervalMm;
  const span = intervalMm;
  const tmp = [0, 0];
  // Polar coordinates about C: arc length along the equator and radial height.
  const polar = (y: number, z: number) => {
    if (!finiteRc) {
      tmp[0] = y;
      tmp[1] = z;
      return;
    }
    const q = z + rc;
    const dist = Math.hypot(y, q);
    tmp[0] = abs * Math.atan2(y, convex ? q : -q);
    tmp[1] = convex ? dist - abs : abs - dist;
  };
  const runLevel = (boxes: [Box[], Box[]], ds: number, binMm: number, from: number, to: number): Level => {
    const nBins = Math.max(1, Math.ceil((to - from) / binMm));
    const width = (to - from) / nBins;
    const lowest: [Float64Array, Float64Array] = [
      new Float64Array(nBins).fill(Number.POSITIVE_INFINITY),
      new Float64Array(nBins).fill(Number.POSITIVE_INFINITY),
    ];
    const who: [Int32Array, Int32Array] = [new Int32Array(nBins).fill(-1), new Int32Array(nBins).fill(-1)];
    const samples: Samples[] = [];
    let sagitta = 0;
    for (const k of [0, 1] as const) {
      const smp = sampleBoxes(geometry[k], boxes[k], ds);
      samples.push(smp);
      const swept = sweepPass(smp.xyz, rf, options.positionStepMm ?? 4 * ds);
      sagitta = Math.max(sagitta, swept.sagitta);
      const low = lowest[k];
      const w = who[k];
      for (let j = 0, i = 0; j < swept.yz.length; j += 2, i++) {
        const y = swept.yz[j] as number;
        const z = swept.yz[j + 1] as number;
        if (k === 0) polar(y, z);
        else if (finiteRc) {
          // Turned about m by phi towards +Y (the sense of the rotation flips with the side C is on).
          const r = rotate([0, y, z], 0, C, convex ? -phi : phi);
          polar(r[1], r[2]);
        } else polar(y + intervalMm, z);
        const b = Math.floor(((tmp[0] as number) - from) / width);
        if (b < 0 || b >= nBins) continue;
        if ((tmp[1] as number) < (low[b] as number)) {
          low[b] = tmp[1] as number;
          w[b] = i;
        }
      }
    }
    return { from, width, lowest, who, samples: samples as [Samples, Samples], sagitta };
  };
  const cuspOf = (lv: Level) => {
    let cusp = Number.NEGATIVE_INFINITY;
    let bin = -1;
    const n = lv.lowest[0].length;
    for (let b = 0; b < n; b++) {
      const centre = lv.from + (b + 0.5) * lv.width;
      if (centre <= 0 || centre >= span) continue;
      const v = Math.min(lv.lowest[0][b] as number, lv.lowest[1][b] as number);
      if (Number.isFinite(v) && v > cusp) {
        cusp = v;
        bin = b;
      }
    }
    return { cusp, bin };
  };
  const ds0 = options.spacingMm;
  const whole = wholeTool(tool.R - tool.Rcr, shank);
  let lv = runLevel([whole, whole], ds0, options.binMm ?? ds0, -0.25 * span, 1.25 * span);
  // The lowest height of pass 0 alone away from its CC point (gouging).
  let lowestAway = Number.POSITIVE_INFINITY;
  {
    const n = lv.lowest[0].length;
    const contactBin = Math.floor(-lv.from / lv.width);
    const skip = Math.ceil((2 * ds0) / lv.width);
    for (let b = 0; b < n; b++) {
      if (Math.abs(b - contactBin) <= skip) continue;
      const v = lv.lowest[0][b] as number;
      if (Number.isFinite(v)) lowestAway = Math.min(lowestAway, v);
    }
  }
  let ds = ds0;
  let found = cuspOf(lv);
  for (let level = 1; level <= levels && found.bin >= 0; level++) {
    // The samples that formed the boundary within 6 bins of the cusp, per pass: their parameter boxes.
    const boxes: [Box[], Box[]] = [[], []];
    const lo = Math.max(0, found.bin - 6);
    const hi = Math.min(lv.lowest[0].length - 1, found.bin + 6);
    for (const k of [0, 1] as const) {
      const smp = lv.samples[k];
      const ranges = new Map<number, [number, number, number, number]>();
      for (let b = lo; b <= hi; b++) {
        const i = lv.who[k][b] as number;
        if (i < 0) continue;
        const p = smp.piece[i] as number;
        const t = smp.t[i] as number;
        const v = smp.v[i] as number;
        const r = ranges.get(p);
        if (r === undefined) ranges.set(p, [t, t, v, v]);
        else ranges.set(p, [Math.min(r[0], t), Math.max(r[1], t), Math.min(r[2], v), Math.max(r[3], v)]);
      }
      for (const [p, r] of ranges) {
        const [dt, dv] = smp.steps[p] as [number, number];
        const vMax = p === 0 ? 0 : p === 1 ? tool.R - tool.Rcr : shank;
        const vMin = p === 0 ? -0.5 * Math.PI : 0;
        // Grown by their own size and two steps each way: where the fold is flat in a parameter (a
        // flat bottom lying flat: every ring angle near the widest one gives nearly the same boundary)
        // the samples that won their bins can sit on one side of it.
        const wt = 0.5 * (r[1] - r[0]) + 2 * dt;
        const wv = 0.5 * (r[3] - r[2]) + 2 * dv;
        boxes[k].push({
          piece: p as 0 | 1 | 2,
          t0: r[0] - wt,
          t1: r[1] + wt,
          v0: Math.max(vMin, r[2] - wv),
          v1: Math.min(vMax, r[3] + wv),
        });
      }
    }
    const centre = lv.from + (found.bin + 0.5) * lv.width;
    const half = 6 * lv.width;
    const bin = lv.width / refine;
    ds /= refine;
    lv = runLevel(boxes, ds, bin, centre - half, centre + half);
    found = cuspOf(lv);
  }
  // Slope of the boundary around the cusp (neighbouring bins within 10 bins).
  let slope = 0;
  const n = lv.lowest[0].length;
  const boundary = (b: number) => Math.min(lv.lowest[0][b] as number, lv.lowest[1][b] as number);
  for (let b = Math.max(1, found.bin - 10); b <= Math.min(n - 1, found.bin + 10); b++) {
    const u = boundary(b - 1);
    const v = boundary(b);
    if (Number.isFinite(u) && Number.isFinite(v)) slope = Math.max(slope, Math.abs(v - u) / lv.width);
  }
  const winner = (k: 0 | 1): ToolSample | null => {
    for (let d = 0; d < n && found.bin >= 0; d++) {
      for (const b of [found.bin - d, found.bin + d]) {
        const i = b >= 0 && b < n ? (lv.who[k][b] as number) : -1;
        if (i < 0) continue;
        const smp = lv.samples[k];
        return { piece: smp.piece[i] as 0 | 1 | 2, t: smp.t[i] as number, v: smp.v[i] as number };
      }
    }
    return null;
  };
  return {
    cuspHeightMm: found.cusp,
    cuspReachMm: lv.from + (found.bin + 0.5) * lv.width,
    boundMm: slope * (lv.width + 2 * ds) + lv.sagitta,
    lowestAwayFromContactMm: lowestAway,
    winners: [winner(0), winner(1)],
  };
}

/**
 * Gouging by brute force: the lowest radial height (mm) of one pass's section in X = 0 (the sampled
 * tool carried along the feed circle as above), over its samples farther than `excludeMm` (arc
 * length along the equator) from the CC point. The shank is sampled up to `shankLengthMm` and only
 * where its points lie at most `capMm` above the CC point (the nearest concave axis's height), on
 * the tool and in the plane X = 0.
 * Negative: the swept tool reaches inside the surface. A sample's height is exact but for the
 * sweep's sagitta (returned), so a value below minus the sagitta proves gouging, and the true lowest
 * value lies within the sampling's reach of it.
 */
export function bruteForceLowestRadialHeight(
  tool: { R: number; Rcr: number; leadDeg: number; tiltDeg: number },
  rf: number,
  rc: number,
  options: {
    spacingMm: number;
    excludeMm: number;
    shankLengthMm: number;
    capMm: number;
    /** Spacing along the shank's straight generators, mm (default the spacing). */
    shankAxialMm?: number;
  },
): { lowestMm: number; sagittaMm: number } {
  const g = toolGeometry(tool.R, tool.Rcr, tool.leadDeg, tool.tiltDeg);
  const smp = sampleBoxes(
    g,
    wholeTool(tool.R - tool.Rcr, options.shankLengthMm),
    options.spacingMm,
    options.shankAxialMm ?? options.spacingMm,
  );
  const keep: number[] = [];
  const isShank: boolean[] = [];
  for (let i = 0; i < smp.piece.length; i++) {
    if (smp.piece[i] === 2 && (smp.xyz[3 * i + 2] as number) > options.capMm) continue;
    keep.push(smp.xyz[3 * i] as number, smp.xyz[3 * i + 1] as number, smp.xyz[3 * i + 2] as number);
    isShank.push(smp.piece[i] === 2);
  }
  const swept = sweepPass(Float64Array.from(keep), rf, options.spacingMm);
  const finiteRc = Number.isFinite(rc);
  const abs = Math.abs(rc);
  let lowest = Number.POSITIVE_INFINITY;
  for (let j = 0; j < swept.yz.length; j += 2) {
    const y = swept.yz[j] as number;
    const z = swept.yz[j + 1] as number;
    // The shank counts up to the cap at its place on the tool and in the plane X = 0.
    if (isShank[j / 2] && z > options.capMm) continue;
    let arc = y;
    let H = z;
    if (finiteRc) {
      const q = z + rc;
      const dist = Math.hypot(y, q);
      arc = abs * Math.atan2(y, rc > 0 ? q : -q);
      H = rc > 0 ? dist - abs : abs - dist;
    }
    if (Math.abs(arc) > options.excludeMm && H < lowest) lowest = H;
  }
  return { lowestMm: lowest, sagittaMm: swept.sagitta };
}
