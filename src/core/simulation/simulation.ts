/**
 * A simulation of the passes, independent of the projection argument of posture.ts: the real tool
 * surface (torus corner and flat bottom, in its posture; placement.ts) is sampled as points, the
 * tool is swept along several adjacent passes over a height field (z-buffer) of the design plane,
 * and the material left is measured along a trace across the passes.
 *
 * Sweep. A pass moves the tool along X through every cell of the field (one placement per cell
 * along the feed). A surface sample at (x, y, z) then visits every cell of the row its y falls in,
 * so the z-buffer keeps, per row, the minimum z of the samples that fall in that row; the field is
 * that row minimum along X. Passes sit `L` apart in Y; zigzag passes are mirrored (y -> -y) on
 * every other pass.
 *
 * Meshing. The surface is meshed by triangles whose corners lie on it: a uniform grid in its own
 * parameters (ring angle and section angle for the corner's lower outer quarter; the same angles
 * and the radius for the bottom disk, so the two meet without cracks), kept only in blocks that can
 * reach below a height cap (taken from a coarse first run, plus its bound) and into the field. A
 * triangle cut by the plane of a row gives a segment whose lowest end is that triangle's value for
 * the row; the row keeps the lowest. So a small scallop under a big tool costs little. Nothing
 * here uses the exact solver or the projected ellipse.
 *
 * Resolution bound (stated with every result). The tool solid is convex, so a triangle with its
 * corners on the surface lies inside the solid: a row's value is at or above the true envelope E
 * and at most the chord error above it (chordErrorMm: `l^2 / (8 Rcr)` across the corner, capped at
 * `2 Rcr` for a corner smaller than a triangle, plus `l^2 / (8 (Rb + Rcr))` around the axis, for
 * the rim of a flat end too; l the longest triangle edge; the flat bottom itself is exact). A cusp is located between rows by intersecting the lines through the two rows on
 * each side: its error adds at most the measured curvature of the trace times `dy^2`. Roughness is
 * integrated on the piecewise-linear trace through the rows and the refined cusps; its values are
 * within twice the height bound. Lengths mm.
 */

import type { PassPattern, ToolInput } from '../domain/tool';
import { type Placement, placeTool } from '../tool/placement';

/** What is simulated: a tool in its posture, a pass pattern and a step-over. */
export interface SimulationInput {
  readonly tool: ToolInput;
  readonly pattern: PassPattern;
  /** Step-over L between adjacent cutter-contact paths, mm (> 0). */
  readonly intervalMm: number;
}

export interface SimulationOptions {
  /** Cells across the feed (Y), default 512. */
  readonly cellsAcross?: number;
  /** Cells along the feed (X), default 512. */
  readonly cellsAlong?: number;
  /** Passes: default 5 one-way, 4 zigzag (both cusps). */
  readonly passes?: number;
}

export interface SimulationResult {
  readonly cellsAcross: number;
  readonly cellsAlong: number;
  /** Y of the first and last row centres, and the X length of the field, mm. */
  readonly acrossFromMm: number;
  readonly acrossToMm: number;
  readonly alongLengthMm: number;
  /** Heights of the material left, mm above the design plane: row-major, `cellsAlong` rows of `cellsAcross`. */
  readonly heightsMm: Float32Array;
  /** The profilometer trace across the passes at mid-length: (y, z) pairs, mm. */
  readonly trace: Float64Array;
  /** Measured height of each cusp between adjacent passes, mm (alternating kinds for zigzag). */
  readonly cuspHeightsMm: number[];
  /** The highest measured cusp, mm. */
  readonly cuspHeightMm: number;
  /** Roughness of the trace over whole periods (one-way: L each, zigzag: 2L each), mm. */
  readonly roughness: { readonly rzMm: number; readonly raMm: number; readonly rqMm: number; readonly meanMm: number };
  /** Bound on the cusp-height error (see the module comment), mm; roughness values within twice it plus s dy. */
  readonly resolutionBoundMm: number;
  /** Bound on the roughness values' error, mm. */
  readonly roughnessBoundMm: number;
  /** Cell size across the feed and the largest sample spacing, mm. */
  readonly cellMm: number;
  readonly sampleSpacingMm: number;
  readonly cells: number;
  /** Tool placements: one per cell along the feed, per pass. */
  readonly placements: number;
  /** Triangles of the tool surface used. */
  readonly samples: number;
}

/**
 * Most triangles of the tool surface one simulation meshes. A large tool leaving a tiny scallop can
 * need far more at the field's resolution (beyond the memory a JavaScript array can hold); the
 * simulation then stops with {@link SimulationTooLargeError} instead of exhausting the memory.
 */
export const MAX_SIMULATION_TRIANGLES = 4_000_000;

/** The simulation of a case would need more than {@link MAX_SIMULATION_TRIANGLES} triangles. */
export class SimulationTooLargeError extends RangeError {
  constructor() {
    super(
      `the simulation would need more than ${MAX_SIMULATION_TRIANGLES} triangles of the tool surface at this resolution (a tool far larger than the step-over it leaves): not run`,
    );
    this.name = 'SimulationTooLargeError';
  }
}

/** Triangles of the tool surface projected on (y, z): 6 numbers each, relative to the pass's contact. */
type Triangles = Float64Array;

/**
 * A point of the tool's lower surface, relative to the contact: the lower outer quarter of the
 * corner (section angle psi from -pi/2, under the ring, to 0, at the equator) continued by the
 * bottom disk (radius r from Rb to 0, at axial -Rcr), both at angle t around the axis. One angle
 * grid serves both, so the corner and the disk meet without cracks.
 */
function surfacePoint(p: Placement, t: number, psi: number, r: number, out: number[]): void {
  const st = Math.sin(t);
  const ct = Math.cos(t);
  const { centre, axis, v1, v2 } = p;
  const rx = st * v1[0] + ct * v2[0];
  const ry = st * v1[1] + ct * v2[1];
  const rz = st * v1[2] + ct * v2[2];
  // Corner: r = Rb + Rcr cos(psi), axial Rcr sin(psi); disk: r in [0, Rb], axial -Rcr.
  const radial = r;
  const axial = p.cornerRadiusMm * Math.sin(psi);
  out[0] = centre[0] + radial * rx + axial * axis[0];
  out[1] = centre[1] + radial * ry + axial * axis[1];
  out[2] = centre[2] + radial * rz + axial * axis[2];
}

/**
 * Meshes the lower surface with triangles of edges about `l`, keeping what can reach below `zCap`,
 * into the field (inRange on a Y interval) and, when `xBand` is finite, within that distance of the
 * plane x = 0. The surface is one grid: angle t around the axis, and a profile parameter q from 0
 * (the disk's centre) through the disk's edge (q = Rb) to the corner's equator (q = Rb + pi Rcr / 2,
 * arc length along the profile). Blocks of the grid are culled and split recursively (quadtree on
 * the grid indices) down to leaves of at most 8 x 8 cells, so only the relevant part is meshed and
 * every triangle is a cell of the same global grid (no cracks between leaves).
 */
function meshSurface(
  p: Placement,
  l: number,
  zCap: number,
  inRange: (a: number, b: number) => boolean,
  xBand = Number.POSITIVE_INFINITY,
): Triangles {
  const rb = p.ringRadiusMm;
  const rcr = p.cornerRadiusMm;
  const qEnd = rb + (Math.PI / 2) * rcr;
  const blocksT = 64;
  const blocksQ = 16;
  const perT = Math.max(1, Math.ceil((2 * Math.PI * (rb + rcr)) / (l * blocksT)));
  const perQ = Math.max(1, Math.ceil(qEnd / (l * blocksQ)));
  const nT = blocksT * perT;
  const nQ = blocksQ * perQ;
  const point = (i: number, j: number, out: number[]) => {
    const t = (2 * Math.PI * i) / nT;
    const q = (qEnd * j) / nQ;
    if (q <= rb) surfacePoint(p, t, -Math.PI / 2, q, out);
    else {
      const psi = -Math.PI / 2 + (q - rb) / rcr;
      surfacePoint(p, t, psi, rb + rcr * Math.cos(psi), out);
    }
  };
  const tris: number[] = [];
  const corners = Array.from({ length: 5 }, () => [0, 0, 0]);
  const leaf = 8;
  const ys = new Float64Array((leaf + 1) * (leaf + 1));
  const zs = new Float64Array((leaf + 1) * (leaf + 1));
  const rxs = new Float64Array(leaf + 1);
  const rys = new Float64Array(leaf + 1);
  const rzs = new Float64Array(leaf + 1);
  const radials = new Float64Array(leaf + 1);
  const axials = new Float64Array(leaf + 1);
  // A block [i0, i1) x [j0, j1): keep it when its bounding ball (centre point, twice the farthest
  // corner, plus a cell) can reach below the cap, into the field and into the x band.
  const keep = (i0: number, i1: number, j0: number, j1: number): boolean => {
    point(i0, j0, corners[0] as number[]);
    point(i1, j0, corners[1] as number[]);
    point(i0, j1, corners[2] as number[]);
    point(i1, j1, corners[3] as number[]);
    point(0.5 * (i0 + i1), 0.5 * (j0 + j1), corners[4] as number[]);
    const c = corners[4] as number[];
    let radius = 0;
    for (let k = 0; k < 4; k++) {
      const q = corners[k] as number[];
      const dx = (q[0] as number) - (c[0] as number);
      const dy = (q[1] as number) - (c[1] as number);
      const dz = (q[2] as number) - (c[2] as number);
      radius = Math.max(radius, Math.sqrt(dx * dx + dy * dy + dz * dz));
    }
    const reach = 2 * radius + l;
    if ((c[2] as number) - reach > zCap) return false;
    if (Math.abs(c[0] as number) - reach > xBand) return false;
    return inRange((c[1] as number) - reach, (c[1] as number) + reach);
  };
  const stack: number[] = [];
  for (let bt = 0; bt < blocksT; bt++)
    for (let bq = 0; bq < blocksQ; bq++) stack.push(bt * perT, (bt + 1) * perT, bq * perQ, (bq + 1) * perQ);
  while (stack.length > 0) {
    const j1 = stack.pop() as number;
    const j0 = stack.pop() as number;
    const i1 = stack.pop() as number;
    const i0 = stack.pop() as number;
    if (!keep(i0, i1, j0, j1)) continue;
    const ni = i1 - i0;
    const nj = j1 - j0;
    if (ni > leaf || nj > leaf) {
      if (ni >= nj) {
        const im = i0 + Math.floor(ni / 2);
        stack.push(i0, im, j0, j1, im, i1, j0, j1);
      } else {
        const jm = j0 + Math.floor(nj / 2);
        stack.push(i0, i1, j0, jm, i0, i1, jm, j1);
      }
      continue;
    }
    // The leaf's grid points: radial directions per angle and (radial, axial) offsets per profile
    // parameter, each computed once (18 trigonometric pairs instead of 81).
    for (let i = 0; i <= ni; i++) {
      const t = (2 * Math.PI * (i0 + i)) / nT;
      const st = Math.sin(t);
      const ct = Math.cos(t);
      rxs[i] = st * p.v1[0] + ct * p.v2[0];
      rys[i] = st * p.v1[1] + ct * p.v2[1];
      rzs[i] = st * p.v1[2] + ct * p.v2[2];
    }
    for (let j = 0; j <= nj; j++) {
      const q = (qEnd * (j0 + j)) / nQ;
      if (q <= rb) {
        radials[j] = q;
        axials[j] = -rcr;
      } else {
        const psi = -Math.PI / 2 + (q - rb) / rcr;
        radials[j] = rb + rcr * Math.cos(psi);
        axials[j] = rcr * Math.sin(psi);
      }
    }
    const [cx, cy, cz] = p.centre;
    const [ax, ay, az] = p.axis;
    for (let i = 0; i <= ni; i++) {
      for (let j = 0; j <= nj; j++) {
        const radial = radials[j] as number;
        const axial = axials[j] as number;
        const x = cx + radial * (rxs[i] as number) + axial * ax;
        ys[i * (nj + 1) + j] = cy + radial * (rys[i] as number) + axial * ay;
        zs[i * (nj + 1) + j] =
          Math.abs(x) > xBand + 2 * l ? Number.POSITIVE_INFINITY : cz + radial * (rzs[i] as number) + axial * az;
      }
    }
    for (let i = 0; i < ni; i++) {
      for (let j = 0; j < nj; j++) {
        const k00 = i * (nj + 1) + j;
        const k10 = k00 + nj + 1;
        const k01 = k00 + 1;
        const k11 = k10 + 1;
        const z00 = zs[k00] as number;
        const z10 = zs[k10] as number;
        const z01 = zs[k01] as number;
        const z11 = zs[k11] as number;
        // Out of the x band (a corner marked infinite) or wholly above the cap: not needed.
        if (!Number.isFinite(z00 + z10 + z01 + z11)) continue;
        if (Math.min(z00, z10, z01, z11) > zCap) continue;
        const y00 = ys[k00] as number;
        const y10 = ys[k10] as number;
        const y01 = ys[k01] as number;
        const y11 = ys[k11] as number;
        tris.push(y00, z00, y10, z10, y11, z11, y00, z00, y11, z11, y01, z01);
      }
    }
    if (tris.length > 6 * MAX_SIMULATION_TRIANGLES) throw new SimulationTooLargeError();
  }
  return Float64Array.from(tris);
}

/**
 * How far a triangle of edges up to `l` with its corners on the tool surface can lie inside it:
 * the sagitta across the corner (radius Rcr; at most 2 Rcr when the corner is smaller than the
 * triangle) plus the sagitta around the axis (radius at least Rb + Rcr, the rim for a flat end).
 * Without the second term and the cap, a flat or nearly flat end got an infinite margin and the
 * whole bottom disk was meshed (tens of millions of triangles).
 */
function chordErrorMm(p: Placement, l: number): number {
  const rcr = p.cornerRadiusMm;
  const across = rcr > 0 ? Math.min((l * l) / (8 * rcr), 2 * rcr) : 0;
  const ring = p.ringRadiusMm + rcr;
  return across + (ring > 0 ? (l * l) / (8 * ring) : 0);
}

/** Y offsets of the passes' contact paths and whether each pass is mirrored. */
function passLayout(input: SimulationInput, passes: number): Array<{ y: number; mirrored: boolean }> {
  const out: Array<{ y: number; mirrored: boolean }> = [];
  for (let k = 0; k < passes; k++)
    out.push({ y: k * input.intervalMm, mirrored: input.pattern === 'zigzag' && k % 2 === 1 });
  return out;
}

interface Field {
  readonly rows: number;
  readonly y0: number;
  readonly dy: number;
  readonly rowMin: Float64Array;
}

/** Rasterises the triangles of one pass into the rows: each row keeps the lowest cut. */
function sweep(tris: Triangles, pass: { y: number; mirrored: boolean }, field: Field): void {
  const { rows, y0, dy, rowMin } = field;
  const sign = pass.mirrored ? -1 : 1;
  const v = [0, 0, 0, 0, 0, 0];
  for (let k = 0; k < tris.length; k += 6) {
    for (let m = 0; m < 3; m++) {
      v[2 * m] = pass.y + sign * (tris[k + 2 * m] as number);
      v[2 * m + 1] = tris[k + 2 * m + 1] as number;
    }
    const yMin = Math.min(v[0] as number, v[2] as number, v[4] as number);
    const yMax = Math.max(v[0] as number, v[2] as number, v[4] as number);
    const j0 = Math.max(0, Math.ceil((yMin - y0) / dy));
    const j1 = Math.min(rows - 1, Math.floor((yMax - y0) / dy));
    for (let j = j0; j <= j1; j++) {
      const y = y0 + j * dy;
      let low = Number.POSITIVE_INFINITY;
      // The row's plane cuts the triangle along a segment whose lowest end lies on an edge.
      for (let e = 0; e < 3; e++) {
        const ya = v[2 * e] as number;
        const za = v[2 * e + 1] as number;
        const yb = v[(2 * e + 2) % 6] as number;
        const zb = v[(2 * e + 3) % 6] as number;
        if ((ya - y) * (yb - y) > 0) continue;
        const z = ya === yb ? Math.min(za, zb) : za + ((zb - za) * (y - ya)) / (yb - ya);
        if (z < low) low = z;
      }
      if (low < (rowMin[j] as number)) rowMin[j] = low;
    }
  }
}

/**
 * The cusp between contacts at y = lo and y = hi: the row maximum, refined by intersecting the
 * lines through the two rows on each side of it; also the trace's largest curvature around it.
 */
function refinedCusp(field: Field, lo: number, hi: number): { y: number; z: number; curvature: number } {
  const { rowMin, y0, dy } = field;
  let jm = -1;
  for (let j = 0; j < field.rows; j++) {
    const y = y0 + j * dy;
    if (y > lo && y < hi && (jm < 0 || (rowMin[j] as number) > (rowMin[jm] as number))) jm = j;
  }
  if (jm < 2 || jm > field.rows - 3) return { y: y0 + jm * dy, z: rowMin[jm] as number, curvature: 0 };
  const z = (j: number) => rowMin[j] as number;
  const line = (j: number) => ({ slope: (z(j + 1) - z(j)) / dy, y: y0 + j * dy, z: z(j) });
  const meet = (l1: ReturnType<typeof line>, l2: ReturnType<typeof line>) => {
    const y = l1.y + (l2.z - l1.z + l1.slope * (l1.y - l1.y) - l2.slope * (l2.y - l1.y)) / (l1.slope - l2.slope);
    return { y, z: l1.z + l1.slope * (y - l1.y) };
  };
  // The cusp lies between jm-1 and jm+1: on the rising side of jm or on the falling side.
  const candidates = [
    { left: line(jm - 1), right: line(jm + 1), from: jm, to: jm + 1 },
    { left: line(jm - 2), right: line(jm), from: jm - 1, to: jm },
  ];
  let best = { y: y0 + jm * dy, z: z(jm) };
  for (const c of candidates) {
    if (!(c.left.slope > 0 && c.right.slope < 0)) continue;
    const m = meet(c.left, c.right);
    if (m.y >= y0 + c.from * dy - 1e-12 && m.y <= y0 + c.to * dy + 1e-12 && m.z >= best.z) best = m;
  }
  const second = (j: number) => Math.abs(z(j + 1) - 2 * z(j) + z(j - 1)) / (dy * dy);
  const curvature = Math.max(second(Math.max(1, jm - 2)), second(Math.min(field.rows - 2, jm + 2)));
  return { ...best, curvature };
}

/** Measures cusps and roughness on the trace through the rows and the refined cusps. */
function measure(field: Field, input: SimulationInput, passes: number) {
  const { rowMin, y0, dy } = field;
  const L = input.intervalMm;
  const cusps = [];
  for (let k = 0; k + 1 < passes; k++) cusps.push(refinedCusp(field, k * L, (k + 1) * L));
  // Whole periods from the first contact: one-way L, zigzag 2L.
  const period = input.pattern === 'zigzag' ? 2 * L : L;
  const periods = Math.max(1, Math.floor(((passes - 1) * L) / period + 1e-9));
  const end = periods * period;
  // The trace: rows inside [0, end], the refined cusps, and the ends interpolated.
  const pts: Array<[number, number]> = [];
  const at = (y: number) => {
    const f = (y - y0) / dy;
    const j = Math.min(field.rows - 2, Math.max(0, Math.floor(f)));
    const u = f - j;
    return (rowMin[j] as number) * (1 - u) + (rowMin[j + 1] as number) * u;
  };
  pts.push([0, at(0)]);
  for (let j = 0; j < field.rows; j++) {
    const y = y0 + j * dy;
    if (y > 0 && y < end) pts.push([y, rowMin[j] as number]);
  }
  for (const c of cusps) if (c.y > 0 && c.y < end) pts.push([c.y, c.z]);
  pts.push([end, at(end)]);
  pts.sort((p1, p2) => p1[0] - p2[0]);
  let area = 0;
  for (let i = 1; i < pts.length; i++) {
    const [ya, za] = pts[i - 1] as [number, number];
    const [yb, zb] = pts[i] as [number, number];
    area += 0.5 * (za + zb) * (yb - ya);
  }
  const mean = area / end;
  let abs = 0;
  let sq = 0;
  let lo = Number.POSITIVE_INFINITY;
  let hi = Number.NEGATIVE_INFINITY;
  for (let i = 1; i < pts.length; i++) {
    const [ya, za] = pts[i - 1] as [number, number];
    const [yb, zb] = pts[i] as [number, number];
    const w = yb - ya;
    const da = za - mean;
    const db = zb - mean;
    // Exact for a straight piece: |z - m| split where it crosses the mean line.
    if (da * db >= 0) abs += 0.5 * Math.abs(da + db) * w;
    else abs += (0.5 * (da * da + db * db) * w) / (Math.abs(da) + Math.abs(db));
    sq += ((da * da + da * db + db * db) / 3) * w;
    lo = Math.min(lo, za, zb);
    hi = Math.max(hi, za, zb);
  }
  let slope = 0;
  for (let j = 1; j < field.rows; j++) {
    const y = y0 + j * dy;
    if (y > 0 && y < end) slope = Math.max(slope, Math.abs((rowMin[j] as number) - (rowMin[j - 1] as number)) / dy);
  }
  return {
    cusps,
    roughness: { rzMm: hi - lo, raMm: abs / end, rqMm: Math.sqrt(sq / end), meanMm: mean },
    slope,
  };
}

/** A simulation that runs in steps, so a worker can yield between them, report progress and cancel. */
export interface SimulationRun {
  /** Does the next step; true when the result is ready. */
  step(): boolean;
  /** Fraction done, 0 to 1. */
  readonly progress: number;
  /** The result, after step() returned true. */
  result(): SimulationResult;
}

/**
 * Prepares a simulation (see the module comment). Steps: a coarse run to bound the height that
 * matters, then the fine sampling, then the sweep of each pass, then the measurement.
 * @param input a valid tool and posture, pattern and step-over (0 < L, below the wall).
 * A step throws {@link SimulationTooLargeError} when the tool surface needs more triangles than
 * {@link MAX_SIMULATION_TRIANGLES}.
 */
export function startSimulation(input: SimulationInput, options: SimulationOptions = {}): SimulationRun {
  const across = Math.max(16, Math.round(options.cellsAcross ?? 512));
  const along = Math.max(2, Math.round(options.cellsAlong ?? 512));
  const passes = Math.max(2, Math.round(options.passes ?? (input.pattern === 'zigzag' ? 4 : 5)));
  const L = input.intervalMm;
  const p = placeTool(input.tool);
  const layout = passLayout(input, passes);
  // Rows from half a step-over before the first pass to half a step-over after the last one.
  const span = passes * L;
  const dy = span / across;
  const y0 = -0.5 * L + 0.5 * dy;
  const yLo = y0 - 0.5 * dy;
  const yHi = y0 + (across - 0.5) * dy;
  const inRange = (a: number, b: number) =>
    layout.some((pass) => {
      const lo = pass.mirrored ? pass.y - b : pass.y + a;
      const hi = pass.mirrored ? pass.y - a : pass.y + b;
      return hi >= yLo && lo <= yHi;
    });
  const newField = (rows: number, step: number, first: number): Field => ({
    rows,
    y0: first,
    dy: step,
    rowMin: new Float64Array(rows).fill(Number.POSITIVE_INFINITY),
  });
  const fine = newField(across, dy, y0);
  // Triangle edges of half a cell: chord error l^2 / (8 Rcr), far below the cell.
  const edge = dy / 2;
  let stage = 0;
  let tris: Triangles = new Float64Array(0);
  let zCap = Number.POSITIVE_INFINITY;
  let passIndex = 0;
  let retries = 0;
  let done: SimulationResult | null = null;
  const totalSteps = 3 + passes;
  return {
    get progress() {
      // Steps: two coarse runs and the mesh (stages 0, 1), one sweep per pass, the measurement.
      const steps = stage < 2 ? stage : stage === 2 ? 2 + passIndex : 2 + passes;
      return done ? 1 : Math.min(0.99, steps / totalSteps);
    },
    step() {
      if (done) return true;
      if (stage === 0) {
        // Coarse runs (64 rows) bound the height that matters. First a strip of the surface around
        // the plane x = 0: any part of the tool leaves material at or above what the whole tool
        // leaves, so its cusps bound the true ones from above. Then the whole surface below that
        // bound, for a close estimate.
        const coarseRows = 64;
        const cdy = span / coarseRows;
        const coarseCap = (tris: Triangles): number => {
          const coarse = newField(coarseRows, cdy, -0.5 * L + 0.5 * cdy);
          for (const pass of layout) sweep(tris, pass, coarse);
          const m = measure(coarse, input, passes);
          const top = Math.max(0, ...m.cusps.map((c) => c.z).filter(Number.isFinite));
          return top + m.slope * cdy + chordErrorMm(p, cdy / 2);
        };
        const strip = coarseCap(meshSurface(p, cdy / 2, Number.POSITIVE_INFINITY, inRange, 2 * cdy));
        // A quarter more covers what the coarse rows cannot resolve; should a row in the measured
        // span still get no triangle below the cap, the sweep doubles the cap and runs again.
        zCap = 1.25 * Math.min(strip, coarseCap(meshSurface(p, cdy / 2, strip, inRange)));
        stage = 1;
        return false;
      }
      if (stage === 1) {
        tris = meshSurface(p, edge, zCap, inRange);
        stage = 2;
        return false;
      }
      if (stage === 2) {
        const pass = layout[passIndex];
        if (pass) sweep(tris, pass, fine);
        passIndex++;
        if (passIndex >= layout.length) stage = 3;
        return false;
      }
      // Every row between the first and the last contact must have met the surface below the cap.
      const lastContact = (passes - 1) * L;
      let missing = false;
      for (let j = 0; j < across; j++) {
        const y = y0 + j * dy;
        if (y >= 0 && y <= lastContact && !Number.isFinite(fine.rowMin[j] as number)) missing = true;
      }
      if (missing && retries < 20) {
        retries++;
        zCap = 2 * zCap + dy;
        fine.rowMin.fill(Number.POSITIVE_INFINITY);
        passIndex = 0;
        stage = 1;
        return false;
      }
      const m = measure(fine, input, passes);
      // Rows no low triangle reached lie above the cap: show them at the cap.
      for (let j = 0; j < across; j++) if (!Number.isFinite(fine.rowMin[j] as number)) fine.rowMin[j] = zCap;
      const heights = new Float32Array(across * along);
      for (let i = 0; i < along; i++)
        for (let j = 0; j < across; j++) heights[i * across + j] = fine.rowMin[j] as number;
      const trace = new Float64Array(2 * across);
      for (let j = 0; j < across; j++) {
        trace[2 * j] = y0 + j * dy;
        trace[2 * j + 1] = fine.rowMin[j] as number;
      }
      // Longest triangle edge: about sqrt(2) grid steps; chord error l^2 / (8 Rcr) (flat bottom: 0).
      const l = Math.SQRT2 * edge * 1.5;
      const chord = chordErrorMm(p, l);
      const curvature = Math.max(0, ...m.cusps.map((c) => c.curvature));
      const bound = chord + curvature * dy * dy;
      const cuspHeights = m.cusps.map((c) => c.z);
      done = {
        cellsAcross: across,
        cellsAlong: along,
        acrossFromMm: y0,
        acrossToMm: y0 + (across - 1) * dy,
        alongLengthMm: along * dy,
        heightsMm: heights,
        trace,
        cuspHeightsMm: cuspHeights,
        cuspHeightMm: Math.max(...cuspHeights),
        roughness: m.roughness,
        resolutionBoundMm: bound,
        roughnessBoundMm: 2 * bound + (m.slope * dy * dy) / (2 * L),
        cellMm: dy,
        sampleSpacingMm: l,
        cells: across * along,
        placements: passes * along,
        samples: tris.length / 6,
      };
      return true;
    },
    result() {
      if (!done) throw new Error('the simulation has not finished');
      return done;
    },
  };
}

/** Runs a simulation to the end (command line, tests). */
export function simulatePasses(input: SimulationInput, options: SimulationOptions = {}): SimulationResult {
  const run = startSimulation(input, options);
  while (!run.step()) {
    // next step
  }
  return run.result();
}
