/**
 * The sliders' limits of a plane's or a cylinder's question (protocol.ts SliderLimits), worked out
 * in the worker beside its answer or its refusal: h below the surface model's scallop-height limit,
 * L below its widest step-over, Ra below the largest Ra (only while Ra is the target), a concave
 * cylinder's radius from the smallest that does not gouge. A concave cylinder too tight for the
 * tool is ranged as the plane. Mm.
 */
import type { PassInput } from '../../core/domain/pass';
import { PLANE } from '../../core/domain/surface';
import { maxRaCachedMm } from '../../core/roughness/raTarget';
import { minConcaveRadiusMm } from '../../core/surfaces/cylinder';
import { maxIntervalMm, scallopHeightLimits } from '../../core/surfaces/validate';
import type { SliderLimits, SolveRequest } from '../protocol';

/** Limits whose every number is finite (Infinity allowed for the concave radius), else null. */
export function finiteLimits(compute: () => SliderLimits | null): SliderLimits | null {
  try {
    const l = compute();
    if (l === null) return null;
    const ok = (v: number | null) => v === null || Number.isFinite(v);
    return Number.isFinite(l.hMm) && ok(l.intervalMm) && ok(l.raMm) && !Number.isNaN(l.concaveMinMm) ? l : null;
  } catch {
    // A request the worker refuses may hold a tool no solver takes: no limits then.
    return null;
  }
}

/** The sliders' limits of a plane's or a cylinder's request (answered or refused); null where none make sense. */
export function classicSliderLimits(request: SolveRequest): SliderLimits | null {
  return finiteLimits(() => {
    const i = request.input;
    const s = i.surface;
    const concave = s.kind === 'cylinder' && s.radiusMm < 0;
    const concaveMinMm = concave ? minConcaveRadiusMm(i, s.axis) : 0;
    const surface = concave && !(-s.radiusMm >= concaveMinMm) ? PLANE : s;
    const pass: PassInput = { ...i, surface };
    return {
      hMm: scallopHeightLimits(i, surface).limitMm,
      intervalMm: maxIntervalMm(i, i.pattern, surface),
      raMm: request.mode === 'ra' ? maxRaCachedMm(pass) : null,
      concaveMinMm,
    };
  });
}
