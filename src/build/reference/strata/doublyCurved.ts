/**
 * The doubly curved point's stratum: domes, bowls, saddles both ways and spheres, ball, bull-nose
 * and flat ends, with and without tilt, both patterns; the inverse (L to the scallop height) against
 * the sampled brute force polished over the tool surface (oracles/doublyCurvedBruteForce.ts,
 * oracles/doublyCurvedPolished.ts), as tests/core/surfaces/doublyCurved/bruteForceCases.ts compares.
 */
import { doublyCurvedGouges } from '../../../core/surfaces/doublyCurved/gouging.ts';
import { doublyCurvedForward, doublyCurvedLimits } from '../../../core/surfaces/doublyCurved/solve.ts';
import type { Draft, ReferenceValue, Stratum, ToolKind } from '../draft.ts';
import { drawTool, logUniform, sig, signedAngle, TOOL_KINDS, toolInputs } from '../draft.ts';
import { bruteForceDoublyCurved } from '../oracles/doublyCurvedBruteForce.ts';
import { polishDoublyCurvedCusp } from '../oracles/doublyCurvedPolished.ts';

/** The families by the signs of [Rf, Rc], and whether both radii are one (a sphere). */
const FAMILIES: ReadonlyArray<{ readonly signs: readonly [number, number]; readonly sphere: boolean }> = [
  { signs: [1, 1], sphere: false }, // dome
  { signs: [-1, -1], sphere: false }, // bowl
  { signs: [1, -1], sphere: false }, // saddle
  { signs: [-1, 1], sphere: false }, // saddle, the other way
  { signs: [1, 1], sphere: true },
  { signs: [-1, -1], sphere: true },
];

/** Signed principal radii [Rf, Rc] of a family, sizes R times 5 to 300 (log-uniform). */
function radii(family: (typeof FAMILIES)[number], R: number, rand: () => number): [number, number] {
  const rf = sig(R * logUniform(rand, 5, 300));
  const rc = family.sphere ? rf : sig(R * logUniform(rand, 5, 300));
  return [family.signs[0] * rf, family.signs[1] * rc];
}

/** The polished cusp height at step-over L; zigzag: the higher of the two cusps (the tool and its mirror). */
function polishedCusp(
  tool: { R: number; Rcr: number; leadDeg: number; tiltDeg: number },
  pattern: 'one-way' | 'zigzag',
  rf: number,
  rc: number,
  L: number,
): ReferenceValue {
  const tilts = pattern === 'zigzag' && tool.tiltDeg !== 0 ? [tool.tiltDeg, -tool.tiltDeg] : [tool.tiltDeg];
  let best: ReferenceValue | null = null;
  for (const tiltDeg of tilts) {
    const t = { ...tool, tiltDeg };
    const b = bruteForceDoublyCurved(t, pattern, rf, rc, L, { spacingMm: tool.R / 60, levels: 3 });
    const polished = polishDoublyCurvedCusp(t, pattern, rf, rc, L, b).polishedMm;
    if (best === null || polished > best.valueMm)
      best = {
        valueMm: polished,
        uncertaintyMm: 1e-12 * Math.max(1, tool.R),
        method: 'doubly-curved-polished',
        sampledMm: b.cuspHeightMm,
        sampledBoundMm: b.boundMm,
      };
  }
  return best as ReferenceValue;
}

export const doublyCurved: Stratum = {
  name: 'doubly-curved',
  count: 120,
  *drafts(rand, n) {
    for (let i = 0; i < n; i++) {
      const family = FAMILIES[i % FAMILIES.length] as (typeof FAMILIES)[number];
      const kind = TOOL_KINDS[Math.floor(i / FAMILIES.length) % TOOL_KINDS.length] as ToolKind;
      const tilted = i % 2 === 1;
      const pattern = Math.floor(i / 2) % 2 === 0 ? 'one-way' : 'zigzag';
      for (let attempt = 0; attempt < 30; attempt++) {
        const { R, Rcr } = drawTool(rand, kind, 0.5, 12);
        const rho = sig(2 + 40 * rand(), 4);
        const tilt = tilted ? signedAngle(rand, 2, 35) : 0;
        const tool = { toolRadiusMm: R, cornerRadiusMm: Rcr, leadAngleDeg: rho, tiltAngleDeg: tilt };
        const [rf, rc] = radii(family, R, rand);
        if (doublyCurvedGouges(tool, { feedRadiusMm: rf, crossRadiusMm: rc })) continue;
        const limit = doublyCurvedLimits({ ...tool, feedRadiusMm: rf, crossRadiusMm: rc }).limitMm;
        if (!(limit > 1e-3 * R)) continue;
        const h = Math.min(0.1 * R, limit * (0.03 + 0.6 * rand()));
        const f = doublyCurvedForward({ ...tool, pattern, feedRadiusMm: rf, crossRadiusMm: rc, scallopHeightMm: h });
        if (!Number.isFinite(f.intervalMm)) continue;
        const L = sig(f.intervalMm * (0.5 + 0.5 * rand()));
        yield {
          stratum: 'doubly-curved',
          mode: 'inverse',
          quantity: 'scallopHeight',
          inputs: {
            ...toolInputs(R, Rcr, rho, tilt, pattern),
            feedRadius: rf,
            crossRadius: rc,
            interval: L,
          },
          reference: () => polishedCusp({ R, Rcr, leadDeg: rho, tiltDeg: tilt }, pattern, rf, rc, L),
        } satisfies Draft;
        break;
      }
    }
  },
};
