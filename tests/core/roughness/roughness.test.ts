import { describe, expect, it } from 'vitest';
import { gaussLegendre } from '../../../src/build/reference/roughnessReference';
import { type ForwardInput, forwardInput, type PassPattern, type ToolInput } from '../../../src/core/input/validate';
import { exactRoughness, maxRaMm, raRuleOfThumbMm, scallopHeightForRaMm } from '../../../src/core/roughness/roughness';
import { cylinderSolver } from '../../../src/core/surfaces/cylinder';
import { exactForward } from '../../../src/core/surfaces/solve';
import { scallopHeightLimits, validateForward } from '../../../src/core/surfaces/validate';
import { flankAtWidth, shapeOfTool } from '../../../src/core/tool/posture';
import { seededRandom } from '../../support/bruteForce';

/** 16-point Gauss-Legendre nodes and weights on [-1, 1], computed once. */
const [GL16_X, GL16_W] = gaussLegendre(16);

/**
 * Independent check of the roughness formulas: the period's profile z(y) integrated directly in y
 * (adaptive Simpson on each flank, split at the mean line), not by the height integrals of
 * roughness.ts. z(y) comes from the flank inverse, itself checked against the 40-digit reference
 * in posture.test.ts.
 */
function directRoughness(
  input: ForwardInput,
  kinks: { readonly right: readonly number[]; readonly left: readonly number[] } = { right: [], left: [] },
): { ra: number; rq: number; mean: number; rz: number } {
  const e = exactForward(input);
  const s = shapeOfTool(input);
  const segs =
    input.pattern === 'one-way'
      ? [
          { flank: 'right' as const, W: e.halfWidthRightMm },
          { flank: 'left' as const, W: e.halfWidthLeftMm },
        ]
      : [
          { flank: 'right' as const, W: e.halfIntervalMm },
          { flank: 'left' as const, W: e.halfIntervalMm },
        ];
  // Composite 16-point Gauss-Legendre on 256 panels: the profile is smooth in y between the
  // breaks passed in (the mean line's crossing, a flat bottom's edge).
  let extra: readonly number[] = [];
  const simpson = (f: (y: number) => number, a: number, b: number): number => {
    const inside = [...(s.flatOnPlane ? [s.a] : []), ...extra].filter((y) => y > a && y < b).sort((x, y) => x - y);
    const breaks = [a, ...inside, b];
    let sum = 0;
    for (let k = 1; k < breaks.length; k++) {
      const lo = breaks[k - 1] as number;
      const hi = breaks[k] as number;
      const panels = 256;
      for (let p = 0; p < panels; p++) {
        const pa = lo + ((hi - lo) * p) / panels;
        const pb = lo + ((hi - lo) * (p + 1)) / panels;
        for (let i = 0; i < 16; i++)
          sum += (GL16_W[i] as number) * f(0.5 * (pa + pb) + 0.5 * (pb - pa) * (GL16_X[i] as number)) * 0.5 * (pb - pa);
      }
    }
    return sum;
  };
  const z = (flank: 'right' | 'left') => (y: number) => flankAtWidth(s, flank, y).heightMm;
  let length = 0;
  let area = 0;
  for (const g of segs) {
    length += g.W;
    extra = kinks[g.flank];
    area += simpson(z(g.flank), 0, g.W);
  }
  const mean = area / length;
  let abs = 0;
  let sq = 0;
  let rz = 0;
  for (const g of segs) {
    const f = z(g.flank);
    extra = kinks[g.flank];
    rz = Math.max(rz, f(g.W));
    // Split at the crossing of the mean line (a kink of |z - m|).
    let lo = 0;
    let hi = g.W;
    if (f(hi) > mean) {
      for (let i = 0; i < 200; i++) {
        const m = 0.5 * (lo + hi);
        if (f(m) < mean) lo = m;
        else hi = m;
      }
    }
    const cross = f(g.W) > mean ? 0.5 * (lo + hi) : g.W;
    abs += simpson((y) => mean - f(y), 0, cross) + (cross < g.W ? simpson((y) => f(y) - mean, cross, g.W) : 0);
    sq += simpson((y) => (f(y) - mean) ** 2, 0, g.W);
  }
  return { ra: abs / length, rq: Math.sqrt(sq / length), mean, rz };
}

const tool = (R: number, Rcr: number, rho: number, tilt: number): ToolInput => ({
  toolRadiusMm: R,
  cornerRadiusMm: Rcr,
  leadAngleDeg: rho,
  tiltAngleDeg: tilt,
});

describe('exact roughness of the passes on a plane', () => {
  it('a ball end: mean line, Ra and Rq of a circular scallop (direct Gauss-Legendre in y), any posture', () => {
    // 64-point Gauss-Legendre on [0, W] for z = y^2 / (R + sqrt(R^2 - y^2)), computed stably.
    const [nodes, weights] = gaussLegendre(64);
    for (const [R, h, rho, tilt] of [
      [3, 0.05, 5, 0],
      [3, 0.05, 30, 40],
      [1, 1e-6, 0, 0],
      [2, 1.5, 0, 0],
      [0.01, 0.002, 80, -60],
    ] as const) {
      const W = Math.sqrt(h * (2 * R - h));
      const z = (y: number) => (y * y) / (R + Math.sqrt(R * R - y * y));
      const gl = (f: (y: number) => number, a: number, b: number) =>
        nodes.reduce((sum, x, i) => sum + (weights[i] as number) * f(0.5 * (a + b) + 0.5 * (b - a) * x), 0) *
        0.5 *
        (b - a);
      const mean = gl(z, 0, W) / W;
      const ym = Math.sqrt(mean * (2 * R - mean));
      const ra = (gl((y) => mean - z(y), 0, ym) + gl((y) => z(y) - mean, ym, W)) / W;
      const rq = Math.sqrt(gl((y) => (z(y) - mean) ** 2, 0, W) / W);
      const r = exactRoughness(forwardInput(tool(R, R, rho, tilt), 'one-way', h));
      expect(Math.abs(r.meanMm - mean), `mean R=${R} h=${h}`).toBeLessThan(1e-12 * R + 1e-18);
      expect(Math.abs(r.raMm - ra), `Ra R=${R} h=${h}`).toBeLessThan(1e-12 * R + 1e-18);
      expect(Math.abs(r.rqMm - rq), `Rq R=${R} h=${h}`).toBeLessThan(1e-12 * R + 1e-18);
      expect(r.rzMm).toBe(h);
    }
  });

  it('tends to the parabolic scallop as h -> 0: Ra/h = 4/(9 sqrt 3), Rq/h = 2/(3 sqrt 5), mean = h/3', () => {
    const r = exactRoughness(forwardInput(tool(3, 1, 5, 0), 'one-way', 1e-8));
    expect(r.raMm / 1e-8).toBeCloseTo(4 / (9 * Math.sqrt(3)), 6);
    expect(r.rqMm / 1e-8).toBeCloseTo(2 / (3 * Math.sqrt(5)), 6);
    expect(r.meanMm / 1e-8).toBeCloseTo(1 / 3, 6);
    // The shop rule h/4 is off by the ratio 9 sqrt(3) / 16 - 1 = -2.6 % here.
    expect(raRuleOfThumbMm(1e-8) / r.raMm - 1).toBeCloseTo((9 * Math.sqrt(3)) / 16 - 1, 5);
  });

  for (const seed of [31, 32, 33]) {
    it(`seed ${seed}: any posture and pattern agree with the direct integral in y within 1e-9 mm`, () => {
      const rand = seededRandom(seed);
      let checked = 0;
      for (let k = 0; k < 8; k++) {
        const R = 0.2 + 10 * rand();
        const t = tool(R, R * rand(), 60 * rand(), 60 * rand() - 30);
        const limit = scallopHeightLimits(t).limitMm;
        if (!(limit > 1e-6)) continue;
        const pattern: PassPattern = rand() < 0.5 ? 'one-way' : 'zigzag';
        const input = forwardInput(t, pattern, limit * (0.001 + 0.8 * rand()));
        const r = exactRoughness(input);
        const d = directRoughness(input);
        const label = JSON.stringify(input);
        expect(Math.abs(r.meanMm - d.mean), `mean ${label}`).toBeLessThan(1e-9);
        expect(Math.abs(r.raMm - d.ra), `Ra ${label}`).toBeLessThan(1e-9);
        expect(Math.abs(r.rqMm - d.rq), `Rq ${label}`).toBeLessThan(1e-9);
        expect(Math.abs(r.rzMm - d.rz), `Rz ${label}`).toBeLessThan(1e-9);
        checked++;
      }
      expect(checked).toBeGreaterThanOrEqual(6);
    });
  }

  it('a flat bottom lying on the plane (rho = 0): its flat part lowers the mean, and a flat end leaves no roughness', () => {
    const input = forwardInput(tool(3, 1, 0, 0), 'one-way', 0.05);
    const r = exactRoughness(input);
    const d = directRoughness(input);
    expect(Math.abs(r.raMm - d.ra)).toBeLessThan(1e-9);
    expect(r.meanMm).toBeLessThan(0.05 / 3);
    expect(exactRoughness(forwardInput(tool(3, 0, 0, 0), 'one-way', 0.05))).toEqual({
      rzMm: 0,
      raMm: 0,
      rqMm: 0,
      meanMm: 0,
    });
  });

  it('a flat bottom tilted at rho = 0 (its flank turns from the corner arc to the straight face): within 1e-9 mm', () => {
    // The left flank: the corner arc out to y = Rcr sin(beta), then the bottom face, a straight
    // line of slope tan(beta), then the other corner: the direct integral splits at those kinks.
    for (const [R, Rcr, beta, h] of [
      [3, 1, 5, 0.1],
      [3, 0.2, 10, 0.1],
    ] as const) {
      expect(validateForward({ R, Rcr, rho: 0, tilt: beta, h }).ok).toBe(true);
      const b = (beta * Math.PI) / 180;
      const arc = Rcr * Math.sin(b);
      const face = arc + 2 * (R - Rcr) * Math.cos(b);
      const input = forwardInput(tool(R, Rcr, 0, beta), 'one-way', h);
      const r = exactRoughness(input);
      const d = directRoughness(input, { right: [], left: [arc, face] });
      expect(Math.abs(r.raMm - d.ra), `Ra ${JSON.stringify(input)}`).toBeLessThan(1e-9);
      expect(Math.abs(r.rqMm - d.rq), `Rq ${JSON.stringify(input)}`).toBeLessThan(1e-9);
      expect(Math.abs(r.meanMm - d.mean), `mean ${JSON.stringify(input)}`).toBeLessThan(1e-9);
    }
  });

  it('zigzag with tilt: Rz is the higher cusp, and the lower cusp lowers Ra against one-way at the same h', () => {
    const t = tool(3, 1, 5, 5);
    const zig = exactRoughness(forwardInput(t, 'zigzag', 0.05));
    const one = exactRoughness(forwardInput(t, 'one-way', 0.05));
    expect(zig.rzMm).toBe(0.05);
    expect(zig.raMm).toBeLessThan(one.raMm);
  });

  it('solving for a target Ra gives back that Ra; targets up to the largest Ra the tool can leave', () => {
    for (const [t, pattern] of [
      [tool(3, 1, 5, 0), 'one-way'],
      [tool(6, 2, 10, 15), 'zigzag'],
      [tool(0.5, 0.5, 0, 0), 'one-way'],
      [tool(3, 1, 0, 0), 'one-way'],
    ] as const) {
      const max = maxRaMm(t, pattern);
      for (const frac of [1e-6, 0.01, 0.3, 0.9]) {
        const target = frac * max;
        const h = scallopHeightForRaMm(t, pattern, target);
        const ra = exactRoughness(forwardInput(t, pattern, h)).raMm;
        expect(Math.abs(ra - target), `${JSON.stringify(t)} ${pattern} ${frac}`).toBeLessThan(1e-12 * max + 1e-15);
      }
    }
  });
});

describe('exact roughness on cylinders (measured radially, over arc length on the surface)', () => {
  it('agrees with a direct integral of the radial height over arc length (both axes, both sides)', () => {
    for (const [rs, axis, pattern] of [
      [20, 'feed', 'one-way'],
      [-60, 'feed', 'zigzag'],
      [15, 'cross', 'one-way'],
      [-80, 'cross', 'zigzag'],
    ] as const) {
      const surface = { kind: 'cylinder' as const, radiusMm: rs, axis };
      const t = tool(3, 1, 5, 8);
      const input = forwardInput(t, pattern, 0.05, surface);
      const e = exactForward(input);
      const c = cylinderSolver(t, surface);
      // The radial height at arc length s from the contact, on each flank (the cylinder's inverse).
      const z = (flank: 'right' | 'left') => (sMm: number) => c.heightAt(flank, c.reachFromInterval(sMm));
      const segs =
        pattern === 'one-way'
          ? [
              { f: z('right'), W: e.halfWidthRightMm },
              { f: z('left'), W: e.halfWidthLeftMm },
            ]
          : [
              { f: z('right'), W: e.halfIntervalMm },
              { f: z('left'), W: e.halfIntervalMm },
            ];
      const gl = (f: (y: number) => number, a: number, b: number) => {
        let sum = 0;
        const panels = 128;
        for (let p = 0; p < panels; p++) {
          const pa = a + ((b - a) * p) / panels;
          const pb = a + ((b - a) * (p + 1)) / panels;
          for (let i = 0; i < 16; i++)
            sum +=
              (GL16_W[i] as number) * f(0.5 * (pa + pb) + 0.5 * (pb - pa) * (GL16_X[i] as number)) * 0.5 * (pb - pa);
        }
        return sum;
      };
      const length = segs.reduce((a, g) => a + g.W, 0);
      const mean = segs.reduce((a, g) => a + gl(g.f, 0, g.W), 0) / length;
      const rq = Math.sqrt(segs.reduce((a, g) => a + gl((y) => (g.f(y) - mean) ** 2, 0, g.W), 0) / length);
      const r = exactRoughness(input);
      expect(Math.abs(r.meanMm - mean), `mean ${rs} ${axis} ${pattern}`).toBeLessThan(1e-9);
      expect(Math.abs(r.rqMm - rq), `Rq ${rs} ${axis} ${pattern}`).toBeLessThan(1e-9);
    }
  });

  it('solving for a target Ra on a cylinder gives back that Ra', () => {
    const surface = { kind: 'cylinder' as const, radiusMm: -40, axis: 'feed' as const };
    const t = tool(3, 1, 5, 0);
    const target = 0.3 * maxRaMm(t, 'one-way', surface);
    const h = scallopHeightForRaMm(t, 'one-way', target, surface);
    expect(Math.abs(exactRoughness(forwardInput(t, 'one-way', h, surface)).raMm - target)).toBeLessThan(1e-12);
  });
});

describe('heightForRaMm: the bracket of the target Ra', () => {
  it('never asks for the Ra of a height below 2 Ra (where the width across a cylinder carries rounding), and finds h', async () => {
    const { heightForRaMm } = await import('../../../src/core/roughness/roughness');
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 10, tiltAngleDeg: 5 };
    for (const surface of [
      { kind: 'cylinder', radiusMm: 50, axis: 'cross' },
      { kind: 'cylinder', radiusMm: -50, axis: 'cross' },
      { kind: 'cylinder', radiusMm: 50, axis: 'feed' },
      undefined,
    ] as const) {
      const max = maxRaMm(tool, 'one-way', surface);
      const limit = scallopHeightLimits(tool, surface).limitMm * (1 - 1e-12);
      for (const target of [0.001 * max, 0.3 * max, 0.95 * max]) {
        let lowest = Number.POSITIVE_INFINITY;
        const h = heightForRaMm(
          (x) => {
            lowest = Math.min(lowest, x);
            return exactRoughness(forwardInput(tool, 'one-way', x, surface)).raMm;
          },
          target,
          limit,
        );
        expect(lowest, JSON.stringify(surface)).toBeGreaterThanOrEqual(2 * target * (1 - 1e-12));
        const ra = exactRoughness(forwardInput(tool, 'one-way', h, surface)).raMm;
        expect(Math.abs(ra - target) / target).toBeLessThan(1e-12);
      }
    }
  });
});

describe('widthIntegrals: rounding in the width', () => {
  it('stops splitting where the error estimate is the width rounding (a few hundred calls, not the 60 000 of the panel cap), to the accuracy the width allows', async () => {
    const { widthIntegrals } = await import('../../../src/core/roughness/roughness');
    // w = 2 sqrt(z) with a relative rounding of 1e-11 (deterministic, unrelated to z's digits).
    let seed = 7;
    const noise = () => {
      seed = (seed * 16807) % 2147483647;
      return seed / 2147483647 - 0.5;
    };
    for (const zMax of [1e-6, 0.003, 0.5]) {
      let calls = 0;
      const [a1, a2] = widthIntegrals((z) => {
        calls++;
        return 2 * Math.sqrt(z) * (1 + 2e-11 * noise());
      }, zMax);
      // int_0^Z 2 sqrt(z) dz = 4/3 Z^1.5; int_0^Z 2 z sqrt(z) dz = 4/5 Z^2.5.
      expect(Math.abs(a1 / ((4 / 3) * zMax ** 1.5) - 1), String(zMax)).toBeLessThan(1e-10);
      expect(Math.abs(a2 / ((4 / 5) * zMax ** 2.5) - 1), String(zMax)).toBeLessThan(1e-10);
      expect(calls, String(zMax)).toBeLessThan(2000);
    }
  });
});
