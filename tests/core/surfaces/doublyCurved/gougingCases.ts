/**
 * Gouging limits checked by brute force (tests/support/reference/doublyCurvedBruteForce.ts): just
 * inside the limit (8 %) the sampled swept tool reaches inside the surface, just outside it does not
 * (below minus the sweep's sagitta). Cases: troughs both ways (the existing cylinder rule), a bowl, a
 * saddle each way, a tilted ball end whose shank binds, and two saddles where a convex radius must be
 * at most a value (found by a search over random postures, seeds 5 and 7).
 */
import { expect } from 'vitest';
import type { ToolInput } from '../../../../src/core/input/validate';
import { doublyCurvedGouges, doublyCurvedRadiusLimit } from '../../../../src/core/surfaces/doublyCurved/gouging';
import { bruteForceLowestRadialHeight } from '../../../support/reference/doublyCurvedBruteForce';

export interface GougingCase {
  readonly tool: ToolInput;
  readonly rf: number;
  readonly rc: number;
  readonly which: 'feed' | 'cross';
  readonly kind: 'concave-at-least' | 'convex-at-most';
}

const I = Number.POSITIVE_INFINITY;
const t = (R: number, Rcr: number, rho: number, tilt: number): ToolInput => ({
  toolRadiusMm: R,
  cornerRadiusMm: Rcr,
  leadAngleDeg: rho,
  tiltAngleDeg: tilt,
});

export const GOUGING_CASES: readonly GougingCase[] = [
  { tool: t(3, 1, 5, 0), rf: I, rc: -30, which: 'cross', kind: 'concave-at-least' },
  { tool: t(3, 1, 5, 0), rf: -30, rc: I, which: 'feed', kind: 'concave-at-least' },
  { tool: t(3, 1, 5, 8), rf: 40, rc: -30, which: 'cross', kind: 'concave-at-least' },
  { tool: t(3, 1, 5, 8), rf: -40, rc: 25, which: 'feed', kind: 'concave-at-least' },
  { tool: t(3, 3, 10, 20), rf: I, rc: -10, which: 'cross', kind: 'concave-at-least' },
  { tool: t(4, 1, 30, -30), rf: -20, rc: -20, which: 'feed', kind: 'concave-at-least' },
  {
    tool: t(3, 0.417192475637421, 44.73893790389411, 5.3511931374669075),
    rf: -15.870579697191715,
    rc: I,
    which: 'cross',
    kind: 'convex-at-most',
  },
  {
    tool: t(3, 0, 39.78857279405929, 38.88319356366992),
    rf: I,
    rc: -70.28038607165217,
    which: 'feed',
    kind: 'convex-at-most',
  },
];

export function describeCase(c: GougingCase): string {
  const { toolRadiusMm: R, cornerRadiusMm: k, leadAngleDeg: rho, tiltAngleDeg: tilt } = c.tool;
  return `R ${R} Rcr ${k} rho ${rho} tilt ${tilt}, Rf ${c.rf} Rc ${c.rc}: ${c.which} radius ${c.kind}`;
}

/** Checks a case: its limit's kind, and the brute force on either side of it. */
export function checkGougingCase(c: GougingCase): void {
  const limit = doublyCurvedRadiusLimit(c.tool, { feedRadiusMm: c.rf, crossRadiusMm: c.rc }, c.which);
  expect(limit.kind).toBe(c.kind);
  const radius = limit.radiusMm as number;
  const { toolRadiusMm: R, cornerRadiusMm: k, leadAngleDeg: rho, tiltAngleDeg: tilt } = c.tool;
  for (const [factor, gouges] of [
    [0.92, true],
    [1.08, false],
  ] as const) {
    // Inside the limit: a tighter concave radius, or a flatter convex one.
    const r = c.kind === 'concave-at-least' ? -radius * factor : radius / factor;
    const rf = c.which === 'feed' ? r : c.rf;
    const rc = c.which === 'cross' ? r : c.rc;
    expect(doublyCurvedGouges(c.tool, { feedRadiusMm: rf, crossRadiusMm: rc }), `x${factor}`).toBe(gouges);
    const cap = Math.min(rf < 0 ? -rf : I, rc < 0 ? -rc : I);
    const deg = Math.PI / 180;
    const b = bruteForceLowestRadialHeight({ R, Rcr: k, leadDeg: rho, tiltDeg: tilt }, rf, rc, {
      spacingMm: 0.03,
      excludeMm: 0.05,
      shankLengthMm: Number.isFinite(cap) ? (cap + R) / (Math.cos(rho * deg) * Math.cos(tilt * deg)) + R : R,
      capMm: cap,
      shankAxialMm: Number.isFinite(cap) ? Math.max(0.05, cap / 700) : 0.05,
    });
    if (gouges) expect(b.lowestMm, `x${factor}`).toBeLessThan(-b.sagittaMm - 1e-5);
    else expect(b.lowestMm, `x${factor}`).toBeGreaterThan(-b.sagittaMm);
  }
}
