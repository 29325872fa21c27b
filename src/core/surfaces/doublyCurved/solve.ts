/**
 * Exact step-over and cusp heights at a doubly curved point (shared/notes/doubly-curved-and-3-axis.md,
 * section 1), one-way and zigzag, any posture: the flanks of passSection.ts seen from `m`
 * (equatorFlank.ts), combined as on a plane (posture-and-surfaces.md, "Pass patterns"):
 *
 * - one-way: the cusp between pass k and k + 1 joins the right flank of k and the left flank of k + 1
 *   turned by phi about m, so `L = wR(h) + wL(h)` (reaches as arc lengths along the equator);
 * - zigzag: every other pass is mirrored in Y (the patch is symmetric in Y), cusps alternate between
 *   two right flanks (where `wR = L/2`) and two left flanks; for no cusp above h,
 *   `L = 2 min(wR(h), wL(h))`, and the other cusp is the wider flank's height at L/2.
 *
 * Rf infinite gives the cylinder with its axis along the feed (cylinder.ts, Rs = Rc), Rc infinite
 * the cylinder across (Rs = Rf), both the plane (exact.ts); the tests check those to 1e-9 mm.
 * The contact offset is the plane's (the tool touches the patch where it touches the tangent
 * plane). Lengths mm.
 */

import type { ToolInput } from '../../domain/tool';
import { bracketedRoot, type Objective } from '../../math/rootFinder';
import { contactOffsetMm, flankLimitsOf, shapeOfTool } from '../../tool/posture';
import { cuspsAtHalfInterval, oneWayCusps } from '../../tool/stepOverRule';
import { type EquatorFlank, equatorFlank } from './equatorFlank';
import { passSection } from './passSection';
import { shankCutHeights } from './shankLimit';
import type {
  DoublyCurvedForward,
  DoublyCurvedForwardInput,
  DoublyCurvedInverse,
  DoublyCurvedInverseInput,
  DoublyCurvedLimits,
  DoublyCurvedPass,
  PrincipalRadii,
} from './types';

/** A doubly curved point prepared for one tool and posture: its two flanks. */
export interface DoublyCurvedSolver {
  readonly right: EquatorFlank;
  readonly left: EquatorFlank;
  /** Contact offset y0 (mm), as on the plane. */
  readonly contactOffsetMm: number;
  /** True without tilt: the flanks are mirror images. */
  readonly symmetric: boolean;
  /** The flank limits (radial, mm): the tops, and the shank where it starts to form a flank (shankLimit.ts). */
  limits(): DoublyCurvedLimits;
}

/**
 * Prepares the flanks of a tool in its posture at a doubly curved point.
 * @param tool validated tool and posture; @param radii signed Rf, Rc (|R| >= 0.001 mm or infinite).
 */
export function doublyCurvedSolver(tool: ToolInput, radii: PrincipalRadii): DoublyCurvedSolver {
  const section = passSection(tool, radii.feedRadiusMm);
  const right = equatorFlank(section, 1, radii.crossRadiusMm);
  const symmetric = tool.tiltAngleDeg === 0;
  const left = symmetric ? right : equatorFlank(section, -1, radii.crossRadiusMm);
  let cached: DoublyCurvedLimits | null = null;
  return {
    right,
    left,
    symmetric,
    contactOffsetMm: contactOffsetMm(shapeOfTool(tool)),
    limits() {
      if (cached === null) {
        const shank = shankCutHeights(tool, radii);
        // The shank first on a tie, as posture.ts.
        cached = flankLimitsOf(right.topMm(), left.topMm(), shank.rightMm, shank.leftMm);
      }
      return cached;
    },
  };
}

/**
 * Exact step-over L (mm, arc length along the equator) for a scallop height h, and the flank reaches,
 * contact offset and zigzag's other cusp. Error below 1e-9 mm for h below the flank limits and
 * without gouging (the caller validates both: doublyCurvedLimits, gouging.ts).
 */
export function doublyCurvedForward(input: DoublyCurvedForwardInput): DoublyCurvedForward {
  return forwardWith(doublyCurvedSolver(input, input), input.pattern, input.scallopHeightMm);
}

/** The forward answer with a prepared solver. */
export function forwardWith(
  solver: DoublyCurvedSolver,
  pattern: DoublyCurvedPass['pattern'],
  heightMm: number,
): DoublyCurvedForward {
  const h = heightMm;
  const wR = solver.right.reachMm(h);
  const wL = solver.symmetric ? wR : solver.left.reachMm(h);
  const L = pattern === 'one-way' ? wR + wL : 2 * Math.min(wR, wL);
  let other: number | null = null;
  if (pattern === 'zigzag') {
    const wider = wR > wL ? solver.right : solver.left;
    other = wR === wL ? h : Math.min(h, wider.heightAtMm(L / 2, h));
  }
  return {
    intervalMm: L,
    halfWidthRightMm: wR,
    halfWidthLeftMm: wL,
    contactOffsetMm: solver.contactOffsetMm,
    cuspHeightMm: h,
    otherCuspHeightMm: other,
  };
}

/**
 * Exact step-over alone (mm) with a prepared solver: the fast path of {@link forwardWith} (no zigzag
 * other cusp). @param heightMm below the flank limits.
 */
export function intervalWith(
  solver: DoublyCurvedSolver,
  pattern: DoublyCurvedPass['pattern'],
  heightMm: number,
): number {
  const wR = solver.right.reachMm(heightMm);
  const wL = solver.symmetric ? wR : solver.left.reachMm(heightMm);
  return pattern === 'one-way' ? wR + wL : 2 * Math.min(wR, wL);
}

/**
 * Exact cusp heights (radial, mm) that passes L apart leave (L arc length along the equator).
 * Zigzag (or no tilt): each cusp is where a flank reaches L/2. One-way with tilt: the root of
 * `wR(z) + wL(z) = L`, by a bracketed Illinois search in `sqrt(z)` (both reaches grow like sqrt(z)
 * near the contact).
 * @param input validated; 0 < L below the reach at the limit height.
 */
export function doublyCurvedInverse(input: DoublyCurvedInverseInput): DoublyCurvedInverse {
  return inverseWith(doublyCurvedSolver(input, input), input.pattern, input.intervalMm);
}

/** The inverse answer with a prepared solver. */
export function inverseWith(
  solver: DoublyCurvedSolver,
  pattern: DoublyCurvedPass['pattern'],
  intervalMm: number,
): DoublyCurvedInverse {
  const L = intervalMm;
  if (pattern === 'zigzag' || solver.symmetric) {
    const hR = Math.max(0, solver.right.heightAtMm(L / 2));
    const hL = solver.symmetric ? hR : Math.max(0, solver.left.heightAtMm(L / 2));
    return cuspsAtHalfInterval(L, hR, hL, pattern === 'zigzag', solver.contactOffsetMm);
  }
  const z = oneWayCuspMm(solver, L);
  return oneWayCusps(L, z, solver.right.reachMm(z), solver.left.reachMm(z), solver.contactOffsetMm);
}

/** `wR(u^2) + wL(u^2) - L`: the one-way cusp's mismatch at height u^2 (u in sqrt(mm)). */
class OneWayMismatch implements Objective {
  constructor(
    private readonly solver: DoublyCurvedSolver,
    private readonly L: number,
  ) {}
  value(u: number): number {
    return this.solver.right.reachMm(u * u) + this.solver.left.reachMm(u * u) - this.L;
  }
}

/**
 * The one-way cusp height for a step-over L: wR(z) + wL(z) = L, by the shared bracketed root
 * (Illinois) in u = sqrt(z), where the reaches grow nearly linearly.
 */
function oneWayCuspMm(solver: DoublyCurvedSolver, L: number): number {
  const f = new OneWayMismatch(solver, L);
  const hi = Math.sqrt(solver.limits().limitMm);
  const fLo = f.value(0);
  const fHi = f.value(hi);
  // A flat face already covers L: no scallop.
  if (fLo >= 0) return 0;
  if (fHi <= 0) return hi * hi;
  return bracketedRoot(f, 0, hi, fLo, fHi, 1e-16) ** 2;
}

/** The flank limits (radial heights, mm) of a tool at a doubly curved point. */
export function doublyCurvedLimits(pass: ToolInput & PrincipalRadii): DoublyCurvedLimits {
  return doublyCurvedSolver(pass, pass).limits();
}

/**
 * The widest step-over (mm) that leaves a scallop at a doubly curved point: the flanks' reaches at
 * the limit height (one-way their sum, zigzag twice the smaller).
 */
export function doublyCurvedMaxIntervalMm(solver: DoublyCurvedSolver, pattern: DoublyCurvedPass['pattern']): number {
  const h = solver.limits().limitMm;
  const right = solver.right.reachMm(h);
  const left = solver.symmetric ? right : solver.left.reachMm(h);
  return pattern === 'one-way' ? right + left : 2 * Math.min(right, left);
}
