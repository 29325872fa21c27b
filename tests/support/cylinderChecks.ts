/**
 * Shared checks of the cylinder tests (issue 17, items 8-10): a solver's step-overs and height
 * limits against the polished brute force of reference/cylinderReach.ts.
 */
import { expect } from 'vitest';
import { forwardInput, type PassPattern, type ToolInput } from '../../src/core/input/validate';
import { type CylinderSurface, cylinderSolver } from '../../src/core/surfaces/cylinder';
import { exactForward, exactIntervalMm } from '../../src/core/surfaces/solve';
import { type CylinderReachReference, cylinderReach } from './reference/cylinderReach';

/** Step-overs agree with the reference to this, mm (issue 7). */
export const TOL_MM = 1e-9;

export const tool = (R: number, Rcr: number, rho: number, tilt: number): ToolInput => ({
  toolRadiusMm: R,
  cornerRadiusMm: Rcr,
  leadAngleDeg: rho,
  tiltAngleDeg: tilt,
});
export const cyl = (radiusMm: number, axis: 'feed' | 'cross'): CylinderSurface => ({
  kind: 'cylinder',
  radiusMm,
  axis,
});

/** Reach converted to length along the surface (arc length for axis = feed). */
export const scaleOf = (s: CylinderSurface) => (s.axis === 'feed' ? Math.abs(s.radiusMm) : 1);

/**
 * The reference step-over, by the definitions of notes/posture-and-surfaces.md written out here:
 * one-way the two flanks' reaches added, zigzag twice the smaller; the real tool with its shank.
 */
export function referenceIntervalMm(ref: CylinderReachReference, s: CylinderSurface, pattern: PassPattern, h: number) {
  const right = ref.reach('right', h, true);
  const left = ref.reach('left', h, true);
  return scaleOf(s) * (pattern === 'one-way' ? right + left : 2 * Math.min(right, left));
}

/**
 * What the reference sees at a limit on its side (mm): the shank's effect (with minus without) just
 * below and just above it, or the tool end's growth just below and just above it.
 */
export function shankSeen(ref: CylinderReachReference, s: CylinderSurface, side: 'right' | 'left', limitMm: number) {
  const shank = (f: number) => scaleOf(s) * (ref.reach(side, f * limitMm, true) - ref.reach(side, f * limitMm, false));
  return { below: shank(0.9999), above: shank(1.001) };
}
export function growthSeen(ref: CylinderReachReference, s: CylinderSurface, side: 'right' | 'left', limitMm: number) {
  const end = (f: number) => scaleOf(s) * ref.reach(side, f * limitMm, false);
  const at = end(1);
  return { below: at - end(0.999), above: end(1.001) - at };
}

/**
 * The same reference, each reach computed once: one-way and zigzag at a height ask for the same
 * two reaches (a reach is a deterministic search of 10-40 ms; the case's checks asked 19, 6 twice).
 */
function remembered(ref: CylinderReachReference): CylinderReachReference {
  const known = new Map<string, number>();
  return {
    ...ref,
    reach(flank, heightMm, withShank) {
      const key = `${flank} ${heightMm} ${withShank}`;
      let r = known.get(key);
      if (r === undefined) {
        r = ref.reach(flank, heightMm, withShank);
        known.set(key, r);
      }
      return r;
    },
  };
}

/**
 * Checks a valid case: L (both patterns, the fast path and the full answer) against the reference
 * at fractions of the height limit, and the limit against what the reference sees there.
 */
export function checkCase(t: ToolInput, s: CylinderSurface, label: string): { limitBy: string } {
  const solver = cylinderSolver(t, s);
  const limits = solver.limits();
  expect(limits.limitMm, `limit ${label}`).toBeGreaterThan(1e-9);
  const ref = remembered(cylinderReach(t, s.radiusMm, s.axis, { ringSamples: 360 }));
  for (const f of [1e-6, 0.3, 0.999]) {
    const h = f * limits.limitMm;
    for (const pattern of ['one-way', 'zigzag'] as const) {
      const want = referenceIntervalMm(ref, s, pattern, h);
      const input = forwardInput(t, pattern, h, s);
      expect(Math.abs(exactIntervalMm(input) - want), `${pattern} h=${h} ${label}`).toBeLessThan(TOL_MM);
      expect(Math.abs(exactForward(input).intervalMm - want), `${pattern} h=${h} ${label}`).toBeLessThan(TOL_MM);
    }
  }
  const side = limits.limitBy.endsWith('right') ? 'right' : 'left';
  if (limits.limitBy.startsWith('shank')) {
    // Up to the limit the shank shapes nothing; just above it, it does (growing like (h - limit)^2).
    const seen = shankSeen(ref, s, side, limits.limitMm);
    expect(Math.abs(seen.below), `shank below ${label}`).toBeLessThan(1e-11);
    expect(seen.above, `shank above ${label}`).toBeGreaterThan(1e-11);
  } else if (s.radiusMm > 0 || s.axis === 'cross') {
    // A wall: the tool end's reach grows up to the limit and no further. (In a trough along the
    // feed the limit is the plane's widest point, which the flank may outgrow: a safe side.)
    const seen = growthSeen(ref, s, side, limits.limitMm);
    expect(seen.below, `growth below ${label}`).toBeGreaterThan(1e-10);
    expect(Math.abs(seen.above), `growth above ${label}`).toBeLessThan(1e-12);
  }
  return { limitBy: limits.limitBy };
}
