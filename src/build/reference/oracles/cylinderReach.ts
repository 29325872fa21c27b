/**
 * Polished brute-force flanks of a filleted end mill on a cylinder, from the 3D tool surface alone.
 * It shares nothing with src/core (no projected ellipse, no section parametrisation, no placement):
 * the tool is built here from its axis, and every answer is a constrained maximum over sampled and
 * then refined points of its surface.
 *
 * Tool (conventions of notes/posture-and-surfaces.md): axis `a = (cos b sin r, sin b, cos b cos r)`,
 * the ring of corner centres (radius Rb = R - Rcr, centre O, normal a) grown by a ball of radius Rcr,
 * and optionally the shank (the cylinder of radius R on axial 0..shankLength above O). The contact
 * is the tool's lowest point (the design surface's normal is Z there): the lowest point of the ring's
 * disk, less Rcr Z; it is put at the origin. The cylinder's axis runs along X (axis = feed) or Y
 * (axis = cross) through (z = -Rs).
 *
 * A flank at radial height h: one pass leaves, at each polar angle about the axis (feed; a pass
 * translates the tool along the axis) or each position along the axis (cross; a pass turns the tool
 * about it), the tool's nearest radius (convex) or farthest one (concave). The flank at h is the
 * farthest angle (or position) out from the contact at which some tool point lies at radial height
 * h or below (`height(P) = d(P) - Rs` convex, `|Rs| - d(P)` concave, d the distance from the axis):
 *
 *   reach(h) = max { sign * obj(P) : P on the tool, height(P) <= h }
 *
 * with obj the polar angle from the contact's direction (feed) or Y (cross). The maximum lies on
 * the tool's surface (inside the tool, turning about the axis or sliding along it keeps the height
 * and moves obj), so it is sought over the surface's patches: the torus's outer half (the lower
 * quarter with the shank), the bottom disk (and the top disk without the shank) and the shank,
 * each swept by ring angle t and a second parameter v. For each t: samples of v, bisection of every
 * change of feasibility and golden section around the best feasible sample; over t: samples, then
 * golden section around the three best local maxima.
 *
 * Error: the maximum's value is found to about 1e-15 relative (a maximum's value is second-order
 * insensitive to its argument; at a crossing the bisection is run to the last bit); measured
 * against closed forms in tests/support/reference.test.ts. Cost: about 10-40 ms per reach.
 */
import { goldenSection } from './goldenSection';

export interface CylinderReachTool {
  readonly toolRadiusMm: number;
  readonly cornerRadiusMm: number;
  readonly leadAngleDeg: number;
  readonly tiltAngleDeg: number;
}

export interface CylinderReachOptions {
  /** Samples of the ring angle t (default 720). */
  readonly ringSamples?: number;
  /** Samples along each patch's second parameter (default 48). */
  readonly patchSamples?: number;
  /** Length of the shank above the ring's plane, mm (default 3 R). */
  readonly shankLengthMm?: number;
}

export interface CylinderReachReference {
  /**
   * How far a flank reaches at radial height h: polar angle about the axis from the contact (feed,
   * radians) or distance along the axis from the contact (cross, mm); -Infinity when no tool point
   * lies that low. `withShank` includes the shank (up to shankLengthMm).
   */
  reach(flank: 'right' | 'left', heightMm: number, withShank: boolean): number;
  /** The tool point (x, y, z relative to the contact) that carries the last reach, and its patch. */
  lastArgMax(): { readonly point: readonly [number, number, number]; readonly patch: string };
}

type Vec = [number, number, number];

/** Golden-section maximum of f on [a, b]; returns the best value and argument seen. */
function golden(f: (x: number) => number, a0: number, b0: number, iterations = 90): { x: number; v: number } {
  // The best value seen: f at the first c, then at each new point (the first d only at the end).
  let best = { x: Number.NaN, v: Number.NaN };
  let asked = 0;
  const negated = (x: number): number => {
    const v = f(x);
    if (asked === 0 || (asked > 1 && v > best.v)) best = { x, v };
    asked++;
    return -v;
  };
  const bracket = goldenSection(negated, a0, b0, iterations, 1e-17, 0);
  const [d, fd] = [bracket.d, -bracket.fd];
  if (fd > best.v) best = { x: d, v: fd };
  return best;
}

/** The reference for a tool on a cylinder of signed radius `rs` (convex > 0) with its axis along `axis`. */
export function cylinderReach(
  tool: CylinderReachTool,
  rs: number,
  axis: 'feed' | 'cross',
  options: CylinderReachOptions = {},
): CylinderReachReference {
  const R = tool.toolRadiusMm;
  const rcr = tool.cornerRadiusMm;
  const rb = R - rcr;
  const nT = options.ringSamples ?? 720;
  const nV = options.patchSamples ?? 48;
  const shankLength = options.shankLengthMm ?? 3 * R;
  const rho = (tool.leadAngleDeg * Math.PI) / 180;
  const beta = (tool.tiltAngleDeg * Math.PI) / 180;
  const a: Vec = [Math.cos(beta) * Math.sin(rho), Math.sin(beta), Math.cos(beta) * Math.cos(rho)];
  // The ring's lowest direction: -Z projected on the ring's plane (none when the ring lies flat);
  // 1 - a_z^2 written a_x^2 + a_y^2, which keeps a lead of 1e-9 degrees.
  const zp: Vec = [-a[2] * a[0], -a[2] * a[1], a[0] * a[0] + a[1] * a[1]];
  const zn = Math.hypot(zp[0], zp[1], zp[2]);
  const flat = !(zn > 0);
  const e1: Vec = flat ? [1, 0, 0] : [-zp[0] / zn, -zp[1] / zn, -zp[2] / zn];
  const e2: Vec = [a[1] * e1[2] - a[2] * e1[1], a[2] * e1[0] - a[0] * e1[2], a[0] * e1[1] - a[1] * e1[0]];
  // O = -Rb e1 + Rcr Z puts the contact (O + Rb e1 - Rcr Z) at the origin; a flat ring touches
  // with its whole disk, whose centre is taken as the contact.
  const O: Vec = flat ? [0, 0, rcr] : [-rb * e1[0], -rb * e1[1], -rb * e1[2] + rcr];
  const side = rs > 0 ? 1 : -1;
  const abs = Math.abs(rs);

  const p: Vec = [0, 0, 0];
  /** A patch of the surface: t the ring angle, v in [v0, v1]. */
  type Patch = { name: string; v0: number; v1: number; at: (t: number, v: number, out: Vec) => void };
  const radial = (t: number, out: Vec) => {
    const c = Math.cos(t);
    const s = Math.sin(t);
    out[0] = c * e1[0] + s * e2[0];
    out[1] = c * e1[1] + s * e2[1];
    out[2] = c * e1[2] + s * e2[2];
  };
  const r: Vec = [0, 0, 0];
  /** The point at `radius` from the tool axis towards ring angle t, `axial` up the axis from O. */
  const ringPoint = (t: number, radius: number, axial: number, out: Vec) => {
    radial(t, r);
    out[0] = O[0] + radius * r[0] + axial * a[0];
    out[1] = O[1] + radius * r[1] + axial * a[1];
    out[2] = O[2] + radius * r[2] + axial * a[2];
  };
  const torus = (psiTop: number): Patch => ({
    name: 'torus',
    v0: -Math.PI / 2,
    v1: psiTop,
    at(t, psi, out) {
      ringPoint(t, rb + rcr * Math.cos(psi), rcr * Math.sin(psi), out);
    },
  });
  const disk = (axial: number, name: string): Patch => ({
    name,
    v0: 0,
    v1: rb,
    at(t, s, out) {
      ringPoint(t, s, axial, out);
    },
  });
  const shank: Patch = {
    name: 'shank',
    v0: 0,
    v1: shankLength,
    at(t, u, out) {
      ringPoint(t, R, u, out);
    },
  };
  const endPatches: Patch[] = [torus(Math.PI / 2), disk(-rcr, 'bottom'), disk(rcr, 'top')];
  const fullPatches: Patch[] = [torus(0), disk(-rcr, 'bottom'), shank];

  // Radial height above the design surface, without cancellation: (d^2 - Rs^2) / (d + |Rs|).
  const heightOf = (q: Vec): number => {
    const u = axis === 'feed' ? q[1] : q[0];
    return (side * (u * u + q[2] * (q[2] + 2 * rs))) / (Math.sqrt(u * u + (q[2] + rs) * (q[2] + rs)) + abs);
  };
  const objOf = (q: Vec): number => (axis === 'feed' ? Math.atan2(q[1], side * (q[2] + rs)) : q[1]);

  let argPoint: Vec = [0, 0, 0];
  let argPatch = '';

  const reach = (flank: 'right' | 'left', h: number, withShank: boolean): number => {
    const sign = flank === 'right' ? 1 : -1;
    const patches = withShank ? fullPatches : endPatches;
    let bestPatch = '';
    const bestPoint: Vec = [0, 0, 0];
    // Value of a point: sign * obj when it lies at height h or below, else -Infinity.
    const value = (patch: Patch, t: number, v: number): number => {
      patch.at(t, v, p);
      return heightOf(p) <= h ? sign * objOf(p) : Number.NEGATIVE_INFINITY;
    };
    const heightAt = (patch: Patch, t: number, v: number): number => {
      patch.at(t, v, p);
      return heightOf(p);
    };
    // Best feasible value along v at ring angle t on one patch.
    const along = (patch: Patch, t: number): { v: number; x: number } => {
      const { v0, v1 } = patch;
      const step = (v1 - v0) / nV;
      const grid = (i: number) => (i >= nV ? v1 : v0 + Math.max(0, i) * step);
      let bestV = Number.NEGATIVE_INFINITY;
      let bestX = v0;
      const consider = (v: number): number => {
        const f = value(patch, t, v);
        if (f > bestV) {
          bestV = f;
          bestX = v;
        }
        return f;
      };
      // The feasible end of a change of feasibility, bisected to the last bit.
      const crossing = (good: number, bad: number): number => {
        let lo = good;
        let hi = bad;
        for (let k = 0; k < 200; k++) {
          const mid = 0.5 * (lo + hi);
          if (mid === lo || mid === hi) break;
          if (heightAt(patch, t, mid) <= h) lo = mid;
          else hi = mid;
        }
        consider(lo);
        return lo;
      };
      let bestI = -1;
      let lowI = 0;
      let lowH = Number.POSITIVE_INFINITY;
      let prevFeasible = false;
      for (let i = 0; i <= nV; i++) {
        const v = grid(i);
        const height = heightAt(patch, t, v);
        if (height < lowH) {
          lowH = height;
          lowI = i;
        }
        const before = bestV;
        const feasible = consider(v) > Number.NEGATIVE_INFINITY;
        if (bestV > before) bestI = i;
        if (i > 0 && feasible !== prevFeasible) crossing(feasible ? v : grid(i - 1), feasible ? grid(i - 1) : v);
        prevFeasible = feasible;
      }
      // The lowest point along v (golden section on the height around the lowest sample): at a small
      // h the feasible set is a speck that can fall between grid points. Its window, bisected, and
      // the best value inside.
      const lo = grid(lowI - 1);
      const hi = grid(lowI + 1);
      const low = golden((v) => -heightAt(patch, t, v), lo, hi).x;
      if (heightAt(patch, t, low) <= h) {
        consider(low);
        const wl = heightAt(patch, t, lo) <= h ? lo : crossing(low, lo);
        const wr = heightAt(patch, t, hi) <= h ? hi : crossing(low, hi);
        if (wr > wl) {
          const g = golden((v) => value(patch, t, v), wl, wr);
          if (g.v > bestV) {
            bestV = g.v;
            bestX = g.x;
          }
        }
      }
      if (bestI >= 0) {
        const g = golden((v) => value(patch, t, v), grid(bestI - 1), grid(bestI + 1));
        if (g.v > bestV) {
          bestV = g.v;
          bestX = g.x;
        }
      }
      return { v: bestV, x: bestX };
    };
    let best = Number.NEGATIVE_INFINITY;
    for (const patch of patches) {
      const ringValue = (t: number) => along(patch, t).v;
      const dt = (2 * Math.PI) / nT;
      const samples = new Float64Array(nT);
      for (let i = 0; i < nT; i++) samples[i] = ringValue(i * dt);
      // The three best local maxima of the samples (the ring is periodic).
      const peaks: number[] = [];
      for (let i = 0; i < nT; i++) {
        const v = samples[i] as number;
        if (v === Number.NEGATIVE_INFINITY) continue;
        if (v >= (samples[(i + nT - 1) % nT] as number) && v >= (samples[(i + 1) % nT] as number)) peaks.push(i);
      }
      peaks.sort((m, n) => (samples[n] as number) - (samples[m] as number));
      for (const i of peaks.slice(0, 3)) {
        // Between the neighbouring samples, narrowed to where some point is low enough (at tiny h
        // a speck around the contact, which golden section alone would step over).
        const edge = (bad: number) => {
          if (ringValue(bad) > Number.NEGATIVE_INFINITY) return bad;
          let good = i * dt;
          let out = bad;
          for (let k = 0; k < 200; k++) {
            const mid = 0.5 * (good + out);
            if (mid === good || mid === out) break;
            if (ringValue(mid) > Number.NEGATIVE_INFINITY) good = mid;
            else out = mid;
          }
          return good;
        };
        const g = golden(ringValue, edge((i - 1) * dt), edge((i + 1) * dt));
        const v = Math.max(g.v, samples[i] as number);
        if (v > best) {
          best = v;
          const t = g.v >= (samples[i] as number) ? g.x : i * dt;
          patch.at(t, along(patch, t).x, bestPoint);
          bestPatch = patch.name;
        }
      }
    }
    argPoint = [bestPoint[0], bestPoint[1], bestPoint[2]];
    argPatch = bestPatch;
    return best;
  };

  return { reach, lastArgMax: () => ({ point: argPoint, patch: argPatch }) };
}
