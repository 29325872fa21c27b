/**
 * The cylinders' strata: axis along and across the feed, convex and concave, both patterns, with and
 * without tilt, against the polished reach of the real tool on the cylinder (oracles/cylinderReach.ts).
 */
import type { SurfaceAxis } from '../../../core/domain/surface.ts';
import { scallopHeightLimits, validateForward } from '../../../core/surfaces/validate.ts';
import type { Draft, Stratum, ToolKind } from '../draft.ts';
import { drawTool, logUniform, sig, signedAngle, TOOL_KINDS, toolInputs } from '../draft.ts';
import { cylinderReach } from '../oracles/cylinderReach.ts';

function cylinderStratum(axis: SurfaceAxis, convex: boolean, count: number): Stratum {
  const name = `cylinder-${axis}-${convex ? 'convex' : 'concave'}`;
  return {
    name,
    count,
    *drafts(rand, n) {
      for (let i = 0; i < n; i++) {
        const kind = TOOL_KINDS[i % TOOL_KINDS.length] as ToolKind;
        const pattern = Math.floor(i / 3) % 2 === 0 ? 'one-way' : 'zigzag';
        const tilted = Math.floor(i / 6) % 2 === 1;
        for (let attempt = 0; attempt < 20; attempt++) {
          const { R, Rcr } = drawTool(rand, kind, 0.2, 20);
          const rho = rand() < 0.1 ? 0 : sig(1 + 44 * rand(), 4);
          const tilt = tilted ? signedAngle(rand, 0.5, 40) : 0;
          // Radii from 1.5 R (convex; 4 R concave) to 1000 R, log-uniform.
          const rs = sig((convex ? 1 : -1) * R * logUniform(rand, convex ? 1.5 : 4, 1000));
          const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt };
          const surface = { kind: 'cylinder', radiusMm: rs, axis } as const;
          const limit = scallopHeightLimits(tool, surface).limitMm;
          if (!(limit >= 1e-6)) continue;
          const h = sig(limit * 0.9 * 10 ** (-4 * rand() ** 1.5));
          const inputs = {
            ...toolInputs(R, Rcr, rho, tilt, pattern),
            surfaceRadius: rs,
            surfaceAxis: axis,
            h,
          };
          // A concave radius the tool gouges is the invalid strata's: draw again.
          if (!validateForward({ ...inputs, h: String(h) }).ok) continue;
          yield {
            stratum: name,
            mode: 'forward',
            quantity: 'interval',
            inputs,
            reference: () => {
              const ref = cylinderReach(tool, rs, axis);
              const scale = axis === 'feed' ? Math.abs(rs) : 1;
              const right = ref.reach('right', h, true);
              const left = ref.reach('left', h, true);
              const L = scale * (pattern === 'one-way' ? right + left : 2 * Math.min(right, left));
              return { valueMm: L, uncertaintyMm: 1e-12 * Math.max(1, L), method: 'cylinder-reach' };
            },
          } satisfies Draft;
          break;
        }
      }
    },
  };
}

export const cylinderFeedConvex = cylinderStratum('feed', true, 100);
export const cylinderFeedConcave = cylinderStratum('feed', false, 100);
export const cylinderCrossConvex = cylinderStratum('cross', true, 100);
export const cylinderCrossConcave = cylinderStratum('cross', false, 100);
