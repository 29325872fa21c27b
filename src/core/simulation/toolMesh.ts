/**
 * The meshed tool surface of the simulation (simulation.ts, whose module comment states the
 * meshing and its bound): triangles with their corners on the real tool surface, projected on (y, z).
 */
import type { Placement } from '../tool/placement';

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
export type Triangles = Float64Array;

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
 * The tool's profile at arc length q from the disk's centre (see meshSurface): fills `out` with the
 * section angle psi (-pi/2 on the disk, up to 0 at the corner's equator) and the radius from the
 * axis. The disk ends at q = Rb and the corner at Rb + pi Rcr / 2; a q past the end by rounding
 * (the grid's last row, `(qEnd j) / n` with j = n, can be an ulp past qEnd) is the end. Without that,
 * a flat end (Rcr = 0, no corner) put its rim at the section angle (q - Rb) / 0: every rim point
 * NaN, no triangle at the contact, every simulated height non-finite (issue 26, point 6).
 */
function profileOffsets(rb: number, rcr: number): (q: number, out: [number, number]) => void {
  return (q, out) => {
    if (q <= rb || !(rcr > 0)) {
      out[0] = -Math.PI / 2;
      out[1] = Math.min(q, rb);
      return;
    }
    const psi = Math.min(0, -Math.PI / 2 + (q - rb) / rcr);
    out[0] = psi;
    out[1] = rb + rcr * Math.cos(psi);
  };
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
export function meshSurface(
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
  const offsets = profileOffsets(rb, rcr);
  const section: [number, number] = [0, 0];
  const point = (i: number, j: number, out: number[]) => {
    offsets((qEnd * j) / nQ, section);
    surfacePoint(p, (2 * Math.PI * i) / nT, section[0], section[1], out);
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
      offsets((qEnd * (j0 + j)) / nQ, section);
      radials[j] = section[1];
      axials[j] = rcr * Math.sin(section[0]);
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
export function chordErrorMm(p: Placement, l: number): number {
  const rcr = p.cornerRadiusMm;
  const across = rcr > 0 ? Math.min((l * l) / (8 * rcr), 2 * rcr) : 0;
  const ring = p.ringRadiusMm + rcr;
  return across + (ring > 0 ? (l * l) / (8 * ring) : 0);
}
