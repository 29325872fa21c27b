/**
 * The three-axis strata (the tool upright, the slope given): raster on a sloped plane, waterline on
 * a sloped plane and on surfaces of revolution (cones, domes, bowls, boss fillets, pocket rims); the
 * inverse (L along the surface to the cusp height) against the machine-frame brute force, sampled
 * then polished (oracles/threeAxisBruteForce.ts), as tests/core/threeAxis/ compares.
 */
import { slopedPlaneForward } from '../../../core/threeAxis/slopedPlane.ts';
import { waterlineForward, waterlineHeightLimitMm } from '../../../core/threeAxis/waterlineRevolution.ts';
import type { Draft, ReferenceValue, Stratum, ToolKind } from '../draft.ts';
import { drawTool, logUniform, sig, TOOL_KINDS } from '../draft.ts';
import { type BruteCusp, bruteRasterCusp, bruteWaterlineCusp } from '../oracles/threeAxisBruteForce.ts';

/** A slope in (0, 89.9] degrees: a tenth of them steep (80 to 89.9), a tenth shallow (0.01 to 1). */
function drawSlope(rand: () => number): number {
  const r = rand();
  if (r < 0.1) return sig(80 + 9.9 * rand(), 4);
  if (r < 0.2) return sig(logUniform(rand, 0.01, 1), 4);
  return sig(1 + 79 * rand(), 4);
}

function polished(b: BruteCusp, R: number, method: string): ReferenceValue {
  return {
    valueMm: b.polishedMm,
    uncertaintyMm: 1e-12 * Math.max(1, R),
    method,
    sampledMm: b.sampledMm,
    sampledBoundMm: b.boundMm,
  };
}

/** Waterline: a flat end's side rises straight from the contact on any slope (refused, wall-only). */
const WATERLINE_KINDS: readonly ToolKind[] = ['ball', 'bull-nose'];

/**
 * A sloped plane: raster at any raster angle (0 and 90 one time in five each, a flat floor one time
 * in seven), or waterline (the passes straight along the contour).
 */
function slopedPlaneStratum(passes: 'raster' | 'waterline', count: number): Stratum {
  const name = `three-axis-${passes === 'raster' ? 'raster' : 'waterline-plane'}`;
  const kinds = passes === 'raster' ? TOOL_KINDS : WATERLINE_KINDS;
  return {
    name,
    count,
    *drafts(rand, n) {
      for (let i = 0; i < n; i++) {
        const kind = kinds[i % kinds.length] as ToolKind;
        for (let attempt = 0; attempt < 20; attempt++) {
          const { R, Rcr } = drawTool(rand, kind, 0.2, 20);
          const slope = passes === 'raster' && i % 7 === 6 ? 0 : drawSlope(rand);
          const psi = passes === 'waterline' ? 90 : i % 5 === 0 ? 0 : i % 5 === 1 ? 90 : sig(90 * rand(), 4);
          const c = { toolRadiusMm: R, cornerRadiusMm: Rcr, slopeDeg: slope, passes, rasterAngleDeg: psi };
          const probe = slopedPlaneForward(c, 1e-9);
          if (!probe.ok || probe.value.noScallop) continue;
          const limit = Math.min(probe.value.heightLimitMm, 0.6 * Rcr + 0.2 * R);
          const f = slopedPlaneForward(c, limit * (0.02 + 0.9 * rand()));
          if (!f.ok || f.value.noScallop) continue;
          const L = sig(f.value.intervalMm * (0.5 + 0.5 * rand()));
          const revolution = { slopeDeg: slope, feedRadiusMm: null, crossRadiusMm: null };
          yield {
            stratum: name,
            mode: 'inverse',
            quantity: 'scallopHeight',
            inputs: { R, Rcr, slope, passes, ...(passes === 'raster' ? { rasterAngle: psi } : {}), interval: L },
            reference: () =>
              passes === 'raster'
                ? polished(bruteRasterCusp({ R, Rcr }, slope, psi, L, 24), R, 'three-axis-raster-brute')
                : polished(bruteWaterlineCusp({ R, Rcr }, revolution, L, 64), R, 'three-axis-waterline-brute'),
          } satisfies Draft;
          break;
        }
      }
    },
  };
}

export const threeAxisRaster = slopedPlaneStratum('raster', 200);
export const threeAxisWaterlinePlane = slopedPlaneStratum('waterline', 100);

/** Surfaces of revolution as multiples of R, [Rf, Rc] (null: straight), sizes drawn in the ranges given. */
const REVOLUTIONS: ReadonlyArray<{ name: string; rf: [number, number] | null; rc: [number, number] | null }> = [
  { name: 'cone', rf: [4, 100], rc: null },
  { name: 'dome', rf: [4, 100], rc: [4, 100] },
  { name: 'bowl', rf: [-100, -8], rc: [-100, -8] },
  { name: 'boss fillet', rf: [8, 100], rc: [-20, -3] },
  { name: 'pocket rim', rf: [-100, -15], rc: [3, 20] },
  { name: 'meridian only', rf: null, rc: [-100, 100] },
];

/** A signed multiple drawn log-uniformly in [lo, hi] (both of one sign, or spanning both: either sign). */
function multiple(rand: () => number, [lo, hi]: [number, number]): number {
  if (lo < 0 && hi > 0) return (rand() < 0.5 ? -1 : 1) * logUniform(rand, 4, hi);
  return Math.sign(lo) * logUniform(rand, Math.min(Math.abs(lo), Math.abs(hi)), Math.max(Math.abs(lo), Math.abs(hi)));
}

/** Waterline on surfaces of revolution. */
export const threeAxisWaterlineRevolution: Stratum = {
  name: 'three-axis-waterline-revolution',
  count: 150,
  *drafts(rand, n) {
    for (let i = 0; i < n; i++) {
      const kind = WATERLINE_KINDS[Math.floor(i / REVOLUTIONS.length) % WATERLINE_KINDS.length] as ToolKind;
      const shape = REVOLUTIONS[i % REVOLUTIONS.length] as (typeof REVOLUTIONS)[number];
      for (let attempt = 0; attempt < 20; attempt++) {
        const { R, Rcr } = drawTool(rand, kind, 0.2, 20);
        const slope = sig(1 + 84 * rand(), 4);
        const rf = shape.rf === null ? null : sig(R * multiple(rand, shape.rf));
        const rc = shape.rc === null ? null : sig(R * multiple(rand, shape.rc));
        const c = { toolRadiusMm: R, cornerRadiusMm: Rcr, slopeDeg: slope, feedRadiusMm: rf, crossRadiusMm: rc };
        const limit = waterlineHeightLimitMm(c);
        if (!(limit > 1e-6)) continue;
        const h = Math.min(limit, Rcr > 0 ? Rcr : 0.2 * R) * (0.02 + 0.9 * rand());
        const f = waterlineForward(c, h);
        if (!f.ok) continue;
        const L = sig(f.value.intervalMm * (0.5 + 0.5 * rand()));
        yield {
          stratum: 'three-axis-waterline-revolution',
          mode: 'inverse',
          quantity: 'scallopHeight',
          inputs: {
            R,
            Rcr,
            slope,
            passes: 'waterline',
            ...(rf === null ? {} : { feedRadius: rf }),
            ...(rc === null ? {} : { crossRadius: rc }),
            interval: L,
          },
          reference: () => polished(bruteWaterlineCusp({ R, Rcr }, c, L, 8), R, 'three-axis-waterline-brute'),
        } satisfies Draft;
        break;
      }
    }
  },
};
