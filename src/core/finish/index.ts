/**
 * The surface the teeth leave (issue 29, shared/notes/surface-finish.md): feed marks, the balanced
 * feed, the areal parameters, the height at any point and the areal map, on a plane at any lead and
 * tilt, one-way and zigzag (and so the three-axis sloped plane, in the posture its slope gives).
 *
 * Typical use (lengths mm):
 *
 *     const v = validateFinish(raw, tool.toolRadiusMm);           // flutes, fz, runout, phases
 *     const r = finishReport(tool, 'one-way', intervalMm, v.value);
 *     r.feedMarks.height; r.feedMarks.period; r.feedMarks.balancedFz; r.areal.Sa ...
 */
import type { PassPattern, ToolInput } from '../domain/tool';
import { arealParameters } from './areal';
import { finishFailureWords } from './envelope';
import { balancedFeed, feedMarks } from './feedMarks';
import type { FinishInput } from './finishInput';
import { toothModel } from './toothModel';

export * from './areal';
export * from './arealMap';
export * from './feedMarks';
export * from './finishInput';
export * from './finishScope';
export { envelopeHeightMm, RunoutRow, runoutEnvelopeHeightMm } from './runout';
export { runoutLowestMm } from './runoutLine';
export * from './toothModel';

/** The finish a pass leaves, as the command line's JSON reports it (mm; Ssk, Sku dimensionless). */
export interface FinishReport {
  readonly feedMarks: {
    /** hf along the CC path. */
    readonly height: number;
    /** Feed period: fz, or z fz with runout. */
    readonly period: number;
    /** fz* (hf = h), or null where there is none (no scallop, or marks below it at every fz). */
    readonly balancedFz: number | null;
  };
  /** The areal parameters, or null where the surface is not defined (see {@link arealRefusal}). */
  readonly areal: {
    readonly Sa: number;
    readonly Sq: number;
    readonly Sz: number;
    readonly Sp: number;
    readonly Sv: number;
    readonly Ssk: number;
    readonly Sku: number;
  } | null;
  /**
   * Why there are no areal parameters (a flat end lying flat leaves slivers between the passes that
   * no tooth cuts: envelope.ts finishFailureWords), one line; null when they are given.
   */
  readonly arealRefusal: string | null;
}

/**
 * The feed marks, balanced feed and areal parameters of passes `intervalMm` apart on a plane (tool
 * and posture validated, L valid for them, finish validated), with or without runout.
 */
export function finishReport(
  tool: ToolInput,
  pattern: PassPattern,
  intervalMm: number,
  finish: FinishInput,
): FinishReport {
  const m = toothModel({ tool, pattern, intervalMm, finish });
  const marks = feedMarks(m);
  const balanced = balancedFeed(tool, pattern, intervalMm, finish);
  const feed = {
    height: marks.heightMm,
    period: marks.periodMm,
    balancedFz: balanced.ok ? balanced.feedPerToothMm : null,
  };
  let a: ReturnType<typeof arealParameters>;
  try {
    a = arealParameters(m);
  } catch (e) {
    // The feed marks stand; only the areal surface is refused, in one line.
    const refusal = finishFailureWords(e, 'areal');
    if (refusal === null) throw e;
    return { feedMarks: feed, areal: null, arealRefusal: refusal };
  }
  return {
    feedMarks: feed,
    areal: { Sa: a.saMm, Sq: a.sqMm, Sz: a.szMm, Sp: a.spMm, Sv: a.svMm, Ssk: a.ssk, Sku: a.sku },
    arealRefusal: null,
  };
}
