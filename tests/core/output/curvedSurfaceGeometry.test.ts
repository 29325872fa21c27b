/**
 * The drawn doubly curved surfaces (core/output/curvedSurfaceGeometry.ts) against their definitions
 * (shared/notes/doubly-curved-and-3-axis.md), checked by equations written here independently of
 * the module: the torus patch's points satisfy the torus's implicit equation (the feed circle
 * revolved about m), its curvatures have the signs of Rf and Rc (dome, bowl, saddle), its limits
 * are the cylinders and the plane to the last digit; the surface of revolution's points lie on the
 * meridian circle revolved about the vertical axis, and its feed lines are level (waterline passes).
 */
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../src/core/math/vec';
import {
  curvedAxisFoot,
  curvedHeightAboveMm,
  type RevolutionPatch,
  revolutionFrame,
  type TorusPatch,
  toMachine,
} from '../../../src/core/output/curvedSurfaceGeometry';
import { surfacePoint } from '../../../src/core/output/surfaceGeometry';

const INF = Number.POSITIVE_INFINITY;
const torus = (feedRadiusMm: number, crossRadiusMm: number): TorusPatch => ({
  kind: 'torus',
  feedRadiusMm,
  crossRadiusMm,
});

/** Dome, bowl, two saddles, a sphere, tight and flat radii (signed mm). */
const FAMILIES: ReadonlyArray<readonly [string, number, number]> = [
  ['dome', 10, 25],
  ['bowl', -12, -30],
  ['saddle (convex along the feed)', 10, -20],
  ['saddle (concave along the feed)', -15, 8],
  ['sphere', 7, 7],
  ['tight dome', 0.5, 0.8],
  ['flat saddle', 400, -600],
];

/** The residual of the offset torus's implicit equation at p (mm^2 scale divided out: mm). */
function torusResidualMm(rf: number, rc: number, h: number, p: Vec3): number {
  const [x, y, z] = p;
  // Distance from m (through (0, 0, -Rc) along X), measured towards the CC point's side.
  const rho = Math.hypot(y, z + rc);
  // The feed circle's centre F = (0, 0, -Rf) in the same half-plane coordinate, and its offset radius.
  const fCoord = Math.sign(rc) * (rc - rf);
  const radius = Math.abs(rf) + Math.sign(rf) * h;
  return Math.hypot(x, rho - fCoord) - radius;
}

describe('the torus patch of a doubly curved point', () => {
  for (const [name, rf, rc] of FAMILIES) {
    it(`${name} (Rf ${rf}, Rc ${rc}): every point of the patch and of its offsets lies on the torus`, () => {
      const s = torus(rf, rc);
      const reach = 0.9 * Math.min(Math.abs(rf), Math.abs(rc));
      let worst = 0;
      for (const h of [0, 0.05, 0.2 * Math.min(Math.abs(rf), Math.abs(rc))])
        for (let i = -4; i <= 4; i++)
          for (let j = -4; j <= 4; j++) {
            const p = surfacePoint(s, (i / 4) * reach, (j / 4) * reach, h);
            worst = Math.max(worst, Math.abs(torusResidualMm(rf, rc, h, p)));
            // The module's own inverse gives the offset back.
            expect(curvedHeightAboveMm(s, p)).toBeCloseTo(h, 9);
          }
      expect(worst).toBeLessThan(1e-12 * Math.max(Math.abs(rf), Math.abs(rc)) + 1e-13);
    });

    it(`${name}: the curvatures have the signs and sizes of Rf along X and Rc along Y`, () => {
      const s = torus(rf, rc);
      const d = 1e-3 * Math.min(Math.abs(rf), Math.abs(rc));
      // z(u, 0) = -u^2 / (2 Rf) + O(u^4), z(0, v) = -v^2 / (2 Rc) + O(v^4).
      const alongFeed = -(2 * surfacePoint(s, d, 0, 0)[2]) / (d * d);
      const across = -(2 * surfacePoint(s, 0, d, 0)[2]) / (d * d);
      expect(alongFeed * rf).toBeCloseTo(1, 5);
      expect(across * rc).toBeCloseTo(1, 5);
    });
  }

  it('the principal curves: the feed circle in Y = 0, the equator in X = 0 with the arc length across', () => {
    const s = torus(10, -20);
    const f = surfacePoint(s, 3, 0, 0);
    expect(f[1]).toBe(0);
    expect(Math.hypot(f[0], f[2] + 10)).toBeCloseTo(10, 12);
    const e = surfacePoint(s, 0, 5, 0);
    expect(e[0]).toBe(0);
    // Concave across: m at z = 20 above; the angle about it is the arc over |Rc|.
    expect(Math.atan2(e[1], 20 - e[2])).toBeCloseTo(5 / 20, 12);
  });

  it('infinite radii are the cylinders and the plane, to the last digit', () => {
    for (const [u, v, h] of [
      [0.7, -1.3, 0],
      [-2, 2.5, 0.05],
    ] as const) {
      expect(surfacePoint(torus(INF, 12), u, v, h)).toEqual(
        surfacePoint({ kind: 'cylinder', radiusMm: 12, axis: 'feed' }, u, v, h),
      );
      expect(surfacePoint(torus(-9, -INF), u, v, h)).toEqual(
        surfacePoint({ kind: 'cylinder', radiusMm: -9, axis: 'cross' }, u, v, h),
      );
      expect(surfacePoint(torus(INF, INF), u, v, h)).toEqual(surfacePoint({ kind: 'plane' }, u, v, h));
    }
  });

  it("the tool axis's foot lies on the patch and on the axis", () => {
    const s = torus(8, -15);
    const centre: Vec3 = [0.3, -0.2, 1.1];
    const axis: Vec3 = [0.1, 0.2, Math.sqrt(1 - 0.05)];
    const foot = curvedAxisFoot(s, centre, axis);
    expect(Math.abs(curvedHeightAboveMm(s, foot))).toBeLessThan(1e-12);
    const t = (centre[2] - foot[2]) / axis[2];
    expect(foot[0]).toBeCloseTo(centre[0] - t * axis[0], 12);
    expect(foot[1]).toBeCloseTo(centre[1] - t * axis[1], 12);
  });
});

describe('the surface of revolution of three-axis waterline passes', () => {
  const CASES: ReadonlyArray<readonly [string, RevolutionPatch]> = [
    ['dome', { kind: 'revolution', slopeDeg: 30, feedRadiusMm: 40, crossRadiusMm: 40 }],
    ['bowl', { kind: 'revolution', slopeDeg: 50, feedRadiusMm: -60, crossRadiusMm: -60 }],
    ['boss fillet (saddle)', { kind: 'revolution', slopeDeg: 70, feedRadiusMm: 25, crossRadiusMm: -6 }],
    ['cone (Rc straight)', { kind: 'revolution', slopeDeg: 45, feedRadiusMm: 30, crossRadiusMm: INF }],
    ['sloped plane', { kind: 'revolution', slopeDeg: 20, feedRadiusMm: INF, crossRadiusMm: INF }],
  ];
  for (const [name, s] of CASES) {
    it(`${name}: points lie on the meridian circle revolved about the vertical axis; feed lines are level`, () => {
      const a = (s.slopeDeg * Math.PI) / 180;
      const frame = revolutionFrame(s.slopeDeg);
      const rf = s.feedRadiusMm;
      const rc = s.crossRadiusMm;
      for (const h of [0, 0.1])
        for (const v of [-3, 0, 2.5]) {
          const level: number[] = [];
          for (const u of [-4, -1, 0, 2, 5]) {
            const p = surfacePoint(s, u, v, h);
            const m = toMachine(frame, p);
            level.push(m[2]);
            // Into the meridian plane y = 0 about the vertical x = Rf sin(a) (a translation when Rf is infinite).
            const xA = rf * Math.sin(a);
            const x = Number.isFinite(rf) ? xA - Math.sign(xA) * Math.hypot(m[0] - xA, m[1]) : m[0];
            // The meridian through the CC point: centre CC - Rc n, n = (-sin a, 0, cos a), radius |Rc| + sign(Rc) h.
            if (Number.isFinite(rc)) {
              const r = Math.hypot(x - rc * Math.sin(a), m[2] + rc * Math.cos(a));
              expect(r).toBeCloseTo(Math.abs(rc) + Math.sign(rc) * h, 10);
            } else expect(-Math.sin(a) * x + Math.cos(a) * m[2]).toBeCloseTo(h, 10);
            expect(curvedHeightAboveMm(s, p)).toBeCloseTo(h, 9);
          }
          // Along the feed the surface stays at one height: the passes are level (Z-level).
          for (const z of level) expect(z).toBeCloseTo(level[0] as number, 10);
        }
      // At the CC point the feed runs along X and the cross along Y, at unit speed (arc lengths).
      const d = 1e-6;
      for (const [p, e] of [
        [surfacePoint(s, d, 0, 0), [1, 0, 0]],
        [surfacePoint(s, 0, d, 0), [0, 1, 0]],
      ] as const)
        for (let k = 0; k < 3; k++) expect((p[k] as number) / d).toBeCloseTo(e[k] as number, 5);
    });
  }

  it('the local frame: X horizontal, Y down the slope, Z the normal at the slope', () => {
    const [X, Y, Z] = revolutionFrame(35);
    expect(X[2]).toBe(0);
    expect(Y[2]).toBeLessThan(0);
    expect(Z[2]).toBeCloseTo(Math.cos((35 * Math.PI) / 180), 15);
  });
});
