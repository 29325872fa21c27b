/**
 * The registry's doubly curved model keeps the last point's prepared solver (models/doublyCurved.ts
 * solverOf: a reply asks one point's limits, widest step-over, answer and flanks in turn). Asked at
 * one point and then at another that differs in a single number, it must answer the second point as
 * the point's own solver prepared afresh does, to the bit: every number of the tool, the posture and
 * both radii is part of what it remembers.
 */
import { describe, expect, it } from 'vitest';
import type { DoublyCurvedSurface } from '../../../../src/core/domain/surface';
import type { PassPattern, ToolInput } from '../../../../src/core/domain/tool';
import { seededRandom } from '../../../../src/core/math/seededRandom';
import {
  doublyCurvedMaxIntervalMm,
  doublyCurvedSolver,
  forwardWith,
  inverseWith,
} from '../../../../src/core/surfaces/doublyCurved/solve';
import { doublyCurvedModel } from '../../../../src/core/surfaces/models/doublyCurved';

type Point = { tool: ToolInput; surface: DoublyCurvedSurface };

/** The point with one of its six numbers changed (a little: the same kind of point). */
const VARIANTS: ReadonlyArray<[string, (p: Point) => Point]> = [
  ['tool radius', (p) => ({ ...p, tool: { ...p.tool, toolRadiusMm: p.tool.toolRadiusMm * 1.05 } })],
  ['corner radius', (p) => ({ ...p, tool: { ...p.tool, cornerRadiusMm: p.tool.cornerRadiusMm * 0.9 } })],
  ['lead', (p) => ({ ...p, tool: { ...p.tool, leadAngleDeg: p.tool.leadAngleDeg + 3 } })],
  ['tilt', (p) => ({ ...p, tool: { ...p.tool, tiltAngleDeg: p.tool.tiltAngleDeg + 4 } })],
  ['Rf', (p) => ({ ...p, surface: { ...p.surface, feedRadiusMm: p.surface.feedRadiusMm * 1.5 } })],
  ['Rc', (p) => ({ ...p, surface: { ...p.surface, crossRadiusMm: p.surface.crossRadiusMm * 1.5 } })],
];

describe("the doubly curved model's memo of the last point", () => {
  it('seed 2731: after a point, a point that differs in any one number gets its own answer (limits, widest L, forward, inverse, flanks)', () => {
    const rand = seededRandom(2731);
    for (let i = 0; i < 6; i++) {
      const R = 1 + 8 * rand();
      const base: Point = {
        tool: {
          toolRadiusMm: R,
          cornerRadiusMm: R * (0.2 + 0.6 * rand()),
          leadAngleDeg: 5 + 30 * rand(),
          tiltAngleDeg: 20 * rand() - 10,
        },
        surface: {
          kind: 'doublyCurved',
          feedRadiusMm: (rand() < 0.5 ? 1 : -1) * R * (20 + 20 * rand()),
          crossRadiusMm: (rand() < 0.5 ? 1 : -1) * R * (20 + 20 * rand()),
        },
      };
      const pattern: PassPattern = i % 2 === 0 ? 'one-way' : 'zigzag';
      for (const [name, vary] of VARIANTS) {
        const p = vary(base);
        const label = `${name}: ${JSON.stringify(p)}`;
        // The base first, so that the model's memo holds it.
        doublyCurvedModel.limits(base.tool, base.surface);
        const fresh = doublyCurvedSolver(p.tool, p.surface);
        const limits = doublyCurvedModel.limits(p.tool, p.surface);
        expect(limits, label).toEqual(fresh.limits());
        const h = 0.3 * limits.limitMm;
        doublyCurvedModel.limits(base.tool, base.surface);
        const f = doublyCurvedModel.forward({ ...p.tool, pattern, surface: p.surface, scallopHeightMm: h });
        expect(f.intervalMm, label).toBe(forwardWith(fresh, pattern, h).intervalMm);
        doublyCurvedModel.limits(base.tool, base.surface);
        const L = 0.5 * doublyCurvedModel.maxIntervalMm(p.tool, pattern, p.surface);
        expect(2 * L, label).toBe(doublyCurvedMaxIntervalMm(fresh, pattern));
        doublyCurvedModel.limits(base.tool, base.surface);
        const e = doublyCurvedModel.inverse({ ...p.tool, pattern, surface: p.surface, intervalMm: L });
        expect(e.cuspHeightMm, label).toBe(inverseWith(fresh, pattern, L).cuspHeightMm);
        doublyCurvedModel.limits(base.tool, base.surface);
        expect(doublyCurvedModel.flankWidths(p.tool, p.surface)('left', h), label).toBe(fresh.left.reachMm(h));
      }
    }
  });
});
