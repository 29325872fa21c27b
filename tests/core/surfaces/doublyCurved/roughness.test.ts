/**
 * Roughness at a doubly curved point (core/roughness/doublyCurved.ts) against independent
 * references: a ball end on a sphere, whose pass section in the cross-feed plane is the ball's own
 * disk (the swept ball is a torus about l, cut by its meridian plane), sampled here along the arc
 * and averaged by a fine midpoint rule (no integration by parts, no flank solver); the cylinder
 * limits (one radius infinite) against roughness.ts on cylinder.ts's solver; the target Ra's h
 * against the cylinder's.
 */
import { describe, expect, it } from 'vitest';
import { forwardInput, type PassPattern } from '../../../../src/core/input/validate';
import {
  doublyCurvedHeightForRaMm,
  doublyCurvedMaxRaMm,
  doublyCurvedRoughness,
  doublyCurvedRoughnessAtInterval,
} from '../../../../src/core/roughness/doublyCurved';
import { exactRoughness, scallopHeightForRaMm } from '../../../../src/core/roughness/roughness';
import { curvedForward, curvedInverse, curvedPoint } from '../../../../src/core/surfaces/doublyCurvedPoint';

const I = Number.POSITIVE_INFINITY;

/** Ra, Rq, Rz of a ball end's profile on a sphere at step-over L (sampled, see the module comment). */
function ballOnSphereRoughness(R: number, rs: number, L: number): { ra: number; rq: number; rz: number } {
  const a = Math.abs(rs);
  const D = rs > 0 ? a + R : a - R;
  const z = (s: number) => {
    const t = s / a;
    const root = Math.sqrt(R * R - D * D * Math.sin(t) ** 2);
    return rs > 0 ? D * Math.cos(t) - root - a : a - (D * Math.cos(t) + root);
  };
  // Half a period (the profile is symmetric): the contact to the cusp.
  const n = 400_000;
  const ds = L / 2 / n;
  const zs = new Float64Array(n);
  let sum = 0;
  let peak = 0;
  for (let i = 0; i < n; i++) {
    const v = z((i + 0.5) * ds);
    zs[i] = v;
    sum += v;
    peak = Math.max(peak, v);
  }
  const m = sum / n;
  let abs = 0;
  let sq = 0;
  for (const v of zs) {
    abs += Math.abs(v - m);
    sq += (v - m) ** 2;
  }
  return { ra: abs / n, rq: Math.sqrt(sq / n), rz: z(L / 2) };
}

describe('roughness at a doubly curved point', () => {
  it('a ball end on a sphere (convex and concave): Ra, Rq, Rz of the sampled circles within 1e-9 mm', () => {
    for (const rs of [40, -40, 8, -15]) {
      for (const pattern of ['one-way', 'zigzag'] as const) {
        const tool = { toolRadiusMm: 2, cornerRadiusMm: 2, leadAngleDeg: 20, tiltAngleDeg: 0 };
        const point = curvedPoint(tool, { feedRadiusMm: rs, crossRadiusMm: rs }, pattern);
        const e = curvedForward(point, 0.03);
        const r = doublyCurvedRoughness(point, e);
        const ref = ballOnSphereRoughness(2, rs, e.intervalMm);
        expect(Math.abs(r.raMm - ref.ra), `${rs} ${pattern}`).toBeLessThan(1e-9);
        expect(Math.abs(r.rqMm - ref.rq), `${rs} ${pattern}`).toBeLessThan(1e-9);
        expect(Math.abs(r.rzMm - ref.rz), `${rs} ${pattern}`).toBeLessThan(1e-9);
        const back = doublyCurvedRoughnessAtInterval(point, curvedInverse(point, e.intervalMm));
        expect(Math.abs(back.raMm - ref.ra)).toBeLessThan(1e-9);
      }
    }
  });

  it('one radius infinite: the cylinders of roughness.ts (tilted bull-nose, both patterns) within 1e-12 mm; both: the plane', () => {
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 7 };
    const cases = [
      [I, 50, { kind: 'cylinder', radiusMm: 50, axis: 'feed' }],
      [I, -70, { kind: 'cylinder', radiusMm: -70, axis: 'feed' }],
      [30, I, { kind: 'cylinder', radiusMm: 30, axis: 'cross' }],
      [-90, I, { kind: 'cylinder', radiusMm: -90, axis: 'cross' }],
      [I, I, undefined],
    ] as const;
    for (const [rf, rc, surface] of cases) {
      for (const pattern of ['one-way', 'zigzag'] as const) {
        const point = curvedPoint(tool, { feedRadiusMm: rf, crossRadiusMm: rc }, pattern);
        const r = doublyCurvedRoughness(point, curvedForward(point, 0.04));
        const c = exactRoughness(forwardInput(tool, pattern, 0.04, surface));
        expect(Math.abs(r.raMm - c.raMm), `${rf} ${rc} ${pattern}`).toBeLessThan(1e-12);
        expect(Math.abs(r.rqMm - c.rqMm), `${rf} ${rc} ${pattern}`).toBeLessThan(1e-12);
        expect(Math.abs(r.rzMm - c.rzMm), `${rf} ${rc} ${pattern}`).toBeLessThan(1e-12);
      }
    }
  });

  it('a target Ra: the h found leaves it (doubly curved), and on a cylinder it is the cylinder target h', () => {
    const tool = { toolRadiusMm: 4, cornerRadiusMm: 0.8, leadAngleDeg: 6, tiltAngleDeg: -12 };
    for (const pattern of ['one-way', 'zigzag'] as PassPattern[]) {
      for (const [rf, rc] of [
        [40, 90],
        [-60, -120],
        [35, -200],
      ]) {
        const radii = { feedRadiusMm: rf as number, crossRadiusMm: rc as number };
        const point = curvedPoint(tool, radii, pattern);
        const max = doublyCurvedMaxRaMm(point);
        const target = 0.3 * max;
        const h = doublyCurvedHeightForRaMm(point, target);
        const ra = doublyCurvedRoughness(point, curvedForward(point, h)).raMm;
        expect(Math.abs(ra - target) / target, `${rf} ${rc} ${pattern}`).toBeLessThan(1e-12);
      }
      const cyl = { feedRadiusMm: I, crossRadiusMm: 45 };
      const target = 0.2 * doublyCurvedMaxRaMm(curvedPoint(tool, cyl, pattern));
      const h = doublyCurvedHeightForRaMm(curvedPoint(tool, cyl, pattern), target);
      const hc = scallopHeightForRaMm(tool, pattern, target, { kind: 'cylinder', radiusMm: 45, axis: 'feed' });
      expect(Math.abs(h - hc) / hc).toBeLessThan(1e-10);
    }
  });
});
