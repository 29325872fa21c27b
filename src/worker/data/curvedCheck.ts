/**
 * The checks of a doubly curved question beyond the tool's own (validate.ts checks the tool and
 * posture): each radius in range (0.001 mm to 1e6 mm, or straight), no gouging (gouging.ts: on the
 * field of each radius whose change would help, with its limit, the other held), the scallop height
 * below the flank and shank limits, the step-over below the widest that leaves a scallop, a target
 * Ra below the largest that the passes leave while leaving a scallop: the limits, the widest
 * step-over and the largest Ra from the registry's model (core surfaces/doublyCurvedPoint.ts), as
 * the answer. They need the point's model, so they run once, in the worker (jobs/curved.ts, which trusts no caller): the page validates the
 * tool and posture only and words this reply's refusals (ui/curvedRequest.ts). Mm.
 */

import type { PassPattern, ToolInput } from '../../core/input/validate';
import { doublyCurvedMaxRaMm } from '../../core/roughness/doublyCurved';
import {
  curvedRadiusInRange,
  doublyCurvedGouges,
  doublyCurvedGouging,
  type PrincipalRadii,
  type RadiusLimit,
} from '../../core/surfaces/doublyCurved';
import {
  type CurvedPoint,
  curvedLimits,
  curvedMaxIntervalMm,
  curvedPoint,
} from '../../core/surfaces/doublyCurvedPoint';
import type { CurvedError } from '../pageProtocol';
import type { SliderLimits } from '../protocol';

/** True for a radius the model takes: straight (infinite), or a magnitude from 0.001 mm to 1e6 mm. */
function radiusInRange(radiusMm: number): boolean {
  return Math.abs(radiusMm) === Number.POSITIVE_INFINITY || curvedRadiusInRange(radiusMm);
}

/** A limit that a change of its radius can meet (not `any`: that radius is not the cause; not `none`). */
function helps(limit: RadiusLimit): boolean {
  return limit.kind === 'concave-at-least' || limit.kind === 'convex-at-most' || limit.kind === 'not-concave';
}

/**
 * The radii's errors: out of range, or gouging. A gouging point puts its message on each radius
 * whose change would avoid it (its limit, the other held); where neither would, on both ("at any
 * radius").
 */
export function curvedRadiusErrors(tool: ToolInput, radii: PrincipalRadii): CurvedError[] {
  const out: CurvedError[] = [];
  if (!radiusInRange(radii.feedRadiusMm))
    out.push({ field: 'feedRadius', code: 'out-of-range', gotMm: radii.feedRadiusMm });
  if (!radiusInRange(radii.crossRadiusMm))
    out.push({ field: 'crossRadius', code: 'out-of-range', gotMm: radii.crossRadiusMm });
  if (out.length > 0 || !doublyCurvedGouges(tool, radii)) return out;
  const g = doublyCurvedGouging(tool, radii);
  const feedHelps = helps(g.feed);
  const crossHelps = helps(g.cross);
  if (feedHelps || !crossHelps)
    out.push({ field: 'feedRadius', code: 'gouging', limit: g.feed, otherMm: radii.crossRadiusMm });
  if (crossHelps || !feedHelps)
    out.push({ field: 'crossRadius', code: 'gouging', limit: g.cross, otherMm: radii.feedRadiusMm });
  return out;
}

/**
 * Every check of a doubly curved question whose tool and posture are valid: the radii, then the
 * scallop height (forward), the target Ra or the step-over (inverse) against this point's limits.
 * @param question `{ h }` forward, `{ ra }` a target Ra, or `{ interval }` inverse, mm.
 */
export function curvedErrors(
  tool: ToolInput,
  radii: PrincipalRadii,
  pattern: PassPattern,
  question: { readonly h: number } | { readonly ra: number } | { readonly interval: number },
): CurvedError[] {
  const radiusErrors = curvedRadiusErrors(tool, radii);
  if (radiusErrors.length > 0) return radiusErrors;
  const point = curvedPoint(tool, radii, pattern);
  const limits = curvedLimits(point);
  if ('h' in question) {
    if (!(question.h < limits.limitMm))
      return [{ field: 'h', code: 'above-limit', limitMm: Math.max(0, limits.limitMm), limitBy: limits.limitBy }];
    return [];
  }
  if ('ra' in question) {
    const maxRaMm = limits.limitMm > 0 ? maxRaAt(point) : 0;
    return question.ra < maxRaMm ? [] : [{ field: 'ra', code: 'beyond-max-ra', maxMm: maxRaMm }];
  }
  const maxMm = curvedMaxIntervalMm(point);
  return question.interval < maxMm ? [] : [{ field: 'interval', code: 'beyond-max', maxMm }];
}

/** The last largest Ra worked out (a few ms): the check and the sliders' limits ask it of one request. */
let lastRa: { key: string; value: number } | null = null;

/** doublyCurvedMaxRaMm, remembered for the last tool, pattern and radii. */
function maxRaAt(c: CurvedPoint): number {
  const { tool, surface } = c;
  const key = JSON.stringify([
    tool.toolRadiusMm,
    tool.cornerRadiusMm,
    tool.leadAngleDeg,
    tool.tiltAngleDeg,
    c.pattern,
    surface.feedRadiusMm,
    surface.crossRadiusMm,
  ]);
  if (lastRa?.key !== key) lastRa = { key, value: doublyCurvedMaxRaMm(c) };
  return lastRa.value;
}

/**
 * A doubly curved point's sliders' limits (protocol.ts SliderLimits) for a valid tool and posture
 * and radii that curvedRadiusErrors takes (in range, no gouging), from the point's model: the
 * scallop height below the flank and shank limits, the widest step-over that leaves a scallop and,
 * while Ra is the target, the largest Ra.
 */
export function curvedSliderLimits(c: CurvedPoint, raTarget: boolean): SliderLimits {
  const hMm = curvedLimits(c).limitMm;
  return {
    hMm,
    intervalMm: curvedMaxIntervalMm(c),
    raMm: raTarget && hMm > 0 ? maxRaAt(c) : null,
    concaveMinMm: 0,
  };
}
