/**
 * The worker's `targetSa` job (src/worker/jobs/targetSa.ts) and the page's question
 * (src/ui/targetSaRequest.ts): the reply echoes its request; runout is refused in one line on its
 * field, named as such; a missing flutes field is named on it, its data beside its English; the best pair's Sa is the target within 1e-6
 * relative, checked with the full areal parameters on a fresh tooth model at that pair; the scallop
 * h is the continuous inverse's at the best step-over; the page asks only of a target Ra's plane answer.
 */
import { describe, expect, it } from 'vitest';
import { arealParameters } from '../../src/core/finish/areal';
import { toothModel } from '../../src/core/finish/toothModel';
import { forwardInput, inverseInput } from '../../src/core/input/validate';
import { validateRaTarget } from '../../src/core/roughness/raTarget';
import { exactInverse } from '../../src/core/surfaces/solve';
import { targetSaAsk } from '../../src/ui/targetSaRequest';
import { solve } from '../../src/worker/jobs/solve';
import { targetSa } from '../../src/worker/jobs/targetSa';
import type { PageReply } from '../../src/worker/pageProtocol';
import { finishInputsOf } from '../support/finishInputs';

const TOOL = { R: 3, Rcr: 1, rho: 5, tilt: 0, pattern: 'one-way' };
const TARGET_SA_MM = 0.0008;

function raReply(sa: number): PageReply {
  const v = validateRaTarget({ ...TOOL, ra: sa });
  if (!v.ok) throw new Error('invalid');
  return solve({ mode: 'ra', input: v.value }) as PageReply;
}

describe('the targetSa job', () => {
  const reply = raReply(TARGET_SA_MM);

  it('asks only of a target Ra answer on a plane, with the teeth fields (not the feed)', () => {
    const request = targetSaAsk(finishInputsOf({ flutes: 4, fz: 0.1 }), reply);
    expect(request?.targetSaMm).toBe(TARGET_SA_MM);
    expect(request?.values).toEqual({ flutes: 4, runout: undefined, runoutPhase: undefined, passPhase: undefined });
    // A forward answer (h given) asks nothing: the page's target Sa is asked as a target Ra.
    const tool = { toolRadiusMm: 3, cornerRadiusMm: 1, leadAngleDeg: 5, tiltAngleDeg: 0 };
    const forward = solve({ mode: 'forward', input: forwardInput(tool, 'one-way', 0.05) }) as PageReply;
    expect(targetSaAsk(finishInputsOf({ flutes: 4 }), forward)).toBeNull();
    expect(targetSaAsk(finishInputsOf({ flutes: 4 }), null)).toBeNull();
  });

  it('refuses runout in one line on its field, and a missing flutes field on that field (reply echoes its input)', () => {
    const base = targetSaAsk(finishInputsOf({ flutes: 4, runout: 0.002 }), reply);
    if (base === null) throw new Error('not asked');
    const r = targetSa(base);
    expect(r.request).toBe(base);
    expect(r.ok).toBe(false);
    if (r.ok) return;
    expect(r.errors).toEqual([
      { field: 'runout', message: expect.stringMatching(/^Target Sa is computed without runout/), refusal: 'runout' },
    ]);
    const none = targetSaAsk(finishInputsOf({ runoutPhase: 10 }), reply);
    if (none === null) throw new Error('not asked');
    const n = targetSa(none);
    expect(n.ok).toBe(false);
    if (!n.ok) expect(n.errors.map((e) => e.field)).toEqual(['flutes']);
    // Each teeth refusal carries its data beside its English (a page words it in its language).
    if (!n.ok) expect(n.errors[0]?.error).toEqual({ field: 'flutes', code: 'missing', got: '' });
  });

  it('the best pair leaves the target Sa within 1e-6 relative (full areal parameters, fresh model; z = 4)', () => {
    const request = targetSaAsk(finishInputsOf({ flutes: 4 }), reply);
    if (request === null) throw new Error('not asked');
    const r = targetSa(request);
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    expect(r.request).toBe(request);
    const { best, curve, zeroFeedIntervalMm } = r.answer;
    expect(best.feedLimited).toBe(false);
    expect(best.intervalMm).toBeGreaterThan(0);
    expect(best.intervalMm).toBeLessThan(zeroFeedIntervalMm);
    const m = toothModel({
      tool: request.pass,
      pattern: request.pass.pattern,
      intervalMm: best.intervalMm,
      finish: { flutes: 4, feedPerToothMm: best.feedPerToothMm, runoutMm: 0, runoutPhaseDeg: 0, passPhase: 0 },
    });
    const sa = arealParameters(m).saMm;
    expect(Math.abs(sa - TARGET_SA_MM) / TARGET_SA_MM).toBeLessThan(1e-6);
    // The largest L * fz of the curve's pairs is not above the best's by more than the quick Sa's slack.
    const area = best.intervalMm * best.feedPerToothMm;
    for (const p of curve) expect(p.intervalMm * p.feedPerToothMm).toBeLessThan(area * 1.01);
    const h = exactInverse(inverseInput(request.pass, 'one-way', best.intervalMm, request.pass.surface)).cuspHeightMm;
    expect(r.answer.bestScallopHeightMm).toBe(h);
  });
});
