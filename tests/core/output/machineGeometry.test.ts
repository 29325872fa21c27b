/**
 * The machine frame of three-axis machining and the programmed steps' dimension lines
 * (core/output/machineGeometry.ts): the frame is a rotation whose vertical, seen from the CC point,
 * is core slopePosture's tool axis; `Lxy` is a horizontal line from this pass's vertical plane to the
 * next one's, as long as slopePosture's `L D`; `dz` is a vertical line between the two tool tips'
 * heights.
 */
import { describe, expect, it } from 'vitest';
import { cross, dot, type Vec3 } from '../../../src/core/math/vec';
import { toLocal, toMachine } from '../../../src/core/output/curvedSurfaceGeometry';
import {
  frameMatrix,
  horizontalStepDimension,
  slopeFrame,
  stepDownDimension,
} from '../../../src/core/output/machineGeometry';
import { applyMatrix } from '../../../src/core/output/surfaceGeometry';
import { slopePosture } from '../../../src/core/threeAxis/slopePosture';

const SLOPES = [0, 15, 30, 45, 60, 75];
const ANGLES = [0, 30, 60, 90];

describe('the local frame of a CC point on a sloped plane, in the machine frame', () => {
  for (const a of SLOPES)
    for (const psi of ANGLES)
      it(`slope ${a}, raster angle ${psi}: a right-handed rotation; the vertical is slopePosture's tool axis`, () => {
        const f = slopeFrame(a, psi);
        const [X, Y, Z] = f;
        for (const [u, v, want] of [
          [X, X, 1],
          [Y, Y, 1],
          [Z, Z, 1],
          [X, Y, 0],
          [Y, Z, 0],
          [X, Z, 0],
        ] as const)
          expect(dot(u, v)).toBeCloseTo(want, 14);
        const c = cross(X, Y);
        for (let k = 0; k < 3; k++) expect(c[k]).toBeCloseTo(Z[k] as number, 14);
        const up = toLocal(f, [0, 0, 1]);
        const axis = slopePosture(a, psi).axis;
        for (let k = 0; k < 3; k++) expect(up[k]).toBeCloseTo(axis[k] as number, 14);
        // The 4 x 4 matrix is the same rotation.
        const p: Vec3 = [0.3, -1.2, 2.5];
        const m = applyMatrix(frameMatrix(f), p);
        const q = toMachine(f, p);
        for (let k = 0; k < 3; k++) expect(m[k]).toBeCloseTo(q[k] as number, 14);
      });
});

describe('Lxy: the horizontal dimension between two raster passes', () => {
  for (const a of SLOPES)
    for (const psi of [0, 30, 60])
      it(`slope ${a}, raster angle ${psi}: horizontal, from this pass's vertical plane to the next one's, L D long`, () => {
        const f = slopeFrame(a, psi);
        const L = 0.8;
        const d = horizontalStepDimension(f, L, 2, 0.05);
        const s = toMachine(f, d.start);
        const e = toMachine(f, d.end);
        expect(e[2]).toBeCloseTo(s[2], 12);
        const lengthMm = Math.hypot(e[0] - s[0], e[1] - s[1]);
        expect(lengthMm).toBeCloseTo(L * slopePosture(a, psi).horizontalStepPerInterval, 12);
        // Each end on its pass's vertical plane (containing the feed X and the vertical).
        const X = f[0];
        const normal = cross([0, 0, 1], X);
        const next = toMachine(f, [0, L, 0]);
        expect(dot(s, normal)).toBeCloseTo(0, 12);
        expect(dot([e[0] - next[0], e[1] - next[1], e[2] - next[2]], normal)).toBeCloseTo(0, 12);
        // The polyline starts at this CC point and ends on the next pass's CC path (local y = L, z = 0).
        const n = d.points.length / 3;
        expect([d.points[0], d.points[1], d.points[2]]).toEqual([0, 0, 0]);
        expect(d.points[3 * (n - 1) + 1]).toBeCloseTo(L, 12);
        expect(d.points[3 * (n - 1) + 2]).toBeCloseTo(0, 12);
      });
});

describe('dz: the vertical dimension between two waterline passes', () => {
  it('its ends stand at the two tool tips, one above the other', () => {
    const f = slopeFrame(40, 90);
    const tip0: Vec3 = [0.1, -0.2, 0.05];
    const tip1: Vec3 = [0.1, 0.7, 0.05];
    const d = stepDownDimension(f, tip0, tip1, 3, 0.05);
    const s = toMachine(f, d.start);
    const e = toMachine(f, d.end);
    expect(s[2]).toBeCloseTo(toMachine(f, tip0)[2], 14);
    expect(e[2]).toBeCloseTo(toMachine(f, tip1)[2], 14);
    expect(e[0]).toBeCloseTo(s[0], 14);
    expect(e[1]).toBeCloseTo(s[1], 14);
    // On a plane the step-down of two passes L apart across the contour is L sin(alpha).
    expect(Math.abs(e[2] - s[2])).toBeCloseTo(0.9 * Math.sin((40 * Math.PI) / 180), 14);
    // The polyline runs from the first tip to the second.
    const n = d.points.length / 3;
    for (let k = 0; k < 3; k++) {
      expect(d.points[k]).toBeCloseTo(tip0[k] as number, 14);
      expect(d.points[3 * (n - 1) + k]).toBeCloseTo(tip1[k] as number, 14);
    }
  });
});
