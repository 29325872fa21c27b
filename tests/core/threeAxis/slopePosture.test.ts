import { describe, expect, it } from 'vitest';
import { slopePosture } from '../../../src/core/threeAxis/slopePosture';

/**
 * The closed-form posture against the local frame built numerically from the definitions (notes
 * section 2a and posture-and-surfaces.md): plane normal n, the CC path as the plane cut by the
 * vertical plane at plan angle psi to the fall line, Y = n x X, the tool axis Zm seen in (X, Y, n);
 * and Lxy as the horizontal distance between the vertical planes through two paths L apart.
 */
type V = [number, number, number];
const dot = (a: V, b: V) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: V, b: V): V => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a: V): V => {
  const l = Math.hypot(...a);
  return [a[0] / l, a[1] / l, a[2] / l];
};
const rad = (d: number) => (d * Math.PI) / 180;
// Exact at 90 degrees, as a frame built by hand would be (cos(pi/2) rounds to 6e-17).
const cosD = (d: number) => (d === 90 ? 0 : Math.cos(rad(d)));
const sinD = (d: number) => (d === 90 ? 1 : Math.sin(rad(d)));

function frame(alphaDeg: number, psiDeg: number) {
  const n: V = [-sinD(alphaDeg), 0, cosD(alphaDeg)];
  const d: V = [cosD(psiDeg), -sinD(psiDeg), 0];
  const X = unit([d[0], d[1], -dot(d, n) / n[2]]);
  const Y = cross(n, X);
  return { n, X, Y };
}

describe('slopePosture (closed form) against the numerical frame', () => {
  const alphas = [0, 1e-9, 1e-3, 5, 17, 30, 45, 60, 75, 89, 89.999];
  const psis = [0, 1e-6, 10, 30, 45, 60, 80, 90];
  for (const a of alphas)
    for (const p of psis)
      it(`alpha ${a}, psi ${p}`, () => {
        const q = slopePosture(a, p);
        const { n, X, Y } = frame(a, p);
        const Zm: V = [0, 0, 1];
        const axis: V = [
          Math.cos(q.tiltRad) * Math.sin(q.leadRad),
          Math.sin(q.tiltRad),
          Math.cos(q.tiltRad) * Math.cos(q.leadRad),
        ];
        expect(Math.abs(axis[0] - dot(Zm, X))).toBeLessThan(1e-14);
        expect(Math.abs(axis[1] - dot(Zm, Y))).toBeLessThan(1e-14);
        expect(Math.abs(axis[2] - dot(Zm, n))).toBeLessThan(1e-14);
        // Valid posture: 0 <= rho < 90 and 0 <= beta < 90 (feed up the slope, uphill on +Y).
        expect(q.leadDeg).toBeGreaterThanOrEqual(0);
        expect(q.leadDeg).toBeLessThan(90);
        expect(q.tiltDeg).toBeGreaterThanOrEqual(0);
        expect(q.tiltDeg).toBeLessThan(90);
        // Lxy: the vertical planes through paths 0 (origin) and 1 (L Y), both containing X.
        const m = unit(cross(Zm, X));
        const L = 1.7;
        expect(
          Math.abs(L * q.horizontalStepPerInterval - Math.abs(dot([L * Y[0], L * Y[1], L * Y[2]], m))),
        ).toBeLessThan(1e-14);
        expect(Math.abs(q.verticalStepPerInterval - Y[2])).toBeLessThan(1e-14);
      });

  it('psi = 0 is pure lead alpha, psi = 90 pure tilt alpha (waterline), alpha = 0 upright', () => {
    for (const a of [0, 12.5, 44, 80]) {
      expect(slopePosture(a, 0).leadDeg).toBeCloseTo(a, 12);
      expect(slopePosture(a, 0).tiltDeg).toBe(0);
      expect(slopePosture(a, 90).leadDeg).toBe(0);
      expect(slopePosture(a, 90).tiltDeg).toBeCloseTo(a, 12);
      expect(slopePosture(a, 90).horizontalStepPerInterval).toBeCloseTo(Math.cos(rad(a)), 14);
    }
    expect(slopePosture(0, 37)).toMatchObject({ leadDeg: 0, tiltDeg: 0, horizontalStepPerInterval: 1 });
  });
});
