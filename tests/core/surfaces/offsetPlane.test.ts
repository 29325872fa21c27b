/**
 * The throwaway offset plane (issue 18's demonstration of adding a surface): translating the design
 * surface moves every pass with it, so every answer is the plane's (the independent check).
 */
import { describe, expect, it } from 'vitest';
import type { PassPattern, ToolInput } from '../../../src/core/domain/tool';
import { surfaceModel } from '../../../src/core/surfaces/registry';
import { exactForward, exactInverse } from '../../../src/core/surfaces/solve';

describe('offset plane', () => {
  it('answers as the plane, whatever the offset', () => {
    const tool: ToolInput = { toolRadiusMm: 4, cornerRadiusMm: 1, leadAngleDeg: 20, tiltAngleDeg: 15 };
    for (const pattern of ['one-way', 'zigzag'] as PassPattern[]) {
      for (const offsetMm of [-3, 0, 12.5]) {
        const surface = { kind: 'offsetPlane', offsetMm } as const;
        const h = 0.03;
        const f = exactForward({ ...tool, pattern, surface, scallopHeightMm: h });
        expect(f).toEqual(exactForward({ ...tool, pattern, surface: { kind: 'plane' }, scallopHeightMm: h }));
        expect(exactInverse({ ...tool, pattern, surface, intervalMm: f.intervalMm }).cuspHeightMm).toBeCloseTo(h, 12);
        expect(surfaceModel(surface).limits(tool, surface)).toEqual(
          surfaceModel({ kind: 'plane' }).limits(tool, { kind: 'plane' }),
        );
      }
    }
  });
});
