/**
 * The plane's strata: the paper's case (lead only), any posture one-way, zigzag, the inverse, and the
 * roughness, against the 64-digit profile (oracles/highPrecision.ts) and, for roughness, the
 * brute-force profile integrated by the layer-cake formulas (roughnessReference.ts).
 */
import { forwardInput } from '../../../core/input/validate.ts';
import { exactRoughness } from '../../../core/roughness/roughness.ts';
import { maxIntervalMm, scallopHeightLimits } from '../../../core/surfaces/validate.ts';
import type { Draft, ReferenceValue, Stratum, ToolKind } from '../draft.ts';
import { drawTool, logUniform, sig, signedAngle, TOOL_KINDS, toolInputs } from '../draft.ts';
import { referenceProfile } from '../oracles/highPrecision.ts';
import { referenceHeightForRa, referenceRoughness } from '../roughnessReference.ts';

const HIGH_PRECISION = 'high-precision-profile';

/** A plane case: tool, posture and pattern. */
interface PlaneCase {
  readonly R: number;
  readonly Rcr: number;
  readonly rho: number;
  readonly tilt: number;
  readonly pattern: 'one-way' | 'zigzag';
}

const toolInput = (c: PlaneCase) => ({
  toolRadiusMm: c.R,
  cornerRadiusMm: c.Rcr,
  leadAngleDeg: c.rho,
  tiltAngleDeg: c.tilt,
});

/** The row's inputs for a plane case (tilt and pattern left empty at their defaults, as a user would). */
function inputsOf(c: PlaneCase): Record<string, number | string> {
  return toolInputs(c.R, c.Rcr, c.rho, c.tilt, c.pattern);
}

/** A lead in [0, 89.9) degrees: exactly 0 one time in ten, steep ones one time in ten. */
function drawLead(rand: () => number): number {
  const r = rand();
  if (r < 0.1) return 0;
  if (r < 0.2) return sig(80 + 9.9 * rand(), 4);
  return sig(75 * rand(), 4);
}

/** A case of the given kind and posture whose scallop height limit is at least 1e-6 mm (10 draws at most). */
function drawCase(
  rand: () => number,
  kind: ToolKind,
  posture: (rand: () => number) => { rho: number; tilt: number },
  pattern: 'one-way' | 'zigzag',
): { c: PlaneCase; limitMm: number } | null {
  for (let attempt = 0; attempt < 10; attempt++) {
    const { R, Rcr } = drawTool(rand, kind, 0.01, 200);
    const { rho, tilt } = posture(rand);
    const c = { R, Rcr, rho, tilt, pattern };
    const limitMm = scallopHeightLimits(toolInput(c)).limitMm;
    if (limitMm >= 1e-6 || (kind === 'flat' && rho === 0 && tilt === 0)) return { c, limitMm };
  }
  return null;
}

/** h from 1e-5 to 0.95 of the limit, log-uniform, 6 digits (R when no limit: a flat end lying flat). */
function drawHeight(rand: () => number, limitMm: number, R: number): number {
  const top = Number.isFinite(limitMm) && limitMm > 0 ? limitMm : R;
  return sig(top * 0.95 * 10 ** (-5 * rand() ** 1.5));
}

/** The step-over by the 64-digit profile's flank widths at h (the whole tool, shank included). */
function profileInterval(c: PlaneCase, h: number): ReferenceValue {
  const p = referenceProfile(c.R, c.Rcr, c.rho, c.tilt);
  const wR = p.widthRightWithShankMm(h);
  const wL = p.widthLeftWithShankMm(h);
  const L = c.pattern === 'one-way' ? wR + wL : 2 * Math.min(wR, wL);
  return { valueMm: L, uncertaintyMm: 4 * Number.EPSILON * L, method: HIGH_PRECISION };
}

function forwardStratum(
  name: string,
  count: number,
  posture: (rand: () => number, i: number) => { rho: number; tilt: number },
  pattern: 'one-way' | 'zigzag',
): Stratum {
  return {
    name,
    count,
    *drafts(rand, n) {
      for (let i = 0; i < n; i++) {
        const kind = TOOL_KINDS[i % TOOL_KINDS.length] as ToolKind;
        const drawn = drawCase(rand, kind, (r) => posture(r, i), pattern);
        if (drawn === null) continue;
        const { c, limitMm } = drawn;
        const h = drawHeight(rand, limitMm, c.R);
        yield {
          stratum: name,
          mode: 'forward',
          quantity: 'interval',
          inputs: { ...inputsOf(c), h },
          reference: () => profileInterval(c, h),
        } satisfies Draft;
      }
    },
  };
}

/** The paper's case: lead only, one-way. */
export const planeLead = forwardStratum('plane-lead', 250, (rand) => ({ rho: drawLead(rand), tilt: 0 }), 'one-way');

/** Any posture, one-way: a tilt of 0.5 to 85 degrees either way. */
export const planePostureOneWay = forwardStratum(
  'plane-posture-one-way',
  250,
  (rand) => ({ rho: drawLead(rand), tilt: signedAngle(rand, 0.5, 85) }),
  'one-way',
);

/** Zigzag, with a tilt four times in five. */
export const planeZigzag = forwardStratum(
  'plane-zigzag',
  250,
  (rand, i) => ({ rho: drawLead(rand), tilt: i % 5 === 4 ? 0 : signedAngle(rand, 0.5, 85) }),
  'zigzag',
);

/**
 * The inverse (L to the scallop height): zigzag in any posture and one-way without tilt, where the
 * cusps stand at L/2 from the contacts, so each is the 64-digit profile's height at width L/2.
 */
export const planeInverse: Stratum = {
  name: 'plane-inverse',
  count: 150,
  *drafts(rand, n) {
    for (let i = 0; i < n; i++) {
      const kind = TOOL_KINDS[i % TOOL_KINDS.length] as ToolKind;
      const pattern = i % 2 === 0 ? 'zigzag' : 'one-way';
      const drawn = drawCase(
        rand,
        kind,
        (r) => ({
          rho: kind === 'flat' ? sig(1 + 80 * r(), 4) : drawLead(r),
          tilt: pattern === 'zigzag' ? signedAngle(r, 0.5, 85) : 0,
        }),
        pattern,
      );
      if (drawn === null) continue;
      const { c } = drawn;
      const max = maxIntervalMm(toolInput(c), c.pattern);
      if (!Number.isFinite(max)) continue;
      const L = sig(max * (0.02 + 0.96 * rand()));
      yield {
        stratum: 'plane-inverse',
        mode: 'inverse',
        quantity: 'scallopHeight',
        inputs: { ...inputsOf(c), interval: L },
        reference: () => {
          const p = referenceProfile(c.R, c.Rcr, c.rho, c.tilt);
          const h = Math.max(p.heightAtWidthRightMm(L / 2), p.heightAtWidthLeftMm(L / 2));
          return { valueMm: h, uncertaintyMm: 4 * Number.EPSILON * h, method: HIGH_PRECISION };
        },
      } satisfies Draft;
    }
  },
};

/**
 * The roughness strata's cases: the tool kinds in turn, one-way and zigzag by threes, a tilt of 1 to
 * 45 degrees by sixes, a lead of 1 to 61 degrees (drawn lazily: each case's own draws follow it).
 */
function* roughnessCases(rand: () => number, n: number): Generator<{ c: PlaneCase; limitMm: number }> {
  for (let i = 0; i < n; i++) {
    const kind = TOOL_KINDS[i % TOOL_KINDS.length] as ToolKind;
    const pattern = Math.floor(i / 3) % 2 === 0 ? 'one-way' : 'zigzag';
    const tilted = Math.floor(i / 6) % 2 === 1;
    const drawn = drawCase(
      rand,
      kind,
      (r) => ({ rho: sig(1 + 60 * r(), 4), tilt: tilted ? signedAngle(r, 1, 45) : 0 }),
      pattern,
    );
    if (drawn !== null) yield drawn;
  }
}

/** Roughness: Rz, Ra and Rq of one case each, one-way and zigzag, with and without tilt. */
export const planeRoughness: Stratum = {
  name: 'roughness',
  count: 110,
  *drafts(rand, n) {
    for (const { c, limitMm } of roughnessCases(rand, n)) {
      // Scallops from 1e-3 to 0.6 of the limit: the brute-force widths are accurate to 1e-9 R.
      const h = sig(logUniform(rand, 1e-3, 0.6) * limitMm);
      let cached: ReturnType<typeof referenceRoughness> | null = null;
      const ref = () => {
        cached ??= referenceRoughness(c.R, c.Rcr, c.rho, c.tilt, c.pattern, h);
        return cached;
      };
      for (const quantity of ['Rz', 'Ra', 'Rq'] as const)
        yield {
          stratum: 'roughness',
          mode: 'roughness',
          quantity,
          inputs: { ...inputsOf(c), h },
          reference: () => {
            const r = ref();
            if (quantity === 'Rz')
              return { valueMm: r.rzMm, uncertaintyMm: 4 * Number.EPSILON * r.rzMm, method: 'roughness-definition' };
            return quantity === 'Ra'
              ? { valueMm: r.raMm, uncertaintyMm: r.raUncertaintyMm, method: 'brute-force-layer-cake' }
              : { valueMm: r.rqMm, uncertaintyMm: r.rqUncertaintyMm, method: 'brute-force-layer-cake' };
          },
        } satisfies Draft;
    }
  },
};

/**
 * A target roughness (the `--ra` mode): Ra to the scallop height that leaves it, one-way and zigzag,
 * with and without tilt; the reference solves the layer-cake Ra of the brute-force profile for h.
 */
export const planeTargetRa: Stratum = {
  name: 'target-ra',
  count: 45,
  *drafts(rand, n) {
    for (const { c, limitMm } of roughnessCases(rand, n)) {
      // A target the passes can leave: the Ra of a scallop from 1e-3 to 0.6 of the limit, 6 digits.
      const Ra = sig(exactRoughness(forwardInput(toolInput(c), c.pattern, logUniform(rand, 1e-3, 0.6) * limitMm)).raMm);
      yield {
        stratum: 'target-ra',
        mode: 'target-ra',
        quantity: 'scallopHeight',
        inputs: { ...inputsOf(c), Ra },
        reference: () => {
          const r = referenceHeightForRa(c.R, c.Rcr, c.rho, c.tilt, c.pattern, Ra);
          return { valueMm: r.heightMm, uncertaintyMm: r.uncertaintyMm, method: 'brute-force-layer-cake-inverse' };
        },
      } satisfies Draft;
    }
  },
};
