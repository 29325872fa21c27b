/**
 * The cross-feed profile at a doubly curved point (issue 19): the section across the feed is the
 * circle of radius Rc (the drawing's surface is then the cylinder of radius Rc with its axis along
 * the feed: surfaceGeometry.ts maps arc length and radial height to the section), one pass's
 * profile in those coordinates from its two flanks seen from `m` (the registry's model's flank
 * widths: reach at each radial height), the cusps the exact answer leaves (the model's inverse), and where the plane's, each cylinder's and the
 * corrected procedures' step-overs put the next pass (core compareDoublyCurved). Mm.
 */
import type { PassPattern, ToolInput } from '../../core/input/validate';
import { compareDoublyCurved, type DoublyCurvedRow } from '../../core/procedures/compareDoublyCurved';
import { CORRECTED_KEYS, correctedRowKey } from '../../core/procedures/procedures';
import type { PrincipalRadii } from '../../core/surfaces/doublyCurved';
import {
  type CurvedPoint,
  curvedFlankWidths,
  curvedInverse,
  curvedLimits,
  curvedMaxIntervalMm,
  curvedPoint,
} from '../../core/surfaces/doublyCurvedPoint';
import type { ExactSummary } from '../protocol';
import type { CurvedMark, CurvedSectionData } from '../teachProtocol';

/** Heights sampled on each flank (squared spacing: the reach grows like sqrt(h) near the contact). */
const FLANK_SAMPLES = 64;

/**
 * One pass's profile (flat s, h pairs, s ascending): the left flank from its top down to the
 * contact, then the right flank up to its top; s the reach along the equator (arc length), h
 * radial. The top is each flank's widest point seen from `m`, a hair inside.
 */
export function curvedPassProfile(c: CurvedPoint): Float64Array {
  const limits = curvedLimits(c);
  const reach = curvedFlankWidths(c);
  const flank = (sign: 1 | -1): number[] => {
    const f = sign > 0 ? 'right' : 'left';
    const top = (sign > 0 ? limits.topRightMm : limits.topLeftMm) * (1 - 1e-9);
    const pts: number[] = [];
    for (let i = 1; i <= FLANK_SAMPLES; i++) {
      const h = top * (i / FLANK_SAMPLES) ** 2;
      const s = reach(f, h);
      if (Number.isFinite(s)) pts.push(sign * s + 0, h);
    }
    return pts;
  };
  const right = flank(1);
  const left = flank(-1);
  const out: number[] = [];
  for (let i = left.length - 2; i >= 0; i -= 2) out.push(left[i] as number, left[i + 1] as number);
  out.push(0, 0);
  out.push(...right);
  return Float64Array.from(out);
}

/** The exact answer as the profile drawing reads it, from the step-over L (mm). */
export function curvedExactSummary(c: CurvedPoint, intervalMm: number): ExactSummary {
  const pattern = c.pattern;
  const e = curvedInverse(c, intervalMm);
  const zig = pattern === 'zigzag';
  const right = { yMm: zig ? intervalMm / 2 : e.halfWidthRightMm, heightMm: e.rightCuspHeightMm };
  const left = { yMm: zig ? -intervalMm / 2 : -e.halfWidthLeftMm, heightMm: e.leftCuspHeightMm };
  return {
    pattern,
    intervalMm,
    halfIntervalMm: intervalMm / 2,
    widthRightMm: e.halfWidthRightMm,
    widthLeftMm: e.halfWidthLeftMm,
    contactOffsetMm: e.contactOffsetMm,
    cuspHeightMm: e.cuspHeightMm,
    otherCuspHeightMm: e.otherCuspHeightMm,
    right,
    left,
    noScallop: false,
    maxIntervalMm: curvedMaxIntervalMm(c),
  };
}

const markOf = (key: CurvedMark['key'], row: DoublyCurvedRow): CurvedMark => ({
  key,
  intervalMm: row.ok ? row.intervalMm : null,
});

/**
 * The profile view's data at a doubly curved point, for the scallop height h (forward; in inverse
 * mode the solved one). @param tool validated tool and posture, not gouging at `radii`.
 */
export function curvedSection(
  tool: ToolInput,
  radii: PrincipalRadii,
  pattern: PassPattern,
  hMm: number,
): CurvedSectionData {
  const point = curvedPoint(tool, radii, pattern);
  const c = compareDoublyCurved({ ...tool, ...radii, pattern, scallopHeightMm: hMm });
  const comparison: CurvedMark[] = [
    markOf('plane', c.plane),
    markOf('cylinderAlong', c.cylinderAlong),
    markOf('cylinderAcross', c.cylinderAcross),
    ...CORRECTED_KEYS.map((key) => markOf(correctedRowKey(key), c.corrected[key])),
  ];
  return {
    toolRadiusMm: tool.toolRadiusMm,
    crossRadiusMm: radii.crossRadiusMm,
    feedRadiusMm: radii.feedRadiusMm,
    passProfile: curvedPassProfile(point),
    exact: curvedExactSummary(point, c.exact.intervalMm),
    comparison,
    untilted: tool.tiltAngleDeg === 0,
  };
}
