/**
 * The exact answer as every view takes it (ExactSummary): the step-over, the flank widths and the
 * two cusps of this pass (where they stand and how high), from the forward or the inverse
 * comparison. Mm.
 */

import type { ForwardInput, InverseInput } from '../../core/input/validate';
import type { compareForward, compareInverse } from '../../core/procedures/compare';
import { maxIntervalMm } from '../../core/surfaces/validate';
import type { Cusp, ExactSummary } from '../protocol';

/** The exact answer of a forward comparison: on zigzag passes, the cusps at L/2 either side. */
export function exactOfForward(input: ForwardInput, c: ReturnType<typeof compareForward>): ExactSummary {
  const e = c.exact;
  const h = e.cuspHeightMm;
  const L = e.intervalMm;
  let right: Cusp;
  let left: Cusp;
  if (input.pattern === 'one-way') {
    right = { yMm: e.halfWidthRightMm, heightMm: h };
    left = { yMm: -e.halfWidthLeftMm, heightMm: h };
  } else {
    // Zigzag: the narrower flank meets its mirror at h, the wider one lower (both at L/2).
    const other = e.otherCuspHeightMm ?? h;
    const rightNarrower = e.halfWidthRightMm <= e.halfWidthLeftMm;
    right = { yMm: L / 2, heightMm: rightNarrower ? h : other };
    left = { yMm: -L / 2, heightMm: rightNarrower && e.halfWidthRightMm !== e.halfWidthLeftMm ? other : h };
  }
  return {
    pattern: input.pattern,
    intervalMm: L,
    halfIntervalMm: e.halfIntervalMm,
    widthRightMm: e.halfWidthRightMm,
    widthLeftMm: e.halfWidthLeftMm,
    contactOffsetMm: e.contactOffsetMm,
    cuspHeightMm: h,
    otherCuspHeightMm: e.otherCuspHeightMm,
    right,
    left,
    noScallop: e.noScallop,
    maxIntervalMm: c.maxIntervalMm,
  };
}

/** The exact answer of an inverse comparison: the cusps' own heights at the step-over. */
export function exactOfInverse(input: InverseInput, c: ReturnType<typeof compareInverse>): ExactSummary {
  const e = c.exact;
  const L = e.intervalMm;
  const zigzag = input.pattern === 'zigzag';
  return {
    pattern: input.pattern,
    intervalMm: L,
    halfIntervalMm: L / 2,
    widthRightMm: e.halfWidthRightMm,
    widthLeftMm: e.halfWidthLeftMm,
    contactOffsetMm: e.contactOffsetMm,
    cuspHeightMm: e.cuspHeightMm,
    otherCuspHeightMm: e.otherCuspHeightMm,
    right: { yMm: zigzag ? L / 2 : e.halfWidthRightMm, heightMm: e.rightCuspHeightMm },
    left: { yMm: zigzag ? -L / 2 : -e.halfWidthLeftMm, heightMm: e.leftCuspHeightMm },
    noScallop: false,
    maxIntervalMm: maxIntervalMm(input, input.pattern, input.surface),
  };
}
