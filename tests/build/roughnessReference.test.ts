/**
 * The reference data set's roughness reference (src/build/reference/roughnessReference.ts: the
 * brute-force profile's widths by the layer-cake formulas, integrated in height) against a ball end's
 * closed-form profile integrated directly across the feed (z = y^2 / (R + sqrt(R^2 - y^2)), 64-point
 * Gauss-Legendre in y, split at the mean line), in any posture (a ball's profile ignores it): the mean
 * line, Ra and Rq within the reference's stated uncertainty.
 */
import { describe, expect, it } from 'vitest';
import { gaussLegendre, referenceRoughness } from '../../src/build/reference/roughnessReference';

const [NODES, WEIGHTS] = gaussLegendre(64);

function gl(f: (y: number) => number, a: number, b: number): number {
  return (
    NODES.reduce((sum, x, i) => sum + (WEIGHTS[i] as number) * f(0.5 * (a + b) + 0.5 * (b - a) * x), 0) * 0.5 * (b - a)
  );
}

/** Ra and Rq of a ball end's scallop of height h over one flank (one-way and zigzag alike: every flank is the same circle). */
function ballRoughness(R: number, h: number): { ra: number; rq: number } {
  const W = Math.sqrt(h * (2 * R - h));
  const z = (y: number) => (y * y) / (R + Math.sqrt(R * R - y * y));
  const mean = gl(z, 0, W) / W;
  const ym = Math.sqrt(mean * (2 * R - mean));
  const ra = (gl((y) => mean - z(y), 0, ym) + gl((y) => z(y) - mean, ym, W)) / W;
  const rq = Math.sqrt(gl((y) => (z(y) - mean) ** 2, 0, W) / W);
  return { ra, rq };
}

describe('roughness reference of the data set against a ball end in closed form', () => {
  for (const [R, h, rho, tilt, pattern] of [
    [3, 0.05, 5, 0, 'one-way'],
    [3, 0.05, 30, 20, 'zigzag'],
    [0.5, 0.001, 10, -35, 'one-way'],
    [12, 2, 45, 10, 'zigzag'],
  ] as const) {
    it(`R ${R}, h ${h}, rho ${rho}, tilt ${tilt}, ${pattern}`, () => {
      const ref = referenceRoughness(R, R, rho, tilt, pattern, h);
      const want = ballRoughness(R, h);
      expect(ref.raUncertaintyMm).toBeLessThan(1e-8 * R);
      expect(Math.abs(ref.raMm - want.ra)).toBeLessThanOrEqual(ref.raUncertaintyMm);
      expect(Math.abs(ref.rqMm - want.rq)).toBeLessThanOrEqual(ref.rqUncertaintyMm);
      expect(ref.rzMm).toBe(h);
    });
  }
});
