import { describe, expect, it } from 'vitest';
import { forwardInput, type ToolInput } from '../../../src/core/input/validate';
import { passGeometry } from '../../../src/core/output/geometry';
import { traceProcedure } from '../../../src/core/procedures/trace';
import { exactForward } from '../../../src/core/surfaces/solve';
import { scallopHeightLimits } from '../../../src/core/surfaces/validate';
import { type Placement, placeTool } from '../../../src/core/tool/placement';
import { seededRandom } from '../../support/bruteForce';

/** Distance (mm) from a point to the surface of the placed tool's torus (ring radius Rb, tube Rcr). */
function torusDistanceMm(p: Placement, q: ArrayLike<number>, i = 0): number {
  const dx = (q[i] as number) - p.centre[0];
  const dy = (q[i + 1] as number) - p.centre[1];
  const dz = (q[i + 2] as number) - p.centre[2];
  const w = dx * p.axis[0] + dy * p.axis[1] + dz * p.axis[2];
  const radial = Math.hypot(dx - w * p.axis[0], dy - w * p.axis[1], dz - w * p.axis[2]);
  return Math.abs(Math.hypot(radial - p.ringRadiusMm, w) - p.cornerRadiusMm);
}

/** A valid tool of a stratum and a height of its range. */
function drawCase(rand: () => number, k: number): { tool: ToolInput; h: number } {
  const R = 10 ** (-2 + 4 * rand());
  const kinds = [
    () => 1e-3 * R * rand(), // small corner: the narrow bands the old 180-step scan missed
    () => R * rand(),
    () => R * (0.999 + 0.001 * rand()), // nearly a ball
  ];
  const Rcr = (kinds[k % 3] as () => number)();
  const rho = [0.5 + 20 * rand(), 60 + 29.9 * rand(), 89 + rand() * 0.99][k % 3] as number;
  const tilt = [0, 40 * rand() - 20, 80 * rand() - 40][(k >> 1) % 3] as number;
  const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt };
  const limit = scallopHeightLimits(tool).limitMm;
  return { tool, h: limit * ([1e-6, 0.01, 0.3, 0.97][k % 4] as number) };
}

describe('the geometry a viewer draws', () => {
  for (const seed of [81, 82, 83]) {
    it(`seed ${seed}: loops lie on the torus and the plane and reach both cusps; sections pass through P_hp`, () => {
      const rand = seededRandom(seed);
      let loopsChecked = 0;
      for (let k = 0; k < 24; k++) {
        const { tool, h } = drawCase(rand, k);
        if (!(h >= 1e-9) || tool.cornerRadiusMm === 0) continue;
        const e = exactForward(forwardInput(tool, 'one-way', h));
        const g = passGeometry(tool, h, h, 96);
        const p = placeTool(tool);
        const R = tool.toolRadiusMm;
        const label = JSON.stringify({ tool, h });
        // P_hp at the cusp height, on the torus, on its section circle, at the flank widths.
        for (const [s, w, sign] of [
          [g.right, e.halfWidthRightMm, 1],
          [g.left, e.halfWidthLeftMm, -1],
        ] as const) {
          expect(torusDistanceMm(p, s.pHp), `P_hp on torus ${label}`).toBeLessThan(1e-9 * R);
          expect(Math.abs(s.pHp[2] - h), label).toBeLessThan(1e-9 * R);
          expect(Math.abs(sign * s.pHp[1] - w), label).toBeLessThan(1e-9 * R);
          const d = [s.pHp[0] - s.sectionCentre[0], s.pHp[1] - s.sectionCentre[1], s.pHp[2] - s.sectionCentre[2]];
          expect(Math.abs(Math.hypot(d[0] as number, d[1] as number, d[2] as number) - s.sectionRadiusMm)).toBeLessThan(
            1e-9 * R,
          );
          const n = s.sectionNormal;
          expect(Math.abs((d[0] as number) * n[0] + (d[1] as number) * n[1] + (d[2] as number) * n[2])).toBeLessThan(
            1e-9 * R,
          );
        }
        // Every loop point on both surfaces; together the loops reach +wR and -wL.
        expect(g.loopsRight.length, `loops ${label}`).toBeGreaterThan(0);
        let maxY = Number.NEGATIVE_INFINITY;
        let minY = Number.POSITIVE_INFINITY;
        for (const loop of g.loopsRight) {
          for (let i = 0; i < loop.length; i += 3) {
            expect(torusDistanceMm(p, loop, i), `loop point on torus ${label}`).toBeLessThan(1e-9 * R);
            expect(Math.abs((loop[i + 2] as number) - h)).toBeLessThan(1e-9 * R);
            maxY = Math.max(maxY, loop[i + 1] as number);
            minY = Math.min(minY, loop[i + 1] as number);
          }
        }
        expect(Math.abs(maxY - e.halfWidthRightMm), `reach right ${label}`).toBeLessThan(1e-6 * R);
        expect(Math.abs(-minY - e.halfWidthLeftMm), `reach left ${label}`).toBeLessThan(1e-6 * R);
        loopsChecked++;
      }
      expect(loopsChecked).toBeGreaterThanOrEqual(20);
    });
  }

  it('issue 7, defect 3: the cases the old scan missed or under-sampled', () => {
    for (const [R, Rcr, rho, h] of [
      [3, 0.003, 10, 0.3],
      [3, 2.999, 89, 2.95],
    ] as const) {
      const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: 0 };
      const e = exactForward(forwardInput(tool, 'one-way', h));
      const g = passGeometry(tool, h, h, 96);
      const ys = g.loopsRight.flatMap((l) => Array.from(l).filter((_, i) => i % 3 === 1));
      expect(Math.abs(Math.max(...ys) - e.halfIntervalMm)).toBeLessThan(1e-6 * R);
    }
  });

  it('issue 7, defect 2: a ball end draws the section through P_hp (any posture)', () => {
    for (const tilt of [0, 25]) {
      const tool = { toolRadiusMm: 3, cornerRadiusMm: 3, leadAngleDeg: 20, tiltAngleDeg: tilt };
      const g = passGeometry(tool, 0.05, 0.05, 32);
      for (const s of [g.right, g.left]) {
        const d = [s.pHp[0] - s.sectionCentre[0], s.pHp[1] - s.sectionCentre[1], s.pHp[2] - s.sectionCentre[2]];
        expect(Math.abs(Math.hypot(d[0] as number, d[1] as number, d[2] as number) - 3)).toBeLessThan(1e-12);
        const n = s.sectionNormal;
        // The section's plane contains the axis and P_hp.
        expect(Math.abs((d[0] as number) * n[0] + (d[1] as number) * n[1] + (d[2] as number) * n[2])).toBeLessThan(
          1e-12,
        );
        const a = placeTool(tool).axis;
        expect(Math.abs(a[0] * n[0] + a[1] * n[1] + a[2] * n[2])).toBeLessThan(1e-12);
      }
    }
  });
});

describe('the trace of the paper procedure, stratified', () => {
  for (const seed of [91, 92]) {
    it(`seed ${seed}: agrees with the exact flanks to 1e-9 mm on every stratum, incl. h/R down to 1e-9`, () => {
      const rand = seededRandom(seed);
      for (let k = 0; k < 24; k++) {
        const { tool, h } = drawCase(rand, k);
        if (!(h >= 1e-9)) continue;
        const e = exactForward(forwardInput(tool, 'one-way', h));
        const t = traceProcedure(forwardInput(tool, 'one-way', h));
        expect(Math.abs(t.right.widthMm - e.halfWidthRightMm), JSON.stringify({ tool, h })).toBeLessThan(1e-9);
        expect(Math.abs(t.left.widthMm - e.halfWidthLeftMm), JSON.stringify({ tool, h })).toBeLessThan(1e-9);
      }
    });
  }

  it('issue 7, defect 4: R 500, Rcr 300, rho 0.0001, h 1e-9', () => {
    const input = forwardInput(
      { toolRadiusMm: 500, cornerRadiusMm: 300, leadAngleDeg: 0.0001, tiltAngleDeg: 0 },
      'one-way',
      1e-9,
    );
    expect(Math.abs(traceProcedure(input).right.widthMm - exactForward(input).halfWidthRightMm)).toBeLessThan(1e-9);
  });
});
