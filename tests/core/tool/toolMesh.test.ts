import { describe, expect, it } from 'vitest';
import { toolMesh } from '../../../src/core/tool/toolMesh';

describe('tool surface mesh', () => {
  it('touches the designed plane at its lowest point and never goes below it', () => {
    for (const [R, Rcr, rhoDeg] of [
      [3, 1, 5],
      [6, 2, 30],
      [3, 3, 10],
      [4, 0, 20],
    ] as const) {
      const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rhoDeg, tiltAngleDeg: 0 };
      const { positions, indices } = toolMesh(tool, R, 64);
      let minZ = Number.POSITIVE_INFINITY;
      for (let i = 2; i < positions.length; i += 3) minZ = Math.min(minZ, positions[i] as number);
      expect(minZ).toBeGreaterThan(-1e-5);
      expect(minZ).toBeLessThan(0.01 * R);
      expect(Math.max(...indices)).toBeLessThan(positions.length / 3);
    }
  });
});
