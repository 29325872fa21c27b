/**
 * The 3D scene's data for a doubly curved point and for three-axis machining (worker/data/curvedScene.ts,
 * through the worker's jobs), checked against the definitions: the drawn cusps stand at the solver's
 * cusp height on the offset surface and on the boundary of both neighbouring passes' swept sections
 * (sampled by brute force); in the machine frame the tool is upright, the tools do not reach into the
 * surface, the dimension lines measure the solver's Lxy and dz between the right points (the tool
 * tips' heights for dz).
 */
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../src/core/math/vec';
import {
  type CurvedPatch,
  curvedHeightAboveMm,
  revolutionFrame,
  toMachine,
} from '../../src/core/output/curvedSurfaceGeometry';
import { applyMatrix, surfacePoint } from '../../src/core/output/surfaceGeometry';
import { passSection } from '../../src/core/surfaces/doublyCurved/passSection';
import type { ThreeAxisProblem } from '../../src/core/threeAxis/validate';
import { solveCurved } from '../../src/worker/jobs/curved';
import { solveThreeAxisRequest } from '../../src/worker/jobs/threeAxis';
import type { SceneGeometry } from '../../src/worker/protocol';

type Frame = readonly [Vec3, Vec3, Vec3];
const frameOf = (g: SceneGeometry): Frame => {
  const m = g.machine?.frameMatrix as number[];
  return [
    [m[0] as number, m[1] as number, m[2] as number],
    [m[4] as number, m[5] as number, m[6] as number],
    [m[8] as number, m[9] as number, m[10] as number],
  ];
};

/** Distance (mm) from (y, z) in the plane X = 0 to the curve of a pass's lowest ball centres, by 40001 samples. */
function distanceToCentres(section: ReturnType<typeof passSection>, y: number, z: number): number {
  let best = Number.POSITIVE_INFINITY;
  const n = 40000;
  for (let i = 0; i <= n; i++) {
    const t = section.yLoMm + ((section.yHiMm - section.yLoMm) * i) / n;
    best = Math.min(best, Math.hypot(t - y, section.lowestCentreMm(t) - z));
  }
  return best;
}

const TOOL = { toolRadiusMm: 3, cornerRadiusMm: 1 };

describe('a doubly curved point: the cusps drawn', () => {
  const CASES = [
    ['dome, one-way, tilted', 40, 25, 'one-way', 5, 4],
    ['bowl, zigzag, tilted', -60, -45, 'zigzag', 8, -6],
    ['saddle, one-way', 30, -50, 'one-way', 10, 0],
    ['sphere, zigzag', 20, 20, 'zigzag', 0, 0],
  ] as const;
  for (const [name, rf, rc, pattern, lead, tilt] of CASES)
    it(`${name}: at the solver's height on the offset surface, on the boundary of both passes' sections`, () => {
      const input = {
        ...TOOL,
        leadAngleDeg: lead,
        tiltAngleDeg: tilt,
        pattern,
        feedRadiusMm: rf,
        crossRadiusMm: rc,
        scallopHeightMm: 0.05,
      };
      const reply = solveCurved({ mode: 'curved-forward', input });
      if (!reply.ok) throw new Error(JSON.stringify(reply.errors));
      const g = reply.scene;
      expect(g.surface).toEqual({ kind: 'torus', feedRadiusMm: rf, crossRadiusMm: rc });
      expect(g.machine).toBeNull();
      const e = reply.exact;
      const heights = [
        e.pattern === 'one-way' || e.halfWidthRightMm <= e.halfWidthLeftMm ? e.cuspHeightMm : e.otherCuspHeightMm,
        e.pattern === 'one-way' || e.halfWidthLeftMm <= e.halfWidthRightMm ? e.cuspHeightMm : e.otherCuspHeightMm,
      ];
      const section = passSection(input, rf);
      const phi = e.intervalMm / Math.abs(rc);
      const points = [g.cuspPoints?.right, g.cuspPoints?.left];
      points.forEach((p, i) => {
        if (!p) throw new Error('a cusp point');
        const s: CurvedPatch = g.surface as CurvedPatch;
        // In the cross-feed plane through the CC point, at the solver's (radial) height.
        expect(p[0]).toBe(0);
        expect(curvedHeightAboveMm(s, p)).toBeCloseTo(heights[i] as number, 9);
        // On this pass's section (ball centres Rcr away) ...
        expect(distanceToCentres(section, p[1], p[2])).toBeCloseTo(TOOL.cornerRadiusMm, 5);
        // ... and on the neighbour's: turned back about m (through (0, 0, -Rc)) by its angle, mirrored for zigzag.
        const turn = (i === 0 ? 1 : -1) * phi * Math.sign(rc);
        const c = Math.cos(turn);
        const sn = Math.sin(turn);
        const qz = p[2] + rc;
        const y = c * p[1] - sn * qz;
        const z = sn * p[1] + c * qz - rc;
        const mirrored = pattern === 'zigzag' ? -y : y;
        expect(distanceToCentres(section, mirrored, z)).toBeCloseTo(TOOL.cornerRadiusMm, 5);
      });
    });
});

/** A three-axis request at h = 0.05 mm (tool R 3, Rcr 1). */
function threeAxis(input: ThreeAxisProblem) {
  const reply = solveThreeAxisRequest({ mode: 'three-axis', input });
  if (!reply.ok || reply.scene === null) throw new Error('a scene');
  return { reply, g: reply.scene };
}

describe('three-axis machining: the scene in the machine frame', () => {
  for (const [passes, psi] of [
    ['raster', 0],
    ['raster', 40],
    ['waterline', 90],
  ] as const)
    it(`sloped plane (30 degrees), ${passes} at ${psi}: the tool upright, the step as programmed`, () => {
      const { reply, g } = threeAxis({
        surface: 'plane',
        case: { ...TOOL, slopeDeg: 30, passes, rasterAngleDeg: psi },
        quantity: 'h',
        mm: 0.05,
      });
      const f = frameOf(g);
      const axis = toMachine(f, g.toolAxis);
      expect(axis[2]).toBeCloseTo(1, 12);
      const step = g.machine?.step;
      if (!step) throw new Error('a step');
      const n = step.points.length / 3;
      const at = (k: number) =>
        toMachine(f, [step.points[3 * k], step.points[3 * k + 1], step.points[3 * k + 2]] as Vec3);
      // The dimension's line: the second point to the eighth (extension, line, arrowheads; see machineGeometry.ts).
      const s = at(1);
      const e = at(6);
      if (passes === 'raster') {
        expect(step.kind).toBe('horizontal');
        expect(e[2]).toBeCloseTo(s[2], 12);
        expect(Math.hypot(e[0] - s[0], e[1] - s[1])).toBeCloseTo(reply.answer.horizontalStepMm, 12);
      } else {
        expect(step.kind).toBe('vertical');
        // From this pass's tool tip to the next one's, their heights dz apart.
        const tip = toMachine(f, [
          g.toolCentre[0] - g.cornerRadiusMm * g.toolAxis[0],
          g.toolCentre[1] - g.cornerRadiusMm * g.toolAxis[1],
          g.toolCentre[2] - g.cornerRadiusMm * g.toolAxis[2],
        ]);
        expect(at(0)[2]).toBeCloseTo(tip[2], 12);
        expect(s[2]).toBeCloseTo(tip[2], 12);
        expect(Math.abs(e[2] - s[2])).toBeCloseTo(reply.answer.stepDownMm as number, 12);
        expect(at(n - 1)[2]).toBeCloseTo(e[2], 12);
      }
      expect(g.machine?.passMatrices).toHaveLength(1);
      expect(g.machine?.pathOffsetsMm).toEqual([0, reply.answer.intervalMm]);
    });

  const REVOLUTIONS = [
    ['dome', 45, 40, 40],
    ['bowl', 35, -50, -50],
    ['boss fillet', 60, 20, -8],
  ] as const;
  for (const [name, slope, rf, rc] of REVOLUTIONS)
    it(`${name} (slope ${slope}), waterline: upright tools clear of the surface, dz between their tips, the cusp at h`, () => {
      const { reply, g } = threeAxis({
        surface: 'revolution',
        case: { ...TOOL, slopeDeg: slope, feedRadiusMm: rf, crossRadiusMm: rc },
        quantity: 'h',
        mm: 0.05,
      });
      const f = frameOf(g);
      const s = g.surface as CurvedPatch;
      expect(s.kind).toBe('revolution');
      expect(toMachine(f, g.toolAxis)[2]).toBeCloseTo(1, 12);
      const next = g.machine?.passMatrices[0] as number[];
      // The drawn surface L down the meridian is the solver's next CC point (meridian plane: s down-slope, z up).
      const cc1 = reply.waterline?.geometry.cc1 as readonly [number, number];
      const onSurface = toMachine(revolutionFrame(slope), surfacePoint(s, 0, reply.answer.intervalMm, 0));
      for (const [k, want] of [
        [0, -cc1[0]],
        [1, 0],
        [2, cc1[1]],
      ] as const)
        expect(onSurface[k]).toBeCloseTo(want, 12);
      // Neither tool reaches into the surface (every vertex of the drawn tools on the tool's side).
      let lowest = Number.POSITIVE_INFINITY;
      for (let i = 0; i < g.toolPositions.length; i += 3) {
        const p: Vec3 = [
          g.toolPositions[i] as number,
          g.toolPositions[i + 1] as number,
          g.toolPositions[i + 2] as number,
        ];
        lowest = Math.min(lowest, curvedHeightAboveMm(s, p), curvedHeightAboveMm(s, applyMatrix(next, p)));
      }
      expect(lowest).toBeGreaterThan(-1e-6);
      // The cusp at the solver's height along the normal.
      const cusp = g.cuspPoints?.right as Vec3;
      expect(curvedHeightAboveMm(s, cusp)).toBeCloseTo(reply.answer.cuspHeightMm, 9);
      // dz: its ends at the two tool tips' heights.
      const step = g.machine?.step;
      if (!step) throw new Error('a step');
      const at = (k: number) =>
        toMachine(f, [step.points[3 * k], step.points[3 * k + 1], step.points[3 * k + 2]] as Vec3);
      const tip0 = toMachine(f, [
        g.toolCentre[0] - g.cornerRadiusMm * g.toolAxis[0],
        g.toolCentre[1] - g.cornerRadiusMm * g.toolAxis[1],
        g.toolCentre[2] - g.cornerRadiusMm * g.toolAxis[2],
      ]);
      const tip1 = toMachine(f, applyMatrix(next, toLocalTip(g)));
      expect(at(1)[2]).toBeCloseTo(tip0[2], 12);
      expect(at(6)[2]).toBeCloseTo(tip1[2], 12);
      expect(at(1)[2] - at(6)[2]).toBeCloseTo(reply.answer.stepDownMm as number, 9);
      expect(reply.waterline?.geometry.tip0[1]).toBeCloseTo(tip0[2], 12);
    });
});

/** The tool tip in the local frame. */
function toLocalTip(g: SceneGeometry): Vec3 {
  return [
    g.toolCentre[0] - g.cornerRadiusMm * g.toolAxis[0],
    g.toolCentre[1] - g.cornerRadiusMm * g.toolAxis[1],
    g.toolCentre[2] - g.cornerRadiusMm * g.toolAxis[2],
  ];
}
