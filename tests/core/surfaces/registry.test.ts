/**
 * The surface interface's contract (issue 18), for every registered surface model: limits that are
 * heights, forward then inverse back to the scallop height, the fast step-over equal to the full
 * answer's, the widest step-over beyond every valid one, the plane as the limit of large radii, and
 * the straight radii of a doubly curved point answered by the plane's and the cylinders' own models
 * to the last digit. A registered kind without samples here fails the first test.
 */
import { describe, expect, it } from 'vitest';
import type { ForwardInput, InverseInput } from '../../../src/core/domain/pass';
import type { PassPattern, ToolInput } from '../../../src/core/domain/tool';
import { doublyCurvedForward, doublyCurvedInverse } from '../../../src/core/surfaces/doublyCurved/solve';
import { answerQuestion, validateQuestion } from '../../../src/core/surfaces/question';
import { SURFACE_KINDS, type SurfaceDescriptor, surfaceModel } from '../../../src/core/surfaces/registry';
import { exactForward, exactIntervalMm, exactInverse } from '../../../src/core/surfaces/solve';
import { slopedPlaneIntervalMm } from '../../../src/core/threeAxis/slopedPlane';
import { contactCurvatureRadiusMm, shapeOfTool } from '../../../src/core/tool/posture';

const I = Number.POSITIVE_INFINITY;

/** Surfaces every model is tried on: each kind convex and concave where it has a side. */
const SAMPLES: readonly SurfaceDescriptor[] = [
  { kind: 'plane' },
  { kind: 'cylinder', radiusMm: 40, axis: 'feed' },
  { kind: 'cylinder', radiusMm: -60, axis: 'feed' },
  { kind: 'cylinder', radiusMm: 25, axis: 'cross' },
  { kind: 'cylinder', radiusMm: -80, axis: 'cross' },
  { kind: 'doublyCurved', feedRadiusMm: 30, crossRadiusMm: 50 },
  { kind: 'doublyCurved', feedRadiusMm: -90, crossRadiusMm: -70 },
  { kind: 'doublyCurved', feedRadiusMm: 40, crossRadiusMm: -200 },
];

const TOOLS: readonly ToolInput[] = [
  { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 0 },
  { toolRadiusMm: 5, cornerRadiusMm: 2, leadAngleDeg: 15, tiltAngleDeg: 12 },
  { toolRadiusMm: 2, cornerRadiusMm: 2, leadAngleDeg: 0, tiltAngleDeg: -20 },
];

const PATTERNS: readonly PassPattern[] = ['one-way', 'zigzag'];

function forwardOf<S extends SurfaceDescriptor>(tool: ToolInput, pattern: PassPattern, surface: S, h: number) {
  return { ...tool, pattern, surface, scallopHeightMm: h } as ForwardInput<S>;
}

function inverseOf<S extends SurfaceDescriptor>(tool: ToolInput, pattern: PassPattern, surface: S, L: number) {
  return { ...tool, pattern, surface, intervalMm: L } as InverseInput<S>;
}

const name = (s: SurfaceDescriptor) => JSON.stringify(s);

describe('surface registry: every registered model keeps the contract', () => {
  it('has samples for every registered kind, and finds each kind its own model', () => {
    expect(SURFACE_KINDS.length).toBeGreaterThanOrEqual(3);
    for (const kind of SURFACE_KINDS)
      expect(
        SAMPLES.some((s) => s.kind === kind),
        kind,
      ).toBe(true);
    for (const s of SAMPLES) expect(surfaceModel(s).kind).toBe(s.kind);
    expect(() => surfaceModel({ kind: 'sphere' } as unknown as SurfaceDescriptor)).toThrow(/sphere/);
  });

  it('limits are heights: positive, finite, the binding one the smallest of the tops and shank heights', () => {
    for (const surface of SAMPLES) {
      for (const tool of TOOLS) {
        const m = surfaceModel(surface);
        expect(m.fit(tool, surface).gouges, name(surface)).toBe(false);
        const l = m.limits(tool, surface);
        const all = [l.topRightMm, l.topLeftMm, l.shankRightMm, l.shankLeftMm].filter((v) => v !== null);
        expect(l.limitMm, name(surface)).toBeGreaterThan(0);
        expect(Number.isFinite(l.limitMm)).toBe(true);
        expect(l.limitMm).toBe(Math.min(...(all as number[])));
      }
    }
  });

  it('forward then inverse gives the scallop height back; the fast step-over is the full answer; the widest lies beyond', () => {
    for (const surface of SAMPLES) {
      for (const tool of TOOLS) {
        const m = surfaceModel(surface);
        const limit = m.limits(tool, surface).limitMm;
        for (const pattern of PATTERNS) {
          const max = m.maxIntervalMm(tool, pattern, surface);
          for (const fraction of [1e-4, 0.05, 0.5]) {
            const h = fraction * limit;
            const where = `${name(surface)} ${JSON.stringify(tool)} ${pattern} h ${h}`;
            const f = exactForward(forwardOf(tool, pattern, surface, h));
            expect(f.cuspHeightMm, where).toBe(h);
            expect(f.halfIntervalMm).toBe(f.intervalMm / 2);
            // The fast path adds the reaches before converting them: the same L to rounding.
            const fast = exactIntervalMm(forwardOf(tool, pattern, surface, h));
            expect(Math.abs(fast - f.intervalMm), where).toBeLessThanOrEqual(4e-16 * f.intervalMm);
            expect(f.intervalMm, where).toBeGreaterThan(0);
            expect(f.intervalMm, where).toBeLessThan(max);
            // The roughness's profile: each flank's width at h is the forward answer's.
            const width = m.flankWidths(tool, surface);
            expect(Math.abs(width('right', h) - f.halfWidthRightMm), where).toBeLessThanOrEqual(1e-12 * f.intervalMm);
            expect(Math.abs(width('left', h) - f.halfWidthLeftMm), where).toBeLessThanOrEqual(1e-12 * f.intervalMm);
            const back = exactInverse(inverseOf(tool, pattern, surface, f.intervalMm));
            expect(Math.abs(back.cuspHeightMm - h), where).toBeLessThan(1e-9 + 1e-9 * h);
            if (pattern === 'zigzag') {
              expect(
                Math.abs((back.otherCuspHeightMm as number) - (f.otherCuspHeightMm as number)),
                where,
              ).toBeLessThan(1e-9);
            }
          }
        }
      }
    }
  });

  it('large radii tend to the plane (an independent answer: the plane solver), L Reff / (2 |R|) apart', () => {
    const large = 1e5;
    const curved: SurfaceDescriptor[] = [
      { kind: 'cylinder', radiusMm: large, axis: 'feed' },
      { kind: 'cylinder', radiusMm: -large, axis: 'cross' },
      { kind: 'doublyCurved', feedRadiusMm: large, crossRadiusMm: -large },
    ];
    for (const tool of TOOLS) {
      for (const pattern of PATTERNS) {
        const h = 0.01;
        const plane = exactForward(forwardOf(tool, pattern, { kind: 'plane' }, h)).intervalMm;
        // The usual correction 1/rho = 1/Reff + 1/R in L = 2 sqrt(2 rho h) moves L by about L Reff / (2 |R|).
        const reff = contactCurvatureRadiusMm(shapeOfTool(tool)) as number;
        for (const surface of curved) {
          const L = exactForward(forwardOf(tool, pattern, surface, h)).intervalMm;
          expect(Math.abs(L - plane), name(surface)).toBeLessThan((plane * reff) / large);
          expect(Math.abs(L - plane), name(surface)).toBeGreaterThan(0);
        }
      }
    }
  });

  it('a doubly curved point with straight radii is the plane or a cylinder, to the last digit', () => {
    for (const tool of TOOLS) {
      for (const pattern of PATTERNS) {
        const h = 0.02;
        const pairs: Array<[SurfaceDescriptor, SurfaceDescriptor]> = [
          [{ kind: 'doublyCurved', feedRadiusMm: I, crossRadiusMm: -I }, { kind: 'plane' }],
          [
            { kind: 'doublyCurved', feedRadiusMm: I, crossRadiusMm: 35 },
            { kind: 'cylinder', radiusMm: 35, axis: 'feed' },
          ],
          [
            { kind: 'doublyCurved', feedRadiusMm: -45, crossRadiusMm: I },
            { kind: 'cylinder', radiusMm: -45, axis: 'cross' },
          ],
        ];
        for (const [patch, straight] of pairs) {
          const f = exactForward(forwardOf(tool, pattern, patch, h));
          expect(f, name(patch)).toEqual(exactForward(forwardOf(tool, pattern, straight, h)));
          const L = 0.8 * f.intervalMm;
          expect(exactInverse(inverseOf(tool, pattern, patch, L))).toEqual(
            exactInverse(inverseOf(tool, pattern, straight, L)),
          );
          const m = surfaceModel(patch);
          expect(m.limits(tool, patch)).toEqual(surfaceModel(straight).limits(tool, straight));
          expect(m.maxIntervalMm(tool, pattern, patch)).toBe(
            surfaceModel(straight).maxIntervalMm(tool, pattern, straight),
          );
        }
      }
    }
  });

  it('a curved doubly curved point gives its own solver’s answers unchanged through the registry', () => {
    const radii = { feedRadiusMm: 30, crossRadiusMm: -120 };
    for (const tool of TOOLS) {
      for (const pattern of PATTERNS) {
        const surface: SurfaceDescriptor = { kind: 'doublyCurved', ...radii };
        const own = doublyCurvedForward({ ...tool, pattern, ...radii, scallopHeightMm: 0.03 });
        const f = exactForward(forwardOf(tool, pattern, surface, 0.03));
        expect(f.intervalMm).toBe(own.intervalMm);
        expect(f.otherCuspHeightMm).toBe(own.otherCuspHeightMm);
        const back = doublyCurvedInverse({ ...tool, pattern, ...radii, intervalMm: own.intervalMm });
        expect(exactInverse(inverseOf(tool, pattern, surface, own.intervalMm)).cuspHeightMm).toBe(back.cuspHeightMm);
      }
    }
  });

  it('a surface that takes a flat face lying on it says so, and its forward answer is no scallop at 2R', () => {
    const flat: ToolInput = { toolRadiusMm: 3, cornerRadiusMm: 0, leadAngleDeg: 0, tiltAngleDeg: 0 };
    expect(surfaceModel({ kind: 'plane' }).leavesNoScallop(flat, { kind: 'plane' })).toBe(true);
    for (const surface of SAMPLES) {
      const m = surfaceModel(surface);
      if (m.leavesNoScallop(flat, surface)) {
        const f = exactForward(forwardOf(flat, 'one-way', surface, 0.1));
        expect(f.noScallop, name(surface)).toBe(true);
        expect(f.intervalMm).toBe(2 * flat.toolRadiusMm);
      } else expect(surface.kind, 'a curved surface').not.toBe('plane');
      for (const tool of TOOLS) expect(m.leavesNoScallop(tool, surface), name(surface)).toBe(false);
    }
  });

  it('a sloped plane is the plane under the three-axis mode (a posture supplier), as threeAxis/slopedPlane.ts answers', () => {
    expect(SURFACE_KINDS).not.toContain('slopedPlane');
    for (const [slopeDeg, passes, rasterAngleDeg] of [
      [25, 'raster', 30],
      [40, 'waterline', 0],
      [0, 'raster', 0],
    ] as const) {
      const mode = { kind: 'threeAxis', slopeDeg, passes, rasterAngleDeg } as const;
      for (const tool of TOOLS) {
        const radii = { toolRadiusMm: tool.toolRadiusMm, cornerRadiusMm: tool.cornerRadiusMm };
        const c = { ...radii, slopeDeg, passes, rasterAngleDeg };
        const probe = validateQuestion({
          tool: radii,
          mode,
          surface: { kind: 'plane' },
          pattern: 'one-way',
          target: { quantity: 'h', mm: 1e-6 },
        });
        if (!probe.ok) throw new Error(JSON.stringify(probe.errors));
        const h = 0.3 * answerQuestion(probe.value).heightLimitMm;
        const own = slopedPlaneIntervalMm(c, h);
        for (const pattern of PATTERNS) {
          const v = validateQuestion({
            tool: radii,
            mode,
            surface: { kind: 'plane' },
            pattern,
            target: { quantity: 'h', mm: h },
          });
          const L = v.ok ? answerQuestion(v.value).intervalMm : Number.NaN;
          expect(Math.abs(L - own), `${slopeDeg} ${passes} ${pattern}`).toBeLessThan(1e-12 * own);
        }
      }
    }
  });
});
