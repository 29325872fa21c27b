/**
 * The registries' promise, "one module and one line" (issue 27 point 3): a throwaway surface
 * (tests/support/throwaway/drumSurface.ts) and a throwaway machine mode (fixedLeadMode.ts), each one
 * module and one registry line (registerSurfaceModel, registerMode: from this test), are validated
 * and answered by the core's one question (surfaces/question.ts) and by the worker's one `solve`
 * job (workerApi.ts: the lazily loaded page job) with no other change; a combination the mode has
 * no posture for is refused in its one line; removing them leaves both registries and every answer
 * as before.
 */
import { afterEach, describe, expect, it } from 'vitest';
import { modeKinds, registerMode } from '../../src/core/surfaces/modes';
import { type Question, validateQuestion } from '../../src/core/surfaces/question';
import { registerSurfaceModel, surfaceKinds } from '../../src/core/surfaces/registry';
import { exactForward, exactInverse } from '../../src/core/surfaces/solve';
import type { QuestionReply, QuestionRequest } from '../../src/worker/pageProtocol';
import { workerApi } from '../../src/worker/workerApi';
import { DRUM_AS_CYLINDER, drumModel } from '../support/throwaway/drumSurface';
import { fixedLeadMode } from '../support/throwaway/fixedLeadMode';

const TOOL = { toolRadiusMm: 5, cornerRadiusMm: 1.5 };
const drumQuestion = (target: Question['target'], lead = 12): Question => ({
  tool: TOOL,
  mode: { kind: 'throwawayFixedLead', leadAngleDeg: lead } as Question['mode'],
  surface: { kind: 'throwawayDrum' },
  pattern: 'zigzag',
  target,
});
const productQuestion: Question = {
  tool: TOOL,
  mode: { kind: 'threeAxis', slopeDeg: 30, passes: 'raster', rasterAngleDeg: 20 } as Question['mode'],
  surface: { kind: 'plane' },
  pattern: 'one-way',
  target: { quantity: 'h', mm: 0.01 },
};

async function ask(input: Question): Promise<QuestionReply> {
  const request: QuestionRequest = { mode: 'question', input };
  return (await workerApi.solve(request)) as QuestionReply;
}

let removers: Array<() => void> = [];
afterEach(() => {
  for (const remove of removers) remove();
  removers = [];
});

describe('a throwaway surface and mode: one module and one line each', () => {
  it('unregistered, they are refused by validation and the worker, each in one line naming it', async () => {
    const v = validateQuestion(drumQuestion({ quantity: 'h', mm: 0.01 }));
    expect(!v.ok && v.errors.map((e) => e.message)).toEqual([
      'No machine mode of kind "throwawayFixedLead" is registered.',
      'No surface model of kind "throwawayDrum" is registered.',
    ]);
    const reply = await ask(drumQuestion({ quantity: 'h', mm: 0.01 }));
    expect(reply.ok).toBe(false);
  });

  it('registered, validation and the worker job answer them: the cylinder R100 at lead 12, tilt 0, both ways', async () => {
    const kindsBefore = [modeKinds(), surfaceKinds()];
    const product = await ask(productQuestion);
    removers.push(registerSurfaceModel(drumModel), registerMode(fixedLeadMode));
    expect(modeKinds()).toContain('throwawayFixedLead');
    expect(surfaceKinds()).toContain('throwawayDrum');

    const tool = { ...TOOL, leadAngleDeg: 12, tiltAngleDeg: 0 };
    const h = 0.01;
    const own = exactForward({ ...tool, pattern: 'zigzag', surface: DRUM_AS_CYLINDER, scallopHeightMm: h });
    const forward = await ask(drumQuestion({ quantity: 'h', mm: h }));
    if (!forward.ok) throw new Error(JSON.stringify(forward.errors));
    expect(forward.answer.intervalMm).toBe(own.intervalMm);
    expect(forward.answer.posture).toEqual({ leadAngleDeg: 12, tiltAngleDeg: 0, pattern: 'zigzag' });
    const L = 0.8 * own.intervalMm;
    const inverse = await ask(drumQuestion({ quantity: 'interval', mm: L }));
    if (!inverse.ok) throw new Error(JSON.stringify(inverse.errors));
    expect(inverse.answer.cuspHeightMm).toBe(
      exactInverse({ ...tool, pattern: 'zigzag', surface: DRUM_AS_CYLINDER, intervalMm: L }).cuspHeightMm,
    );

    // The mode's own parameters, its refusal on a surface it has no posture for, and the drum's limits.
    const steep = await ask(drumQuestion({ quantity: 'h', mm: h }, 45));
    expect(!steep.ok && steep.errors.map((e) => e.message)).toEqual([
      'Lead angle must be from 0 to 30 degrees on this head (got 45).',
    ]);
    const onPoint = await ask({
      ...drumQuestion({ quantity: 'h', mm: h }),
      surface: { kind: 'doublyCurved', feedRadiusMm: 50, crossRadiusMm: 50 } as Question['surface'],
    });
    expect(!onPoint.ok && onPoint.errors.map((e) => e.message)).toEqual([
      'The fixed-lead head has no posture on a surface of kind "doublyCurved": the plane or the drum only.',
    ]);
    const wide = await ask(drumQuestion({ quantity: 'interval', mm: 20 }));
    expect(!wide.ok && wide.errors[0]?.message).toMatch(/^Step-over L must be below \d+(\.\d+)? mm here \(got 20\)/);
    // A product mode over the throwaway surface: five-axis has a posture everywhere.
    const five = await ask({
      ...drumQuestion({ quantity: 'h', mm: h }),
      mode: { kind: 'fiveAxis', leadAngleDeg: 12, tiltAngleDeg: 0 } as Question['mode'],
    });
    expect(five.ok && five.answer.intervalMm).toBe(own.intervalMm);

    // Removed: the registries and the answers are as before.
    for (const remove of removers) remove();
    removers = [];
    expect([modeKinds(), surfaceKinds()]).toEqual(kindsBefore);
    expect((await ask(drumQuestion({ quantity: 'h', mm: h }))).ok).toBe(false);
    const again = await ask(productQuestion);
    expect(again.ok && product.ok && again.answer).toEqual(product.ok && product.answer);
  });
});
