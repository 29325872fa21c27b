/**
 * The invalid domain: inputs the calculator must refuse, each with its error code, the field it
 * names and the limit it states; where the limit has an independent value (a constant of the valid
 * domain, the 64-digit profile's flank and shank heights, a closed form), that is the reference.
 * Four strata: the plane and cylinder problems (forward and inverse), target roughness, the doubly
 * curved point and three-axis machining.
 */
import type { Draft, ReferenceValue, Stratum, ToolKind } from '../draft.ts';
import { drawTool, logUniform, sig, signedAngle, TOOL_KINDS } from '../draft.ts';
import { referenceProfile } from '../oracles/highPrecision.ts';

type Inputs = Record<string, number | string>;

/** A refused input and the reference of its limit (null where none is independent). */
interface Refusal {
  readonly mode: Draft['mode'];
  readonly inputs: Inputs;
  readonly limit?: (answerMm: number) => ReferenceValue | null;
}

/** A limit stated by the valid domain (README, Valid inputs). */
const stated = (value: number) => (): ReferenceValue => ({ valueMm: value, uncertaintyMm: 0, method: 'stated-limit' });

/** A random valid tool and posture (tilt often 0). */
function toolOf(rand: () => number, i: number): { R: number; Rcr: number; rho: number; tilt: number } {
  const { R, Rcr } = drawTool(rand, TOOL_KINDS[i % TOOL_KINDS.length] as ToolKind, 0.1, 50);
  return { R, Rcr, rho: sig(2 + 60 * rand(), 4), tilt: i % 2 === 0 ? 0 : signedAngle(rand, 1, 40) };
}

/** The lowest of the 64-digit profile's flank tops and shank heights: where h stops leaving a scallop. */
function planeHeightLimit(t: { R: number; Rcr: number; rho: number; tilt: number }): ReferenceValue {
  const p = referenceProfile(t.R, t.Rcr, t.rho, t.tilt);
  const v = Math.min(p.hmaxRightMm, p.hmaxLeftMm, p.shankHeightRightMm, p.shankHeightLeftMm);
  return { valueMm: v, uncertaintyMm: 4 * Number.EPSILON * v, method: 'high-precision-limit' };
}

/** The plane and cylinder problems. */
const PASS: ReadonlyArray<(rand: () => number, i: number) => Refusal> = [
  (rand) => ({
    mode: 'forward',
    inputs: { R: sig(logUniform(rand, 1e-6, 9e-4)), Rcr: 0, rho: 5, h: 1e-4 },
    limit: stated(0.001),
  }),
  (rand) => ({
    mode: 'forward',
    inputs: { R: sig(logUniform(rand, 1001, 1e5)), Rcr: 1, rho: 5, h: 0.01 },
    limit: stated(1000),
  }),
  (rand) => ({ mode: 'forward', inputs: { R: sig(-10 * rand()), Rcr: 0, rho: 5, h: 0.01 } }),
  (rand, i) => {
    const t = toolOf(rand, i);
    const Rcr = sig(t.R * (1.001 + rand()));
    return { mode: 'forward', inputs: { R: t.R, Rcr, rho: t.rho, h: 0.01 }, limit: stated(t.R) };
  },
  (rand, i) => ({ mode: 'forward', inputs: { ...toolOf(rand, i), Rcr: sig(-rand()), h: 0.01 } }),
  (rand, i) => ({ mode: 'forward', inputs: { ...toolOf(rand, i), rho: sig(90 + 30 * rand() ** 2, 4), h: 0.01 } }),
  (rand, i) => ({ mode: 'forward', inputs: { ...toolOf(rand, i), rho: sig(-30 * rand() - 0.01, 4), h: 0.01 } }),
  (rand, i) => ({ mode: 'forward', inputs: { ...toolOf(rand, i), tilt: signedAngle(rand, 90, 120), h: 0.01 } }),
  (rand, i) => ({ mode: 'forward', inputs: { ...toolOf(rand, i), h: 0 } }),
  (rand, i) => ({
    mode: 'forward',
    inputs: { ...toolOf(rand, i), h: sig(logUniform(rand, 1e-14, 9.9e-10)) },
    limit: stated(1e-9),
  }),
  (rand, i) => {
    // Above the lowest flank top or shank height, on a plane in any posture.
    const t = toolOf(rand, i);
    const ref = planeHeightLimit(t);
    return { mode: 'forward', inputs: { ...t, h: sig(ref.valueMm * (1.0001 + 2 * rand())) }, limit: () => ref };
  },
  (rand, i) => ({
    mode: 'forward',
    inputs: { ...toolOf(rand, i), R: ['abc', '1,5', '3 mm', '0x10', 'NaN'][i % 5] as string, h: 0.01 },
  }),
  (rand, i) => ({
    mode: 'forward',
    inputs: { ...toolOf(rand, i), h: ['', 'Infinity', '1e400', '.'][i % 4] as string },
  }),
  (rand, i) => ({
    mode: 'forward',
    inputs: { ...toolOf(rand, i), pattern: ['zig', 'oneway', 'spiral'][i % 3] as string, h: 0.01 },
  }),
  (rand, i) => ({
    mode: 'forward',
    inputs: {
      ...toolOf(rand, i),
      surfaceRadius: 50,
      surfaceAxis: ['diagonal', 'x', 'along'][i % 3] as string,
      h: 0.01,
    },
  }),
  (rand, i) => ({
    mode: 'forward',
    inputs: { ...toolOf(rand, i), surfaceRadius: sig((i % 2 ? -1 : 1) * logUniform(rand, 1e-6, 9e-4)), h: 0.01 },
  }),
  (rand, i) => ({
    mode: 'forward',
    inputs: { ...toolOf(rand, i), surfaceRadius: sig((i % 2 ? -1 : 1) * logUniform(rand, 1.01e6, 1e9)), h: 0.01 },
  }),
  (rand, i) => {
    // A concave cylinder tighter than the tool.
    const t = toolOf(rand, i);
    return {
      mode: 'forward',
      inputs: {
        ...t,
        surfaceRadius: sig(-t.R * (0.2 + 0.7 * rand())),
        surfaceAxis: i % 4 < 2 ? 'feed' : 'cross',
        h: 0.01,
      },
    };
  },
  (rand, i) => ({ mode: 'inverse', inputs: { ...toolOf(rand, i), interval: sig(-rand()) } }),
  (rand, i) => ({
    mode: 'inverse',
    inputs: { ...toolOf(rand, i), interval: sig(logUniform(rand, 1e-15, 1.9e-9)) },
    limit: stated(2e-9),
  }),
  (rand, i) => {
    // At or beyond the diameter without tilt on a plane: L = 2R is the widest.
    const t = { ...toolOf(rand, i), tilt: 0 };
    return { mode: 'inverse', inputs: { ...t, interval: sig(2 * t.R * (1 + rand())) }, limit: stated(2 * t.R) };
  },
];

/** Target roughness beyond the largest Ra, or not positive. */
const TARGET_RA: ReadonlyArray<(rand: () => number, i: number) => Refusal> = [
  (rand, i) => {
    const t = toolOf(rand, i);
    return { mode: 'target-ra', inputs: { ...t, Ra: sig(t.R * (0.6 + rand())) } };
  },
  (rand, i) => ({ mode: 'target-ra', inputs: { ...toolOf(rand, i), Ra: sig(-rand()) } }),
  (rand, i) => ({
    mode: 'target-ra',
    inputs: { ...toolOf(rand, i), Ra: sig(logUniform(rand, 1e-15, 9e-10)) },
    limit: stated(1e-9),
  }),
];

/** The doubly curved point: radii out of range, points the tool gouges, h above the limits. */
const DOUBLY_CURVED: ReadonlyArray<(rand: () => number, i: number) => Refusal> = [
  (rand, i) => ({
    mode: 'forward',
    inputs: { ...toolOf(rand, i), feedRadius: sig(logUniform(rand, 1e-7, 9e-4)), crossRadius: 100, h: 0.01 },
  }),
  (rand, i) => ({ mode: 'forward', inputs: { ...toolOf(rand, i), feedRadius: 100, crossRadius: 0, h: 0.01 } }),
  (rand, i) => {
    // A bowl or a sphere tighter than the tool.
    const t = toolOf(rand, i);
    const r = sig(-t.R * (0.3 + 0.6 * rand()));
    return { mode: 'forward', inputs: { ...t, feedRadius: i % 2 ? r : sig(-50 * t.R), crossRadius: r, h: 0.01 } };
  },
  (rand, i) => {
    const t = toolOf(rand, i);
    return {
      mode: 'forward',
      inputs: { ...t, feedRadius: sig(t.R * 40), crossRadius: sig(t.R * 60), h: sig(t.R * (1.5 + rand())) },
    };
  },
  (rand, i) => {
    const t = toolOf(rand, i);
    return {
      mode: 'inverse',
      inputs: { ...t, feedRadius: sig(t.R * 40), crossRadius: sig(-t.R * 60), interval: sig(t.R * (2.5 + rand())) },
    };
  },
];

/** Three-axis machining. */
const THREE_AXIS: ReadonlyArray<(rand: () => number, i: number) => Refusal> = [
  (rand, i) => {
    const { R, Rcr } = drawTool(rand, TOOL_KINDS[i % 3] as ToolKind, 0.1, 50);
    return { mode: 'forward', inputs: { R, Rcr, slope: 90, passes: i % 2 ? 'waterline' : 'raster', h: 0.01 } };
  },
  (rand, i) => {
    const { R, Rcr } = drawTool(rand, TOOL_KINDS[i % 3] as ToolKind, 0.1, 50);
    return { mode: 'forward', inputs: { R, Rcr, slope: sig(90.01 + 90 * rand(), 4), h: 0.01 } };
  },
  (rand) => {
    const { R, Rcr } = drawTool(rand, 'ball', 0.1, 50);
    return { mode: 'forward', inputs: { R, Rcr, slope: 0, passes: 'waterline', h: sig(0.01 * R) } };
  },
  (rand) => {
    const { R, Rcr } = drawTool(rand, 'bull-nose', 0.1, 50);
    return { mode: 'forward', inputs: { R, Rcr, rho: 5, slope: 30, h: 0.01 } };
  },
  (rand) => {
    const { R, Rcr } = drawTool(rand, 'bull-nose', 0.1, 50);
    return { mode: 'forward', inputs: { R, Rcr, slope: 30, passes: 'spiral', h: 0.01 } };
  },
  (rand) => {
    // Waterline on a sloped plane above Rcr (1 - sin(slope)), the README's closed form of the shank's limit.
    const { R, Rcr } = drawTool(rand, 'bull-nose', 0.1, 50);
    const slope = sig(5 + 80 * rand(), 4);
    const limit = Rcr * (1 - Math.sin((slope * Math.PI) / 180));
    return {
      mode: 'forward',
      inputs: { R, Rcr, slope, passes: 'waterline', h: sig(limit * (1.001 + rand())) },
      limit: () => ({ valueMm: limit, uncertaintyMm: 4 * Number.EPSILON * Rcr, method: 'closed-form-limit' }),
    };
  },
  (rand) => {
    // A bowl too tight for the tool.
    const { R, Rcr } = drawTool(rand, 'bull-nose', 0.1, 50);
    const r = sig(-R * (0.3 + 0.6 * rand()));
    return {
      mode: 'forward',
      inputs: { R, Rcr, slope: sig(10 + 60 * rand(), 4), passes: 'waterline', feedRadius: r, crossRadius: r, h: 0.01 },
    };
  },
  (rand) => {
    const { R, Rcr } = drawTool(rand, 'bull-nose', 0.1, 50);
    return { mode: 'forward', inputs: { R, Rcr, slope: 30, passes: 'raster', feedRadius: 100, h: 0.01 } };
  },
];

function invalidStratum(
  name: string,
  count: number,
  makers: ReadonlyArray<(rand: () => number, i: number) => Refusal>,
): Stratum {
  return {
    name,
    count,
    *drafts(rand, n) {
      for (let i = 0; i < n; i++) {
        const r = (makers[i % makers.length] as (rand: () => number, i: number) => Refusal)(
          rand,
          Math.floor(i / makers.length),
        );
        const limit = r.limit;
        yield {
          stratum: name,
          mode: r.mode,
          quantity: 'errorLimit',
          inputs: r.inputs,
          reference: (answerMm) => (limit === undefined || Number.isNaN(answerMm) ? null : limit(answerMm)),
        } satisfies Draft;
      }
    },
  };
}

export const invalidPass = invalidStratum('invalid-plane-cylinder', 210, PASS);
export const invalidTargetRa = invalidStratum('invalid-target-ra', 30, TARGET_RA);
export const invalidDoublyCurved = invalidStratum('invalid-doubly-curved', 50, DOUBLY_CURVED);
export const invalidThreeAxis = invalidStratum('invalid-three-axis', 80, THREE_AXIS);
